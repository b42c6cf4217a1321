#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Time and peak memory of one whole process, for `cargo xtask bench fit`
(xtask/src/bench/clouds.rs).

usage: measure.py TIMEOUT PROGRAM [ARGS...]
  Runs PROGRAM ARGS once as a child process (its stdout and stderr captured, its stdin empty)
  and prints one line of JSON:
    seconds    wall time from starting the child to its exit (time.perf_counter);
    peak_kib   the child's peak resident set size, getrusage(RUSAGE_CHILDREN).ru_maxrss, in KiB
               (Linux counts kibibytes); the only child this process waits for is PROGRAM, so it
               is PROGRAM's own peak (threads included; a process PROGRAM starts and waits for
               would count on its own, not added);
    status     the exit status, or null when the child was killed;
    timed_out  whether the child ran past TIMEOUT seconds and was killed;
    stderr     the last 4 000 characters of the child's stderr.
  The exit status of this script is 0 whenever it could run PROGRAM at all (the child's failure
  is reported in the JSON), 2 for bad usage, 127 when PROGRAM cannot be started.

On Linux the child starts as a copy of this process (fork or vfork) and keeps the larger of
that copy's and its own resident set as its peak, so a measurement cannot go below this
interpreter's own size (about 10 MiB): `measure.py 60 true` shows that floor.
"""
import json
import resource
import subprocess
import sys
import time


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    try:
        timeout = float(sys.argv[1])
    except ValueError:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    command = sys.argv[2:]
    timed_out = False
    start = time.perf_counter()
    try:
        child = subprocess.Popen(
            command, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE
        )
    except OSError as e:
        print(f"measure.py: cannot start {command[0]}: {e}", file=sys.stderr)
        sys.exit(127)
    try:
        _, err = child.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        child.kill()
        _, err = child.communicate()
    seconds = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    status = child.returncode if child.returncode >= 0 else None
    text = err.decode("utf-8", errors="replace")[-4000:]
    print(json.dumps({
        "seconds": seconds,
        "peak_kib": peak,
        "status": status,
        "timed_out": timed_out,
        "stderr": text,
    }))


if __name__ == "__main__":
    main()
