"""The Python API computes what the JavaScript API computes: the same inputs through the built npm
package in Node (``parity.mjs``, loaded as ``tests/node/load.mjs`` loads it) and through
``ruledlab._core``, compared to 1e-12 (the same Rust core, compiled to wasm and natively: the
numbers agree to the last bit except where a libm function differs)."""

from __future__ import annotations

import json
import math
import shutil
import subprocess
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import ruledlab
from ruledlab import AnalyticCongruence, AnalyticSurface, RuledSurface, ToolPath

REPO = Path(__file__).resolve().parents[2]
TOL = 1e-12


def numbers(value: Any) -> np.ndarray:
    """A list from JSON (NaN and infinities written as strings) as float64."""
    return np.array([float(x) if isinstance(x, str) else x for x in value], dtype=float)


@pytest.fixture(scope="module")
def js(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    if not (REPO / "pkg" / "ruledlab_bg.wasm").is_file():
        pytest.fail("pkg/ is missing: run bash scripts/build.sh")
    node = shutil.which("node")
    assert node, "node is needed to run the JavaScript API"
    rng = np.random.default_rng(2026)
    a = rng.normal(size=(2000, 3))
    b = a + rng.normal(size=(2000, 3))
    # a hyperboloid's rulings after the random ones: well-conditioned pairs too
    u = np.linspace(0, 2 * np.pi, 60, endpoint=False)
    a = np.vstack([a, np.stack([np.cos(u), np.sin(u), -np.ones(60)], axis=1)])
    b = np.vstack([b, np.stack([np.cos(u + 1), np.sin(u + 1), np.ones(60)], axis=1)])
    points = rng.normal(size=(500, 3))
    at = np.linspace(-2, 2, 101)
    work = tmp_path_factory.mktemp("parity")
    given = {"segments": np.hstack([a, b]).ravel().tolist(), "points": points.ravel().tolist(), "at": at.tolist()}
    (work / "in.json").write_text(json.dumps(given))
    subprocess.run([node, str(REPO / "python" / "tests" / "parity.mjs"), work / "in.json", work / "out.json"], check=True)
    out: dict[str, Any] = json.loads((work / "out.json").read_text())
    out["_a"], out["_b"], out["_points"], out["_at"] = a, b, points, at
    return out


def same(python: np.ndarray, javascript: Any, tol: float = TOL) -> None:
    js_values = numbers(javascript)
    py_values = np.asarray(python, dtype=float).ravel()
    assert py_values.shape == js_values.shape
    assert np.array_equal(np.isnan(py_values), np.isnan(js_values))
    finite = np.isfinite(js_values)
    assert np.array_equal(py_values[~finite & ~np.isnan(js_values)], js_values[~finite & ~np.isnan(js_values)])
    scale = np.maximum(1.0, np.abs(js_values[finite]))
    assert np.all(np.abs(py_values[finite] - js_values[finite]) <= tol * scale)


def test_the_invariants_are_the_javascript_apis(js):
    surface = RuledSurface.from_segments(js["_a"], js["_b"])
    for closed, key in ((False, "invariants"), (True, "invariantsClosed")):
        inv = surface.invariants(closed=closed)
        theirs = js[key]
        for name, js_name in [
            ("angle", "angle"),
            ("distance", "distance"),
            ("distribution", "distribution"),
            ("footpoints", "footpoints"),
            ("central_normal", "centralNormal"),
            ("striction", "striction"),
            ("distribution_mean", "distributionMean"),
            ("perpendicular_midpoints", "perpendicularMidpoints"),
        ]:
            same(inv[name], theirs[js_name])
        assert inv["parallel"].astype(int).tolist() == theirs["parallel"]


def test_the_schemes_isometries_and_development_are_the_javascript_apis(js):
    surface = RuledSurface.from_segments(js["_a"], js["_b"])
    same(surface.subdivide(scheme="four-point", steps=2).segments(), js["fourPoint"])
    same(surface.subdivide(scheme="variational", steps=1, n=6).segments(), js["variational"], 1e-9)
    same(surface.subdivide(scheme="bspline", degree=3, space="lines").segments(), js["lines"])
    same(surface.development(), js["development"], 1e-9)
    same(surface.envelope_radii(), js["envelopeRadii"], 1e-9)
    same(surface.hinge_angles(), js["hingeAngles"])
    same(surface.bend(0.4).segments(), js["bend"], 1e-9)
    fit = surface.linear_complex()
    same(fit["spectrum"], js["complex"]["spectrum"], 1e-9)
    assert fit["nullity"] == js["complex"]["nullity"] and fit["kind"] == js["complex"]["kind"]
    points = js["_points"]
    same(ruledlab.subdivide_polygon(points, scheme="bspline", degree=3, steps=2), js["polygon"])
    same(ruledlab.subdivide_polygon(points, scheme="four-point"), js["fourPointPolygon"])


def test_congruences_formulas_and_the_catalogue_are_the_javascript_apis(js):
    values = ruledlab.evaluate_formulas(["sin(a*u)", "u^3 - b"], js["_at"], parameters={"a": 2, "b": 0.5})
    same(values, js["formulas"])
    same(AnalyticSurface.by_name("helical").sample(50).segments(), js["sample"])
    errors = AnalyticSurface.by_name("hyperboloid").sampling_errors(40)
    for key, value in js["samplingErrors"].items():
        snake = "".join("_" + c.lower() if c.isupper() else c for c in key)
        assert math.isclose(errors[snake], value, rel_tol=TOL, abs_tol=TOL), key  # type: ignore[literal-required]
    grid = AnalyticCongruence.by_name("example5").grid(7, 8)
    same(grid.subdivide(scheme="butterfly").segments(), js["butterfly"])
    same(grid.subdivide(scheme="variational", K=4).segments(), js["coupled"], 1e-9)
    focal = grid.focal()
    same(focal["points"], js["focal"]["points"], 1e-9)
    same(focal["parameters"], js["focal"]["parameters"], 1e-9)
    assert focal["kind"].ravel().tolist() == js["focal"]["kind"]


def test_tool_paths_and_the_posts_are_the_javascript_apis(js):
    path = ToolPath.example(7).refine(steps=2)
    assert path.export("gcode", machine="table-table-ac", dialect="sinumerik") == js["gcode"]
    post = path.post(machine="head-table-bc")
    assert post["text"] == js["post"]["text"] and "deviation" not in post
    measured = path.post(machine="head-table-bc", target=ToolPath.example_profile(40))
    deviation = measured["deviation"]
    for key in ("gouge", "leave", "rms", "largest"):
        assert math.isclose(deviation[key], js["deviation"][key], rel_tol=TOL, abs_tol=TOL), key  # type: ignore[literal-required]
    # where along the poses: the minimiser's argument, flat at its minimum (wasm and native round
    # apart there by 3e-9 of a pose while the distance agrees to 1e-12)
    assert math.isclose(deviation["pose"], js["deviation"]["pose"], abs_tol=1e-6)
    assert deviation["worst"] == js["deviation"]["worst"]
    same(deviation["at"], js["deviation"]["at"])
    same(deviation["points"], js["deviation"]["points"])
    assert "deviation of the program as posted from the target, 40 points" in measured["text"]
    same(post["axes"], js["post"]["axes"])
    same(post["block_minutes"], js["post"]["blockMinutes"])
