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

/**
 * Curve subdivision: the largest turning angle of the refined polygon is measured after each step
 * up to this many (more than are drawn: smoothness shows over many steps) …
 */
export const TURNING_STEPS = 12;
/** … and the readout and the claims compare it with its value this many steps in (the texts quote both). */
export const TURNING_FROM = 8;

/** The nearest the camera comes to its target, and the least radius a fitted view frames. */
export const CAMERA_NEAREST = 1e-6;
/** The steepest the camera looks down or up (radians, just short of the pole, where yaw is lost). */
export const PITCH_LIMIT = 1.55;

/** Output sizes (rulings) above this are computed in the worker. */
export const WORKER_THRESHOLD = 50_000;
/**
 * Refined tool poses above this are refined and posted in the worker (the milling scene's long
 * jobs: its G-code post takes about a second for 40 000 poses on the page).
 */
export const POST_WORKER_THRESHOLD = 5_000;
/**
 * Refined tool poses times target points above this: the post and the deviation of its program
 * from the target are made in the worker, with progress (the milling scene; about 10 ms of work on
 * the page at this size: a ring of 151 poses against 1 200 points takes 35–175 ms).
 */
export const SWEEP_WORKER_WORK = 50_000;
/** Most rulings drawn as a strip (a level of detail above it). */
export const DRAW_LIMIT = 100_000;
/**
 * Most rulings in the strip drawn while the camera moves (a lighter stand-in, Layer.moving):
 * enough for a moving picture, light enough for software WebGL (bench/page.mjs); the full
 * strip returns as soon as the camera rests.
 */
export const MOVING_LIMIT = 2_000;
/**
 * Your rulings (the data scene, a notebook's view) above this are drawn at a level of detail: the
 * strip, the rulings and the striction curve through every k-th ruling, the footpoints, striction
 * points and handles left out; the numbers are of every ruling.
 */
export const DATA_DETAIL_LIMIT = 20_000;
/**
 * Rulings the data scene draws above DATA_DETAIL_LIMIT (the strip and the striction curve
 * through every k-th ruling; as lines at most LINE_LIMIT): on a view some thousand pixels wide
 * more merge into the same pixels, and software WebGL took about 1.5 s a frame for a strip of
 * 20 000 (SwiftShader; 0.3 s for 2 000).
 */
export const DATA_DRAWN = 2_000;
/** Most rulings drawn as lines: a few pixels apart in a full view; more would merge into a moiré. */
export const LINE_LIMIT = 160;

/** Below this width (CSS px) the panel goes under the view (and, for a box taller than wide, below PORTRAIT). */
export const NARROW = 640;
export const PORTRAIT = 1000;
/** Below this width the controls' labels go above them. */
export const TINY = 360;
/** Below this width of the view, the mouse hint is left out (the toolbar needs the room). */
export const SMALL_VIEW = 560;

/** Longest hash read, in characters (imported data of up to MAX_LINK_RULINGS rulings fits at full precision). */
export const MAX_HASH = 65536;
/** Most rulings (or lines) of imported data kept in the link; larger imports go to session storage. */
export const MAX_LINK_RULINGS = 200;
/** Most handles of an edited input kept in the link; a larger edit goes to session storage. */
export const MAX_LINK_HANDLES = 200;
/** Longest text parameter (a formula), in characters, unless the parameter sets its own maxLength. */
export const MAX_TEXT_PARAM = 1000;
/**
 * A slider gets − / + and a number field where a value has fewer CSS px than this: one with a
 * mouse (a pixel skips values), this many with a finger (a tap or a drag lands within a few
 * pixels of where it aims, so closer values take tries).
 */
export const SLIDER_PX_PER_VALUE = { fine: 1, coarse: 8 };
/** A handle is grabbed within this distance of the pointer (CSS px), on fine and on coarse pointers. */
export const HANDLE_REACH = 10;
export const HANDLE_REACH_COARSE = 22;
/**
 * A dragged handle snaps onto a point, line or plane of the figure the core puts within this
 * distance of the pointer (CSS px), on fine and on coarse pointers (a finger is off by a few).
 */
export const SNAP_REACH = 8;
export const SNAP_REACH_COARSE = 16;
/** Handles closer than this on screen (CSS px) are offered as a list to pick from, not grabbed blindly. */
export const HANDLE_OVERLAP = 8;
/** Most handles in that list (the nearest). */
export const PICK_LIST = 8;
/** After a long press a dragged handle follows at this share of the pointer's speed (a fine drag). */
export const FINE_DRAG = 0.2;
/** Handles stay in the box of the scene's bounds scaled by this about its centre. */
export const EDIT_BOX = 10;
/** One arrow key moves a handle by this share of the scene's size (Shift: a tenth of it). */
export const KEY_STEP = 0.02;
/** A finger held this long on a handle without moving shows its coordinates (ms). */
export const LONG_PRESS = 500;
/** A pointer that moves less than this (CSS px) has not started a drag yet (a press, a long press). */
export const DRAG_SLOP = 3;

/** Points of an exact striction curve whose straightness is measured (an exercise's "straight line"). */
export const STRAIGHTNESS_SAMPLES = 201;
/**
 * A striction curve shorter than this share of its surface's size is too short to call straight
 * or not (a tiny range of u would make any curve "straight"): its straightness is undefined.
 */
export const STRAIGHTNESS_MIN_EXTENT = 1e-3;

/**
 * "Closed in u" fits a typed surface when the rulings at the two ends of u are one line: parallel
 * at a distance of at most this share of the largest coordinate (rounding of the core's sampling).
 */
export const CLOSING_GAP = 1e-9;

/**
 * Most triangles of one mesh drawn in a figure (SVG, TikZ): a larger mesh is drawn by its lighter
 * stand-in (Layer.moving) where it has one — facets far below a printed line's width add bytes,
 * not detail.
 */
export const FIGURE_TRIANGLES = 20_000;
/** The printed width of an SVG or TikZ figure, cm: a column of 8 by default, and the range the page offers. */
export const PRINT_WIDTH = { min: 2, max: 40, default: 8 };
/** Distance of hatch lines on a surface in a black-and-white figure (CSS pixels on paper). */
export const HATCH_SPACING = 4;
/** Inserted lines (or rulings) above this many are drawn in the thinner style, so they stay apart. */
export const FINE_LINES = 400;
/** Most points of a series in a plot drawn with markers (more would merge into a thick line). */
export const PLOT_MARKERS = 80;

// Exercises (task/format.js): what an exercise may hold; the texts quote these.

/** Longest exercise read (characters of JSON). */
export const MAX_TASK = 32768;
/** Longest title or answer label, in characters. */
export const MAX_TASK_TITLE = 200;
/** Longest prompt or hint, in characters. */
export const MAX_TASK_TEXT = 2000;
/** Largest magnitude of a number in an exercise. */
export const MAX_TASK_NUMBER = 1e12;
/** Most answers, conditions and hints. */
export const MAX_TASK_ANSWERS = 3;
export const MAX_TASK_GOAL = 6;
export const MAX_TASK_HINTS = 3;
/** The most checks a lecturer may ask for before the solution is offered (task/solution-rule.js). */
export const MAX_SOLUTION_AFTER = 9;
/** Points at which a typed curve is compared with the exact one, by default and at most. */
export const TASK_SAMPLES = 50;
export const MAX_TASK_SAMPLES = 1000;
/** Longest id of an exercise (lowercase letters, digits and dashes). */
export const MAX_TASK_ID = 64;
/** The title's share of an id the author makes (then a dash and a hash of at most 7 characters: within MAX_TASK_ID). */
export const MAX_TASK_SLUG = 40;
/** Longest name (a parameter, a readout, a measure, an answer), in characters. */
export const MAX_TASK_NAME = 80;
/** Most entries of a list of names (change, hide) and of parameter values. */
export const MAX_TASK_NAMES = 64;
/** Longest camera of an exercise, in characters (six numbers, as the link writes them). */
export const MAX_TASK_CAMERA = 200;
/** Longest edited input of an exercise, in characters: no more than a link can hold. */
export const MAX_TASK_INPUT = MAX_HASH;
/** Most characters of the JSON parser's message an exercise's error quotes. */
export const MAX_TASK_DETAIL = 120;
/** Most numbers an exercise draws per attempt, and most values a list of them may hold. */
export const MAX_TASK_DRAWS = 6;
export const MAX_DRAW_LIST = 64;
/** Most values a drawn range may hold ((to − from) / step + 1). */
export const MAX_DRAW_CHOICES = 100_000;
/** Most values of a drawn parameter checked one by one against its control (a longer range: its ends). */
export const MAX_TASK_CHECKED_DRAWS = 1000;
/** Largest seed of the drawn numbers (a 32-bit unsigned integer). */
export const MAX_SEED = 4_294_967_295;
/** Most checks an attempt keeps (the oldest go first), and how many the panel lists. */
export const MAX_TASK_HISTORY = 30;
export const TASK_HISTORY_SHOWN = 5;
/** A typed number within this share of the right one is "a little" too large or too small. */
export const ANSWER_CLOSE = 0.1;

// Course systems (www/course/, page/scorm.js): what a package may hold and what SCORM allows.

/** Most exercises in one SCORM package or H5P file. */
export const MAX_PACKAGE_TASKS = 12;
/** Longest suspend_data SCORM 1.2 keeps (CMIString4096) and SCORM 2004 4th edition (SPM 64000). */
export const SCORM12_SUSPEND = 4096;
export const SCORM2004_SUSPEND = 64000;
/** Longest text of a SCORM 1.2 interaction's student_response (CMIString255), and 2004's learner_response of type "other" (SPM 4000). */
export const SCORM12_RESPONSE = 255;
export const SCORM2004_RESPONSE = 4000;
/** Longest SCORM 2004 interaction description (SPM 250). */
export const SCORM2004_DESCRIPTION = 250;
/** How many frames up a package's page looks for the course system's runtime (the standard's search allows 500). */
export const SCORM_FRAMES = 500;
/** Longest H5P or SCORM package this page reads back (bytes). */
export const MAX_PACKAGE_BYTES = 64 * 1024 * 1024;
/** Height of an exercise in an H5P activity (CSS pixels), by default. */
export const H5P_HEIGHT = 640;

/**
 * The most lines the Klein view beside the 3D view draws (its points and steps are drawn in full,
 * without a lighter stand-in while the camera moves).
 */
export const MAX_KLEIN_LINES = 100_000;

/**
 * The Klein image's projection (klein-projection.js): α (mix, degrees), β (turn, degrees) and ℓ
 * (the unit of length), with the steps the sliders take — the Klein scene's and the Klein view's
 * beside any scene; a link's or an attribute's value outside is held at the nearest end.
 */
export const KLEIN_RANGES = Object.freeze({
  mix: Object.freeze({ min: 0, max: 90, step: 1 }),
  turn: Object.freeze({ min: 0, max: 360, step: 1 }),
  unit: Object.freeze({ min: 0.25, max: 4, step: 0.05 }),
});
