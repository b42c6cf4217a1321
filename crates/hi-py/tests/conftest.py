# SPDX-License-Identifier: MIT
"""What the tests of the ``harmonic`` package share: the repository's folders, the shared
third-party models (skipped with a reason when ``HI_SKIP_SHARED_DATA=1`` or absent), and the
``hi`` command of the same workspace, whose output the package must reproduce."""

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
MODELS = ROOT / "fixtures" / "models"
SHARED = ROOT.parent / "shared" / "data" / "models"


def shared_model(name: str) -> Path:
    """A third-party model beside the repository, or a skip saying why it is not there."""
    if os.environ.get("HI_SKIP_SHARED_DATA") == "1":
        pytest.skip("skipped, as HI_SKIP_SHARED_DATA=1 asks: the shared models are not here")
    path = SHARED / name
    if not SHARED.is_dir():
        pytest.fail(
            f"the shared models ({SHARED}) are absent; HI_SKIP_SHARED_DATA=1 skips their checks"
        )
    if not path.is_file():
        pytest.fail(f"the shared model {name} is missing from {SHARED}")
    return path


def hi_binary() -> Path:
    """The workspace's ``hi`` (``HI_BIN``, else the release build, else the debug build)."""
    for candidate in [os.environ.get("HI_BIN"), ROOT / "target" / "release" / "hi",
                      ROOT / "target" / "debug" / "hi", shutil.which("hi")]:
        if candidate and Path(candidate).is_file():
            return Path(candidate)
    pytest.fail("no hi binary: build it with `cargo build --release -p hi-cli` (or set HI_BIN)")


def run_hi(*args: str, input: str = None) -> subprocess.CompletedProcess:
    """Runs ``hi`` with ``args``."""
    return subprocess.run([str(hi_binary()), *map(str, args)], input=input,
                          capture_output=True, text=True)


def hi_json(*args: str, input: str = None):
    """Runs ``hi`` that must succeed and returns its JSON."""
    out = run_hi(*args, input=input)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def hi_error(*args: str) -> str:
    """Runs ``hi`` that must fail with bad input and returns its message without ``hi: ``."""
    out = run_hi(*args)
    assert out.returncode == 2, (out.returncode, out.stderr)
    line = out.stderr.strip()
    assert line.startswith("hi: ") and "\n" not in line, line
    return line[len("hi: "):]


def ellipsoid(n: int, axes=(1.0, 1.0, 1.0)):
    """``n`` points spread over an ellipsoid (a golden-angle spiral)."""
    import numpy as np

    k = np.arange(n)
    z = 1.0 - (2 * k + 1) / n
    s = np.sqrt(1.0 - z * z)
    phi = k * np.pi * (3.0 - np.sqrt(5.0))
    return np.column_stack([axes[0] * s * np.cos(phi), axes[1] * s * np.sin(phi), axes[2] * z])


def write_xyz(path: Path, points) -> Path:
    """Writes points as an XYZ file, each coordinate in its shortest round-trip form."""
    path.write_text("".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in points.tolist()))
    return path
