// Every tolerance and size limit of the page, in one place (the core's are in src/tolerance.rs):
// when a number counts as exact, how loosely a fit may hold the data a file or a slider gave, how
// much is drawn, and where the layout changes.

/** A readout or an error below this is shown as "exact" (rounding of ~1-sized numbers). */
export const EXACT_ZERO = 1e-13;

/** Claims that hold "to rounding" compare within this (a few dozen operations on ~1-sized numbers). */
export const ROUNDING = 1e-12;

/**
 * The root-mean-square residual under which a linear complex holds imported or typed lines:
 * looser than the core's default 1e-9 (COMPLEX_TOLERANCE), for the digits a file printed or a
 * slider gave.
 */
export const DATA_COMPLEX_TOLERANCE = 1e-6;

/** The nearest the camera comes to its target, and the least radius a fitted view frames. */
export const CAMERA_NEAREST = 1e-6;
/** The steepest the camera looks down or up (radians, just short of the pole, where yaw is lost). */
export const PITCH_LIMIT = 1.55;

/** Output sizes (rulings) above this are computed in the worker. */
export const WORKER_THRESHOLD = 50_000;
/** Most rulings drawn as a strip (a level of detail above it). */
export const DRAW_LIMIT = 100_000;
/**
 * Most rulings in the strip drawn while the camera moves (a lighter stand-in, Layer.moving):
 * enough for a moving picture, light enough for software WebGL (bench/page.mjs); the full
 * strip returns as soon as the camera rests.
 */
export const MOVING_LIMIT = 2_000;
/** Most rulings drawn as lines: a few pixels apart in a full view; more would merge into a moiré. */
export const LINE_LIMIT = 160;

/** Below this width (CSS px) the panel goes under the view (and, for a box taller than wide, below PORTRAIT). */
export const NARROW = 640;
export const PORTRAIT = 1000;
/** Below this width the controls' labels go above them. */
export const TINY = 360;
/** Below this width of the view, the mouse hint is left out (the toolbar needs the room). */
export const SMALL_VIEW = 560;

/**
 * Most triangles of one mesh drawn in a figure (SVG, TikZ): a larger mesh is drawn by its lighter
 * stand-in (Layer.moving) where it has one — facets far below a printed line's width add bytes,
 * not detail.
 */
export const FIGURE_TRIANGLES = 20_000;
/** Distance of hatch lines on a surface in a black-and-white figure (CSS pixels). */
export const HATCH_SPACING = 4;
