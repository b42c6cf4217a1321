#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Peer timings for `cargo xtask bench curves` (xtask/src/bench/curves.rs).

usage: curve_peers.py RUNS N1 N2 ...
         for each n, the n planar points x_k = (3 sin 0.37k, cos 1.3k + 0.01k) sampled at 16n
         uniform parameters by scipy.signal.resample along axis 0 (the same periodic spectral
         zero-padding as the harmonic curve, docs/math.md §7); prints {"seconds": [median per n]},
         each the median of RUNS runs after one warm-up.
Exit status 3: scipy is not installed.
"""
import json, sys, time


def main(runs, sizes):
    try:
        import numpy as np
        from scipy.signal import resample
    except ImportError:
        sys.exit(3)
    out = []
    for n in sizes:
        k = np.arange(n)
        x = np.stack([np.sin(k * 0.37) * 3.0, np.cos(k * 1.3) + 0.01 * k], axis=1)
        times = []
        for _ in range(runs + 1):  # the first run warms up
            t = time.perf_counter()
            y = resample(x, 16 * n, axis=0)
            times.append(time.perf_counter() - t)
        assert y.shape == (16 * n, 2)
        times = sorted(times[1:])
        out.append(times[(len(times) - 1) // 2])
    print(json.dumps({"seconds": out}))


if __name__ == "__main__":
    if len(sys.argv) >= 3:
        main(int(sys.argv[1]), [int(a) for a in sys.argv[2:]])
    else:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
