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
//!
//! The files: the camera (`view.rs`), the triangles as occluders and how far their neighbours
//! bend (`occluder.rs`), their screen grid (`grid.rs`), a segment clipped to the near plane
//! (`segment.rs`), the runs of one visibility along a line (`runs.rs`), the tolerances
//! (`options.rs`), and the whole (`hidden_lines.rs`).
//!
//! [`HIDDEN_LINE_TOLERANCE`]: crate::tolerance::HIDDEN_LINE_TOLERANCE
//! [`HIDDEN_LINE_BEND`]: crate::tolerance::HIDDEN_LINE_BEND
//! [`HIDDEN_LINE_MIN_PIECE`]: crate::tolerance::HIDDEN_LINE_MIN_PIECE

mod grid;
mod hidden_lines;
mod occluder;
mod options;
mod runs;
mod segment;
mod view;

#[cfg(test)]
mod fixtures;

pub use hidden_lines::{hidden_lines, LineKind};
pub use options::HiddenLineOptions;
pub use runs::Run;
pub use view::{transformed, View};
