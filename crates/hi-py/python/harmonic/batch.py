# SPDX-License-Identifier: MIT
"""Batches of scans fitted into one folder, on this machine or over a Dask cluster.

Both ways run the same Rust code as ``hi fit SCAN... --out-dir DIR`` (the crate ``hi-fit``):
the same inputs (files, folders, glob patterns), the same outputs ``DIR/<name>.<format>``, the
same line per scan in ``DIR/summary.jsonl`` and the same resume rule (a scan with an ``ok``
line whose output exists is skipped unless ``force``). With a Dask ``distributed.Client`` the
driver plans the batch, each task fits one scan on a worker (the fit itself uses the worker's
cores, with the GIL released), and the driver appends each task's line to the summary as it
completes. Paths must be visible to the workers (a shared file system); ``s3://...`` and other
``fsspec`` URLs are staged through a local folder on each worker (see docs/batch.md).
"""

from __future__ import annotations

import json
import os
import tempfile
import uuid
from typing import Any, Iterable, List, Optional, Sequence, Union

from . import _harmonic

PathLike = Union[str, "os.PathLike[str]"]

#: The name of the file of a batch's records in its output folder.
SUMMARY_FILE = "summary.jsonl"


def _is_url(path: str) -> bool:
    return "://" in path


def fit_many(
    paths: Union[PathLike, Sequence[PathLike]],
    out_dir: PathLike,
    *,
    client: Any = None,
    format: str = "glb",
    force: bool = False,
    jobs: Optional[int] = None,
) -> List[dict]:
    """Fit every scan of ``paths`` into ``out_dir``, as ``hi fit SCAN... --out-dir DIR`` does.

    ``paths`` are scan files, folders of scans and glob patterns. Each scan ``NAME.EXT`` is
    written to ``out_dir/NAME.<format>`` (``glb``, ``gltf``, ``obj`` or ``json``) and one JSON
    line is appended to ``out_dir/summary.jsonl`` (input, output, status, method, errors both
    ways, times, warnings, or the error that stopped it). A scan that cannot be read or fitted
    is recorded and the rest go on. Scans already done are skipped unless ``force``.

    Without ``client``, the scans are fitted on this machine, ``jobs`` at a time (default: the
    number of cores). With a Dask ``distributed.Client``, each scan is one task on the
    cluster's workers; the outputs and summary lines are those of the one-machine run.

    Returns the records of the scans fitted (or tried) as dicts, in the order of the inputs.

    >>> import harmonic, tempfile
    >>> harmonic.fit_many(["no-such-scan.obj"], tempfile.mkdtemp())[0]["status"]
    'failed'
    """
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    given = [os.fspath(p) for p in paths]
    out = os.fspath(out_dir)
    if client is None:
        if _is_url(out) or any(_is_url(p) for p in given):
            raise ValueError(
                "object storage paths need a Dask client (fit_many(..., client=...)): "
                "the workers stage them through local folders"
            )
        scans = _harmonic.expand(given)
        lines, _skipped = _harmonic.fit_many_local(scans, out, format, force, jobs)
        return [json.loads(line) for line in lines]
    return _fit_on_cluster(given, out, client, format, force)


def _fit_on_cluster(
    given: List[str], out: str, client: Any, format: str, force: bool
) -> List[dict]:
    """The batch as one Dask task per scan; the driver keeps the summary."""
    from distributed import as_completed

    if _is_url(out) or any(_is_url(p) for p in given):
        jobs, summary = _plan_remote(given, out, format, force)
        submit = _fit_remote
    else:
        scans = _harmonic.expand(given)
        jobs, _skipped = _harmonic.plan(scans, out, format, force)
        jobs = [(os.fspath(i), os.fspath(o)) for i, o in jobs]
        summary = None
        submit = _fit_local_path
    # Keys unique to this call: a key the scheduler still holds from an earlier batch would
    # hand back that batch's result (its scan, its folder) instead of fitting this one.
    batch = uuid.uuid4().hex
    futures = {
        client.submit(submit, i, o, format, key=f"harmonic-fit-{batch}-{n}", pure=False): n
        for n, (i, o) in enumerate(jobs)
    }
    records: List[Optional[dict]] = [None] * len(jobs)
    for future in as_completed(futures):
        line = future.result()
        if summary is None:
            _harmonic.append_line(out, line)
        else:
            summary.append(line)
        records[futures[future]] = json.loads(line)
    if summary is not None:
        _write_remote_summary(out, summary)
    return [r for r in records if r is not None]


def _fit_local_path(input: str, output: str, format: str) -> str:
    """One scan on a worker, paths on a shared file system: its summary line."""
    from harmonic import _harmonic as native

    return native.fit_one(input, output, format)


def _fit_remote(input: str, output: str, format: str) -> str:
    """One scan on a worker through ``fsspec``: staged in, fitted, staged out."""
    import fsspec

    from harmonic import _harmonic as native

    with tempfile.TemporaryDirectory() as tmp:
        local_in = os.path.join(tmp, os.path.basename(input.split("://", 1)[-1]))
        local_out = os.path.join(tmp, "out", os.path.basename(output.split("://", 1)[-1]))
        os.makedirs(os.path.dirname(local_out))
        try:
            with fsspec.open(input, "rb") as src, open(local_in, "wb") as dst:
                dst.write(src.read())
        except OSError as e:
            seconds = {"read": 0.0, "fit": 0.0, "write": 0.0, "total": 0.0}
            failed = {"input": input, "output": output, "status": "failed", "files": [],
                      "seconds": seconds, "warnings": [], "error": f"cannot read {input}: {e}"}
            return json.dumps(failed)
        record = json.loads(native.fit_one(local_in, local_out, format))
        for name in os.listdir(os.path.dirname(local_out)):
            target = output.rsplit("/", 1)[0] + "/" + name
            with open(os.path.join(os.path.dirname(local_out), name), "rb") as src:
                with fsspec.open(target, "wb") as dst:
                    dst.write(src.read())
        record["input"], record["output"] = input, output
        folder = output.rsplit("/", 1)[0]
        record["files"] = [folder + "/" + os.path.basename(f) for f in record["files"]]
        record["warnings"] = [w.replace(local_in, input) for w in record["warnings"]]
        if "error" in record:
            record["error"] = record["error"].replace(local_in, input)
        return json.dumps(record)


def _plan_remote(given: List[str], out: str, format: str, force: bool):
    """The jobs of a batch on object storage, by the same resume rule as ``hi-fit``'s plan."""
    import fsspec

    fs, root = fsspec.core.url_to_fs(out)
    scans: List[str] = []
    for p in given:
        pfs, ppath = fsspec.core.url_to_fs(p)
        protocol = p.split("://", 1)[0] + "://" if _is_url(p) else ""
        if any(ch in ppath for ch in "*?["):
            scans.extend(sorted(protocol + m for m in pfs.glob(ppath)))
        else:
            scans.append(p)
    prefix = out.rstrip("/")
    done = set()
    summary: List[str] = []
    if not force and fs.exists(root.rstrip("/") + "/" + SUMMARY_FILE):
        with fs.open(root.rstrip("/") + "/" + SUMMARY_FILE, "r") as f:
            summary = [line.rstrip("\n") for line in f if line.strip()]
        for line in summary:
            try:
                r = json.loads(line)
            except ValueError:
                continue
            if r.get("status") == "ok":
                done.add((r.get("input"), r.get("output")))
    jobs = []
    seen = {}
    for s in scans:
        name = os.path.splitext(os.path.basename(s.split("://", 1)[-1]))[0]
        output = f"{prefix}/{name}.{format}"
        if output in seen:
            raise ValueError(
                f"{seen[output]} and {s} would both be written to {output}: "
                "fit them into different folders"
            )
        seen[output] = s
        ofs, opath = fsspec.core.url_to_fs(output)
        if (s, output) in done and ofs.exists(opath):
            continue
        jobs.append((s, output))
    return jobs, summary


def _write_remote_summary(out: str, lines: Iterable[str]) -> None:
    """Writes the summary of a batch on object storage (which has no appends) whole."""
    import fsspec

    with fsspec.open(out.rstrip("/") + "/" + SUMMARY_FILE, "w") as f:
        for line in lines:
            f.write(line + "\n")
