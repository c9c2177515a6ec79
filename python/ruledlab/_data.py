"""NumPy arrays to the view's binary buffers and back (never JSON lists).

Your rulings and congruences are checked by the core first (``ruledlab.RuledSurface``,
``ruledlab.LineCongruence``): what it refuses — a NaN, a ruling of zero length, a wrong shape,
complex numbers or strings — raises RuledlabError at once, with the core's code, and never reaches
a view. They go as little-endian float64: six numbers per line (its point ``a``, then ``b``), as
``<ruled-view>``'s ``data`` takes them; the scene's input comes back as one (n, 3) array of
points per handle set (pairs: rows 2k and 2k + 1 are line k's ends).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._core import LineCongruence, RuledSurface
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


def _as(call: str, error: RuledlabError) -> RuledlabError:
    """The core's error as the view's function `call` raises it."""
    message = error.message.split(": ", 1)[-1] if ": " in error.message else error.message
    return RuledlabError(f"{call}: {message}", error.code, error.details)


def segments(a: Any, b: Any, call: str = "View.from_segments") -> dict[str, Any]:
    """The view's source for rulings from points ``a[i]`` to ``b[i]`` (N × 3 each), checked by
    the core (`call` names the function in its errors)."""
    try:
        surface = RuledSurface.from_segments(a, b)
    except RuledlabError as e:
        raise _as(call, e) from None
    return {"segments": surface.segments().reshape(-1)}


def grid(p: Any, q: Any, call: str = "View.from_grid") -> dict[str, Any]:
    """The view's source for a congruence: the line of grid point (i, j) through ``p[i, j]``
    and ``q[i, j]`` (rows × cols × 3 each), checked by the core."""
    try:
        congruence = LineCongruence.from_grid(p, q)
    except RuledlabError as e:
        raise _as(call, e) from None
    return {"segments": congruence.segments().reshape(-1), "rows": congruence.rows, "cols": congruence.cols}


def source_to_json(value: dict[str, Any] | None, _widget: object = None) -> dict[str, Any] | None:
    """The source as the model holds it: the doubles as one binary buffer."""
    if not value:
        return None
    out: dict[str, Any] = {"segments": np.ascontiguousarray(value["segments"], dtype=F64).data.cast("B")}
    if value.get("rows"):
        out["rows"], out["cols"] = int(value["rows"]), int(value["cols"])
    return out


def source_from_json(value: dict[str, Any] | None, _widget: object = None) -> dict[str, Any] | None:
    if not value:
        return None
    return {**value, "segments": np.frombuffer(bytes(value["segments"]), dtype=F64).copy()}


def input_to_json(value: dict[str, Any] | None, _widget: object = None) -> dict[str, Any]:
    """The scene's input, one binary buffer of doubles per handle set."""
    return {k: np.ascontiguousarray(v, dtype=F64).reshape(-1).data.cast("B") for k, v in (value or {}).items()}


def input_from_json(value: dict[str, Any] | None, _widget: object = None) -> dict[str, np.ndarray]:
    return {k: np.frombuffer(bytes(v), dtype=F64).reshape(-1, 3).copy() for k, v in (value or {}).items()}


def check_input(value: dict[str, Any]) -> dict[str, np.ndarray]:
    """The scene's input as Python may set it: (n, 3) arrays of numbers per handle set."""
    if not isinstance(value, dict):
        raise RuledlabError("data must be a dict of (n, 3) arrays, one per handle set", "invalid-argument")
    return {str(k): _points(v, f"data[{k!r}]", 2) for k, v in value.items()}
