"""The invariants of Section 2 of rulings computed in NumPy, headless: no view, no browser.

Run it with the package installed (``pip install dist/python/ruledlab-*.whl``):
``python examples/invariants.py``. It is typed: ``mypy --strict examples/invariants.py`` accepts
it against the package's stubs (python/tests/test_typing.py checks that).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

import ruledlab


def hyperboloid(n: int, phi: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Rulings of a hyperboloid of revolution: a_i on the circle z = −1, b_i on z = 1, turned by φ."""
    u = np.linspace(0, 2 * np.pi, n, endpoint=False)
    a = np.stack([np.cos(u), np.sin(u), -np.ones(n)], axis=1)
    b = np.stack([np.cos(u + phi), np.sin(u + phi), np.ones(n)], axis=1)
    return a, b


def main() -> None:
    a, b = hyperboloid(200, 1.2)
    surface = ruledlab.RuledSurface.from_segments(a, b)
    inv: ruledlab.Invariants = surface.invariants(closed=True)
    delta = inv["distribution"]
    print(f"{len(surface)} rulings, δ from {delta.min():.6f} to {delta.max():.6f}")
    print(f"striction points on z = 0 to {np.abs(inv['striction'][:, 2]).max():.1e}")
    refined = surface.subdivide(scheme="four-point", steps=2, closed=True)
    print(f"four-point, two steps: {len(refined)} rulings")
    try:
        ruledlab.RuledSurface.from_segments(a, a)
    except ruledlab.RuledlabError as e:
        print(e.code, "|", e)
    fit: ruledlab.LinearComplexFit = ruledlab.linear_complex(a, b)
    print(f"a regulus: {fit['kind']}, nullity {fit['nullity']}")


if __name__ == "__main__":
    main()
