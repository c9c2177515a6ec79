//! The suite of flank cuts the pose optimisation is measured on (`tests/optimise.rs`, the example
//! `optimise`, the book's table in `docs/src/cam/tool-paths.md`), millimetres: a hyperbolic
//! paraboloid patch, the paper's Example 6, a twisted blade and a closed ring on a hyperboloid's
//! flank. Each is a part's ruled surface, its rulings where the poses stand, the tool and the
//! side it cuts from, and the part's points the cut is measured at.

use glam::DVec3;
use ruledlab::{RuledSurface, Scheme, Segment, Variant};
use ruledlab_cam::{example_tool_path, PostOptions, Tool, ToolEnd};

/// One flank cut.
pub struct Case {
    /// Its name in the table.
    pub name: &'static str,
    /// The rulings the poses stand on, from the foot to the end.
    pub rulings: RuledSurface,
    /// The tool.
    pub tool: Tool,
    /// The side of the part the tool stands on (±1, `ruling_aligned`).
    pub side: f64,
    /// The part's points, between a tenth and nine tenths up the rulings.
    pub targets: Vec<DVec3>,
}

/// The share of each ruling the target covers: a tenth to nine tenths up.
const BAND: (f64, f64) = (0.1, 0.9);

/// A case of an analytic ruled surface p(u, v) = a(u) + v·d(u): `poses` rulings evenly in
/// `range`, targets at `along` × `up` points.
fn analytic(
    name: &'static str,
    surface: impl Fn(f64, f64) -> DVec3,
    range: (f64, f64),
    poses: usize,
    (along, up): (usize, usize),
    tool: Tool,
    side: f64,
) -> Case {
    let u = |i: usize, n: usize| range.0 + (range.1 - range.0) * i as f64 / (n - 1) as f64;
    let rulings = RuledSurface::new(
        (0..poses).map(|k| Segment::new(surface(u(k, poses), 0.0), surface(u(k, poses), 1.0))).collect(),
    )
    .expect("rulings");
    let targets = (0..along)
        .flat_map(|i| {
            let uu = range.0 + (range.1 - range.0) * (i as f64 + 0.5) / along as f64;
            (0..up).map(move |j| (uu, BAND.0 + (BAND.1 - BAND.0) * j as f64 / (up - 1) as f64))
        })
        .map(|(uu, v)| surface(uu, v))
        .collect();
    Case { name, rulings, tool, side, targets }
}

/// The hyperbolic paraboloid y = x·z/60 over x ∈ [−30, 30], z ∈ [0, 30]: its rulings x = const lean
/// up to 26.6° from the vertical, turning along the cut; 41 poses, a flat end of radius 5.
pub fn paraboloid() -> Case {
    let s = |u: f64, v: f64| DVec3::new(u, u * 30.0 * v / 60.0, 30.0 * v);
    analytic("hyperbolic paraboloid", s, (-30.0, 30.0), 41, (200, 5), Tool::new(5.0, 40.0, ToolEnd::Flat).unwrap(), 1.0)
}

/// Example 6 of the paper as a part: the axis surface of its 7 given poses refined by two steps
/// of the coupled variational scheme (25 rulings), ×10 to millimetres (rulings 15 mm), the
/// surface between rulings the discrete one's (bilinear); a ball end of radius 2.5.
pub fn example6() -> Case {
    let path =
        example_tool_path(7).unwrap().refine(Scheme::Variational { n: 12, variant: Variant::Coupled }, 5).unwrap();
    let segs: Vec<(DVec3, DVec3)> =
        path.poses.iter().map(|p| (10.0 * p.tip, 10.0 * (p.tip + path.tool.length * p.axis))).collect();
    let n = segs.len();
    let at = |u: f64, v: f64| {
        let k = (u.floor() as usize).min(n - 2);
        let s = u - k as f64;
        let (a, b) = (segs[k].0.lerp(segs[k + 1].0, s), segs[k].1.lerp(segs[k + 1].1, s));
        a.lerp(b, v)
    };
    analytic(
        "Example 6 (axis surface)",
        at,
        (0.0, (n - 1) as f64),
        49,
        (240, 5),
        Tool::new(2.5, 25.0, ToolEnd::Ball).unwrap(),
        1.0,
    )
}

/// A twisted blade 70 mm long: its base curve (u, 4 sin(u/25), 0), its rulings 30 mm long
/// turning from −20° to +20° about the blade's length (and swaying ±0.2 along it); 57 poses, a
/// ball end of radius 3.
pub fn blade() -> Case {
    let s = |u: f64, v: f64| {
        let beta = (-20.0 + 40.0 * u / 70.0f64).to_radians();
        let d = DVec3::new(0.2 * (u / 20.0).sin(), beta.sin(), beta.cos()).normalize();
        DVec3::new(u, 4.0 * (u / 25.0).sin(), 0.0) + 30.0 * v * d
    };
    analytic("twisted blade", s, (0.0, 70.0), 57, (280, 5), Tool::new(3.0, 40.0, ToolEnd::Ball).unwrap(), 1.0)
}

/// A closed ring on the flank of the hyperboloid of one sheet of waist radius 40 mm whose
/// rulings lean 30° (tangent to the waist circle), 20 mm high: 121 poses round 360°, the last on
/// the first; a flat end of radius 5, from outside.
pub fn ring() -> Case {
    let beta = 30f64.to_radians();
    let height = 20.0 / beta.cos();
    let s = |u: f64, v: f64| {
        let (sn, c) = u.to_radians().sin_cos();
        let d = beta.cos() * DVec3::Z + beta.sin() * DVec3::new(-sn, c, 0.0);
        DVec3::new(40.0 * c, 40.0 * sn, 0.0) + height * v * d
    };
    analytic(
        "closed ring (hyperboloid)",
        s,
        (0.0, 360.0),
        121,
        (300, 4),
        Tool::new(5.0, 30.0, ToolEnd::Flat).unwrap(),
        -1.0,
    )
}

/// The four cases.
pub fn cases() -> Vec<Case> {
    vec![paraboloid(), example6(), blade(), ring()]
}

/// How each case is posted: LinuxCNC, machine coordinates, the table–table A/C machine, a
/// chordal tolerance of 1 µm (so that the program's interpolation adds little to what the poses
/// leave), the case's target measured.
pub fn post_options(case: &Case) -> PostOptions {
    PostOptions { tolerance: 0.001, target: Some(case.targets.clone()), ..PostOptions::default() }
}
