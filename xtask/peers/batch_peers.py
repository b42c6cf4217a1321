#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The Python timings of `cargo xtask bench batch` (xtask/src/bench/batch.rs).

usage: batch_peers.py throughput RUNS OUT_DIR SCAN...
         the scans fitted by harmonic.fit_many on this machine, then by harmonic.fit_many over
         a Dask distributed.LocalCluster of 2 single-threaded workers (started, and harmonic
         imported on them, before the clock); each way one untimed run, then RUNS timed runs,
         each into a fresh folder under OUT_DIR; every scan must fit. Prints
         {"local": [seconds per run], "dask": [seconds per run], "scans": count}.
       batch_peers.py overhead RUNS N,REPS ...
         for each n, the planar curve through x_k = (3 sin 0.37k, cos 1.3k + 0.01k), k < n,
         sampled at 16n uniform parameters by harmonic.HarmonicCurve(x).sample_uniform(16 * n):
         one untimed run, then RUNS runs of REPS calls each. Prints {"seconds": [[seconds per
         call, per run] per n]}.
Exit status 3: harmonic cannot be imported; 4: distributed cannot be imported (throughput).
"""
import json
import os
import shutil
import sys
import time


def import_harmonic():
    try:
        import harmonic
    except ImportError as e:
        print(f"import harmonic: {e}", file=sys.stderr)
        sys.exit(3)
    return harmonic


def fit_all(harmonic, scans, out, client=None):
    """Seconds to fit every scan into the fresh folder `out`; fails unless every scan is ok."""
    shutil.rmtree(out, ignore_errors=True)
    start = time.perf_counter()
    records = harmonic.fit_many(scans, out, client=client)
    seconds = time.perf_counter() - start
    failed = [r for r in records if r.get("status") != "ok"]
    if len(records) != len(scans) or failed:
        detail = "; ".join(f"{r.get('input')}: {r.get('error')}" for r in failed)
        sys.exit(f"fit_many fitted {len(records) - len(failed)} of {len(scans)} scans: {detail}")
    # Each output written in this run's folder (not a record handed back from another batch).
    elsewhere = [r["output"] for r in records
                 if os.path.dirname(os.path.abspath(r["output"])) != os.path.abspath(out)
                 or not os.path.isfile(r["output"])]
    if elsewhere:
        sys.exit(f"fit_many did not write {', '.join(elsewhere)} into {out}")
    return seconds


def throughput(runs, out_dir, scans):
    harmonic = import_harmonic()
    try:
        from distributed import Client, LocalCluster
    except ImportError as e:
        print(f"import distributed: {e}", file=sys.stderr)
        sys.exit(4)
    local = [fit_all(harmonic, scans, os.path.join(out_dir, f"local-{k}")) for k in range(runs + 1)]
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        # The workers' start-up and import are not the batch's.
        client.run(lambda: __import__("harmonic"))
        dask = [fit_all(harmonic, scans, os.path.join(out_dir, f"dask-{k}"), client)
                for k in range(runs + 1)]
    # The first run of each way warms up.
    print(json.dumps({"local": local[1:], "dask": dask[1:], "scans": len(scans)}))


def overhead(runs, cases):
    harmonic = import_harmonic()
    import numpy as np

    out = []
    for n, reps in cases:
        k = np.arange(n)
        x = np.column_stack([3.0 * np.sin(0.37 * k), np.cos(1.3 * k) + 0.01 * k])
        curve = harmonic.HarmonicCurve(x)
        count = 16 * n
        times = []
        for _ in range(runs + 1):  # the first run warms up
            start = time.perf_counter()
            for _ in range(reps):
                y = curve.sample_uniform(count)
            times.append((time.perf_counter() - start) / reps)
        assert y.shape == (count, 2), y.shape
        out.append(times[1:])
    print(json.dumps({"seconds": out}))


def main(args):
    if len(args) >= 4 and args[0] == "throughput":
        throughput(int(args[1]), args[2], args[3:])
    elif len(args) >= 3 and args[0] == "overhead":
        cases = [tuple(int(v) for v in a.split(",")) for a in args[2:]]
        overhead(int(args[1]), cases)
    else:
        print(__doc__, file=sys.stderr)
        sys.exit(2)


if __name__ == "__main__":
    main(sys.argv[1:])
