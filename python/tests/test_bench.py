"""The benchmark against careful NumPy (bench/python.py) runs — at 2000 rulings, without writing
the book: it is timed by npm run bench, never judged by a test — and finds the same numbers."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def test_the_benchmark_runs_and_agrees_with_numpy():
    out = subprocess.run(
        [sys.executable, str(REPO / "bench" / "python.py"), "--no-write", "--n", "2000"],
        capture_output=True,
        text=True,
        check=True,
    )
    rows = [line for line in out.stdout.splitlines() if line.startswith("| ") and "ms" not in line]
    assert len(rows) == 4, out.stdout
    assert rows[-1].endswith("| 0 (bit for bit) |"), rows[-1]
    for row in rows[:3]:
        assert float(row.split("|")[-2]) < 1e-9, row
