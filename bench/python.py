"""The core from Python against careful vectorised NumPy, in one process (npm run bench):
the invariants of Section 2 of 10⁶ rulings and one step of the four-point scheme (8) on 10⁶
points, each timed through ``ruledlab`` (the wheel installed in .venv/) and through the NumPy
baselines the tests keep (python/tests/baselines.py), the results compared. Rewrites the table
between the ``bench-python`` markers of docs/src/internals/benchmarks.md.

Run: ``.venv/bin/python bench/python.py`` (``--no-write`` leaves the book alone; ``--n 2000`` times
2000 rulings and points instead, as python/tests/test_bench.py does to keep the script working).
"""

from __future__ import annotations

import datetime
import os
import platform
import statistics
import sys
import time
from pathlib import Path
from typing import Callable

import numpy as np

import ruledlab

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "python" / "tests"))
import baselines  # noqa: E402

BOOK = REPO / "docs" / "src" / "internals" / "benchmarks.md"
ROUNDS = 9


def median_ms(calls: dict[str, Callable[[], object]]) -> dict[str, float]:
    """Median wall time of each call over ROUNDS rounds, the calls interleaved round by round (the
    machine's drift shared), after one warm-up round."""
    times: dict[str, list[float]] = {name: [] for name in calls}
    for round_ in range(ROUNDS + 1):
        for name, call in calls.items():
            start = time.perf_counter()
            call()
            elapsed = time.perf_counter() - start
            if round_:
                times[name].append(1e3 * elapsed)
    return {name: statistics.median(t) for name, t in times.items()}


def worst(got: dict[str, np.ndarray], want: dict[str, np.ndarray]) -> float:
    """The largest difference of two results' arrays relative to their scale (NaN where both are)."""
    out = 0.0
    for key, value in want.items():
        a, b = np.asarray(got[key], dtype=float), np.asarray(value, dtype=float)
        assert a.shape == b.shape and np.array_equal(np.isnan(a), np.isnan(b)), key
        finite = np.isfinite(b)
        out = max(out, float(np.max(np.abs(a[finite] - b[finite]) / np.maximum(1.0, np.abs(b[finite])), initial=0.0)))
    return out


def main() -> None:
    n = int(sys.argv[sys.argv.index("--n") + 1]) if "--n" in sys.argv else 1_000_000
    rng = np.random.default_rng(2026)
    # rulings of a twisted strip, each pair well inside the non-parallel range
    u = np.linspace(0.0, 40.0, n)
    a = np.stack([np.cos(u), np.sin(u), 0.1 * u], axis=1) + 1e-3 * rng.normal(size=(n, 3))
    b = a + np.stack([-np.sin(2 * u), np.cos(2 * u), np.ones(n)], axis=1)
    segments = np.hstack([a, b])
    surface = ruledlab.RuledSurface.from_segments(a, b)
    points = a.copy()

    same_inv = worst(ruledlab.RuledSurface.from_segments(a, b).invariants(), baselines.invariants(a, b))
    fp_core = ruledlab.subdivide_polygon(points, scheme="four-point")
    fp_numpy = baselines.four_point(points)
    same_fp = float(np.max(np.abs(fp_core - fp_numpy)))
    bitwise = bool(np.array_equal(fp_core, fp_numpy))

    t = median_ms(
        {
            "inv_core": lambda: ruledlab.RuledSurface.from_segments(a, b).invariants(),
            "inv_core_one": lambda: ruledlab.RuledSurface(segments).invariants(),
            "inv_core_only": lambda: surface.invariants(),
            "inv_numpy": lambda: baselines.invariants(a, b),
            "fp_core": lambda: ruledlab.subdivide_polygon(points, scheme="four-point"),
            "fp_numpy": lambda: baselines.four_point(points),
        }
    )
    rows = [
        (
            "invariants (1)–(7): `RuledSurface.from_segments(a, b).invariants()`",
            t["inv_core"],
            t["inv_numpy"],
            f"{same_inv:.1e}",
        ),
        (
            "the same from one (N, 6) array: `RuledSurface(segments).invariants()`",
            t["inv_core_one"],
            t["inv_numpy"],
            f"{same_inv:.1e}",
        ),
        ("`invariants()` of a surface already made", t["inv_core_only"], t["inv_numpy"], f"{same_inv:.1e}"),
        (
            "four-point step (8) on 10⁶ points: `subdivide_polygon(p, scheme=\"four-point\")`",
            t["fp_core"],
            t["fp_numpy"],
            "0 (bit for bit)" if bitwise else f"{same_fp:.1e}",
        ),
    ]
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    today = datetime.date.today().isoformat()
    load = os.getloadavg()[0]
    machine = f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}, NumPy {np.__version__}"
    table = [
        "<!-- bench-python:begin -->",
        f"<!-- written by bench/python.py (npm run bench) on {today}: {machine} -->",
        "",
        f"Measured {today} on {machine} (load average {load:.1f} at the end: other work shared the"
        f" cores); one process, the calls interleaved round by round, median of {ROUNDS} rounds; wall"
        " time of the whole Python call (arguments checked, arrays in and out).",
        "",
        "| 10⁶ rulings or points | ruledlab ms | careful NumPy ms | NumPy / ruledlab | largest difference |",
        "|---|---:|---:|---:|---:|",
    ]
    for name, core, numpy_ms, diff in rows:
        table.append(f"| {name} | {core:.1f} | {numpy_ms:.1f} | {numpy_ms / core:.2f} | {diff} |")
    table.append("<!-- bench-python:end -->")
    print("\n".join(table))
    if "--no-write" not in sys.argv and n == 1_000_000:
        text = BOOK.read_text()
        start, end = text.index("<!-- bench-python:begin -->"), text.index("<!-- bench-python:end -->")
        BOOK.write_text(text[:start] + "\n".join(table) + text[end + len("<!-- bench-python:end -->") :])
        print(f"bench: the table in {BOOK.relative_to(REPO)} rewritten")


if __name__ == "__main__":
    main()
