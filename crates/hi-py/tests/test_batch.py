# SPDX-License-Identifier: MIT
"""``fit_many``: the batch of ``hi fit SCAN... --out-dir DIR`` from Python, on this machine and
over a two-worker Dask ``LocalCluster``, whose outputs must equal the one-machine batch's byte
for byte, with the same summary lines (times apart)."""

import json
from pathlib import Path

import pytest

import harmonic
from conftest import ellipsoid, run_hi, write_xyz


@pytest.fixture
def scans(tmp_path):
    folder = tmp_path / "scans"
    folder.mkdir()
    write_xyz(folder / "round.xyz", ellipsoid(400))
    write_xyz(folder / "long.xyz", ellipsoid(400, (2.0, 1.0, 1.0)))
    write_xyz(folder / "flat.xyz", ellipsoid(500, (1.5, 1.0, 0.5)))
    (folder / "broken.xyz").write_text("0 0 0\n1 0 0\n0 1\n")
    return folder


def summary(out: Path):
    return [json.loads(line) for line in (out / "summary.jsonl").read_text().splitlines()]


def without_times(records):
    """Records by input, their times left out (they differ from run to run)."""
    return sorted(({k: v for k, v in r.items() if k != "seconds"} for r in records),
                  key=lambda r: r["input"])


def outputs(out: Path):
    return {p.name: p.read_bytes() for p in sorted(out.iterdir()) if p.name != "summary.jsonl"}


def test_a_local_batch_records_every_scan_and_resumes(scans, tmp_path):
    out = tmp_path / "out"
    records = harmonic.fit_many([scans], out)
    assert [Path(r["input"]).name for r in records] == ["broken.xyz", "flat.xyz", "long.xyz",
                                                        "round.xyz"]
    status = {Path(r["input"]).name: r["status"] for r in records}
    assert status == {"broken.xyz": "failed", "flat.xyz": "ok", "long.xyz": "ok",
                      "round.xyz": "ok"}
    broken = next(r for r in records if r["status"] == "failed")
    assert "XYZ, line 3: expected 3 numbers" in broken["error"]
    assert sorted(outputs(out)) == ["flat.glb", "long.glb", "round.glb"]
    assert without_times(summary(out)) == without_times(records)
    # Again: only the failed scan is tried; with force, all of them.
    again = harmonic.fit_many([scans], out)
    assert [r["status"] for r in again] == ["failed"]
    assert len(summary(out)) == 5
    assert len(harmonic.fit_many([str(scans / "*.xyz")], out, force=True)) == 4


def test_the_command_line_batch_writes_the_same_files(scans, tmp_path):
    harmonic.fit_many([scans], tmp_path / "py", jobs=1)
    cli = run_hi("fit", scans, "--out-dir", tmp_path / "cli")
    assert cli.returncode == 2 and "1 scan failed" in cli.stderr
    assert outputs(tmp_path / "py") == outputs(tmp_path / "cli")
    py = [dict(r, input=Path(r["input"]).name, output=Path(r["output"]).name, files=[])
          for r in summary(tmp_path / "py")]
    cli = [dict(r, input=Path(r["input"]).name, output=Path(r["output"]).name, files=[])
           for r in summary(tmp_path / "cli")]
    assert without_times(py) == without_times(cli)


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c


def test_a_dask_cluster_writes_what_one_machine_writes(scans, tmp_path, client):
    local = harmonic.fit_many([scans], tmp_path / "local")
    remote = harmonic.fit_many([scans], tmp_path / "cluster", client=client)
    assert len(client.scheduler_info()["workers"]) == 2
    assert outputs(tmp_path / "local") == outputs(tmp_path / "cluster")

    def relative(records, out):
        return without_times(
            dict(r, output=Path(r["output"]).name, files=[Path(f).name for f in r["files"]])
            for r in records
        )

    assert relative(remote, "cluster") == relative(local, "local")
    assert relative(summary(tmp_path / "cluster"), "") == relative(summary(tmp_path / "local"), "")
    # The cluster's run resumes by the same rule.
    again = harmonic.fit_many([scans], tmp_path / "cluster", client=client)
    assert [r["status"] for r in again] == ["failed"]


def test_each_batch_on_one_client_fits_its_own_scans(scans, tmp_path, client):
    # Two batches of the same scans on the same client, one after the other, into two
    # folders: the second must fit its scans into its own folder, not hand back the first's.
    first = harmonic.fit_many([scans], tmp_path / "first", client=client)
    second = harmonic.fit_many([scans], tmp_path / "second", client=client)
    assert [Path(r["output"]).parent.name for r in first] == ["first"] * 4
    assert [Path(r["output"]).parent.name for r in second] == ["second"] * 4
    assert sorted(outputs(tmp_path / "second")) == ["flat.glb", "long.glb", "round.glb"]
    assert outputs(tmp_path / "first") == outputs(tmp_path / "second")


def test_object_storage_urls_are_staged_through_the_workers(scans, tmp_path, client):
    pytest.importorskip("fsspec")
    local = harmonic.fit_many([scans / "round.xyz", scans / "long.xyz"], tmp_path / "local")
    urls = [f"file://{scans / 'round.xyz'}", f"file://{scans / 'long.xyz'}"]
    remote = harmonic.fit_many(urls, f"file://{tmp_path / 'bucket'}", client=client)
    assert [r["status"] for r in remote] == ["ok", "ok"]
    assert [r["input"] for r in remote] == urls
    assert outputs(tmp_path / "local") == outputs(tmp_path / "bucket")
    assert len(summary(tmp_path / "bucket")) == 2
    assert harmonic.fit_many(urls, f"file://{tmp_path / 'bucket'}", client=client) == []
