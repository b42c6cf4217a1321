# SPDX-License-Identifier: MIT
"""Scans fitted per minute on this machine, four ways, on the same scans: one `hi fit` process
per scan (one after the other), `hi fit SCAN... --out-dir` (one process, scans in parallel),
`harmonic.fit_many` on this machine, and `harmonic.fit_many` over a two-worker Dask
`LocalCluster`; and the Python calls' overhead against the Rust work for a small and a large
input (the Rust figure is `cargo xtask bench curves`'s). Prints Markdown tables (docs/batch.md).

    python3 crates/hi-py/bench/batch_throughput.py [SCAN...]   # default: fixtures/models/*
"""

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import harmonic

ROOT = Path(__file__).resolve().parents[3]
HI = os.environ.get("HI_BIN", str(ROOT / "target" / "release" / "hi"))


def timed(f):
    start = time.perf_counter()
    f()
    return time.perf_counter() - start


def per_process(scans, out):
    for scan in scans:
        subprocess.run([HI, "fit", str(scan), "-o", str(out / (Path(scan).stem + ".glb"))],
                       check=True, capture_output=True)


def batch_cli(scans, out):
    subprocess.run([HI, "fit", *map(str, scans), "--out-dir", str(out)], check=True,
                   capture_output=True)


def cluster(scans, out):
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as c, \
            Client(c) as client:
        # Started before the clock: the workers' start-up is not the batch's.
        client.run(lambda: __import__("harmonic"))
        return timed(lambda: harmonic.fit_many(scans, out, client=client))


def main():
    scans = sys.argv[1:] or sorted(str(p) for p in (ROOT / "fixtures" / "models").iterdir()
                                   if p.suffix in {".obj", ".pts", ".stl", ".off", ".ply"})
    print(f"{len(scans)} scans, {os.cpu_count()} cores\n")
    print("| way | seconds | scans per minute |\n|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        rows = [
            ("one `hi fit` process per scan", timed(lambda: per_process(scans, Path(tmp)))),
            ("`hi fit SCAN... --out-dir`", timed(lambda: batch_cli(scans, Path(tmp, "b")))),
            ("`fit_many` (this machine)", timed(lambda: harmonic.fit_many(scans, Path(tmp, "c")))),
            ("`fit_many` (Dask, 2 workers)", cluster(scans, Path(tmp, "d"))),
        ]
    for way, seconds in rows:
        print(f"| {way} | {seconds:.1f} | {60 * len(scans) / seconds:.1f} |")
    # The Python call against the Rust call: the curve of `cargo xtask bench curves`
    # (docs/performance.md, "FFT (ours)", one thread), sampled at N = 16n, median of 7 runs.
    print("\n| call | n | N | Python (ms) |\n|---|---|---|---|")
    for n in [16, 16384]:
        k = np.arange(n)
        x = np.column_stack([3 * np.sin(0.37 * k), np.cos(1.3 * k) + 0.01 * k])
        curve = harmonic.HarmonicCurve(x)
        curve.sample_uniform(16 * n)
        reps = 2000 if n < 100 else 20
        runs = sorted(timed(lambda: [curve.sample_uniform(16 * n) for _ in range(reps)]) / reps
                      for _ in range(7))
        print(f"| `curve.sample_uniform(16 * n)` | {n} | {16 * n} | {1e3 * runs[3]:.4f} |")

if __name__ == "__main__":
    main()
