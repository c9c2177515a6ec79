"""The compiled core (``ruledlab._core``) on NumPy arrays: answers against exact values and the
independent NumPy baselines (``baselines.py``), arrays in and out (shapes, dtypes, no copies),
the error codes and what their details count, the GIL released while the core computes.

What the JavaScript API computes for the same input is compared in ``test_js_parity.py``.
"""

from __future__ import annotations

import threading
import time

import numpy as np
import pytest

import ruledlab
from ruledlab import (
    AnalyticCongruence,
    AnalyticSurface,
    LineCongruence,
    RuledlabError,
    RuledSurface,
    ToolPath,
)

import baselines


def hyperboloid(n: int = 24, phi: float = 1.2) -> tuple[np.ndarray, np.ndarray]:
    """Rulings of a hyperboloid of revolution: a_i on the circle z = −1, b_i on z = 1, turned by φ."""
    u = np.linspace(0, 2 * np.pi, n, endpoint=False)
    a = np.stack([np.cos(u), np.sin(u), -np.ones(n)], axis=1)
    b = np.stack([np.cos(u + phi), np.sin(u + phi), np.ones(n)], axis=1)
    return a, b


def random_rulings(n: int, seed: int = 7) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    a = rng.normal(size=(n, 3))
    return a, a + rng.normal(size=(n, 3))


def close(x: np.ndarray, y: np.ndarray, tol: float) -> bool:
    """Equal within `tol` times the scale of the numbers, NaN where the other is NaN."""
    scale = max(1.0, float(np.nanmax(np.abs(y))) if np.isfinite(y).any() else 1.0)
    return bool(np.array_equal(np.isnan(x), np.isnan(y)) and np.nanmax(np.abs(x - y), initial=0.0) <= tol * scale)


# --- Section 2: the invariants


@pytest.mark.parametrize("closed", [False, True])
@pytest.mark.parametrize("data", ["hyperboloid", "random"])
def test_the_invariants_are_the_papers_formulas(data, closed):
    a, b = hyperboloid(40) if data == "hyperboloid" else random_rulings(500)
    got = RuledSurface.from_segments(a, b).invariants(closed=closed)
    want = baselines.invariants(a, b, closed)
    assert set(got) == set(want)
    for key, value in want.items():
        assert got[key].shape == value.shape, key
        if key == "parallel":
            assert got[key].dtype == np.bool_ and np.array_equal(got[key], value)
        else:
            assert got[key].dtype == np.float64, key
            # random rulings include nearly parallel pairs, whose footpoints are ill-conditioned
            assert close(got[key], value, 1e-12 if data == "hyperboloid" else 1e-9), key


def test_the_invariants_of_a_hyperboloid_of_revolution_are_constant_and_symmetric():
    n, phi = 24, 1.2
    inv = RuledSurface.from_segments(*hyperboloid(n, phi)).invariants(closed=True)
    # every pair is the first turned about the z axis: the same φ, h, δ
    for key in ("angle", "distance", "distribution", "distribution_mean"):
        assert np.ptp(inv[key]) < 1e-13, key
    # the half-turn about the x axis maps the surface to itself: the striction points lie on z = 0
    assert np.abs(inv["striction"][:, 2]).max() < 1e-14
    # δ = h/φ (1)
    assert np.allclose(inv["distribution"], inv["distance"] / inv["angle"], rtol=0, atol=1e-15)


def test_parallel_pairs_are_flagged_and_their_quantities_nan():
    a = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0.5]], dtype=float)
    b = a + np.array([[0, 0, 1], [0, 0, 1], [0, 1, 1]], dtype=float)
    inv = RuledSurface.from_segments(a, b).invariants()
    assert inv["parallel"].tolist() == [True, False]
    assert inv["distance"][0] == 1.0  # the unsigned distance of the parallel lines
    assert np.isnan(inv["distribution"][0]) and np.isnan(inv["footpoints"][0]).all()


def test_the_results_own_the_cores_memory_and_the_input_is_read_in_place():
    a, b = hyperboloid(10)
    inv = RuledSurface.from_segments(a, b).invariants()
    for value in inv.values():
        # a view of the array NumPy made around the core's vector: nothing was copied
        assert not value.flags.owndata or value.base is None
        assert value.flags.c_contiguous and value.flags.writeable
    base = inv["striction"].base
    assert base is not None and type(base).__name__ != "ndarray" or base.base is not None
    # float64 in C order is the argument the core reads; other layouts are converted once
    segments = np.hstack([a, b])
    assert np.array_equal(RuledSurface(segments).segments(), segments)
    assert np.array_equal(RuledSurface(np.asfortranarray(segments)).segments(), segments)
    assert np.array_equal(RuledSurface(segments.astype(np.float32)).segments(), segments.astype(np.float32))
    assert np.array_equal(RuledSurface(segments.reshape(-1, 2, 3)).segments(), segments)
    assert np.array_equal(RuledSurface(segments.tolist()).segments(), segments)
    assert np.array_equal(RuledSurface(segments.astype(">f8")).segments(), segments)


# --- Section 3: isometries and the development


def test_bending_is_an_isometry_and_ends_at_the_conoidal_model():
    s = RuledSurface.from_segments(*hyperboloid(16, 0.8))
    for t in (0.0, 0.3, 1.0):
        assert s.max_edge_change(s.bend(t)) < 1e-12
    assert s.bend(0.0).max_angle_to(s) < 1e-12
    conoidal = s.conoidal()
    assert np.allclose(conoidal.segments(), s.bend(1.0).segments(), atol=1e-12)
    # every ruling of the conoidal model is parallel to the plane of R_0 and R_1 (Example 2)
    frame = s.reference_frame()
    dirs = conoidal.directions() @ frame[:3, :3].T
    assert np.abs(dirs[:, 2]).max() < 1e-12
    assert np.allclose(s.hinge(np.zeros(14)).segments(), s.segments(), atol=1e-12)
    assert np.allclose(s.hinge(s.hinge_angles() * 0).segments(), s.segments(), atol=1e-12)


def test_the_development_lies_in_the_reference_plane():
    s = RuledSurface.from_segments(*random_rulings(12, seed=3))
    m = s.reference_frame()
    assert m.shape == (4, 4) and np.allclose(m[3], [0, 0, 0, 1])
    world = s.development_in_space().reshape(-1, 3)
    local = (np.hstack([world, np.ones((len(world), 1))]) @ m.T)[:, :3]
    assert np.abs(local[:, 2]).max() < 1e-12
    assert np.allclose(local[:, :2].reshape(-1, 4), s.development(), atol=1e-12)
    assert s.development_striction().shape == (10, 2) and s.development_envelope().shape == (11, 2)
    assert s.envelope_radii().shape == (10,)


# --- Section 4: the curve and strip schemes


@pytest.mark.parametrize("closed", [False, True])
@pytest.mark.parametrize("w", [1 / 16, 0.1, -0.05])
def test_the_four_point_scheme_is_rule_eight(closed, w):
    rng = np.random.default_rng(11)
    p = rng.normal(size=(57, 3))
    got = ruledlab.subdivide_polygon(p, scheme="four-point", w=w, closed=closed)
    want = baselines.four_point(p, w, closed)
    assert got.shape == want.shape
    # the same operations in the same order: the same numbers
    assert np.array_equal(got, want)
    assert np.array_equal(got[0::2], p)


def test_four_point_with_w_one_sixteenth_reproduces_cubics():
    t = np.arange(9.0)
    p = np.stack([t, 0.5 * t**2 - t, 0.1 * t**3 - 0.3 * t**2 + 2], axis=1)
    q = ruledlab.subdivide_polygon(p, scheme="four-point", steps=2)
    s = np.arange(len(q)) / 4.0
    assert np.allclose(q, np.stack([s, 0.5 * s**2 - s, 0.1 * s**3 - 0.3 * s**2 + 2], axis=1), atol=1e-12)


def test_chaikin_cuts_corners_at_a_quarter():
    p = np.array([[0, 0, 0], [4, 0, 0], [4, 4, 0]], dtype=float)
    q = ruledlab.subdivide_polygon(p, scheme="chaikin")
    assert np.array_equal(q, [[1, 0, 0], [3, 0, 0], [4, 1, 0], [4, 3, 0]])
    angles = ruledlab.turning_angles(p, scheme="chaikin", steps=3)
    assert angles[0] == pytest.approx(np.pi / 2) and np.all(np.diff(angles) < 0)


def test_interpolatory_strip_schemes_keep_the_rulings():
    s = RuledSurface.from_segments(*hyperboloid(12))
    for scheme in ("four-point", "variational"):
        r = s.subdivide(scheme=scheme, steps=2, closed=scheme == "four-point")
        assert np.array_equal(r.segments()[::4], s.segments())
        assert np.array_equal(r.inserted(4)[:3], np.delete(r.segments(), np.s_[::4], axis=0)[:3])
    lines = s.subdivide(scheme="four-point", space="lines", length=2.0, closed=True)
    assert np.allclose(np.linalg.norm(lines.segments()[:, 3:] - lines.segments()[:, :3], axis=1), 2.0)
    assert s.division_point(2, 1, 4) == pytest.approx(0.75 * s.segments()[2, :3] + 0.25 * s.segments()[2, 3:])


# --- Section 5: congruences, focal geometry, linear complexes


def test_a_congruence_refines_and_keeps_its_lines():
    exact = AnalyticCongruence.by_name("hyperbolic-paraboloid")
    grid = exact.grid(5, 6)
    fine = grid.subdivide(scheme="butterfly", steps=2)
    assert (fine.rows, fine.cols) == (17, 21)
    assert np.array_equal(fine.segments()[::4, ::4], grid.segments())
    errors = exact.errors(fine)
    assert errors["distance"] < 1e-2 and errors["angle"] < 1e-1
    p, q = grid.segments()[..., :3], grid.segments()[..., 3:]
    assert np.array_equal(LineCongruence.from_grid(p, q).segments(), grid.segments())
    assert np.array_equal(grid.row(2).segments(), grid.segments()[2])


def test_the_focal_points_of_a_normal_congruence_are_its_centres_of_curvature():
    # the normals of z = (x² + y²/4)/2: at the origin the centres of curvature are at heights 1
    # and 4 (radii 1/κ), and the focal planes of a normal congruence are orthogonal
    h = 0.02
    x, y = np.meshgrid(np.arange(-5, 6) * h, np.arange(-4, 5) * h, indexing="ij")
    surface = np.stack([x, y, (x**2 + y**2 / 4) / 2], axis=2)
    normal = np.stack([-x, -y / 4, np.ones_like(x)], axis=2)
    normal /= np.linalg.norm(normal, axis=2, keepdims=True)
    c = LineCongruence.from_grid(surface, surface + normal)
    f = c.focal()
    assert f["points"].shape == (11, 9, 6) and f["kind"].dtype == np.uint8
    assert f["kind"][5, 4] == 1  # hyperbolic: two real focal points
    assert f["parameters"][5, 4] == pytest.approx([1.0, 4.0], rel=1e-3)
    assert np.allclose(f["points"][5, 4], [0, 0, 1, 0, 0, 4], atol=4e-3)
    assert np.nanmax(f["normality"]) < 1e-2


def test_a_regulus_lies_in_three_linear_complexes():
    fit = ruledlab.linear_complex(*hyperboloid(30))
    assert fit["nullity"] == 3 and fit["kind"] == "regulus"
    a, b = random_rulings(30)
    assert ruledlab.linear_complex(a, b)["nullity"] == 0


# --- formulas, data files, tool paths


def test_a_preset_typed_as_formulas_is_its_surface():
    for preset in AnalyticSurface.formula_presets()[:4]:
        exact = AnalyticSurface.by_name(preset["name"])
        typed = AnalyticSurface.from_formulas(
            preset["a"], preset["e"], preset["u"], v=preset["v"], closed=preset["closed"], parameters=preset["parameters"]
        )
        assert np.allclose(typed.sample(20).segments(), exact.sample(20).segments(), atol=1e-12), preset["name"]
    values = ruledlab.evaluate_formulas(["u^2", "sin(a*u)"], [0.0, 0.5], parameters={"a": 2})
    assert np.allclose(values, [[0, 0], [0.25, np.sin(1.0)]])


def test_segments_round_trip_through_csv_and_json():
    s = RuledSurface.from_segments(*random_rulings(5))
    for fmt in ("csv", "json"):
        back = ruledlab.import_segments(s.export(fmt))
        assert np.array_equal(back["segments"], s.segments())
    assert ruledlab.detect_import(s.export("csv")) == "segments"


def test_a_tool_path_posts_g_code():
    path = ToolPath.example(7)
    refined = path.refine(steps=2)
    assert len(refined) == 25 and np.array_equal(refined.tips()[::4], path.tips())
    heard: list[float] = []
    post = refined.post(machine="table-table-ac", on_progress=heard.append)
    assert "G93" in post["text"] and post["text"].rstrip().endswith("M30")
    assert post["after"]["tip"] <= post["tolerance"] + 1e-12
    assert post["axes"].shape == (post["poses"], 5) and heard and heard[-1] <= 1.0
    assert post["text"] == refined.export("gcode", machine="table-table-ac")
    machine = ToolPath.machine("table-table-ac")
    assert refined.export("gcode", machine=machine) == post["text"]
    back = ruledlab.import_tool_poses(refined.export("csv"))
    assert np.allclose(back["tips"], refined.tips()) and back["tool"]["radius"] == 0.25


# --- errors: stable codes, details that count what the message counts


def test_a_nan_is_named_by_the_array_and_index_the_caller_wrote():
    a, b = hyperboloid(6)
    b[2, 1] = np.nan
    with pytest.raises(RuledlabError) as e:
        RuledSurface.from_segments(a, b)
    assert e.value.code == "not-finite"
    assert "b[2, 1] (ruling 2, b.y) is NaN" in str(e.value)
    assert e.value.details["index"] == 2  # the ruling, as the message counts
    assert (e.value.details["array"], e.value.details["at"]) == ("b", [2, 1])
    segments = np.hstack(hyperboloid(6)).reshape(6, 2, 3)
    segments[4, 0, 2] = np.inf
    with pytest.raises(RuledlabError) as e:
        RuledSurface(segments)
    assert e.value.details["index"] == 4 and e.value.details["at"] == [4, 0, 2]
    assert "segments[4, 0, 2] (ruling 4, a.z) is inf" in str(e.value)
    p = np.zeros((3, 4, 3))
    q = p + [0, 0, 1]
    q[1, 3, 0] = np.nan
    with pytest.raises(RuledlabError) as e:
        LineCongruence.from_grid(p, q)
    assert e.value.details["index"] == [1, 3]
    assert "q[1, 3, 0] (line (1, 3), q.x)" in str(e.value)
    with pytest.raises(RuledlabError) as e:
        RuledSurface.from_segments(a, a + [[1e200, 0, 0]] * 6)
    assert e.value.code == "out-of-range" and e.value.details["index"] == 0 and e.value.details["limit"] == 1e150


@pytest.mark.parametrize(
    ("given", "says"),
    [
        (np.zeros((4, 3), dtype=complex), "complex numbers"),
        (np.array([["1", "2", "3"]] * 4), "strings"),
        (np.array([[1, 2, 3]] * 4, dtype=object), "Python objects"),
        ([[1, 2, None]] * 4, "Python objects"),
        (np.ones((4, 3), dtype=bool), "booleans"),
        ([[1, 2, 3], [4, 5]], "NumPy cannot read it"),
    ],
)
def test_what_is_not_an_array_of_real_numbers_is_refused(given, says):
    with pytest.raises(RuledlabError) as e:
        RuledSurface.from_segments(given, np.ones((4, 3)))
    assert e.value.code == "invalid-argument" and e.value.details["option"] == "a"
    assert says in str(e.value)


def test_every_error_has_a_code():
    s = RuledSurface.from_segments(*hyperboloid(8))
    cases = [
        (lambda: RuledSurface.from_segments(np.zeros((1, 3)), np.ones((1, 3))), "too-small"),
        (lambda: RuledSurface.from_segments(np.zeros((4, 3)), np.zeros((4, 3))), "degenerate"),
        (lambda: RuledSurface(np.zeros((4, 5))), "invalid-argument"),
        (lambda: s.subdivide(scheme="chaikin", w=0.1), "invalid-argument"),
        (lambda: s.subdivide(scheme="four-point", steps=30), "invalid-argument"),
        (lambda: s.subdivide(scheme="four-point", steps=23), "too-large"),
        (lambda: s.subdivide(scheme="simplex"), "invalid-argument"),
        (lambda: s.bend("half"), "invalid-argument"),
        (lambda: s.bend(True), "invalid-argument"),
        (lambda: s.invariants(closed=1), "invalid-argument"),
        (lambda: s.division_point(8, 0, 1), "invalid-argument"),
        (lambda: ruledlab.import_segments("0,0,0,1,0\n"), "parse-error"),
        (lambda: AnalyticSurface.from_formulas(["sni(u)", "0", "0"], ["1", "0", "0"], [0, 1]), "parse-error"),
        (lambda: AnalyticSurface.by_name("torus"), "invalid-argument"),
        (lambda: ToolPath.example(7).export("gcode", machine={"rotary": []}), "invalid-argument"),
        (lambda: ToolPath.example(7).post(machine="table-table-ac", tolerance=-1), "invalid-argument"),
        (lambda: ToolPath.example(7).post(feeed=100), "invalid-argument"),
        (lambda: ToolPath.example(7).export("gcode", target=[[0, 0, float("nan")], [1, 1, 1]]), "not-finite"),
        (lambda: ToolPath.example(7).export("csv", target=[[0, 0, 0]]), "invalid-argument"),
    ]
    for call, code in cases:
        with pytest.raises(RuledlabError) as e:
            call()
        assert e.value.code == code, (str(e.value), code)
        assert str(e.value).split(":")[0].replace("_", "").isalnum() or "." in str(e.value).split(":")[0]
    with pytest.raises(RuledlabError) as e:
        AnalyticSurface.from_formulas(["sni(u)", "0", "0"], ["1", "0", "0"], [0, 1])
    assert (e.value.details["option"], e.value.details["column"]) == ("a[0]", 1)
    with pytest.raises(RuledlabError, match='unknown option "feeed"; the options are dialect, mode') as e:
        ToolPath.example(7).post(feeed=100)
    assert e.value.details["option"] == "feeed"


# --- the GIL


def test_the_gil_is_released_while_the_core_computes():
    """A thread keeps counting while the core refines a large surface in another."""
    a, b = random_rulings(200_000, seed=1)
    s = RuledSurface.from_segments(a, b)
    ticks: list[float] = []
    done = threading.Event()

    def count() -> None:
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        time.sleep(0.01)
        start = time.perf_counter()
        s.subdivide(scheme="variational", steps=1)
        end = time.perf_counter()
    finally:
        done.set()
        counter.join()
    during = [t for t in ticks if start < t < end]
    assert end - start > 0.05, "the computation was too short to tell"
    # the counting thread ran throughout: no gap as long as the computation
    gaps = np.diff([start, *during, end])
    assert len(during) > 5 and gaps.max() < 0.5 * (end - start)


def test_the_catalogue_lists_each_entry_with_its_domain_as_by_name_gives_it():
    entry = ["name", "title", "u_min", "u_max", "v_min", "v_max"]
    surfaces = AnalyticSurface.list()
    assert [list(d) for d in surfaces] == [entry + ["closed"]] * len(surfaces)
    for d in surfaces:
        s = AnalyticSurface.by_name(d["name"])
        assert (s.name, s.title) == (d["name"], d["title"])
        assert d["u_min"] < d["u_max"] and d["v_min"] < d["v_max"]
    hyperboloid = surfaces[0]
    assert hyperboloid["name"] == "hyperboloid" and hyperboloid["closed"] is True
    assert (hyperboloid["u_min"], hyperboloid["u_max"]) == (0.0, 2 * np.pi)
    congruences = AnalyticCongruence.list()
    assert [list(d) for d in congruences] == [entry + ["rows", "cols"]] * len(congruences)
    sphere = congruences[0]
    assert (sphere["name"], sphere["u_min"], sphere["v_max"], sphere["rows"]) == ("sphere", -0.8, 0.6, 6)
