"""The package's type stubs (``ruledlab/_core.pyi`` and ``py.typed``) satisfy ``mypy --strict`` on
a program that uses them, ``examples/invariants.py`` (run for real too), and catch a wrong use."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
EXAMPLE = REPO / "examples" / "invariants.py"
WRONG = """import ruledlab
s = ruledlab.RuledSurface([[0, 0, 0, 1, 0, 0], [0, 1, 0, 1, 1, 1]])
x: str = s.invariants()["angle"]
n: int = ruledlab.AnalyticSurface.formula_presets()
"""


def test_mypy_strict_accepts_the_example_and_refuses_a_wrong_use(tmp_path):
    (tmp_path / "wrong.py").write_text(WRONG)
    # (the cache lives in .venv/, beside the packages it describes)
    out = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--cache-dir", str(REPO / ".venv" / "mypy-cache"), str(EXAMPLE),
         str(tmp_path / "wrong.py")],
        capture_output=True,
        text=True,
    )  # fmt: skip
    errors = [line for line in out.stdout.splitlines() if ": error:" in line]
    assert len(errors) == 2, out.stdout + out.stderr
    assert "wrong.py:3: error: Incompatible types in assignment" in errors[0]
    # (a class's method named list shadows the builtin in its later annotations: they say builtins.list)
    assert "wrong.py:4: error: Incompatible types in assignment" in errors[1]


def test_the_example_runs_headless():
    out = subprocess.run([sys.executable, str(EXAMPLE)], capture_output=True, text=True, check=True)
    lines = out.stdout.splitlines()
    assert lines[0] == "200 rulings, δ from -1.461725 to -1.461725"
    assert lines[3].startswith("degenerate | RuledSurface.from_segments: ruling 0 has zero length")
    assert lines[4] == "a regulus: regulus, nullity 3"


def test_mypy_strict_accepts_the_package_itself():
    # the package's own modules (the widget, its data, its figures), with its configuration
    out = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--config-file", str(REPO / "python" / "pyproject.toml"),
         "--cache-dir", str(REPO / ".venv" / "mypy-cache"), str(REPO / "python" / "ruledlab")],
        capture_output=True,
        text=True,
    )  # fmt: skip
    assert out.returncode == 0, out.stdout + out.stderr
