//! Hidden lines: which parts of a figure's lines the triangles of its surfaces hide from the
//! camera, computed rather than sorted — Appel's question ("A. Appel, The notion of quantitative
//! invisibility and the machine rendering of solids", 1967) answered segment by segment against
//! every triangle, for vector figures (SVG, TikZ) that print like the paper's line drawings.
//!
//! The camera is a 4 × 4 view-projection matrix M (column-major, as WebGL takes it; perspective
//! or orthographic, clip z from −w at the near plane to w at the far one) and a viewport of
//! `width` × `height` pixels, y down: x ↦ ((c_x/c_w + 1)/2 · width, (1 − c_y/c_w)/2 · height) for
//! c = M·(x, 1). The eye is the homogeneous point M⁻¹·(0, 0, 1, 0) (a direction for an
//! orthographic camera). A point P of a line is **hidden** by a triangle T when
//!
//! 1. its image lies in T's image (edges included), and
//! 2. P lies behind T's plane as seen from the eye by more than T's tolerance τ_T:
//!    σ_T (n̂_T·P − d_T) < −τ_T, with n̂_T·x = d_T the plane and σ_T = ±1 the side of the eye.
//!
//! With τ_T > 0 a line lying *on* a surface — a ruling of a strip (an edge of its own
//! triangles), the striction polygon or an exact curve of the smooth surface, near its
//! triangulation — is not hidden by that surface, while a surface farther than τ_T in front of
//! a line hides it. τ_T is the larger of a global τ ([`HIDDEN_LINE_TOLERANCE`] times the
//! diagonal of the triangles' bounding box unless given) and [`HIDDEN_LINE_BEND`] times how far
//! the neighbours of T (triangles sharing an edge) bend away from T's plane: a coarse strip of
//! twisted quads carries lines that lie far off its triangles, a flat square none.
//!
//! Along a segment A → B (clipped to the near plane) both conditions are intervals of the
//! screen parameter s of its image a + s(b − a): the edge functions of T's image are linear in
//! s, and the plane distance is linear in the segment's parameter t, a monotone projective
//! function of s, t = s·w_A / ((1 − s)·w_B + s·w_A) (w the clip w). So each triangle hides one
//! closed interval of s, found exactly; the visible pieces are the complement of the union.
//! An edge shared by two triangles is evaluated from the same ordered pair of corners in both,
//! so a line crossing a mesh leaves no gap between the intervals of neighbouring triangles.
//!
//! The triangles' images are binned in a screen grid of about one triangle per cell; a segment
//! visits only the cells its image crosses, and a triangle lying wholly behind the segment is
//! skipped. Finally, along each polyline (or segment) the runs of one visibility are joined,
//! and a run shorter than `min_piece` pixels between runs of the other kind — a sliver where a
//! line grazes an edge, never a feature of a printed figure — is given to its neighbours
//! ([`HIDDEN_LINE_MIN_PIECE`] pixels unless given).

use crate::error::{Error, Result};
use crate::tolerance::{
    CAMERA_UP_SINE, HIDDEN_LINE_BEND, HIDDEN_LINE_EDGE_ON, HIDDEN_LINE_GRID_ENTRIES, HIDDEN_LINE_MIN_PIECE,
    HIDDEN_LINE_TOLERANCE, MAX_COORD, MAX_HIDDEN_LINE_GRID, MAX_HIDDEN_LINE_ITEMS, MAX_HIDDEN_LINE_MIN_PIECE,
};
use glam::{DMat4, DVec2, DVec3, DVec4};

/// A camera: the view-projection matrix and the viewport in pixels.
#[derive(Debug, Clone, Copy)]
pub struct View {
    matrix: DMat4,
    width: f64,
    height: f64,
    /// M⁻¹·(0, 0, 1, 0): the eye, homogeneous (w < 0 for a perspective camera, 0 for an
    /// orthographic one, whose xyz then points away from the viewer).
    eye: DVec4,
}

/// The image of a point: pixel coordinates (y down), its clip w, and the clip z + w (≥ 0 in
/// front of the near plane).
#[derive(Debug, Clone, Copy)]
struct Image {
    screen: DVec2,
    w: f64,
}

impl View {
    /// A view from a column-major 4 × 4 view-projection matrix (16 numbers) and a viewport of
    /// `width` × `height` pixels. Refused: a matrix that is not finite or not invertible, a
    /// viewport that is not positive and finite.
    pub fn new(matrix: &[f64], width: f64, height: f64) -> Result<Self> {
        if matrix.len() != 16 {
            return Err(Error::InvalidParameter {
                name: "viewProj",
                message: format!("needs 16 numbers (a column-major 4 × 4 matrix), got {}", matrix.len()).into(),
            });
        }
        if let Some((k, &x)) = matrix.iter().enumerate().find(|(_, x)| !x.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "viewProj",
                message: format!("entry {k} is not finite ({x})").into(),
            });
        }
        for (name, x) in [("width", width), ("height", height)] {
            if !(x.is_finite() && x > 0.0 && x <= 1e6) {
                return Err(Error::InvalidParameter {
                    name: if name == "width" { "width" } else { "height" },
                    message: format!("{name} must be a number of pixels in (0, 1e6], got {x}").into(),
                });
            }
        }
        let m = DMat4::from_cols_slice(matrix);
        let det = m.determinant();
        if !(det.is_finite() && det != 0.0) {
            return Err(Error::InvalidParameter {
                name: "viewProj",
                message: "the matrix is not invertible".to_string().into(),
            });
        }
        let eye = m.inverse() * DVec4::Z;
        if !eye.is_finite() {
            return Err(Error::InvalidParameter {
                name: "viewProj",
                message: "the matrix is not invertible".to_string().into(),
            });
        }
        Ok(View { matrix: m, width, height, eye })
    }

    /// The page's camera (`www/camera.js`): perspective with vertical field of view `fov_y`
    /// (radians) from `eye` towards `target`, z up (y up when looking along z), the near and far
    /// planes at 1/100 and 100 times the distance, on a `width` × `height` viewport. Refused: an
    /// eye or target with a coordinate beyond ±[`MAX_COORD`], an eye nearer the target than
    /// 1/[`MAX_COORD`], a field of view outside (0, π).
    pub fn looking(eye: DVec3, target: DVec3, fov_y: f64, width: f64, height: f64) -> Result<Self> {
        let distance = eye.distance(target);
        let within = |p: DVec3| p.abs().max_element() <= MAX_COORD;
        if !(within(eye) && within(target) && distance >= 1.0 / MAX_COORD) {
            return Err(Error::InvalidParameter {
                name: "eye",
                message: format!(
                    "need an eye and a target within ±{MAX_COORD:e}, at least {:e} apart, got {eye} and {target}",
                    1.0 / MAX_COORD
                )
                .into(),
            });
        }
        if !(fov_y > 0.0 && fov_y < std::f64::consts::PI) {
            return Err(Error::InvalidParameter {
                name: "fovY",
                message: format!("the field of view must be in (0, π), got {fov_y}").into(),
            });
        }
        let (near, far) = (distance / 100.0, distance * 100.0);
        let f = 1.0 / (fov_y / 2.0).tan();
        let aspect = width / height;
        let projection = DMat4::from_cols_array(&[
            f / aspect,
            0.0,
            0.0,
            0.0,
            0.0,
            f,
            0.0,
            0.0,
            0.0,
            0.0,
            (far + near) / (near - far),
            -1.0,
            0.0,
            0.0,
            2.0 * far * near / (near - far),
            0.0,
        ]);
        let z = (eye - target) / distance;
        let up = if z.cross(DVec3::Z).length() < CAMERA_UP_SINE { DVec3::Y } else { DVec3::Z };
        let x = up.cross(z).normalize();
        let y = z.cross(x);
        let look = DMat4::from_cols(
            DVec4::new(x.x, y.x, z.x, 0.0),
            DVec4::new(x.y, y.y, z.y, 0.0),
            DVec4::new(x.z, y.z, z.z, 0.0),
            DVec4::new(-x.dot(eye), -y.dot(eye), -z.dot(eye), 1.0),
        );
        View::new(&(projection * look).to_cols_array(), width, height)
    }

    fn clip(&self, p: DVec3) -> DVec4 {
        self.matrix * p.extend(1.0)
    }

    fn image_of_clip(&self, c: DVec4) -> Image {
        Image {
            screen: DVec2::new((c.x / c.w + 1.0) / 2.0 * self.width, (1.0 - c.y / c.w) / 2.0 * self.height),
            w: c.w,
        }
    }

    /// The pixel position of a point in front of the near plane (None behind it).
    pub fn project(&self, p: DVec3) -> Option<DVec2> {
        let c = self.clip(p);
        (c.z + c.w >= 0.0 && c.w > 0.0).then(|| self.image_of_clip(c).screen)
    }

    /// σ·(n·x − d) for the eye x: positive when the eye is on the side n points to.
    fn eye_side(&self, n: DVec3, d: f64) -> f64 {
        -(n.dot(self.eye.truncate()) - self.eye.w * d)
    }
}

/// How the points of a set of lines are joined.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineKind {
    /// Two points per segment.
    Segments,
    /// Consecutive points joined; a non-finite point breaks the polyline; `closed` joins the
    /// last point to the first.
    Polyline {
        /// Whether the last point is joined to the first.
        closed: bool,
    },
    /// Separate points (dots).
    Points,
}

/// A run of one visibility along a line: its image as pixel positions (one for a dot).
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Pixel positions (x right, y down) of the run's polyline: at least two, or one for a dot.
    pub points: Vec<DVec2>,
    /// Whether this run is seen (or hidden by a surface).
    pub visible: bool,
}

/// Tolerances of [`hidden_lines`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HiddenLineOptions {
    /// Lines within this distance of a triangle's plane are not hidden by it, as a fraction of
    /// the diagonal of the triangles' bounding box.
    pub tolerance: f64,
    /// Runs shorter than this (pixels) between runs of the other kind are given to their
    /// neighbours.
    pub min_piece: f64,
}

impl Default for HiddenLineOptions {
    fn default() -> Self {
        HiddenLineOptions { tolerance: HIDDEN_LINE_TOLERANCE, min_piece: HIDDEN_LINE_MIN_PIECE }
    }
}

/// A triangle ready for the tests: its image's edge functions, its plane, its depth range.
#[derive(Debug, Clone, Copy)]
struct Occluder {
    /// The three corners' images (in the orientation of the triangle's image: counter-clockwise
    /// in pixel coordinates, y down, once made so).
    corners: [DVec2; 3],
    /// Unit normal and offset of the plane, oriented so that the eye is on the positive side.
    normal: DVec3,
    offset: f64,
    /// Smallest clip w of the corners (a segment nearer than this everywhere is in front).
    near_w: f64,
    /// The triangle's own tolerance: the global τ, or how far the triangles across its edges
    /// bend away from its plane, whichever is larger (see [`bend`]).
    tau: f64,
    min: DVec2,
    max: DVec2,
}

impl Occluder {
    /// e(x) ≥ 0 inside, for edge k (from corner k to corner k + 1), evaluated from the corners
    /// in a fixed order (the lexicographically smaller first) so that a neighbouring triangle
    /// sharing the edge gets the same number with the opposite sign.
    fn edge(&self, k: usize, x: DVec2) -> f64 {
        let (p, q) = (self.corners[k], self.corners[(k + 1) % 3]);
        if (p.x, p.y) <= (q.x, q.y) {
            (q - p).perp_dot(x - p)
        } else {
            -(p - q).perp_dot(x - q)
        }
    }
}

/// The triangles and their screen grid.
struct Scene {
    occluders: Vec<Occluder>,
    origin: DVec2,
    cell: DVec2,
    cols: usize,
    rows: usize,
    /// CSR layout: the triangles of cell c are `items[starts[c]..starts[c + 1]]`.
    starts: Vec<u32>,
    items: Vec<u32>,
}

impl Scene {
    fn new(view: &View, meshes: &[(&[DVec3], &[u32])], tau: f64) -> Self {
        let mut occluders = Vec::new();
        for (positions, indices) in meshes {
            let bends = bend(positions, indices);
            for (t, bent) in indices.chunks_exact(3).zip(bends) {
                let Some(corners) = t.iter().map(|&i| positions.get(i as usize).copied()).collect::<Option<Vec<_>>>()
                else {
                    continue;
                };
                if let Some(o) = occluder(view, [corners[0], corners[1], corners[2]], tau.max(HIDDEN_LINE_BEND * bent))
                {
                    occluders.push(o);
                }
            }
        }
        // the grid: the viewport with a margin of one viewport around it (images beyond are
        // clamped into the border cells, queries likewise), about one triangle per cell — coarser
        // while the triangles would fill more than HIDDEN_LINE_GRID_ENTRIES cells each on
        // average (huge triangles, seen from close by)
        let n = occluders.len().max(1) as f64;
        let (w, h) = (view.width, view.height);
        let aspect = (w / h).clamp(0.1, 10.0);
        let mut side = (n.sqrt().ceil() as usize).clamp(1, MAX_HIDDEN_LINE_GRID);
        let mut scene = loop {
            let cols = ((side as f64 * aspect.sqrt()).round() as usize).clamp(1, MAX_HIDDEN_LINE_GRID);
            let rows = ((side as f64 / aspect.sqrt()).round() as usize).clamp(1, MAX_HIDDEN_LINE_GRID);
            let origin = DVec2::new(-w, -h);
            let cell = DVec2::new(3.0 * w / cols as f64, 3.0 * h / rows as f64);
            let scene =
                Scene { occluders: Vec::new(), origin, cell, cols, rows, starts: Vec::new(), items: Vec::new() };
            let entries: usize = occluders
                .iter()
                .map(|o| {
                    let ((c0, r0), (c1, r1)) = (scene.cell_of(o.min), scene.cell_of(o.max));
                    (c1 - c0 + 1) * (r1 - r0 + 1)
                })
                .sum();
            if side == 1 || entries <= HIDDEN_LINE_GRID_ENTRIES * occluders.len() + 4096 {
                break Scene { occluders, starts: vec![0; cols * rows + 1], ..scene };
            }
            side /= 2;
        };
        let (cols, rows) = (scene.cols, scene.rows);
        let mut counts = vec![0u32; cols * rows];
        for o in &scene.occluders {
            let (c0, r0) = scene.cell_of(o.min);
            let (c1, r1) = scene.cell_of(o.max);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    counts[r * cols + c] += 1;
                }
            }
        }
        for c in 0..cols * rows {
            scene.starts[c + 1] = scene.starts[c] + counts[c];
        }
        let mut fill: Vec<u32> = scene.starts[..cols * rows].to_vec();
        scene.items = vec![0; scene.starts[cols * rows] as usize];
        for (k, o) in scene.occluders.iter().enumerate() {
            let (c0, r0) = scene.cell_of(o.min);
            let (c1, r1) = scene.cell_of(o.max);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    let slot = &mut fill[r * cols + c];
                    scene.items[*slot as usize] = k as u32;
                    *slot += 1;
                }
            }
        }
        scene
    }

    fn cell_of(&self, p: DVec2) -> (usize, usize) {
        let f = (p - self.origin) / self.cell;
        let clamp = |x: f64, n: usize| if x.is_nan() { 0 } else { (x.floor().max(0.0) as usize).min(n - 1) };
        (clamp(f.x, self.cols), clamp(f.y, self.rows))
    }

    /// Calls `visit` with every triangle binned in a cell the image segment a → b crosses
    /// (each cell once; a triangle in several cells may come more than once).
    fn cells_along(&self, a: DVec2, b: DVec2, mut visit: impl FnMut(u32)) {
        let (ca, _) = self.cell_of(a);
        let (cb, _) = self.cell_of(b);
        let (c0, c1) = (ca.min(cb), ca.max(cb));
        for c in c0..=c1 {
            // the part of the segment over column c (the border columns reach to infinity)
            let left = if c == 0 { f64::NEG_INFINITY } else { self.origin.x + c as f64 * self.cell.x };
            let right = if c + 1 == self.cols { f64::INFINITY } else { self.origin.x + (c + 1) as f64 * self.cell.x };
            let (y0, y1) = if (b.x - a.x).abs() <= f64::EPSILON * (a.x.abs() + b.x.abs()).max(1.0) {
                (a.y.min(b.y), a.y.max(b.y))
            } else {
                let at = |x: f64| {
                    let s = ((x - a.x) / (b.x - a.x)).clamp(0.0, 1.0);
                    a.y + s * (b.y - a.y)
                };
                let (ya, yb) = (at(left.max(a.x.min(b.x))), at(right.min(a.x.max(b.x))));
                (ya.min(yb), ya.max(yb))
            };
            let (_, r0) = self.cell_of(DVec2::new(a.x, y0));
            let (_, r1) = self.cell_of(DVec2::new(a.x, y1));
            for r in r0..=r1 {
                let cell = r * self.cols + c;
                for &k in &self.items[self.starts[cell] as usize..self.starts[cell + 1] as usize] {
                    visit(k);
                }
            }
        }
    }
}

/// A triangle as an occluder; None when a corner is behind the eye or not finite, or its image
/// has no area (seen edge-on, it hides nothing).
fn occluder(view: &View, [p0, p1, p2]: [DVec3; 3], tau: f64) -> Option<Occluder> {
    if !(p0.is_finite() && p1.is_finite() && p2.is_finite()) {
        return None;
    }
    let clips = [view.clip(p0), view.clip(p1), view.clip(p2)];
    if clips.iter().any(|c| c.w <= 0.0 || !c.is_finite()) {
        return None;
    }
    let mut corners = clips.map(|c| view.image_of_clip(c).screen);
    let area = (corners[1] - corners[0]).perp_dot(corners[2] - corners[0]);
    let scale = (corners[1] - corners[0]).length_squared().max((corners[2] - corners[0]).length_squared());
    if area.is_nan() || area.abs() <= HIDDEN_LINE_EDGE_ON * scale {
        return None;
    }
    if area < 0.0 {
        corners.swap(1, 2);
    }
    let n = (p1 - p0).cross(p2 - p0).normalize_or_zero();
    if n == DVec3::ZERO {
        return None;
    }
    let d = n.dot(p0);
    let side = view.eye_side(n, d);
    let (normal, offset) = if side >= 0.0 { (n, d) } else { (-n, -d) };
    Some(Occluder {
        corners,
        normal,
        offset,
        near_w: clips.iter().map(|c| c.w).fold(f64::INFINITY, f64::min),
        tau,
        min: corners[0].min(corners[1]).min(corners[2]),
        max: corners[0].max(corners[1]).max(corners[2]),
    })
}

/// How far each triangle's neighbours bend away from its plane: the largest distance from the
/// plane of a corner opposite one of its edges in a triangle sharing that edge (by indices).
/// A line drawn on the smooth surface the mesh samples — an exact curve, a polygon between
/// rulings — lies off the triangles by a fraction of this, which is therefore part of the
/// triangle's own tolerance: a twisted quad of a ruled strip bends by its twist, a flat mesh by
/// nothing.
fn bend(positions: &[DVec3], indices: &[u32]) -> Vec<f64> {
    let triangles = indices.len() / 3;
    let corner = |t: usize, k: usize| positions.get(indices[3 * t + k] as usize).copied();
    // every edge (i < j) filed under i, with its triangle and the opposite corner: the triangles
    // sharing an edge are in the same bucket (a counting sort, no comparisons)
    // (a triangle naming no point is no one's neighbour)
    let vertices = positions.len();
    let valid = |t: usize| (0..3).all(|k| (indices[3 * t + k] as usize) < vertices);
    let mut starts = vec![0usize; vertices + 1];
    for t in (0..triangles).filter(|&t| valid(t)) {
        for k in 0..3 {
            let (i, j) = (indices[3 * t + k], indices[3 * t + (k + 1) % 3]);
            starts[i.min(j) as usize + 1] += 1;
        }
    }
    for v in 0..vertices {
        starts[v + 1] += starts[v];
    }
    let mut fill = starts.clone();
    let mut edges = vec![(0u32, 0usize, 0u32); starts[vertices]];
    for t in (0..triangles).filter(|&t| valid(t)) {
        for k in 0..3 {
            let (i, j) = (indices[3 * t + k], indices[3 * t + (k + 1) % 3]);
            edges[fill[i.min(j) as usize]] = (i.max(j), t, indices[3 * t + (k + 2) % 3]);
            fill[i.min(j) as usize] += 1;
        }
    }
    let mut out = vec![0.0f64; triangles];
    for v in 0..vertices {
        let bucket = &edges[starts[v]..starts[v + 1]];
        for &(j, t, _) in bucket {
            let (Some(a), Some(b), Some(c)) = (corner(t, 0), corner(t, 1), corner(t, 2)) else { continue };
            let n = (b - a).cross(c - a).normalize_or_zero();
            for &(_, _, opposite) in bucket.iter().filter(|e| e.0 == j && e.1 != t) {
                if let Some(d) = positions.get(opposite as usize).map(|q| n.dot(*q - a).abs()) {
                    if d.is_finite() {
                        out[t] = out[t].max(d);
                    }
                }
            }
        }
    }
    out
}

/// The interval of [0, 1] where a + s(b − a) ≥ 0 (closed), None when empty.
fn nonnegative(a: f64, b: f64) -> Option<(f64, f64)> {
    match (a >= 0.0, b >= 0.0) {
        (true, true) => Some((0.0, 1.0)),
        (false, false) => None,
        (true, false) => Some((0.0, a / (a - b))),
        (false, true) => Some((a / (a - b), 1.0)),
    }
}

fn meet(x: Option<(f64, f64)>, y: Option<(f64, f64)>) -> Option<(f64, f64)> {
    let ((a0, a1), (b0, b1)) = (x?, y?);
    let (lo, hi) = (a0.max(b0), a1.min(b1));
    (lo <= hi).then_some((lo, hi))
}

/// A segment ready for the tests: its world endpoints (clipped to the near plane), their images.
struct Clipped {
    a: DVec3,
    b: DVec3,
    ia: Image,
    ib: Image,
}

/// The segment p → q clipped to the near plane (z + w ≥ 0) and to w > 0; None when nothing is left.
fn clip_segment(view: &View, p: DVec3, q: DVec3) -> Option<Clipped> {
    if !(p.is_finite() && q.is_finite()) {
        return None;
    }
    let (cp, cq) = (view.clip(p), view.clip(q));
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    // near plane, and a small positive w (a guard for degenerate matrices)
    for (fp, fq) in [(cp.z + cp.w, cq.z + cq.w), (cp.w, cq.w)] {
        match nonnegative(fp, fq) {
            None => return None,
            Some((lo, hi)) => {
                t0 = t0.max(lo);
                t1 = t1.min(hi);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    // the ends as they are where nothing is clipped, so that consecutive segments of a polyline
    // meet in exactly the same image point
    let (a, ca) = if t0 == 0.0 { (p, cp) } else { (p.lerp(q, t0), cp.lerp(cq, t0)) };
    let (b, cb) = if t1 == 1.0 { (q, cq) } else { (p.lerp(q, t1), cp.lerp(cq, t1)) };
    if !(ca.w > 0.0 && cb.w > 0.0) {
        return None;
    }
    Some(Clipped { a, b, ia: view.image_of_clip(ca), ib: view.image_of_clip(cb) })
}

/// Whether the world point p (image `image`) is hidden by occluder o.
fn hides_point(o: &Occluder, p: DVec3, image: DVec2) -> bool {
    (0..3).all(|k| o.edge(k, image) >= 0.0) && o.normal.dot(p) - o.offset < -o.tau
}

/// The hidden interval (in the image parameter s) of a clipped segment behind occluder o.
fn hidden_interval(o: &Occluder, seg: &Clipped) -> Option<(f64, f64)> {
    let (a, b) = (seg.ia.screen, seg.ib.screen);
    let mut inside = Some((0.0, 1.0));
    for k in 0..3 {
        inside = meet(inside, nonnegative(o.edge(k, a), o.edge(k, b)));
    }
    let (s0, s1) = inside?;
    // behind by more than τ: −(n·P(t) − d) − τ > 0, linear in t
    let g = |p: DVec3| -(o.normal.dot(p) - o.offset) - o.tau;
    let (ga, gb) = (g(seg.a), g(seg.b));
    let behind_t = match (ga > 0.0, gb > 0.0) {
        (true, true) => (0.0, 1.0),
        (false, false) => return None,
        (true, false) => (0.0, ga / (ga - gb)),
        (false, true) => (ga / (ga - gb), 1.0),
    };
    let (wa, wb) = (seg.ia.w, seg.ib.w);
    let to_s = |t: f64| t * wb / ((1.0 - t) * wa + t * wb);
    meet(Some((s0, s1)), Some((to_s(behind_t.0), to_s(behind_t.1))))
}

/// The hidden parts of one clipped segment, as sorted disjoint intervals of s.
fn hidden_parts(scene: &Scene, seg: &Clipped, stamp: &mut [u32], id: u32) -> Vec<(f64, f64)> {
    let far_w = seg.ia.w.max(seg.ib.w);
    let mut parts = Vec::new();
    scene.cells_along(seg.ia.screen, seg.ib.screen, |k| {
        if stamp[k as usize] == id {
            return;
        }
        stamp[k as usize] = id;
        let o = &scene.occluders[k as usize];
        if o.near_w > far_w {
            return; // wholly behind the segment
        }
        if let Some(part) = hidden_interval(o, seg) {
            parts.push(part);
        }
    });
    // by their starts (an insertion sort: a segment crosses few triangles)
    for k in 1..parts.len() {
        let mut j = k;
        while j > 0 && parts[j - 1].0 > parts[j].0 {
            parts.swap(j - 1, j);
            j -= 1;
        }
    }
    let mut merged: Vec<(f64, f64)> = Vec::with_capacity(parts.len());
    for (lo, hi) in parts {
        match merged.last_mut() {
            // intervals that touch (to rounding) are one: no sliver between neighbouring triangles
            Some(last) if lo <= last.1 + 1e-12 => last.1 = last.1.max(hi),
            _ => merged.push((lo, hi)),
        }
    }
    merged
}

/// A chain of pieces along one polyline or segment, before runs are formed.
struct Chain {
    /// (image point, visible) per piece: the pieces are the polylines between consecutive
    /// breakpoints; `visible[k]` is the visibility of the piece from point k to k + 1.
    points: Vec<DVec2>,
    visible: Vec<bool>,
}

impl Chain {
    fn new() -> Self {
        Chain { points: Vec::new(), visible: Vec::new() }
    }

    /// Appends a segment's pieces (`parts`: its hidden intervals of s); the segment starts where
    /// the chain ends, or the chain is empty.
    fn push_segment(&mut self, a: DVec2, b: DVec2, parts: &[(f64, f64)]) {
        let at = |s: f64| a + (b - a) * s;
        if self.points.is_empty() {
            self.points.push(a);
        }
        let mut s = 0.0;
        for &(lo, hi) in parts {
            if lo > s {
                self.points.push(at(lo));
                self.visible.push(true);
            }
            self.points.push(at(hi));
            self.visible.push(false);
            s = hi;
        }
        if s < 1.0 {
            self.points.push(b);
            self.visible.push(true);
        }
    }

    /// The runs of one visibility, slivers shorter than `min` pixels given to their neighbours.
    fn runs(self, min: f64) -> Vec<Run> {
        // pieces → runs (start index, end index, visible, length)
        let mut runs: Vec<(usize, usize, bool, f64)> = Vec::new();
        for (k, &v) in self.visible.iter().enumerate() {
            let len = self.points[k].distance(self.points[k + 1]);
            match runs.last_mut() {
                Some(r) if r.2 == v => {
                    r.1 = k + 1;
                    r.3 += len;
                }
                _ => runs.push((k, k + 1, v, len)),
            }
        }
        // give the shortest sliver to its neighbours until none is left (or one run remains)
        while runs.len() > 1 {
            let Some((k, _)) =
                runs.iter().enumerate().filter(|(_, r)| r.3 < min).min_by(|x, y| x.1 .3.total_cmp(&y.1 .3))
            else {
                break;
            };
            let v = !runs[k].2;
            runs[k].2 = v;
            // join with neighbours of the same visibility
            if k + 1 < runs.len() && runs[k + 1].2 == v {
                let next = runs.remove(k + 1);
                runs[k].1 = next.1;
                runs[k].3 += next.3;
            }
            if k > 0 && runs[k - 1].2 == v {
                let this = runs.remove(k);
                runs[k - 1].1 = this.1;
                runs[k - 1].3 += this.3;
            }
        }
        runs.into_iter()
            .map(|(start, end, visible, _)| Run { points: drop_repeats(&self.points[start..=end]), visible })
            .collect()
    }
}

/// Consecutive equal points removed (a piece boundary at a vertex repeats it); at least two kept.
fn drop_repeats(points: &[DVec2]) -> Vec<DVec2> {
    let mut out: Vec<DVec2> = Vec::with_capacity(points.len());
    for &p in points {
        if out.last() != Some(&p) {
            out.push(p);
        }
    }
    if out.len() == 1 {
        out.push(out[0]);
    }
    out
}

/// The visible and hidden runs of every set of lines, as images in pixels: for each entry of
/// `lines` (its kind and world points), the runs of its polylines or segments in order, a dot per
/// point (`Points`). Occluders are the triangles of `meshes` (world points and three indices per
/// triangle; an index naming no point, a corner behind the eye or an image without area leaves
/// the triangle out). Lines and parts of lines behind the near plane are left out.
pub fn hidden_lines(
    view: &View,
    meshes: &[(&[DVec3], &[u32])],
    lines: &[(LineKind, &[DVec3])],
    options: HiddenLineOptions,
) -> Result<Vec<Vec<Run>>> {
    hidden_lines_at_most(view, meshes, lines, options, MAX_HIDDEN_LINE_ITEMS)
}

/// [`hidden_lines`] with at most `max_items` triangles and line points (a parameter so that a
/// test can reach the limit).
fn hidden_lines_at_most(
    view: &View,
    meshes: &[(&[DVec3], &[u32])],
    lines: &[(LineKind, &[DVec3])],
    options: HiddenLineOptions,
    max_items: usize,
) -> Result<Vec<Vec<Run>>> {
    for (name, x, ok) in [
        ("tolerance", options.tolerance, options.tolerance >= 0.0 && options.tolerance <= 1.0),
        ("minPiece", options.min_piece, options.min_piece >= 0.0 && options.min_piece <= MAX_HIDDEN_LINE_MIN_PIECE),
    ] {
        if !(x.is_finite() && ok) {
            return Err(Error::InvalidParameter {
                name: if name == "tolerance" { "tolerance" } else { "minPiece" },
                message: format!(
                    "{name} must be a number in {}, got {x}",
                    if name == "tolerance" {
                        "[0, 1]".to_string()
                    } else {
                        format!("[0, {MAX_HIDDEN_LINE_MIN_PIECE}]")
                    }
                )
                .into(),
            });
        }
    }
    let triangles: usize = meshes.iter().map(|(_, idx)| idx.len() / 3).sum();
    let points: usize = lines.iter().map(|(_, p)| p.len()).sum();
    for (what, got) in [("triangles", triangles), ("line points", points)] {
        if got > max_items {
            return Err(Error::TooMany { what, got, max: max_items });
        }
    }
    // τ from the triangles' bounding box
    let (lo, hi) = meshes
        .iter()
        .flat_map(|(p, idx)| idx.iter().filter_map(|&i| p.get(i as usize)))
        .filter(|p| p.is_finite())
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let tau = if lo.x <= hi.x { options.tolerance * (hi - lo).length() } else { 0.0 };
    let scene = Scene::new(view, meshes, tau);
    let mut stamp = vec![u32::MAX; scene.occluders.len()];
    let mut next_id = 0u32;
    let mut id = || {
        next_id = next_id.wrapping_add(1);
        if next_id == u32::MAX {
            next_id = 0;
        }
        next_id
    };
    let mut out = Vec::with_capacity(lines.len());
    for &(kind, points) in lines {
        let mut runs = Vec::new();
        match kind {
            LineKind::Points => {
                for &p in points {
                    let Some(image) = view.project(p) else { continue };
                    let mut hidden = false;
                    scene.cells_along(image, image, |k| {
                        hidden = hidden || hides_point(&scene.occluders[k as usize], p, image);
                    });
                    runs.push(Run { points: vec![image], visible: !hidden });
                }
            }
            LineKind::Segments => {
                for pair in points.chunks_exact(2) {
                    if let Some(seg) = clip_segment(view, pair[0], pair[1]) {
                        let parts = hidden_parts(&scene, &seg, &mut stamp, id());
                        let mut chain = Chain::new();
                        chain.push_segment(seg.ia.screen, seg.ib.screen, &parts);
                        runs.extend(chain.runs(options.min_piece));
                    }
                }
            }
            LineKind::Polyline { closed } => {
                // pieces of consecutive finite points; `closed` joins the last to the first when
                // no point is missing
                let all_finite = points.iter().all(|p| p.is_finite());
                let mut edges: Vec<(DVec3, DVec3)> = points.windows(2).map(|w| (w[0], w[1])).collect::<Vec<_>>();
                if closed && all_finite && points.len() > 2 {
                    edges.push((points[points.len() - 1], points[0]));
                }
                let mut chain = Chain::new();
                for (p, q) in edges {
                    let seg = clip_segment(view, p, q);
                    let joins = seg.as_ref().is_some_and(|s| chain.points.last() == Some(&s.ia.screen));
                    if !joins && !chain.visible.is_empty() {
                        runs.extend(std::mem::replace(&mut chain, Chain::new()).runs(options.min_piece));
                    }
                    if let Some(seg) = seg {
                        let parts = hidden_parts(&scene, &seg, &mut stamp, id());
                        chain.push_segment(seg.ia.screen, seg.ib.screen, &parts);
                    }
                }
                if !chain.visible.is_empty() {
                    runs.extend(chain.runs(options.min_piece));
                }
            }
        }
        out.push(runs);
    }
    Ok(out)
}

/// Points transformed by a 4 × 4 model matrix (column-major), or as they are.
pub fn transformed(points: &[DVec3], model: Option<&DMat4>) -> Vec<DVec3> {
    match model {
        None => points.to_vec(),
        Some(m) => points.iter().map(|&p| m.transform_point3(p)).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tolerance::test::uniform;

    /// The page's camera: perspective (35°) looking from `eye` at `target`, z up unless looking
    /// along z, on a 640 × 420 viewport.
    fn camera(eye: DVec3, target: DVec3) -> View {
        View::looking(eye, target, 35f64.to_radians(), 640.0, 420.0).unwrap()
    }

    /// The square [−1, 1]² in the plane z = 0, as two triangles.
    fn square() -> (Vec<DVec3>, Vec<u32>) {
        let p = vec![
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(-1.0, 1.0, 0.0),
        ];
        (p, vec![0, 1, 2, 0, 2, 3])
    }

    /// The name of the refused parameter.
    fn refused<T: std::fmt::Debug>(r: Result<T>) -> &'static str {
        match r {
            Err(Error::InvalidParameter { name, .. }) => name,
            other => panic!("expected a refusal, got {other:?}"),
        }
    }

    /// The visibility of each run.
    fn seen(runs: &[Run]) -> Vec<bool> {
        runs.iter().map(|r| r.visible).collect()
    }

    fn exact() -> HiddenLineOptions {
        HiddenLineOptions { min_piece: 0.0, ..Default::default() }
    }

    #[test]
    fn a_line_behind_a_square_is_hidden_exactly_over_its_shadow() {
        // seen from (0, 0, 10), the square's shadow on the plane z = −1 is [−1.1, 1.1]²
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let (p, idx) = square();
        let line = [DVec3::new(-5.0, 0.3, -1.0), DVec3::new(5.0, 0.3, -1.0)];
        let runs = hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &line)], exact()).unwrap();
        let runs = &runs[0];
        assert_eq!(seen(runs), [true, false, true]);
        let shadow = |x: f64| view.project(DVec3::new(x, 0.3, -1.0)).unwrap();
        crate::assert_near!(runs[1].points[0], shadow(-1.1), 1e-9);
        crate::assert_near!(runs[1].points[1], shadow(1.1), 1e-9);
        crate::assert_near!(runs[0].points[0], shadow(-5.0), 1e-9);
        crate::assert_near!(runs[2].points[1], shadow(5.0), 1e-9);
        // in front of the square, or beside its shadow: seen whole
        let front = [DVec3::new(-5.0, 0.3, 1.0), DVec3::new(5.0, 0.3, 1.0)];
        let beside = [DVec3::new(-5.0, 1.2, -1.0), DVec3::new(5.0, 1.2, -1.0)];
        let runs =
            hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &front), (LineKind::Segments, &beside)], exact())
                .unwrap();
        assert!(runs.iter().all(|r| r.len() == 1 && r[0].visible));
        // a line piercing the square: hidden from the crossing on, exactly
        let through = [DVec3::new(0.5, 0.0, 1.0), DVec3::new(0.5, 0.0, -1.0)];
        let slanted = [DVec3::new(-0.5, 0.0, 1.0), DVec3::new(0.5, 0.0, -1.0)];
        let runs = hidden_lines(
            &view,
            &[(&p, &idx)],
            &[(LineKind::Segments, &through), (LineKind::Segments, &slanted)],
            exact(),
        )
        .unwrap();
        assert_eq!(seen(&runs[0]), [true, false]);
        assert_eq!(seen(&runs[1]), [true, false]);
        let tau = HIDDEN_LINE_TOLERANCE * 8f64.sqrt();
        // hidden from where it is τ below the plane: z = −τ, x = τ/2 on the slanted line
        let crossing = view.project(DVec3::new(tau / 2.0, 0.0, -tau)).unwrap();
        crate::assert_near!(runs[1][1].points[0], crossing, 1e-9);
        // the same lines the other way: hidden up to there
        let (up, rising) = ([through[1], through[0]], [slanted[1], slanted[0]]);
        let runs =
            hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &up), (LineKind::Segments, &rising)], exact())
                .unwrap();
        assert_eq!(seen(&runs[0]), [false, true]);
        assert_eq!(seen(&runs[1]), [false, true]);
        crate::assert_near!(runs[1][0].points[1], crossing, 1e-9);
        crate::assert_near!(runs[1][0].points[0], view.project(rising[0]).unwrap(), 1e-9);
    }

    #[test]
    fn the_same_in_an_orthographic_view() {
        // x/3, y/2 onto [−1, 1]², looking down −z from z = 10 (near 0.1, far 100)
        let m = DMat4::from_cols_array(&[
            1.0 / 3.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.5,
            0.0,
            0.0,
            0.0,
            0.0,
            -2.0 / 99.9,
            0.0,
            0.0,
            0.0,
            (20.0 - 100.1) / 99.9,
            1.0,
        ]);
        let view = View::new(&m.to_cols_array(), 600.0, 400.0).unwrap();
        let (p, idx) = square();
        let line = [DVec3::new(-2.0, 0.0, -1.0), DVec3::new(2.0, 0.0, -1.0)];
        let runs = hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &line)], exact()).unwrap();
        assert_eq!(runs[0].len(), 3);
        crate::assert_near!(runs[0][1].points[0], DVec2::new(200.0, 200.0), 1e-9);
        crate::assert_near!(runs[0][1].points[1], DVec2::new(400.0, 200.0), 1e-9);
    }

    #[test]
    fn lines_on_a_surface_stay_visible_and_a_grid_leaves_no_sliver() {
        let view = camera(DVec3::new(3.0, -4.0, 6.0), DVec3::ZERO);
        // a 10 × 10 grid of squares on [−1, 1]², slightly bent (z = 0.05 x²)
        let n = 11;
        let p: Vec<DVec3> = (0..n * n)
            .map(|k| {
                let (x, y) = (-1.0 + 0.2 * (k % n) as f64, -1.0 + 0.2 * (k / n) as f64);
                DVec3::new(x, y, 0.05 * x * x)
            })
            .collect();
        let idx = crate::grid_indices(n, n);
        // its edges, a diagonal through its vertices, a curve on the smooth surface between them
        let edge: Vec<DVec3> = (0..n).map(|i| p[5 * n + i]).collect();
        let diagonal: Vec<DVec3> = (0..n).map(|i| p[i * n + i]).collect();
        let curve: Vec<DVec3> = (0..=200)
            .map(|k| {
                let x = -1.0 + 0.01 * k as f64;
                DVec3::new(x, 0.37, 0.05 * x * x)
            })
            .collect();
        let lines = [
            (LineKind::Polyline { closed: false }, &edge[..]),
            (LineKind::Polyline { closed: false }, &diagonal[..]),
            (LineKind::Polyline { closed: false }, &curve[..]),
        ];
        let runs = hidden_lines(&view, &[(&p, &idx)], &lines, exact()).unwrap();
        for r in &runs {
            assert_eq!(r.len(), 1);
            assert!(r[0].visible);
        }
        // the same lines pushed below the grid by 0.05 (> τ = 0.014): hidden whole, in one run each
        // (the diagonal passes exactly through vertices of the grid's image: no gap between triangles)
        // (their inner parts: an end below the grid's border peeks out beside it in perspective)
        let below = |v: &[DVec3]| {
            let k = v.len() / 10;
            v[k..v.len() - k].iter().map(|q| *q - DVec3::new(0.0, 0.0, 0.05)).collect::<Vec<_>>()
        };
        let (e, d, c) = (below(&edge), below(&diagonal), below(&curve));
        let lines = [
            (LineKind::Polyline { closed: false }, &e[..]),
            (LineKind::Polyline { closed: false }, &d[..]),
            (LineKind::Polyline { closed: false }, &c[..]),
        ];
        let runs = hidden_lines(&view, &[(&p, &idx)], &lines, exact()).unwrap();
        for r in &runs {
            assert!(r.iter().all(|run| !run.visible), "{r:?}");
        }
        assert_eq!(runs[1].len(), 1, "one run along the diagonal: {:?}", runs[1]);
    }

    #[test]
    fn dots_slivers_and_the_near_plane() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let (p, idx) = square();
        let dots = [DVec3::new(0.0, 0.0, -1.0), DVec3::new(3.0, 0.0, -1.0), DVec3::new(0.0, 0.0, 1.0)];
        let runs = hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Points, &dots)], exact()).unwrap();
        assert_eq!(
            runs[0].iter().map(|r| (r.points.len(), r.visible)).collect::<Vec<_>>(),
            [(1, false), (1, true), (1, true)]
        );
        // a line whose hidden part is a fraction of a pixel: the sliver goes to its neighbours
        let tiny = [
            DVec3::new(1.0995, -3.0, -1.0),
            DVec3::new(1.0995, -1.1, -1.0),
            DVec3::new(1.2, -1.0, -1.0),
            DVec3::new(2.0, -1.0, -1.0),
        ];
        let sliver =
            hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Polyline { closed: false }, &tiny)], exact()).unwrap();
        assert!(sliver[0].len() > 1, "the exact answer has a hidden sliver");
        let clean = hidden_lines(
            &view,
            &[(&p, &idx)],
            &[(LineKind::Polyline { closed: false }, &tiny)],
            HiddenLineOptions::default(),
        )
        .unwrap();
        assert_eq!(clean[0].len(), 1);
        assert!(clean[0][0].visible);
        let drawn = &clean[0][0].points;
        assert_eq!(
            (drawn[0], drawn[drawn.len() - 1]),
            (view.project(tiny[0]).unwrap(), view.project(tiny[3]).unwrap())
        );
        // behind the eye: cut at the near plane (0.1 in front of the eye), the rest drawn
        let long = [DVec3::new(0.5, 0.5, 20.0), DVec3::new(0.5, 0.5, 5.0)];
        let runs = hidden_lines(&view, &[], &[(LineKind::Segments, &long)], exact()).unwrap();
        assert_eq!(runs[0].len(), 1);
        // a NaN point breaks a polyline in two; bad options and views are refused
        let broken = [DVec3::ZERO, DVec3::X, DVec3::NAN, DVec3::Y, DVec3::ONE];
        let runs = hidden_lines(&view, &[], &[(LineKind::Polyline { closed: true }, &broken)], exact()).unwrap();
        assert_eq!(runs[0].len(), 2);
        // 20 000 triangles each filling the view: binned coarsely, answered quickly
        let huge: Vec<DVec3> = (0..20_000)
            .flat_map(|k| {
                let z = -0.5 - k as f64 * 1e-4;
                [DVec3::new(-50.0, -50.0, z), DVec3::new(50.0, -50.0, z), DVec3::new(0.0, 50.0, z)]
            })
            .collect();
        let idx: Vec<u32> = (0..60_000).collect();
        let runs = hidden_lines(&view, &[(&huge, &idx)], &[(LineKind::Points, &dots)], exact()).unwrap();
        assert_eq!(seen(&runs[0]), [false, false, true]);
        // a triangle naming no point hides nothing (and breaks nothing)
        let wild = [0, 1, u32::MAX, 0, 2, 3];
        let runs = hidden_lines(&view, &[(&p, &wild)], &[(LineKind::Points, &dots)], exact()).unwrap();
        assert_eq!(seen(&runs[0]), [false, true, true]);
        let bad = HiddenLineOptions { tolerance: f64::NAN, ..Default::default() };
        assert_eq!(hidden_lines(&view, &[], &[], bad).unwrap_err().code(), "invalid-argument");
        assert!(View::new(&[0.0; 16], 10.0, 10.0).is_err());
        assert!(View::new(&[1.0; 15], 10.0, 10.0).is_err());
        assert!(View::new(&DMat4::IDENTITY.to_cols_array(), 0.0, 10.0).is_err());
    }

    #[test]
    fn the_page_camera_puts_the_target_mid_screen_and_the_field_of_view_at_its_edges() {
        // from 10 before the target along +y, a field of view of 90° (tan 45° = 1) on 800 × 400
        // (aspect 2): z is up, x to the right; 10 above the target is the top edge, 20 to a side
        // a side edge
        let (eye, target) = (DVec3::new(3.0, -4.0, 2.0), DVec3::new(3.0, 6.0, 2.0));
        let v = View::looking(eye, target, std::f64::consts::FRAC_PI_2, 800.0, 400.0).unwrap();
        let at = |p: DVec3| v.project(p).unwrap();
        let close = |a: DVec2, b: [f64; 2]| (a - DVec2::from(b)).length() < 1e-9;
        assert!(close(at(target), [400.0, 200.0]), "{}", at(target));
        assert!(close(at(target + DVec3::new(0.0, 0.0, 10.0)), [400.0, 0.0]));
        assert!(close(at(target + DVec3::new(20.0, 0.0, -10.0)), [800.0, 400.0]));
        assert!(close(at(target - DVec3::new(20.0, 0.0, 0.0)), [0.0, 200.0]));
        // the near plane is a hundredth of the distance from the eye
        assert!(v.project(eye + DVec3::new(0.0, 0.1001, 0.0)).is_some());
        assert!(v.project(eye + DVec3::new(0.0, 0.0999, 0.0)).is_none());
        assert!(v.project(eye - DVec3::Y).is_none());
        // looking straight down, y is up on the screen
        let down =
            View::looking(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO, std::f64::consts::FRAC_PI_2, 400.0, 400.0).unwrap();
        assert!(close(down.project(DVec3::new(0.0, 10.0, 0.0)).unwrap(), [200.0, 0.0]));
        assert!(close(down.project(DVec3::new(10.0, 0.0, 0.0)).unwrap(), [400.0, 200.0]));
    }

    #[test]
    fn views_are_refused_by_name_at_their_bounds() {
        let (eye, t) = (DVec3::new(0.0, -5.0, 0.0), DVec3::ZERO);
        assert_eq!(refused(View::looking(t, t, 1.0, 100.0, 100.0)), "eye");
        for fov in [0.0, -0.5, std::f64::consts::PI, f64::NAN] {
            assert_eq!(refused(View::looking(eye, t, fov, 100.0, 100.0)), "fovY", "{fov}");
        }
        assert!(View::looking(eye, t, 3.1, 100.0, 100.0).is_ok());
        // eye and target within the coordinate limit, 2e150 apart: the target mid-screen
        // (2·far·near = 2·distance² would overflow from 9.5e153 on)
        let far = View::looking(DVec3::new(0.0, -1e150, 0.0), DVec3::new(0.0, 1e150, 0.0), 1.0, 100.0, 100.0).unwrap();
        crate::assert_near!(far.project(DVec3::new(0.0, 1e150, 0.0)).unwrap(), DVec2::new(50.0, 50.0), 1e-12);
        for beyond in [DVec3::new(0.0, -1.000_000_1e150, 0.0), DVec3::new(1e300, 0.0, 0.0), DVec3::NEG_INFINITY] {
            assert_eq!(refused(View::looking(beyond, t, 1.0, 100.0, 100.0)), "eye", "{beyond}");
            assert_eq!(refused(View::looking(DVec3::X, beyond, 1.0, 100.0, 100.0)), "eye", "{beyond}");
        }
        // as near as 1e−150, not nearer (2·far·near would no longer be a normal number)
        let near = View::looking(DVec3::new(0.0, -1e-150, 0.0), t, 1.0, 100.0, 100.0).unwrap();
        crate::assert_near!(near.project(DVec3::new(0.0, 1e-150, 0.0)).unwrap(), DVec2::new(50.0, 50.0), 1e-12);
        assert_eq!(refused(View::looking(DVec3::new(0.0, -0.999e-150, 0.0), t, 1.0, 100.0, 100.0)), "eye");
        let id: Vec<f64> = DMat4::IDENTITY.to_cols_array().to_vec();
        assert!(View::new(&id, 1e6, 1.0).is_ok());
        for (w, h, which) in
            [(0.0, 1.0, "width"), (1e6 + 1.0, 1.0, "width"), (1.0, -1.0, "height"), (1.0, f64::NAN, "height")]
        {
            assert_eq!(refused(View::new(&id, w, h)), which);
        }
        assert_eq!(refused(View::new(&id[..15], 1.0, 1.0)), "viewProj");
        let mut nan = id.clone();
        nan[5] = f64::INFINITY;
        assert_eq!(refused(View::new(&nan, 1.0, 1.0)), "viewProj");
        assert_eq!(refused(View::new(&[0.0; 16], 1.0, 1.0)), "viewProj");
    }

    /// A screen grid of `cols` × `rows` cells from `origin`, each holding one item, its own
    /// number r·cols + c: what `cells_along` visits are then the cells themselves.
    fn numbered_grid(origin: DVec2, cell: DVec2, cols: usize, rows: usize) -> Scene {
        let n = (cols * rows) as u32;
        Scene { occluders: Vec::new(), origin, cell, cols, rows, starts: (0..=n).collect(), items: (0..n).collect() }
    }

    /// The cells `cells_along` visits, sorted; none twice.
    fn visited(scene: &Scene, a: DVec2, b: DVec2) -> Vec<u32> {
        let mut cells = Vec::new();
        scene.cells_along(a, b, |k| cells.push(k));
        let n = cells.len();
        cells.sort_unstable();
        cells.dedup();
        assert_eq!(cells.len(), n, "a cell visited twice along {a} → {b}");
        cells
    }

    /// The cells whose closed rectangle (the border cells reaching to infinity) the segment
    /// a → b meets, by clipping the segment to each rectangle (Liang–Barsky): the same answer
    /// found another way.
    fn crossed(scene: &Scene, a: DVec2, b: DVec2) -> Vec<u32> {
        let bounds = |k: usize, n: usize, origin: f64, size: f64| {
            let lo = if k == 0 { f64::NEG_INFINITY } else { origin + k as f64 * size };
            let hi = if k + 1 == n { f64::INFINITY } else { origin + (k + 1) as f64 * size };
            (lo, hi)
        };
        let mut out = Vec::new();
        for r in 0..scene.rows {
            for c in 0..scene.cols {
                let (x0, x1) = bounds(c, scene.cols, scene.origin.x, scene.cell.x);
                let (y0, y1) = bounds(r, scene.rows, scene.origin.y, scene.cell.y);
                let (mut t0, mut t1) = (0.0f64, 1.0f64);
                for (p, d, lo, hi) in [(a.x, b.x - a.x, x0, x1), (a.y, b.y - a.y, y0, y1)] {
                    if d == 0.0 {
                        if p < lo || p > hi {
                            t0 = 2.0;
                        }
                    } else {
                        let (ta, tb) = ((lo - p) / d, (hi - p) / d);
                        t0 = t0.max(ta.min(tb));
                        t1 = t1.min(ta.max(tb));
                    }
                }
                if t0 <= t1 {
                    out.push((r * scene.cols + c) as u32);
                }
            }
        }
        out
    }

    /// The screen grid: a point's cell (clamped into the border cells, NaN to the first), and
    /// the cells a segment visits — exactly those it crosses, for 2 000 random segments, as many
    /// vertical ones and as many single points, over the grid and beyond its borders.
    #[test]
    fn a_segment_visits_exactly_the_cells_it_crosses() {
        let scene = numbered_grid(DVec2::new(-300.0, -200.0), DVec2::new(100.0, 50.0), 9, 12);
        assert_eq!(scene.cell_of(DVec2::new(150.0, 60.0)), (4, 5));
        assert_eq!(scene.cell_of(DVec2::new(-300.0, -200.0)), (0, 0));
        assert_eq!(scene.cell_of(DVec2::new(599.999, 399.999)), (8, 11));
        assert_eq!(scene.cell_of(DVec2::new(-1e9, 1e9)), (0, 11));
        assert_eq!(scene.cell_of(DVec2::new(f64::NAN, 0.0)), (0, 4));
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..2000 {
            let mut point = || DVec2::new(-500.0 + 1300.0 * uniform(&mut seed), -400.0 + 1000.0 * uniform(&mut seed));
            let (a, b) = (point(), point());
            let vertical = DVec2::new(a.x, b.y);
            for (a, b) in [(a, b), (a, vertical), (b, b)] {
                assert_eq!(visited(&scene, a, b), crossed(&scene, a, b), "{a} → {b}");
            }
        }
        // a segment whose x extent is within rounding of zero (one unit in the last place at
        // x = 100, a column border) counts as vertical: its whole y range in both columns, a
        // harmless superset; ten units are a slope like any other
        let scene = numbered_grid(DVec2::new(0.0, -200.0), DVec2::new(100.0, 50.0), 9, 12);
        let below = |x: f64, units: u64| f64::from_bits(x.to_bits() - units);
        let (a, b) = (DVec2::new(below(100.0, 1), 30.0), DVec2::new(100.0, 380.0));
        let mut both: Vec<u32> = (4..=11).flat_map(|r| [r * 9, r * 9 + 1]).collect();
        both.sort_unstable();
        assert_eq!(visited(&scene, a, b), both);
        let a = DVec2::new(below(100.0, 10), 30.0);
        let exact = visited(&scene, a, b);
        assert_eq!(exact, crossed(&scene, a, b));
        assert_eq!(exact.iter().filter(|&&k| k % 9 == 1).collect::<Vec<_>>(), [&(11 * 9 + 1)]);
    }

    /// A chain along the x axis from 0: pieces of the given lengths and visibilities.
    fn chain(pieces: &[(f64, bool)]) -> Chain {
        let mut c = Chain::new();
        c.points.push(DVec2::ZERO);
        let mut x = 0.0;
        for &(length, visible) in pieces {
            x += length;
            c.points.push(DVec2::new(x, 0.0));
            c.visible.push(visible);
        }
        c
    }

    /// Runs as (visible, first x, last x, number of points).
    fn shape(runs: &[Run]) -> Vec<(bool, f64, f64, usize)> {
        runs.iter().map(|r| (r.visible, r.points[0].x, r.points[r.points.len() - 1].x, r.points.len())).collect()
    }

    /// Runs of pieces, and slivers (shorter than `min`, 1 here) given to their neighbours, the
    /// shortest first, with lengths that add up: a run exactly `min` long stays, so does a run
    /// made of two short pieces, or made long enough by the sliver it took in (first, last).
    #[test]
    fn runs_join_pieces_and_give_slivers_away() {
        const V: bool = true;
        const H: bool = false;
        let runs = |pieces: &[(f64, bool)]| shape(&chain(pieces).runs(1.0));
        assert_eq!(runs(&[(5.0, V), (5.0, H)]), [(V, 0.0, 5.0, 2), (H, 5.0, 10.0, 2)]);
        assert_eq!(runs(&[(0.625, V), (0.625, V), (5.0, H)]), [(V, 0.0, 1.25, 3), (H, 1.25, 6.25, 2)]);
        assert_eq!(runs(&[(0.5, V)]), [(V, 0.0, 0.5, 2)]);
        assert_eq!(runs(&[(5.0, V), (1.0, H), (5.0, V)]), [(V, 0.0, 5.0, 2), (H, 5.0, 6.0, 2), (V, 6.0, 11.0, 2)]);
        assert_eq!(runs(&[(5.0, V), (0.5, H), (5.0, V)]), [(V, 0.0, 10.5, 4)]);
        // the first run a sliver: it joins the next, 0.375 + 0.75 = 1.125, no longer a sliver
        assert_eq!(runs(&[(0.375, V), (0.75, H), (3.0, V)]), [(H, 0.0, 1.125, 3), (V, 1.125, 4.125, 2)]);
        // the last: it joins the one before
        assert_eq!(runs(&[(3.0, V), (0.75, H), (0.375, V)]), [(V, 0.0, 3.0, 2), (H, 3.0, 4.125, 3)]);
        // the shortest sliver goes first: 0.25 joins its neighbours (0.5 + 0.25 + 0.75 = 1.5)
        assert_eq!(
            runs(&[(4.0, V), (0.5, H), (0.25, V), (0.75, H), (4.0, V)]),
            [(V, 0.0, 4.0, 2), (H, 4.0, 5.5, 4), (V, 5.5, 9.5, 2)]
        );
        // min = 0 keeps everything, a zero-length piece too
        assert_eq!(shape(&chain(&[(0.0, H), (2.0, V)]).runs(0.0)), [(H, 0.0, 0.0, 2), (V, 0.0, 2.0, 2)]);
    }

    /// Options at their bounds, refused beyond by name; at most `max_items` triangles (counted
    /// in threes of indices) and line points.
    #[test]
    fn options_and_sizes_are_refused_by_name_at_their_bounds() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let with =
            |tolerance: f64, min_piece: f64| hidden_lines(&view, &[], &[], HiddenLineOptions { tolerance, min_piece });
        assert!(with(1.0, 1000.0).is_ok());
        assert!(with(0.0, 0.0).is_ok());
        for (tolerance, min_piece, which) in [
            (1.000_000_1, 1.0, "tolerance"),
            (-1e-9, 1.0, "tolerance"),
            (f64::INFINITY, 1.0, "tolerance"),
            (0.5, 1000.5, "minPiece"),
            (0.5, -1.0, "minPiece"),
            (0.5, f64::NAN, "minPiece"),
        ] {
            assert_eq!(refused(with(tolerance, min_piece)), which, "{tolerance} {min_piece}");
        }
        let e = with(0.5, 1000.5).unwrap_err().to_string();
        assert!(e.contains("minPiece must be a number in [0, 1000], got 1000.5"), "{e}");
        let (p, _) = square();
        let at_most_10 = |idx: &[u32], points: &[DVec3]| {
            hidden_lines_at_most(&view, &[(&p, idx)], &[(LineKind::Points, points)], exact(), 10)
        };
        let ten: Vec<u32> = [0, 1, 2].repeat(10);
        assert!(at_most_10(&ten, &[DVec3::ZERO; 10]).is_ok());
        let and_one_index: Vec<u32> = [&ten[..], &[3]].concat();
        assert!(at_most_10(&and_one_index, &[]).is_ok());
        let eleven: Vec<u32> = [0, 1, 2].repeat(11);
        let too_many = |r: Result<Vec<Vec<Run>>>| match r {
            Err(Error::TooMany { what, got, max }) => (what, got, max),
            other => panic!("expected too many, got {other:?}"),
        };
        assert_eq!(too_many(at_most_10(&eleven, &[])), ("triangles", 11, 10));
        assert_eq!(too_many(at_most_10(&ten, &[DVec3::ZERO; 11])), ("line points", 11, 10));
    }

    /// A closed polyline joins its last point to its first (three points or more); two points
    /// are one segment either way.
    #[test]
    fn closed_polylines_come_back_to_their_first_point() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let triangle = [DVec3::new(-1.0, -1.0, 0.0), DVec3::new(1.0, -1.0, 0.0), DVec3::new(0.0, 1.0, 0.0)];
        let images: Vec<DVec2> = triangle.iter().map(|&q| view.project(q).unwrap()).collect();
        let draw = |closed: bool, points: &[DVec3]| {
            hidden_lines(&view, &[], &[(LineKind::Polyline { closed }, points)], exact()).unwrap().remove(0)
        };
        assert_eq!(draw(true, &triangle), [Run { points: [&images[..], &images[..1]].concat(), visible: true }]);
        assert_eq!(draw(false, &triangle), [Run { points: images.clone(), visible: true }]);
        assert_eq!(draw(true, &triangle[..2]), [Run { points: images[..2].to_vec(), visible: true }]);
    }

    #[test]
    fn transformed_moves_points_by_the_model_matrix() {
        let points = [DVec3::new(1.0, 2.0, 3.0), DVec3::new(-1.0, 0.0, 0.5)];
        assert_eq!(transformed(&points, None), points);
        let m = DMat4::from_translation(DVec3::new(10.0, 20.0, 30.0)) * DMat4::from_scale(DVec3::splat(2.0));
        assert_eq!(transformed(&points, Some(&m)), [DVec3::new(12.0, 24.0, 36.0), DVec3::new(8.0, 20.0, 31.0)]);
    }

    /// A view from a matrix given by its rows.
    fn view_of_rows(rows: [[f64; 4]; 4]) -> View {
        let m = DMat4::from_cols_array_2d(&rows).transpose();
        View::new(&m.to_cols_array(), 2.0, 2.0).unwrap()
    }

    /// Clipping to the near plane (z + w ≥ 0, closed) and to w > 0 (open: a point at w = 0 has
    /// no image), with matrices that set clip z and w apart; a segment with a point at infinity
    /// is left out.
    #[test]
    fn segments_are_clipped_to_the_near_plane_and_to_positive_w() {
        // clip (y, z, 5, x): z + w ≥ 0 for x ≥ −5; w = x
        let w_is_x =
            view_of_rows([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 5.0], [1.0, 0.0, 0.0, 0.0]]);
        assert_eq!(w_is_x.project(DVec3::new(2.0, 0.5, 0.25)), Some(DVec2::new(1.25, 0.875)));
        assert_eq!(w_is_x.project(DVec3::new(0.0, 0.5, 0.25)), None);
        assert!(clip_segment(&w_is_x, DVec3::X, DVec3::ZERO).is_none());
        assert!(clip_segment(&w_is_x, DVec3::ZERO, DVec3::X).is_none());
        let whole = clip_segment(&w_is_x, DVec3::X, DVec3::new(3.0, 1.0, 0.0)).unwrap();
        assert_eq!((whole.a, whole.b, whole.ia.w, whole.ib.w), (DVec3::X, DVec3::new(3.0, 1.0, 0.0), 1.0, 3.0));
        // clip (y, z, −1, x): the near plane is x = 1
        let near_at_1 =
            view_of_rows([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, -1.0], [1.0, 0.0, 0.0, 0.0]]);
        let cut = clip_segment(&near_at_1, DVec3::new(0.5, 0.0, 0.0), DVec3::new(3.0, 2.0, 0.0)).unwrap();
        crate::assert_near!(cut.a, DVec3::new(1.0, 0.4, 0.0), 1e-15);
        assert_eq!(cut.b, DVec3::new(3.0, 2.0, 0.0));
        crate::assert_near!(cut.ia.screen, DVec2::new(1.4, 1.0), 1e-15);
        // touching the near plane in one point: that point is kept
        let touch = clip_segment(&near_at_1, DVec3::X, DVec3::new(0.5, 0.0, 0.0)).unwrap();
        assert_eq!((touch.a, touch.b), (DVec3::X, DVec3::X));
        // clip (y, z, x + 1, x + 2): a point at x = ∞ has z + w = w = ∞ but no image
        let x_grows =
            view_of_rows([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0]]);
        let far = DVec3::new(f64::INFINITY, 0.0, 0.0);
        assert!(clip_segment(&x_grows, far, DVec3::X).is_none());
        assert!(clip_segment(&x_grows, DVec3::X, far).is_none());
        assert!(clip_segment(&x_grows, DVec3::X, DVec3::Y).is_some());
    }

    /// An occluder is left out when a corner is behind the eye, or its image is edge-on: with
    /// A = |(b − a) × (c − a)| (twice its area) and L its longer side from a, kept when
    /// A > [`HIDDEN_LINE_EDGE_ON`] L² (10⁻¹²): a triangle far from the origin with A = 10⁻¹¹ L² is
    /// kept, whichever side is longer; one with A = 10⁻¹³ L² is not.
    #[test]
    fn occluders_leave_out_what_hides_nothing() {
        // clip (x, y, z, 1): the image of (x, y, z) is (x + 1, 1 − y)
        let flat = View::new(&DMat4::IDENTITY.to_cols_array(), 2.0, 2.0).unwrap();
        assert_eq!(HIDDEN_LINE_EDGE_ON, 1e-12);
        let triangle = |c0: DVec2, d1: DVec2, d2: DVec2| [c0.extend(0.0), (c0 + d1).extend(0.0), (c0 + d2).extend(0.0)];
        let far = DVec2::splat(1000.0);
        let (long, short) = (DVec2::new(1.0, 0.0), DVec2::new(0.5, 1e-11));
        assert!(occluder(&flat, triangle(far, long, short), 0.0).is_some());
        assert!(occluder(&flat, triangle(far, short, long), 0.0).is_some());
        let (long, short) = (DVec2::new(100.0, 0.0), DVec2::new(0.5, 1e-11));
        assert!(occluder(&flat, triangle(far, long, short), 0.0).is_none());
        assert!(occluder(&flat, triangle(far, short, long), 0.0).is_none());
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let (p, _) = square();
        assert!(occluder(&view, [p[0], p[1], p[2]], 0.0).is_some());
        assert!(occluder(&view, [p[0], p[1], DVec3::new(0.0, 0.0, 20.0)], 0.0).is_none());
        // seen edge-on
        assert!(occluder(&view, [DVec3::X, DVec3::new(1.0, 0.0, 1.0), DVec3::new(2.0, 0.0, 0.0)], 0.0).is_none());
    }

    /// A point or a line ending on a surface is not hidden by it, tolerance zero or not; a square
    /// between the eye and the origin hides what is behind it, not what is in front (the eye's
    /// side of its plane from the homogeneous eye).
    #[test]
    fn what_lies_on_a_surface_is_seen_and_the_eye_decides_the_side() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let (p, idx) = square();
        let on = [DVec3::new(0.3, 0.2, 0.0)];
        let up = [DVec3::new(0.3, 0.2, 0.0), DVec3::new(0.3, 0.2, 1.0)];
        let down = [up[1], up[0]];
        for tolerance in [0.0, HIDDEN_LINE_TOLERANCE] {
            let options = HiddenLineOptions { tolerance, min_piece: 0.0 };
            let lines = [(LineKind::Points, &on[..]), (LineKind::Segments, &up[..]), (LineKind::Segments, &down[..])];
            let runs = hidden_lines(&view, &[(&p, &idx)], &lines, options).unwrap();
            for r in &runs {
                assert_eq!(seen(r), [true], "τ = {tolerance}: {r:?}");
            }
        }
        // from 100 above the origin (the eye's homogeneous w ≈ −1/2), a square at z = 60
        let view = camera(DVec3::new(0.0, 0.0, 100.0), DVec3::ZERO);
        let lifted: Vec<DVec3> = p.iter().map(|q| *q + DVec3::new(0.0, 0.0, 60.0)).collect();
        let dots = [DVec3::new(0.0, 0.0, 59.0), DVec3::new(0.0, 0.0, 61.0)];
        let runs = hidden_lines(&view, &[(&lifted, &idx)], &[(LineKind::Points, &dots)], exact()).unwrap();
        assert_eq!(seen(&runs[0]), [false, true]);
    }

    /// How far the triangles across each edge bend away from a triangle's plane, against the
    /// same found pair by pair; a triangle naming a point that does not exist is no one's
    /// neighbour and bends nothing.
    #[test]
    fn bend_is_the_largest_distance_of_a_neighbours_far_corner() {
        let n = 5;
        let mut seed = 7u64;
        let mut p: Vec<DVec3> =
            (0..n * n).map(|k| DVec3::new((k % n) as f64, (k / n) as f64, uniform(&mut seed) - 0.5)).collect();
        p.push(DVec3::NAN);
        let mut idx = crate::grid_indices(n, n);
        // a triangle with a NaN corner (across the edge 0–1 of the grid) and one naming no point
        idx.extend([0, 1, (n * n) as u32, (n * n + 1) as u32, (n * n + 1) as u32, 0]);
        let triangles = idx.len() / 3;
        let mut pairwise = vec![0.0f64; triangles];
        let corners = |t: usize| [idx[3 * t], idx[3 * t + 1], idx[3 * t + 2]];
        for (a, out) in pairwise.iter_mut().enumerate() {
            let ca = corners(a);
            let Some(pa) = ca.iter().map(|&i| p.get(i as usize).copied()).collect::<Option<Vec<_>>>() else { continue };
            let normal = (pa[1] - pa[0]).cross(pa[2] - pa[0]).normalize_or_zero();
            for b in (0..triangles).filter(|&b| b != a) {
                let cb = corners(b);
                if cb.iter().any(|&i| i as usize >= p.len()) {
                    continue;
                }
                for k in 0..3 {
                    let (i, j) = (ca[k], ca[(k + 1) % 3]);
                    if cb.contains(&i) && cb.contains(&j) {
                        let far = cb.iter().find(|&&c| c != i && c != j).unwrap();
                        let d = normal.dot(p[*far as usize] - pa[0]).abs();
                        if d.is_finite() {
                            *out = out.max(d);
                        }
                    }
                }
            }
        }
        let b = bend(&p, &idx);
        assert_eq!(b.len(), triangles);
        for t in 0..triangles {
            crate::assert_near!(b[t], pairwise[t], 1e-14);
        }
        // the same triangles with their corners named from the second on (the smallest index
        // is no longer always first)
        let turned: Vec<u32> = idx.chunks_exact(3).flat_map(|t| [t[1], t[2], t[0]]).collect();
        for (x, y) in bend(&p, &turned).into_iter().zip(&b) {
            crate::assert_near!(x, *y, 1e-14);
        }
        assert!(b[..triangles - 2].iter().all(|&x| x > 0.0), "{b:?}");
        assert_eq!(&b[triangles - 2..], [0.0, 0.0]);
        // flat: nothing bends
        let (square, idx) = square();
        assert_eq!(bend(&square, &idx), [0.0, 0.0]);
    }

    /// The page camera: the near plane at a hundredth of the distance (0.1 here), to ±5·10⁻⁶ (the
    /// far plane's far − near in place of far + near would move it to 0.10001); "up" is z until
    /// the view direction is within the sine [`CAMERA_UP_SINE`] of z (exactly, here).
    #[test]
    fn the_page_camera_near_plane_and_up_direction() {
        let eye = DVec3::new(0.0, -10.0, 0.0);
        let v = View::looking(eye, DVec3::ZERO, 1.0, 400.0, 300.0).unwrap();
        assert!(v.project(eye + DVec3::new(0.0, 0.100_005, 0.0)).is_some());
        assert!(v.project(eye + DVec3::new(0.0, 0.099_995, 0.0)).is_none());
        let square = |eye: DVec3| View::looking(eye, DVec3::ZERO, std::f64::consts::FRAC_PI_2, 400.0, 400.0).unwrap();
        let tilted = square(DVec3::new(1e-9, 0.0, 1.0));
        assert_eq!(DVec3::new(1e-9, 0.0, 1.0).cross(DVec3::Z).length(), CAMERA_UP_SINE);
        // up is z: the view's right is the world's +y
        crate::assert_near!(tilted.project(DVec3::new(0.0, 0.5, 0.0)).unwrap(), DVec2::new(300.0, 200.0), 1e-6);
        // along z: up is y
        crate::assert_near!(
            square(DVec3::Z).project(DVec3::new(0.0, 0.5, 0.0)).unwrap(),
            DVec2::new(200.0, 100.0),
            1e-9
        );
    }

    /// Eight squares in a row above a line drawn from right to left: the grid finds their
    /// triangles column by column, left to right, so the hidden intervals (in the line's
    /// parameter, which grows leftwards) come in falling order and must be sorted before they
    /// are merged; each shadow is hidden exactly, the gaps between them seen.
    #[test]
    fn hidden_parts_found_out_of_order_are_sorted() {
        let view = camera(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO);
        let mut p = Vec::new();
        let mut idx = Vec::new();
        for k in 0..8 {
            let x = -3.75 + k as f64;
            let base = p.len() as u32;
            p.extend([
                DVec3::new(x - 0.25, -0.25, 0.0),
                DVec3::new(x + 0.25, -0.25, 0.0),
                DVec3::new(x + 0.25, 0.25, 0.0),
                DVec3::new(x - 0.25, 0.25, 0.0),
            ]);
            idx.extend([base, base + 1, base + 2, base, base + 2, base + 3]);
        }
        let scene = Scene::new(&view, &[(&p, &idx)], 0.0);
        assert!(scene.cols >= 3, "the squares lie in several columns of the grid");
        let line = [DVec3::new(5.0, 0.1, -1.0), DVec3::new(-5.0, 0.1, -1.0)];
        let runs = hidden_lines(&view, &[(&p, &idx)], &[(LineKind::Segments, &line)], exact()).unwrap().remove(0);
        assert_eq!(runs.len(), 17);
        // seen from z = 10, a square's shadow on z = −1 is 1.1 times as wide
        let shadow = |x: f64| view.project(DVec3::new(1.1 * x, 0.1, -1.0)).unwrap();
        for (k, run) in runs.iter().enumerate() {
            assert_eq!(run.visible, k % 2 == 0, "run {k}");
            if !run.visible {
                let x = 3.25 - (k / 2) as f64;
                crate::assert_near!(run.points[0], shadow(x + 0.25), 1e-9);
                crate::assert_near!(run.points[1], shadow(x - 0.25), 1e-9);
            }
        }
    }
}
