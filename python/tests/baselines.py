"""Careful vectorised NumPy baselines of two computations of the core: the discrete invariants of
Section 2 (equations (1)–(7) and Example 1) and one step of the four-point scheme (8) with the
core's end rule (cubic ghost points, ``src/subdivision/four_point.rs``).

They are an independent reference for the tests (``test_core.py``: the same numbers to rounding)
and the baselines the benchmark times the core against (``bench/python.py``). "Careful" means
written as a NumPy user who cares about speed would: whole-array operations only, no Python loop
over rulings, dot and cross products component by component (``np.cross`` and ``einsum`` are
slower on (N, 3) arrays), the scratch arrays reused through ``out=`` where NumPy allows it, and the
formulas of the paper in the numerically sound form the core uses (φ by atan2, the footpoints by
triple products over |c|², conventions of ``docs/src/conventions.md``).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]

#: |sin φ| below which a pair of rulings counts as parallel (the core's PARALLEL_SIN)
PARALLEL_SIN = 1e-9


def _dot(x0: F64, x1: F64, x2: F64, y0: F64, y1: F64, y2: F64) -> F64:
    out = x0 * y0
    out += x1 * y1
    out += x2 * y2
    return out


def invariants(a: F64, b: F64, closed: bool = False) -> dict[str, Any]:
    """The invariants of the rulings a_i → b_i ((N, 3) each) as ``RuledSurface.invariants``
    returns them: φ, h, δ = h/φ (1), the footpoints (3), n, the striction polygon and the mean
    distribution parameter (7), Example 1's midpoints, the parallel flags."""
    d = b - a
    length = np.sqrt(_dot(d[:, 0], d[:, 1], d[:, 2], d[:, 0], d[:, 1], d[:, 2]))
    e = d / length[:, None]
    if closed:
        e0, e1, p0, p1 = e, np.roll(e, -1, axis=0), a, np.roll(a, -1, axis=0)
    else:
        e0, e1, p0, p1 = e[:-1], e[1:], a[:-1], a[1:]
    x0, y0, z0 = e0[:, 0], e0[:, 1], e0[:, 2]
    x1, y1, z1 = e1[:, 0], e1[:, 1], e1[:, 2]
    # c = e_i × e_{i+1}, |c| = sin φ
    cx = y0 * z1 - z0 * y1
    cy = z0 * x1 - x0 * z1
    cz = x0 * y1 - y0 * x1
    sin2 = _dot(cx, cy, cz, cx, cy, cz)
    sin = np.sqrt(sin2)
    angle = np.arctan2(sin, _dot(x0, y0, z0, x1, y1, z1))
    parallel = sin < PARALLEL_SIN
    dd = p1 - p0
    dx, dy, dz = dd[:, 0], dd[:, 1], dd[:, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        # h = (d·c)/|c|; for a parallel pair the distance |d − (d·e_i) e_i|
        distance = _dot(dx, dy, dz, cx, cy, cz) / sin
        if parallel.any():
            k = np.flatnonzero(parallel)
            along = (dd[k] * e0[k]).sum(axis=1)
            distance[k] = np.linalg.norm(dd[k] - along[:, None] * e0[k], axis=1)
        distribution = distance / angle
        normal = np.stack([cx / sin, cy / sin, cz / sin], axis=1)
        # f_{i,i+1} = a_i + t e_i, f_{i+1,i} = a_{i+1} + s e_{i+1}: t = ((d × e_{i+1})·c)/|c|²,
        # s = ((d × e_i)·c)/|c|² (3)
        t = _dot(dy * z1 - dz * y1, dz * x1 - dx * z1, dx * y1 - dy * x1, cx, cy, cz) / sin2
        s = _dot(dy * z0 - dz * y0, dz * x0 - dx * z0, dx * y0 - dy * x0, cx, cy, cz) / sin2
    f0 = p0 + t[:, None] * e0
    f1 = p1 + s[:, None] * e1
    distribution[parallel] = np.nan
    normal[parallel] = np.nan
    f0[parallel] = np.nan
    f1[parallel] = np.nan
    if closed:
        # m_i = (f_{i,i−1} + f_{i,i+1})/2 for every ruling, f_{0,N−1} from the last pair
        striction = 0.5 * (np.roll(f1, 1, axis=0) + f0)
        mean = 0.5 * (np.roll(distribution, 1) + distribution)
    else:
        striction = 0.5 * (f1[:-1] + f0[1:])
        mean = 0.5 * (distribution[:-1] + distribution[1:])
    return {
        "angle": angle,
        "distance": distance,
        "distribution": distribution,
        "footpoints": np.hstack([f0, f1]),
        "central_normal": normal,
        "striction": striction,
        "distribution_mean": mean,
        "perpendicular_midpoints": 0.5 * (f0 + f1),
        "parallel": parallel,
    }


def _ghost(p0: F64, p1: F64, p2: F64, p3: F64) -> F64:
    """The point before p0 on the cubic through p0 … p3 (the core's end rule)."""
    out: F64 = p0 * 4.0 - p1 * 6.0 + p2 * 4.0 - p3
    return out


def four_point(p: F64, w: float = 1.0 / 16.0, closed: bool = False) -> F64:
    """One step of the four-point scheme (8), p_{i+½} = (½ + w)(p_i + p_{i+1}) − w(p_{i−1} +
    p_{i+2}), on a polygon of N ≥ 4 points ((N, 3)): 2N − 1 points (2N closed), the old ones at
    even indices. An open polygon's end edges use ghost points extrapolating the cubic through
    the four end points."""
    n = len(p)
    out = np.empty((2 * n - (0 if closed else 1), 3))
    out[0::2] = p
    new = out[1::2]
    # the edges with both neighbours: (b + c)(½ + w) − (a + d)w, in the core's order
    inner = new[1 : n - 2]
    np.add(p[1:-2], p[2:-1], out=inner)
    inner *= 0.5 + w
    outer = p[:-3] + p[3:]
    outer *= w
    inner -= outer
    if closed:
        ends = [(n - 1, 0, 1, 2), (n - 3, n - 2, n - 1, 0), (n - 2, n - 1, 0, 1)]
        slots = [0, n - 2, n - 1]
        for slot, (i, j, k, m) in zip(slots, ends):
            new[slot] = (p[j] + p[k]) * (0.5 + w) - (p[i] + p[m]) * w
    else:
        before = _ghost(p[0], p[1], p[2], p[3])
        after = _ghost(p[-1], p[-2], p[-3], p[-4])
        new[0] = (p[0] + p[1]) * (0.5 + w) - (before + p[2]) * w
        new[n - 2] = (p[n - 2] + p[n - 1]) * (0.5 + w) - (p[n - 3] + after) * w
    return out
