//! The CAM crate's limits and tolerances, one module (the geometry's are `ruledlab::tolerance`):
//! the pole of a machine, the post's linearisation, the G-code's decimals, safe moves, the values
//! a machine description may hold. Each constant says where it is used.

/// The pole of a five-axis machine: a vector within this sine of the rotary axis that turns it
/// (|v × u| below it) leaves that axis's angle undetermined (`kinematics`).
pub const POLE_SIN: f64 = 1e-9;

/// Samples per block at which the post compares the controller's linear interpolation with the
/// path (`linearise`).
pub const LINEARISATION_SAMPLES: usize = 16;

/// Most rounds of halving the blocks whose interpolation strays beyond the tolerance (each round
/// halves every such block once; 16 rounds split a block into up to 65 536).
pub const MAX_LINEARISATION_ROUNDS: usize = 16;

/// Most poses the post writes (the refined path with the poses the linearisation inserted).
pub const MAX_POST_POSES: usize = 1 << 20;

/// The smallest linearisation tolerance accepted, in mm (below the 1e-4 mm the programs print).
pub const MIN_LINEARISATION_TOLERANCE: f64 = 1e-4;

/// Decimals of lengths (mm) and angles (degrees) in the G-code: 1e-4 mm and 1e-4°.
pub const GCODE_DECIMALS: usize = 4;

/// Decimals of a tool-axis vector's components (Sinumerik `A3= B3= C3=`).
pub const GCODE_VECTOR_DECIMALS: usize = 7;

/// The smallest vertical component of a tool axis that the safe moves retract along: a tool
/// axis within about 5.7° of horizontal cannot be retracted along itself to a safe height.
pub const MIN_RETRACT_COS: f64 = 0.1;

/// Most distinct unwrappings (multiples of 360°) of one limited rotary axis the inverse
/// kinematics considers per pose.
pub const MAX_AXIS_TURNS: usize = 8;

/// The largest coordinate (mm, degrees, feed) a machine description or post option accepts.
pub const MAX_MACHINE_VALUE: f64 = 1e7;

/// Degrees a tilting axis may swing beyond the tool axis's turn (and twice the pole cone) in one
/// block before the block is a flip of the rotary axes (`flip`).
pub const FLIP_MARGIN: f64 = 0.01;

/// The fairness weight λ of the pose optimisation's energy (`optimise`, (1)) by default: the
/// second differences of the poses' tips and axis ends weigh λ times as much as the squared
/// deviations of the target points nearest them.
pub const OPTIMISE_FAIRNESS: f64 = 0.01;

/// Most rounds of the pose optimisation by default (`optimise`).
pub const OPTIMISE_ROUNDS: usize = 40;

/// Most rounds of the pose optimisation accepted.
pub const MAX_OPTIMISE_ROUNDS: usize = 1000;

/// The pose optimisation stops when a step lowers its energy by less than this share of it.
pub const OPTIMISE_STOP: f64 = 1e-4;

/// The pose optimisation stops when its energy falls below this share of where it began: the
/// poses then fit the target to the rounding of their lengths.
pub const OPTIMISE_FLOOR: f64 = 1e-16;

/// The pose optimisation stops when its damping μ grows beyond this (its steps are then a
/// ten-thousandth of Gauss–Newton's, and none lowered the energy).
pub const OPTIMISE_MAX_DAMPING: f64 = 1e4;

/// The least damping μ of the pose optimisation.
pub const OPTIMISE_LEAST_DAMPING: f64 = 1e-9;

/// The damping μ the pose optimisation starts with (`optimise`).
pub const OPTIMISE_DAMPING: f64 = 1e-3;

/// The pose optimisation's τ, as a share of the mean diagonal of its normal equations: it keeps
/// the unknowns no target point reaches (a pose's slide along its own axis) determined.
pub const OPTIMISE_TAU: f64 = 1e-9;

/// The step of the central differences that give the gradient of a point's distance from the
/// tool in the pose optimisation, as a share of the tool's radius.
pub const OPTIMISE_GRADIENT_STEP: f64 = 1e-6;
