//! Every tolerance and size limit of ruledlab, in one place.
//!
//! Geometric thresholds are dimensionless (sines of angles, ratios of lengths), so results
//! do not change when a model is scaled. Test tolerances live here too, so that a reader
//! sees at once how exact each kind of result is claimed to be.

/// Consecutive rulings whose angle φ has |sin φ| below this count as parallel.
///
/// The footpoint parameter of skew lines is t = ((d × e₁)·(e₀ × e₁)) / sin²φ; its rounding
/// error relative to its size is about ε/sin φ, so at this threshold footpoints are still
/// good to ~1e-7 relative. Below it the common perpendicular is not meaningfully unique.
pub const PARALLEL_SIN: f64 = 1e-9;

/// A segment is of zero length when |b − a| ≤ this · max(|a|, |b|): its direction would be
/// dominated by rounding.
pub const ZERO_LENGTH_REL: f64 = 1e-12;

/// A dragged handle counts as on a line or plane of the figure (a snap under a constraint: a
/// point on the handle's line, two lines that meet) within this share of the edit box's
/// diagonal — rounding of a scene's numbers, far below a pixel.
pub const SNAP_ON: f64 = 1e-9;

/// Most snap targets one placement of a dragged handle looks at (the page offers those near the
/// pointer: a handful).
pub const MAX_SNAP_TARGETS: usize = 4096;

/// Largest accepted coordinate magnitude. Squares of differences stay far from overflow. Also
/// the hidden-line camera's limit for its eye and target, and 1/MAX_COORD the least distance
/// between them (its near and far planes' product, distance²/50, stays a normal number).
pub const MAX_COORD: f64 = 1e150;

/// Largest number of rulings in one discrete ruled surface (input or output, checked before
/// allocating). 2²² rulings are 192 MiB of f64 segment coordinates.
pub const MAX_RULINGS: usize = 1 << 22;

/// Largest number of refinement levels of the convergence study.
pub const MAX_STUDY_LEVELS: usize = 20;

/// Longest formula, in characters (checked before parsing).
pub const MAX_FORMULA_CHARS: usize = 1000;

/// Deepest nesting of parentheses in a formula (checked before parsing, so neither the
/// parser nor the evaluator can recurse deeper than the formula's length allows).
pub const MAX_FORMULA_DEPTH: usize = 64;

/// Parameter samples at which a formula surface or congruence is checked when it is made:
/// every value and derivative finite, the ruling direction nonzero (per parameter direction).
pub const FORMULA_PROBES: usize = 257;

/// A formula's ruling direction counts as vanishing where |e| ≤ this · max |e| over the probes.
pub const FORMULA_ZERO_DIRECTION: f64 = 1e-12;

/// Most signs in a row in a formula ("--u" is fine, "-----u" is refused).
pub const MAX_FORMULA_SIGNS: usize = 4;

/// Probes per parameter direction when a formula congruence is made (a 33 × 33 grid): every
/// value and derivative finite, the direction nonzero.
pub const CONGRUENCE_FORMULA_PROBES: usize = 33;

/// Largest Bézier control polygon: de Casteljau costs O(degree) per output point, and
/// Bernstein bases of higher degree are numerically meaningless anyway.
pub const MAX_BEZIER_POINTS: usize = 1001;

/// Largest number of subdivision steps accepted in one call (the size limit usually binds
/// first).
pub const MAX_SUBDIVISION_STEPS: usize = 24;

/// Largest degree of the uniform B-spline scheme.
pub const MAX_BSPLINE_DEGREE: usize = 7;

/// Largest text accepted by the importers (64 MiB, about a million rulings of CSV).
pub const MAX_IMPORT_TEXT: usize = 64 << 20;

/// Deepest nesting of arrays and objects in an imported JSON file.
pub const MAX_JSON_DEPTH: usize = 16;

/// Most numbers in an imported JSON file: six for each of [`MAX_RULINGS`] segments (counted
/// while parsing, before the values pile up).
pub const MAX_JSON_NUMBERS: usize = 6 * MAX_RULINGS;

/// Convergence study: errors below this (relative to the surface's size, ~1) are rounding noise
/// and carry no order.
pub const CONVERGENCE_NOISE_FLOOR: f64 = 1e-13;

/// Largest number of samples asked of an analytic surface in one call.
pub const MAX_SAMPLES: usize = MAX_RULINGS;

/// Distance of a point from a smooth surface: rulings scanned before the golden-section search.
pub const DISTANCE_SCAN: usize = 64;

/// Distance of a point from a smooth surface: golden-section steps around the best scanned ruling
/// (each shrinks the bracket by 0.618: 80 reach the rounding of u).
pub const DISTANCE_REFINE_STEPS: usize = 80;

/// Pairs of rulings whose invariants the wasm bindings compute at a time before copying them into
/// JavaScript's arrays (`invariants()`, `invariantsInto`): about 600 KiB of results, which stay
/// in the processor's cache between the kernel and the copy.
pub const INVARIANTS_BLOCK: usize = 4096;

/// Largest stride of the buffers of inserted rulings (2^k after k steps).
pub const MAX_STRIDE: usize = 1 << 24;

/// Most parts of a segment in the variational schemes (n of Section 4.2, K of Section 5.2) and
/// in the drawn triangulations of Fig. 9.
pub const MAX_PARTS: usize = 1000;

/// Most rows or columns of a grid asked for by size: a formula congruence's default grid, the
/// milling example's part mesh.
pub const MAX_GRID_SIDE: usize = 1000;

/// Most vertices per ring of a tool or envelope mesh.
pub const MAX_MESH_SIDES: usize = 256;

/// Longest segment of an analytic congruence's grid, in multiples of its direction vector.
pub const MAX_REACH: f64 = 1e6;

/// Longest torsal stroke, in grid steps.
pub const MAX_STROKE_SCALE: f64 = 10.0;

/// Longest object name in an OBJ file, in characters.
pub const MAX_OBJECT_NAME: usize = 200;

/// Most poses of the built-in milling example.
pub const MAX_EXAMPLE_POSES: usize = 1000;

/// Most steps of a congruence subdivision in one call (each quadruples the lines).
pub const MAX_CONGRUENCE_STEPS: usize = 12;

/// Most vertices of a mesh handed in for shading: the two endpoints of the most rulings.
pub const MAX_MESH_VERTICES: usize = 2 * MAX_RULINGS;

// The limits admit what the others produce (checked when compiling): the stride of the inserted
// rulings after the most subdivision steps, a mesh of the most rulings' endpoints.
const _: () = assert!(MAX_STRIDE >= 1 << MAX_SUBDIVISION_STEPS);
const _: () = assert!(MAX_MESH_VERTICES >= 2 * MAX_RULINGS);
const _: () = assert!(MAX_JSON_NUMBERS >= 6 * MAX_RULINGS);

/// Focal geometry: a line is parabolic (one double focal point) when the discriminant of (F3)
/// is within this fraction of b² + 4|ac|: exact data only; a grid of a parabolic congruence
/// shows both other kinds, with nearly equal focal points.
pub const FOCAL_PARABOLIC: f64 = 1e-10;

/// Focal geometry: a displacement across the line shorter than this fraction of the line's
/// derivatives counts as zero (every direction torsal there, as for a bundle of lines).
pub const FOCAL_TORSAL_ZERO: f64 = 1e-10;

/// Focal geometry: |du| below which a torsal direction's sign is fixed by dv > 0 instead of du > 0.
pub const FOCAL_TORSAL_SIGN: f64 = 1e-9;

/// Focal geometry: focal sheets are drawn within this many diagonals of the lines' bounding box
/// from its centre.
pub const FOCAL_SHEET_REACH: f64 = 3.0;

/// Linear complexes: default tolerance of the root-mean-square residual, in the fit's frame
/// (centred at the lines' midpoints, lengths divided by their spread), under which a complex
/// counts as holding the lines.
pub const COMPLEX_TOLERANCE: f64 = 1e-9;

/// Linear complexes: the Klein form restricted to a three-dimensional null space is called
/// degenerate (lines of a bundle or a field, not a regulus) when |det| is below this.
pub const COMPLEX_REGULUS_DET: f64 = 1e-6;

/// Conjugate gradients of the coupled congruence scheme stop when ‖r‖ ≤ this · (largest
/// coordinate) · √(nodes), or at this fraction of the first residual: a few hundred roundings
/// above what the arithmetic can resolve.
pub const SOLVE_TOLERANCE: f64 = 1e-13;

/// Most conjugate-gradient iterations of the coupled congruence scheme (its systems converge
/// in a bounded number, about 20; this only catches a broken one).
pub const SOLVE_MAX_ITERATIONS: usize = 2000;

/// Hidden lines: a line within this distance of a triangle's plane is never hidden by it, as a
/// fraction of the diagonal of the triangles' bounding box (rounding of f32 buffers, lines on a
/// flat mesh); see also [`HIDDEN_LINE_BEND`].
pub const HIDDEN_LINE_TOLERANCE: f64 = 1e-3;

/// Hidden lines: a line within this fraction of a triangle's bend (how far the triangles
/// sharing its edges leave its plane) is not hidden by it, so that lines lying on a surface are
/// not hidden by the surface they lie on. Measured on the hyperboloid strip of Fig. 2 with 12,
/// 24, 36 and 72 rulings: the striction polygon, the common perpendiculars and the exact
/// striction curve lie within 0.30–0.32 bends of the triangles they cross (0.078 for a bend of
/// 0.44 at 36 rulings); half a bend leaves a margin of 1.6.
pub const HIDDEN_LINE_BEND: f64 = 0.5;

/// Hidden lines: a run of one visibility shorter than this many pixels between runs of the other
/// is a sliver where a line grazes an edge, and goes to its neighbours.
pub const HIDDEN_LINE_MIN_PIECE: f64 = 1.0;

/// Hidden lines: the largest `minPiece` (pixels) an export may ask for.
pub const MAX_HIDDEN_LINE_MIN_PIECE: f64 = 1e3;

/// Hidden lines: a triangle whose image has |(b − a) × (c − a)| (twice its area) at most this
/// times its longer side from a, squared, is seen edge-on and hides nothing.
pub const HIDDEN_LINE_EDGE_ON: f64 = 1e-12;

/// The hidden-line camera (`View::looking`) takes z as up unless the view direction is within
/// this sine of z, where it takes y.
pub const CAMERA_UP_SINE: f64 = 1e-9;

/// Hidden lines: most cells per side of the screen grid the triangles are binned in.
pub const MAX_HIDDEN_LINE_GRID: usize = 1024;

/// Hidden lines: most grid cells a triangle is binned in on average; a view of huge triangles
/// (seen from close by) gets a coarser grid instead of a quadratic number of entries.
pub const HIDDEN_LINE_GRID_ENTRIES: usize = 16;

/// Hidden lines: most triangles and most line points in one call (checked before binning).
pub const MAX_HIDDEN_LINE_ITEMS: usize = 1 << 22;

/// Developable strips: a pair of consecutive rulings counts as coplanar (torsal) when the height η
/// of the tetrahedron of its four ends over its largest face (an end's distance from the plane of
/// the other three, where that plane is best defined: `developable::coplanar`) is at most this times max(1, the strip's size: the diagonal of
/// its bounding box). η, not |δ| = h/φ (1), because δ magnifies the rounding of the ends by 1/φ²
/// where rulings meet at small angles; the constructions and the repair of `developable/` reach
/// η ≈ 1e-16 of the size. The exact unfolding refuses a strip with a pair above it.
pub const TORSAL_HEIGHT: f64 = 1e-12;

/// Developable strips, the repair: most Gauss–Newton steps towards the nearest developable strip
/// (they converge quadratically: a drag on the page takes 3 to 5; the sweep that follows them makes
/// every pair torsal in any case).
pub const REPAIR_STEPS: usize = 50;

/// Flat patterns: two faces overlap when their interiors overlap by more than this share of the
/// pattern's size (faces that only touch, at a cone's apex or along a ruling, do not).
pub const OVERLAP_REL: f64 = 1e-9;

/// Flat patterns: most millimetres per unit of the model (and least: 1/this).
pub const MAX_PATTERN_SCALE: f64 = 1e4;

/// Flat patterns: the largest sheet, in millimetres per side (10 m: a roll of paper or a big
/// laser bed; tiling it into A4 pages gives at most [`MAX_PAGES`]).
pub const MAX_SHEET_MM: f64 = 10_000.0;

/// Flat patterns: most printed pages of a tiling.
pub const MAX_PAGES: usize = 2500;

/// Flat patterns: the widest kerf (the width a laser or knife cuts away), millimetres.
pub const MAX_KERF_MM: f64 = 5.0;

/// Flat patterns: the widest glue tab, millimetres.
pub const MAX_TAB_MM: f64 = 50.0;

/// Flat patterns: the side of the check square printed beside every pattern, millimetres: a
/// printer that scales the page shows it as another length.
pub const CHECK_SQUARE_MM: f64 = 100.0;

/// Flat patterns: the blank margin on each side of a printed page, millimetres (most printers
/// print to within 5 mm of the edge).
pub const PAGE_MARGIN_MM: f64 = 10.0;

/// Flat patterns: how far neighbouring pages of a tiled print overlap, millimetres (the
/// registration marks sit in the middle of the overlap).
pub const PAGE_OVERLAP_MM: f64 = 10.0;

/// `|a − b| ≤ tol · max(1, |a|, |b|)`: relative for large numbers, absolute near zero; an
/// infinity is near only itself (the relative bound would let ∞ be near every number).
pub fn near(a: f64, b: f64, tol: f64) -> bool {
    if a.is_infinite() || b.is_infinite() {
        return a == b;
    }
    (a - b).abs() <= tol * 1f64.max(a.abs()).max(b.abs())
}

/// The Klein view: the least and greatest unit of length ℓ that makes moments comparable with
/// directions in the split of P⁵ into two spheres (`klein/image.rs`, K4).
pub const MIN_KLEIN_UNIT: f64 = 1e-6;
/// See [`MIN_KLEIN_UNIT`].
pub const MAX_KLEIN_UNIT: f64 = 1e6;

/// The Klein view: most circles of the quadric's outline, and most chords a circle or a conic
/// is drawn with (`klein/image.rs`, `klein/sections.rs`).
pub const MAX_KLEIN_OUTLINE_SAMPLES: usize = 1024;
/// The Klein view's drawing: parallels (and half meridians) of the outline's outer sphere.
pub const KLEIN_OUTLINE_CIRCLES: usize = 5;
/// The Klein view's drawing: chords of each circle of the outline, and points of a conic.
pub const KLEIN_OUTLINE_SAMPLES: usize = 64;

/// Two consecutive normalised rulings meet (a torsal step) when |Ω(L₁, L₂)| ≤ this ·
/// max(1, |m₁|, |m₂|) (`klein/polygon.rs`): rounding of the moments' few products. The plane of
/// three lines lies on M (they meet pairwise: no conic) when the Klein form is at most this on
/// its orthonormal basis (`klein/sections.rs`).
pub const KLEIN_TORSAL: f64 = 1e-12;

/// Tolerances the test suites use, named by what they claim.
pub mod test {
    /// Results that are exact up to rounding of a few dozen operations.
    pub const EXACT: f64 = 1e-12;
    /// The Klein residual Ω(L, L)/2 of every line drawn on the Klein quadric, after every edit
    /// and subdivision step (`tests/klein.rs`).
    pub const KLEIN_RESIDUAL: f64 = 1e-12;
    /// Slack allowed around a measured convergence order (1 or 2).
    pub const ORDER: f64 = 0.1;
    /// The invariants kernel's φ against `f64::atan2`, in units in the last place, over the whole
    /// upper half-plane (`tests/kernels.rs`). Measured: 1 against glibc's `atan2` (natively,
    /// within about ½ ulp of the exact angle), 2 against fdlibm's (Rust's in wasm), where both
    /// are off the exact angle by up to 1.4 ulp, in opposite directions.
    pub const KERNEL_ANGLE_ULPS: u64 = 2;
    /// The kernel's δ = h/φ against the scalar path's (h is the same bits, φ within
    /// [`KERNEL_ANGLE_ULPS`], and the division rounds once more); (δ_{i−1,i} + δ_{i,i+1})/2
    /// within as many ulp of the larger term.
    pub const KERNEL_DELTA_ULPS: u64 = 3;

    /// Reproducible pseudo-random numbers in [0, 1) for the unit tests (of this crate and of
    /// ruledlab-cam): a 64-bit linear congruential generator (Knuth's MMIX constants), the top 53 bits.
    pub fn uniform(seed: &mut u64) -> f64 {
        *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Asserts `|a − b| ≤ tol · max(1, |a|, |b|)` for numbers or `DVec3`s, with a useful message;
/// a value with an infinite part is near only an equal value.
#[macro_export]
macro_rules! assert_near {
    ($a:expr, $b:expr, $tol:expr $(,)?) => {{
        let (a, b, tol) = ($a, $b, $tol);
        let err = $crate::tolerance::Distance::distance(&a, &b);
        let scale = 1f64.max($crate::tolerance::Distance::size(&a)).max($crate::tolerance::Distance::size(&b));
        let ok = if scale.is_finite() { err <= tol * scale } else { a == b };
        assert!(ok, "assert_near failed: {:?} vs {:?}: error {:e} > {:e}", a, b, err, tol * scale);
    }};
}

/// What [`assert_near!`] needs of a value: a distance and a size.
pub trait Distance {
    /// Distance between two values.
    fn distance(&self, other: &Self) -> f64;
    /// The value's magnitude.
    fn size(&self) -> f64;
}

impl Distance for f64 {
    fn distance(&self, other: &Self) -> f64 {
        (self - other).abs()
    }
    fn size(&self) -> f64 {
        self.abs()
    }
}

impl Distance for glam::DVec3 {
    fn distance(&self, other: &Self) -> f64 {
        (*self - *other).length()
    }
    fn size(&self) -> f64 {
        self.length()
    }
}

impl Distance for glam::DVec2 {
    fn distance(&self, other: &Self) -> f64 {
        (*self - *other).length()
    }
    fn size(&self) -> f64 {
        self.length()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_is_relative_for_large_and_absolute_for_small() {
        assert!(near(1e6, 1e6 + 1e-7, 1e-12));
        assert!(!near(1e6, 1e6 + 1e-4, 1e-12));
        assert!(near(0.0, 1e-13, 1e-12));
        assert!(!near(0.0, 1e-11, 1e-12));
    }

    /// assert_near! measures each kind of value: far apart fails, near passes, relative to the
    /// larger size above 1.
    #[test]
    fn assert_near_measures_distances_relative_to_the_size() {
        use glam::{DVec2, DVec3};
        let fails = |f: fn()| std::panic::catch_unwind(f).is_err();
        assert!(fails(|| assert_near!(1.0, 2.0, 1e-3)));
        assert!(fails(|| assert_near!(DVec3::X, DVec3::Y, 1e-3)));
        assert!(fails(|| assert_near!(DVec2::X, DVec2::Y, 1e-3)));
        // 1 apart at a size of 1.7e6: within 1e-5 relative, not absolute
        assert_near!(1e6, 1e6 + 1.0, 1e-5);
        assert_near!(DVec3::splat(1e6), DVec3::splat(1e6 + 1.0), 1e-5);
        assert_near!(DVec2::splat(1e6), DVec2::splat(1e6 + 1.0), 1e-5);
        assert!(fails(|| assert_near!(DVec3::splat(10.0), DVec3::splat(11.0), 1e-5)));
    }

    #[test]
    fn an_infinity_is_near_only_itself() {
        assert!(near(f64::INFINITY, f64::INFINITY, 1e-12));
        assert!(!near(f64::INFINITY, 5.0, 1e-12));
        assert!(!near(-1e300, f64::NEG_INFINITY, 1e-12));
        assert!(!near(f64::INFINITY, f64::NEG_INFINITY, 1e-12));
        assert_near!(f64::INFINITY, f64::INFINITY, 1e-12);
        assert_near!(glam::DVec3::new(1.0, 2.0, 3.0), glam::DVec3::new(1.0, 2.0, 3.0 + 1e-13), 1e-12);
        let caught = std::panic::catch_unwind(|| assert_near!(f64::INFINITY, 5.0, 1e-12));
        assert!(caught.is_err(), "∞ passed as near 5");
        let caught = std::panic::catch_unwind(|| {
            assert_near!(glam::DVec3::new(f64::INFINITY, 0.0, 0.0), glam::DVec3::ZERO, 1e-12)
        });
        assert!(caught.is_err(), "a point at infinity passed as near the origin");
    }
}
