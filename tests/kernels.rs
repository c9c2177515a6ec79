//! The f64x2 kernels against the scalar code they replace, over random and adversarial input.
//! Runs natively (`cargo test --test kernels`: the portable lanes, SSE2 on x86-64) and, with the
//! same body, in Chromium and Firefox under wasm-bindgen-test (`core::arch::wasm32` simd128
//! lanes, fdlibm's `atan2` as the reference), so both builds are held to the same bounds.
//!
//! The bounds (src/tolerance.rs, `tolerance::test`):
//! - bit for bit: h, the footpoints, n, the striction polygon, Example 1's polygon, the parallel
//!   flags, and every point of a four-point, Chaikin or B-spline step (exact same operations);
//! - φ within [`KERNEL_ANGLE_ULPS`] of `f64::atan2`, over the whole upper half-plane;
//! - δ = h/φ within [`KERNEL_DELTA_ULPS`]; (δ_{i−1,i} + δ_{i,i+1})/2 within as many ulp of the
//!   larger of its two terms (a sum of two terms of opposite sign can be far smaller than
//!   either, and an ulp of the terms is then many ulp of the sum);
//! - the same errors for the same bad input (a step that overflows, a zero-length ruling).

use glam::DVec3;
use ruledlab::tolerance::test::{KERNEL_ANGLE_ULPS, KERNEL_DELTA_ULPS};
use ruledlab::tolerance::{MAX_COORD, PARALLEL_SIN};
use ruledlab::{atan2_x2, bspline, chaikin, four_point, subdivide_strip, Invariants, Line, Pair, RuledSurface, Scheme};
use ruledlab::{AnalyticSurface, SmoothRuled};

#[cfg(target_family = "wasm")]
use wasm_bindgen_test::wasm_bindgen_test;
#[cfg(target_family = "wasm")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

/// splitmix64: the same numbers on every machine.
struct Random(u64);

impl Random {
    fn bits(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.bits() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [−s, s).
    fn sym(&mut self, s: f64) -> f64 {
        (2.0 * self.unit() - 1.0) * s
    }
    fn below(&mut self, n: u64) -> u64 {
        self.bits() % n
    }
    fn vec(&mut self, s: f64) -> DVec3 {
        DVec3::new(self.sym(s), self.sym(s), self.sym(s))
    }
}

/// Distance in units in the last place (0 for equal numbers, both NaN, or ±0).
fn ulps(a: f64, b: f64) -> u64 {
    if a == b || (a.is_nan() && b.is_nan()) {
        return 0;
    }
    if a.is_nan() || b.is_nan() || a.is_sign_negative() != b.is_sign_negative() {
        // opposite signs: through zero
        return if a.is_nan() || b.is_nan() { u64::MAX } else { a.abs().to_bits() + b.abs().to_bits() };
    }
    a.to_bits().abs_diff(b.to_bits())
}

/// The same number, NaN as NaN (the NaN's sign and payload are left open by IEEE-754).
fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

fn same3(a: &[DVec3], b: &[DVec3]) -> Option<usize> {
    assert_eq!(a.len(), b.len());
    a.iter().zip(b).position(|(p, q)| !(same(p.x, q.x) && same(p.y, q.y) && same(p.z, q.z)))
}

/// The kernel's invariants against the scalar ones of the same lines, with the bounds above.
fn check_invariants(what: &str, s: &RuledSurface, closed: bool) {
    let lines: Vec<Line> = s.lines().collect();
    let scalar = if closed { Invariants::from_lines_closed(&lines) } else { Invariants::of(&lines) };
    let kernel = if closed { s.invariants_closed() } else { s.invariants() };
    let at = |i: usize| format!("{what} (N = {}, closed: {closed}), index {i}", s.len());
    assert_eq!(kernel.parallel, scalar.parallel, "{}", at(0));
    for (i, (a, b)) in kernel.distance.iter().zip(&scalar.distance).enumerate() {
        assert!(same(*a, *b), "h: {a:e} vs {b:e} at {}", at(i));
    }
    for (name, a, b) in [
        ("footpoints", &kernel.footpoints, &scalar.footpoints),
        ("normals", &kernel.central_normal, &scalar.central_normal),
        ("striction", &kernel.striction, &scalar.striction),
        ("midpoints", &kernel.perpendicular_midpoints, &scalar.perpendicular_midpoints),
    ] {
        if let Some(i) = same3(a, b) {
            panic!("{name}: {:?} vs {:?} at {}", a[i], b[i], at(i));
        }
    }
    for (i, (a, b)) in kernel.angle.iter().zip(&scalar.angle).enumerate() {
        assert!(ulps(*a, *b) <= KERNEL_ANGLE_ULPS, "φ: {a:e} vs {b:e} at {}", at(i));
    }
    for (i, (a, b)) in kernel.distribution.iter().zip(&scalar.distribution).enumerate() {
        assert!(ulps(*a, *b) <= KERNEL_DELTA_ULPS, "δ: {a:e} vs {b:e} at {}", at(i));
    }
    assert_eq!(kernel.distribution_mean.len(), scalar.distribution_mean.len());
    let pairs = scalar.distribution.len();
    for (j, (a, b)) in kernel.distribution_mean.iter().zip(&scalar.distribution_mean).enumerate() {
        // the two δ it averages (closed: entry j belongs to ruling j, open to ruling j + 1)
        let i = if closed { j } else { j + 1 };
        let terms = [scalar.distribution[(i + pairs - 1) % pairs], scalar.distribution[i % pairs]];
        let scale = terms[0].abs().max(terms[1].abs());
        let ulp = f64::from_bits(scale.to_bits() + 1) - scale;
        let ok = same(*a, *b) || (a - b).abs() <= KERNEL_DELTA_ULPS as f64 * ulp;
        assert!(ok, "mean δ: {a:e} vs {b:e} (terms {terms:?}) at {}", at(j));
    }
}

fn surface(points: Vec<DVec3>) -> RuledSurface {
    RuledSurface::from_points(points).expect("a valid surface")
}

/// φ over the whole upper half-plane: random arguments over every binade and both signs of x,
/// the borders of fdlibm's intervals (ratio 7/16, 11/16, 1) and of the octants, zeros, and the
/// angles of unit vectors, against `f64::atan2`. Returns the largest difference in ulp.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn atan2_is_within_its_bound_of_the_library_over_the_upper_half_plane() {
    let mut r = Random(7);
    let mut worst = (0, 0.0, 0.0);
    let mut check = |y: f64, x: f64| {
        let [a, b] = atan2_x2([y, y], [x, -x]);
        for (got, x) in [(a, x), (b, -x)] {
            let d = ulps(got, y.atan2(x));
            if d > worst.0 {
                worst = (d, y, x);
            }
        }
    };
    for _ in 0..100_000 {
        // any finite y ≥ 0 and x: random bits
        let y = f64::from_bits(r.bits() & 0x7FEF_FFFF_FFFF_FFFF);
        let x = f64::from_bits(r.bits() & 0xFFEF_FFFF_FFFF_FFFF);
        check(y, x);
        // ratios near the interval borders and the diagonal, at random scales
        let scale = 2f64.powi(r.below(200) as i32 - 100);
        let border = [7.0 / 16.0, 11.0 / 16.0, 1.0][r.below(3) as usize];
        let ratio = border * (1.0 + r.sym(1e-12));
        check(ratio * scale, scale);
        check(scale, ratio * scale);
        // unit vectors: the angles φ of the invariants, and tiny angles
        let phi = std::f64::consts::PI * r.unit();
        check(phi.sin().abs(), phi.cos());
        let tiny = 2f64.powi(-(r.below(1070) as i32)) * (1.0 + r.unit());
        check(tiny, 1.0);
        check(1.0, tiny);
    }
    for (y, x) in [(0.0, 1.0), (0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (f64::MIN_POSITIVE, 1.0), (1.0, f64::MAX)] {
        check(y, x);
        check(y, -0.0);
    }
    assert!(worst.0 <= KERNEL_ANGLE_ULPS, "{} ulp at atan2({:e}, {:e})", worst.0, worst.1, worst.2);
    // glibc's atan2 is within about half an ulp of the exact angle: against it, one ulp at most
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    assert!(worst.0 <= 1, "{} ulp from glibc's atan2 at ({:e}, {:e})", worst.0, worst.1, worst.2);
}

/// Random surfaces of every size from 2 to 40 rulings (both tails of the kernel's two-pair
/// steps, open and closed), at scales from 1e-100 to 1e100.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn invariants_match_the_scalar_path_on_random_surfaces() {
    let mut r = Random(11);
    for n in 2..=40 {
        for _ in 0..20 {
            let scale = 10f64.powi(r.below(201) as i32 - 100);
            let far = 10f64.powi(r.below(6) as i32);
            let offset = r.vec(scale * far);
            let points = (0..2 * n).map(|_| offset + r.vec(scale)).collect();
            let s = surface(points);
            check_invariants("random", &s, false);
            check_invariants("random", &s, true);
        }
    }
}

/// Smooth surfaces sampled densely: nearly parallel consecutive rulings, the regime of
/// Propositions 1 and 2 (sin φ from 1e-2 down to below the parallel threshold).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn invariants_match_the_scalar_path_on_nearly_parallel_rulings() {
    for steps in [1e2, 1e4, 1e6, 1e8, 1e10] {
        let h = 1.0 / steps;
        // a helicoid-like twist and a hyperboloid, 33 rulings around u = 0.3
        let twist: Vec<DVec3> = (0..33)
            .flat_map(|i| {
                let u = 0.3 + h * i as f64;
                let (s, c) = u.sin_cos();
                [DVec3::new(0.0, 0.0, 0.5 * u), DVec3::new(c, s, 0.5 * u)]
            })
            .collect();
        let hyp: Vec<DVec3> = (0..33)
            .flat_map(|i| {
                let u = 0.3 + h * i as f64;
                let (s, c) = u.sin_cos();
                [DVec3::new(c + s, s - c, -1.0), DVec3::new(c - s, s + c, 1.0)]
            })
            .collect();
        for (name, p) in [("twist", twist), ("hyperboloid", hyp)] {
            let s = surface(p);
            check_invariants(name, &s, false);
            check_invariants(name, &s, true);
        }
    }
}

/// Parallel, antiparallel, coincident and intersecting rulings, rulings just above and below the
/// parallel threshold, huge and tiny coordinates (the checked limit 1e150 and far below 1):
/// mixed in one surface so that every pattern meets both lanes and the tails.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn invariants_match_the_scalar_path_on_adversarial_rulings() {
    let z = DVec3::Z;
    let tilt = |sin: f64| DVec3::new(sin, 0.0, (1.0 - sin * sin).sqrt());
    let rulings: Vec<(DVec3, DVec3)> = vec![
        (DVec3::ZERO, z),
        (DVec3::new(3.0, 4.0, 7.0), z),        // parallel
        (DVec3::new(3.0, 4.0, 7.0), -z),       // antiparallel
        (DVec3::new(3.0, 4.0, 9.0), -z),       // coincident with the one before
        (DVec3::new(3.0, 4.0, 9.0), DVec3::X), // intersecting
        (DVec3::new(1.0, 2.0, 3.0), DVec3::X.lerp(DVec3::Y, 1e-13).normalize()), // nearly parallel
        (DVec3::new(0.0, 1.0, 0.0), tilt(PARALLEL_SIN * 0.5)),
        (DVec3::new(0.0, 2.0, 0.0), tilt(PARALLEL_SIN * 2.0)),
        (DVec3::new(1.0, 0.0, 0.0), tilt(PARALLEL_SIN * 0.999_999)),
        (DVec3::new(1.0, 0.0, 1.0), DVec3::Y),
    ];
    let mut r = Random(3);
    for scale in [1e-150, 1e-20, 1.0, 1e20, 1e149] {
        for start in 0..rulings.len() {
            for len in 2..=rulings.len() {
                let points: Vec<DVec3> = (0..len)
                    .flat_map(|i| {
                        let (p, e) = rulings[(start + i) % rulings.len()];
                        [p * scale, (p + e) * scale]
                    })
                    .collect();
                let s = surface(points);
                check_invariants("adversarial", &s, false);
                check_invariants("adversarial", &s, true);
            }
        }
        // far from the origin: the segment short against its position
        let far: Vec<DVec3> = (0..9)
            .flat_map(|_| {
                let p = DVec3::splat((scale * 1e3).min(1e149)) + r.vec(scale);
                [p, p + r.vec(scale * 1e-3)]
            })
            .collect();
        check_invariants("far", &surface(far), false);
    }
    // the largest coordinates accepted
    let huge: Vec<DVec3> = (0..7).flat_map(|_| [r.vec(MAX_COORD), r.vec(MAX_COORD)]).collect();
    check_invariants("huge", &surface(huge), false);
}

/// The kernel through `invariants_into`: the arrays are reused, the numbers those of a fresh call.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn invariants_into_reused_arrays_are_those_of_a_fresh_call() {
    let mut r = Random(5);
    let mut out = Invariants::default();
    for (n, closed) in [(50, false), (20, true), (50, true), (3, false), (50, false)] {
        let s = surface((0..2 * n).map(|_| r.vec(1.0)).collect());
        s.invariants_into(&mut out, closed);
        let fresh = if closed { s.invariants_closed() } else { s.invariants() };
        assert_eq!(format!("{out:?}"), format!("{fresh:?}"));
    }
}

/// The generic step (`four_point`, `chaikin`, `bspline` on endpoint pairs, then the full
/// validation): what `subdivide_strip` did before its kernels.
fn generic(s: &RuledSurface, scheme: Scheme, closed: bool, steps: usize) -> Result<RuledSurface, ruledlab::Error> {
    let mut p: Vec<Pair> = s.points().chunks_exact(2).map(|ab| Pair(ab[0], ab[1])).collect();
    for _ in 0..steps {
        p = match scheme {
            Scheme::FourPoint { w } => four_point(&p, w, closed),
            Scheme::Chaikin => chaikin(&p, closed),
            Scheme::BSpline { degree } => bspline(&p, degree, closed),
            _ => unreachable!(),
        };
    }
    RuledSurface::from_points(p.iter().flat_map(|q| [q.0, q.1]).collect())
}

/// The kernel's step against the generic one: the same points bit for bit, or the same error
/// (returned, so that a test can see which errors its strips met).
fn check_step(what: &str, s: &RuledSurface, scheme: Scheme, closed: bool, steps: usize) -> Option<String> {
    let want = generic(s, scheme, closed, steps);
    let got = subdivide_strip(s, scheme, closed, steps);
    match (got, want) {
        (Ok(g), Ok(w)) => {
            if let Some(i) = same3(g.points(), w.points()) {
                panic!("{what}: {scheme:?}, closed {closed}, {steps} steps, N = {}: point {i}", s.len());
            }
            None
        }
        (Err(g), Err(w)) => {
            let g = format!("{g:?}");
            assert_eq!(g, format!("{w:?}"), "{what}: {scheme:?}");
            Some(g.split([' ', '{', '(']).next().unwrap_or_default().to_string())
        }
        (g, w) => panic!("{what}: {scheme:?}, closed {closed}, {steps} steps: {g:?} vs {w:?}"),
    }
}

fn schemes() -> Vec<Scheme> {
    let mut all = vec![Scheme::Chaikin];
    all.extend([1.0 / 16.0, 0.0, -0.1, 0.25, 1.0 / 13.0].map(|w| Scheme::FourPoint { w }));
    all.extend((1..=7).map(|degree| Scheme::BSpline { degree }));
    all
}

/// Random strips of 2 to 24 rulings (every end and tail of the kernels' loops), open and
/// closed, one to three steps, at scales from 1e-100 to 1e100.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn strip_steps_match_the_generic_code_on_random_strips() {
    let mut r = Random(13);
    for scheme in schemes() {
        for n in 2..=24 {
            let scale = 10f64.powi(r.below(201) as i32 - 100);
            let s = surface((0..2 * n).map(|_| r.vec(scale)).collect());
            for closed in [false, true] {
                for steps in 1..=3 {
                    if scheme.output_len_after(n, closed, steps).is_ok() {
                        check_step("random", &s, scheme, closed, steps);
                    }
                }
            }
        }
    }
}

/// Strips whose steps fail the validation, or nearly: refined coordinates beyond 1e150 (the
/// four-point scheme overshoots, the B-splines stay inside), exactly at the limit, boundary
/// polygons that cross so that a new ruling has length zero, or nearly zero; and sampled
/// surfaces (rulings nearly parallel, segments far from the origin).
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn strip_steps_match_the_generic_code_on_adversarial_strips() {
    let mut r = Random(17);
    let zigzag = |n: usize, s: f64| -> Vec<DVec3> {
        (0..n)
            .flat_map(|i| [DVec3::new(i as f64, (i % 2) as f64, 0.0) * s, DVec3::new(i as f64, 0.0, 1.0) * s])
            .collect()
    };
    let limit = |n: usize| -> Vec<DVec3> {
        (0..n)
            .flat_map(|i| {
                let x = if i % 2 == 0 { MAX_COORD } else { -MAX_COORD };
                [DVec3::new(x, 0.0, 0.0), DVec3::new(x, MAX_COORD, 0.0)]
            })
            .collect()
    };
    // a and b swap sides between rulings: the polygons cross, midway a = b
    let crossing = |n: usize| -> Vec<DVec3> {
        (0..n)
            .flat_map(|i| {
                let s = if i % 2 == 0 { 1.0 } else { -1.0 };
                [DVec3::new(i as f64, s, 0.0), DVec3::new(i as f64, -s, 0.0)]
            })
            .collect()
    };
    let nearly_crossing = |n: usize| -> Vec<DVec3> {
        (0..n)
            .flat_map(|i| {
                let s = if i % 2 == 0 { 1.0 } else { -1.0 + 1e-13 };
                [DVec3::new(0.0, s, 0.0), DVec3::new(0.0, -s, 0.0)]
            })
            .collect()
    };
    let far = |n: usize, r: &mut Random| -> Vec<DVec3> {
        (0..n)
            .flat_map(|_| {
                let p = DVec3::splat(1e140) + r.vec(1e130);
                [p, p + r.vec(1e129)]
            })
            .collect()
    };
    let mut errors = std::collections::BTreeSet::new();
    for n in [2, 3, 4, 5, 6, 7, 8, 9, 16, 17] {
        let strips = [
            ("zigzag", zigzag(n, 1.0)),
            ("zigzag, tiny", zigzag(n, 1e-140)),
            ("at the coordinate limit", limit(n)),
            ("crossing", crossing(n)),
            ("nearly crossing", nearly_crossing(n)),
            ("far", far(n, &mut r)),
        ];
        for (what, points) in strips {
            let Ok(s) = RuledSurface::from_points(points) else { continue };
            for scheme in schemes() {
                for closed in [false, true] {
                    for steps in 1..=2 {
                        if scheme.output_len_after(n, closed, steps).is_ok() {
                            errors.extend(check_step(what, &s, scheme, closed, steps));
                        }
                    }
                }
            }
        }
    }
    // the strips met every way a step can fail
    let met: Vec<&str> = errors.iter().map(String::as_str).collect();
    assert_eq!(met, ["OutOfRange", "TooFew", "ZeroLength"]);
    // sampled surfaces of the catalogue, 1000 rulings
    for name in ["hyperboloid", "helicoid", "quartic"] {
        let a = AnalyticSurface::by_name(name).expect("in the catalogue");
        let s = a.sample(1000, a.ranges()).expect("valid");
        for scheme in schemes() {
            check_step(name, &s, scheme, false, 1);
        }
    }
}

/// Block by block, as the wasm bindings fill JavaScript's arrays: the same numbers as the whole
/// surface at once, for blocks of every size against both tails and the wrap.
#[cfg_attr(not(target_family = "wasm"), test)]
#[cfg_attr(target_family = "wasm", wasm_bindgen_test)]
fn invariants_by_blocks_are_those_of_the_whole_surface() {
    let mut r = Random(19);
    for n in [2, 3, 4, 5, 9, 10, 33] {
        let s = surface((0..2 * n).map(|_| r.vec(1.0)).collect());
        for closed in [false, true] {
            let whole = if closed { s.invariants_closed() } else { s.invariants() };
            for block in [2, 3, 4, 5, 7, 64] {
                let mut got = whole.clone();
                let nan = DVec3::splat(f64::NAN);
                got.angle.fill(f64::NAN);
                got.footpoints.fill(nan);
                got.striction.fill(nan);
                got.distribution_mean.fill(f64::NAN);
                got.perpendicular_midpoints.fill(nan);
                let mut scratch = Invariants::default();
                Invariants::by_blocks(s.points(), closed, block, &mut scratch, |b| {
                    let (p, m, k) = (b.pairs_from, b.interior_from, b.inv.angle.len());
                    got.angle[p..p + k].copy_from_slice(&b.inv.angle);
                    got.footpoints[2 * p..2 * (p + k)].copy_from_slice(&b.inv.footpoints);
                    got.perpendicular_midpoints[p..p + k].copy_from_slice(&b.inv.perpendicular_midpoints);
                    let l = b.inv.striction.len();
                    got.striction[m..m + l].copy_from_slice(&b.inv.striction);
                    got.distribution_mean[m..m + l].copy_from_slice(&b.inv.distribution_mean);
                });
                assert_eq!(format!("{got:?}"), format!("{whole:?}"), "N = {n}, closed {closed}, blocks of {block}");
            }
        }
    }
}
