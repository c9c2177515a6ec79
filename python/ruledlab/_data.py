"""NumPy arrays to the view's binary buffers and back (never JSON lists).

Segments go as little-endian float64: six numbers per line (its point ``a``, then ``b``), as
``<ruled-view>``'s ``data`` takes them; the scene's input comes back as one (n, 3) array of
points per handle set (pairs: rows 2k and 2k + 1 are line k's ends).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._errors import RuledlabError

F64 = np.dtype("<f8")


def _points(x: Any, name: str, ndim: int) -> np.ndarray:
    try:
        a = np.asarray(x, dtype=F64)
    except (TypeError, ValueError) as e:
        raise RuledlabError(f"{name} must be an array of numbers ({e})", "invalid-argument", {"option": name}) from e
    if a.ndim != ndim or a.shape[-1] != 3:
        want = "N × 3" if ndim == 2 else "rows × cols × 3"
        raise RuledlabError(
            f"{name} must be an array of shape {want} (one point per row), not {a.shape}",
            "invalid-argument",
            {"option": name, "shape": list(a.shape)},
        )
    return a


def segments(a: Any, b: Any) -> dict[str, Any]:
    """The view's source for rulings from points ``a[i]`` to ``b[i]`` (N × 3 each)."""
    pa, pb = _points(a, "a", 2), _points(b, "b", 2)
    if pa.shape != pb.shape:
        raise RuledlabError(
            f"a and b must have the same shape, not {pa.shape} and {pb.shape}",
            "invalid-argument",
            {"option": "b", "shape": list(pb.shape)},
        )
    return {"segments": np.ascontiguousarray(np.hstack([pa, pb]), dtype=F64).reshape(-1)}


def grid(p: Any, q: Any) -> dict[str, Any]:
    """The view's source for a congruence: the line of grid point (i, j) through ``p[i, j]``
    and ``q[i, j]`` (rows × cols × 3 each)."""
    pp, pq = _points(p, "p", 3), _points(q, "q", 3)
    if pp.shape != pq.shape:
        raise RuledlabError(
            f"p and q must have the same shape, not {pp.shape} and {pq.shape}",
            "invalid-argument",
            {"option": "q", "shape": list(pq.shape)},
        )
    rows, cols = pp.shape[:2]
    lines = np.concatenate([pp, pq], axis=2).reshape(-1)
    return {"segments": np.ascontiguousarray(lines, dtype=F64), "rows": int(rows), "cols": int(cols)}


def source_to_json(value: dict[str, Any] | None, _widget: object = None) -> dict[str, Any] | None:
    """The source as the model holds it: the doubles as one binary buffer."""
    if not value:
        return None
    out: dict[str, Any] = {"segments": memoryview(np.ascontiguousarray(value["segments"], dtype=F64)).cast("B")}
    if value.get("rows"):
        out["rows"], out["cols"] = int(value["rows"]), int(value["cols"])
    return out


def source_from_json(value: dict[str, Any] | None, _widget: object = None) -> dict[str, Any] | None:
    if not value:
        return None
    return {**value, "segments": np.frombuffer(bytes(value["segments"]), dtype=F64).copy()}


def input_to_json(value: dict[str, Any] | None, _widget: object = None) -> dict[str, Any]:
    """The scene's input, one binary buffer of doubles per handle set."""
    return {k: memoryview(np.ascontiguousarray(v, dtype=F64).reshape(-1)).cast("B") for k, v in (value or {}).items()}


def input_from_json(value: dict[str, Any] | None, _widget: object = None) -> dict[str, np.ndarray]:
    return {k: np.frombuffer(bytes(v), dtype=F64).reshape(-1, 3).copy() for k, v in (value or {}).items()}


def check_input(value: dict[str, Any]) -> dict[str, np.ndarray]:
    """The scene's input as Python may set it: (n, 3) arrays of numbers per handle set."""
    if not isinstance(value, dict):
        raise RuledlabError("data must be a dict of (n, 3) arrays, one per handle set", "invalid-argument")
    return {str(k): _points(v, f"data[{k!r}]", 2) for k, v in value.items()}
