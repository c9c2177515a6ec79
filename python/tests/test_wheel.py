"""The wheel scripts/wheel.sh builds, installed by one ``pip install`` into a fresh virtual
environment (``python3 -m venv``, nothing else in it): ``import ruledlab`` computes the invariants
of NumPy rulings headless — no kernel, no view, no browser — and carries the one-file script of
the view."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from ruledlab import RuledSurface

REPO = Path(__file__).resolve().parents[2]
PROBE = """
import json, sys
import numpy as np
import ruledlab, ruledlab._script
u = np.linspace(0, 2 * np.pi, 24, endpoint=False)
a = np.stack([np.cos(u), np.sin(u), -np.ones(24)], axis=1)
b = np.stack([np.cos(u + 1.2), np.sin(u + 1.2), np.ones(24)], axis=1)
inv = ruledlab.RuledSurface.from_segments(a, b).invariants()
print(json.dumps({
    "file": ruledlab.__file__, "script": str(ruledlab._script.script_path()),
    "distribution": inv["distribution"].tolist(), "striction": inv["striction"].tolist(),
    "python": sys.version_info[:2],
}))
"""


def test_one_pip_install_into_a_fresh_venv_computes_headless(tmp_path):
    wheels = sorted((REPO / "dist" / "python").glob("ruledlab-*.whl"))
    if not wheels:
        pytest.fail("no wheel in dist/python/: run bash scripts/wheel.sh")
    venv = tmp_path / "venv"
    # the interpreter this venv's Python came from, as a user's `python3 -m venv` would
    base = getattr(sys, "_base_executable", sys.executable)
    subprocess.run([base, "-m", "venv", str(venv)], check=True)
    python = venv / "bin" / "python"
    subprocess.run([python, "-m", "pip", "install", "-q", "--disable-pip-version-check", str(wheels[-1])], check=True)
    out = subprocess.run([python, "-c", PROBE], cwd=tmp_path, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    got = json.loads(out.stdout)
    assert got["file"].startswith(str(venv)) and got["script"].startswith(str(venv))
    assert Path(got["script"]).read_bytes() == (REPO / "dist" / "ruledlab-embed.js").read_bytes()
    u = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    a = np.stack([np.cos(u), np.sin(u), -np.ones(24)], axis=1)
    b = np.stack([np.cos(u + 1.2), np.sin(u + 1.2), np.ones(24)], axis=1)
    here = RuledSurface.from_segments(a, b).invariants()
    assert got["distribution"] == here["distribution"].tolist()
    assert got["striction"] == here["striction"].tolist()


def test_the_wheel_builds_from_a_plain_venv(tmp_path):
    """What the book's one command does, from ``python3 -m venv`` with nothing added (its pip and,
    on Python < 3.12, its old setuptools): pip builds with isolation, fetching the build backend
    python/pyproject.toml pins (maturin), so nothing of .venv/ is needed."""
    import zipfile

    if not (REPO / "python" / "ruledlab" / "static" / "ruledlab-embed.js").exists():
        pytest.fail("python/ruledlab/static/ruledlab-embed.js is missing: run bash scripts/wheel.sh")
    venv = tmp_path / "venv"
    base = getattr(sys, "_base_executable", sys.executable)
    subprocess.run([base, "-m", "venv", str(venv)], check=True)
    python = venv / "bin" / "python"
    out = subprocess.run(
        [python, "-m", "pip", "wheel", "-q", "--disable-pip-version-check", "--no-deps", "-w", str(tmp_path / "dist"),
         str(REPO / "python")],
        capture_output=True, text=True,
    )  # fmt: skip
    assert out.returncode == 0, out.stderr[-3000:]
    (wheel,) = (tmp_path / "dist").glob("ruledlab-*-cp39-abi3-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    assert any(n.startswith("ruledlab/_core") and n.endswith(".so") for n in names), names
    assert "ruledlab/static/ruledlab-embed.js" in names and "ruledlab/widget.js" in names
    assert "ruledlab/_still.py" in names and "ruledlab/_core.pyi" in names and "ruledlab/py.typed" in names
