//! # ruledlab
//!
//! Discrete models of ruled surfaces and line congruences, after B. Odehnal and
//! H. Pottmann, *Computing with Discrete Models of Ruled Surfaces and Line Congruences*.
//!
//! A discrete ruled surface is a sequence of lines R_0, R_1, …, each given as a segment
//! a_i → b_i ([`RuledSurface`]). From it ruledlab computes the discrete counterparts of the
//! differential invariants (Section 2: angles, signed distances, common perpendiculars and
//! their footpoints, the distribution parameter, the striction polygon), with the
//! convergence orders of Propositions 1 and 2 measured by [`convergence_study`].
//!
//! The core is pure Rust on `f64` and glam's `DVec3`; it knows nothing of JavaScript, nor of
//! machining: the five-axis tool paths of Example 6 and their G-code are the crate
//! `ruledlab-cam`, which builds on this one; the WebAssembly bindings are the crates
//! `ruledlab-wasm` and `ruledlab-cam-wasm` (the workspace's `crates/`). The conventions ruledlab keeps and its corrections of the paper, with
//! the equation numbers, are in `docs/src/conventions.md` (the book's page "Conventions"), which
//! each module's documentation cites.
//!
//! The crate's modules are private; this page is the public surface, grouped below by the
//! paper's sections. How the modules depend on each other (a tree: shared vocabulary at the
//! bottom, the catalogue of analytic surfaces at the top, which no algorithm imports) is in
//! `ARCHITECTURE.md` and checked by `tests/architecture.rs`.
//!
//! ```
//! use ruledlab::{AnalyticSurface, RuledSurface, SmoothRuled};
//! let hyperboloid = AnalyticSurface::by_name("hyperboloid").unwrap();
//! let surface: RuledSurface = hyperboloid.sample(64, hyperboloid.ranges()).unwrap();
//! let inv = surface.invariants();
//! assert_eq!(inv.striction.len(), 62);
//! ```

#[cfg_attr(doctest, doc = include_str!("../README.md"))] // the README's Rust snippets run as doctests
mod base;
mod catalogue;
mod congruence;
mod developable;
mod error;
mod formula;
mod io;
mod klein;
mod linalg;
mod line;
mod line_fit;
mod linear_complex;
mod mesh;
mod ruled;
mod snap;
mod subdivision;
pub mod tolerance;
mod visibility;

// errors and messages
pub use error::{
    message_number, message_template, Arg, Args, Catalogue, Details, Error, Message, Problem, Record, Result, MESSAGES,
    TEXT_REASON,
};

// shared vocabulary: lines, jets, parameter ranges
pub use base::{atan2_x2, check_coordinates, sample_parameters, CongruenceJet, Jet, Ranges};
pub use line::{Line, Segment};
// banded symmetric positive definite systems (the variational schemes'; the CAM crate's pose optimisation)
pub use linalg::banded::{CholeskyBanded, SymmetricBanded};
pub use line_fit::{fit_line, LineFit};
pub use mesh::{grid_indices, strip_indices, Mesh};

// the reader's hand: where a dragged handle goes (constraints and snapping)
pub use snap::{place, Bounds, Constraint, Held, Placement, Ray, Target};

// figures: hidden lines of vector drawings
pub use visibility::{hidden_lines, transformed, HiddenLineOptions, LineKind, Run, View};

// Section 2: discrete ruled surfaces, their invariants, convergence and accuracy
pub use ruled::accuracy::{sampling_errors, sampling_orders, SamplingErrors, SamplingOrders};
pub use ruled::convergence::{convergence_study, fit_order, ConvergenceSeries, ConvergenceStudy};
pub use ruled::surface::{checked_points, points_from_flat};
pub use ruled::{Invariants, InvariantsBlock, PairInvariants, RuledSurface, SmoothRuled};

// Section 3: isometries and the development
pub use ruled::development::Frame;
pub use ruled::{envelope_radii, Development, HingeChain};

// Section 3, beyond it: developable strips, their exact unfolding and flat patterns for cutting
pub use developable::approximate::ApproximatePattern;
pub use developable::construct::{cone, cylinder, rectifying_developable, tangent_surface, Span};
pub use developable::coplanar::{max_abs_delta, max_off_plane, pair_delta, size_of};
pub use developable::outline::{offset, outline, perimeter, signed_area, Outline, Side, Stroke};
pub use developable::overlap::{overlapping_faces, pieces};
pub use developable::repair::{make_developable, Repair};
pub use developable::sheet::{bends, closes, tile, Paper, Sheet, SheetLabel, SheetOptions, SheetPiece, Tile, Tiling};
pub use developable::unfold::{crossed_faces, isometry_error, IsometryError, Unfolding};

// Section 4: subdivision
pub use subdivision::accuracy::max_distance;
pub use subdivision::bezier::de_casteljau;
pub use subdivision::bspline::bspline;
pub use subdivision::chaikin::chaikin;
pub use subdivision::four_point::four_point;
pub use subdivision::line_space::{subdivide_lines, DualLine};
pub use subdivision::triangulation::{division_point, triangulation_edges, Triangulation};
pub use subdivision::turning::{largest_turning_angle, turning_angles};
pub use subdivision::variational::refine_variational;
pub use subdivision::{recut, subdivide_polygon, subdivide_strip, Affine, Pair, Scheme, Variant};

// Section 5: line congruences, and their focal geometry (beyond the paper)
pub use congruence::focal::{focal_analytic, focal_grid, focal_sheet, torsal_strokes};
pub use congruence::grid::check_grid_shape;
pub use congruence::line_space::butterfly_lines;
pub use congruence::variational::{coupled_congruence, two_stage, EdgeScheme, SolveReport};
pub use congruence::{
    butterfly_diagonal, subdivide_congruence, CongruenceScheme, Focal, FocalKind, LineCongruence, SmoothCongruence,
};

// the Klein quadric: lines as points of P⁵ (beyond the paper)
pub use klein::departure::{line_space_departure, Departure};
pub use klein::image::Projection;
pub use klein::net::KleinNet;
pub use klein::point::{klein_form, KleinPoint};
pub use klein::polygon::KleinPolygon;
pub use klein::sections::{complex_residuals, RegulusPlane};

// linear complexes (beyond the paper)
pub use linear_complex::{fit_linear_complex, ComplexKind, LinearComplex};

// reading and writing segments
pub use io::csv::{read_csv, read_csv_with, write_csv};
pub use io::invariants::{invariants_csv, invariants_json};
pub use io::json::{read_json, read_json_with, write_json};
pub use io::obj::write_obj;
pub use io::sheet_dxf::sheet_dxf;
pub use io::sheet_svg::{page_svg, sheet_svg};
pub use io::Imported;

// reading text: what ruledlab-cam's readers of tool poses and target curves build on, and what
// kind of data a text holds
pub use io::json::{read_json_value, JsonValue};
pub use io::sniff::{detect_import, looks_like_poses, looks_like_target, pose_columns, PoseColumns};
pub use io::table::{fields, read_table, Row, Table};
pub use io::{check_records, classify, position, rust_number, NumberParser, Token};

// formulas, and the catalogue of analytic surfaces and congruences
pub use catalogue::{
    AnalyticCongruence, AnalyticSurface, CongruenceSpec, CongruenceTexts, FormulaCongruence, FormulaSpec,
    FormulaSurface, SurfaceTexts, CONGRUENCE_FORMULAS, ORTHOGONAL_SLOPE, SURFACE_FORMULAS,
};
pub use formula::check::{decimal_commas, FORMULA_CONSTANTS, FORMULA_FUNCTIONS};
pub use formula::dual::Dual;
pub use formula::{Formula, PARAMETERS};
