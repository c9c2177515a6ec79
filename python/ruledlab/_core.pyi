"""Type stubs of ``ruledlab._core``, the compiled core (crates/ruledlab-py): the geometry of
Odehnal & Pottmann and the CAM of ruledlab on NumPy arrays. Import it as ``ruledlab``.

Arrays in are anything NumPy reads as real numbers (``ArrayLike``; float64 in C order is read
without a copy, complex, strings, booleans and objects are refused); arrays out are float64 (bool,
uint8, uint32 where said), one row per record.
"""

import builtins
from typing import Any, Callable, Literal, Optional, Sequence, TypedDict, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray
from typing_extensions import NotRequired, Unpack

F64 = NDArray[np.float64]
Bound = Union[float, str]
Scheme = Literal["chaikin", "bspline", "bezier", "four-point", "variational"]
CurveScheme = Literal["chaikin", "bspline", "bezier", "four-point"]
DecimalComma = Union[bool, Literal["unambiguous"]]

__version__: str

def version() -> str: ...

# --- results

class Invariants(TypedDict):
    """The discrete invariants of Section 2; P pairs, M interior rulings."""

    angle: F64  # (P,) φ ∈ [0, π]
    distance: F64  # (P,) signed h
    distribution: F64  # (P,) δ = h/φ (1)
    footpoints: F64  # (P, 6) f_{i,i+1} then f_{i+1,i}
    central_normal: F64  # (P, 3)
    striction: F64  # (M, 3) (7)
    distribution_mean: F64  # (M,) (7)
    perpendicular_midpoints: F64  # (P, 3)
    parallel: NDArray[np.bool_]  # (P,)

class LinearComplexFit(TypedDict):
    plucker: F64
    pitch: float
    axis_point: F64
    axis_direction: F64
    axis_segment: F64
    residual: float
    spectrum: F64
    nullity: int
    kind: Literal["general", "complex", "congruence", "regulus", "special"]

class FocalGeometry(TypedDict):
    rows: int
    cols: int
    points: F64  # (rows, cols, 6)
    parameters: F64  # (rows, cols, 2)
    kind: NDArray[np.uint8]  # (rows, cols): 0 elliptic, 1 hyperbolic, 2 parabolic
    torsal: F64  # (rows, cols, 4)
    middle: F64  # (rows, cols, 3)
    normality: F64  # (rows, cols)

class Mesh(TypedDict):
    positions: F64  # (V, 3)
    indices: NDArray[np.uint32]  # (T, 3)

class FocalSheet(Mesh):
    normals: F64
    min: F64
    max: F64

class LineFit(TypedDict):
    point: F64
    direction: F64
    deviation: float
    extent: float

class ImportedSegments(TypedDict):
    segments: F64  # (N, 6)
    rows: NotRequired[int]
    cols: NotRequired[int]

class CatalogueEntry(TypedDict):
    """What ``AnalyticSurface.list()`` and ``AnalyticCongruence.list()`` say of every entry."""

    name: str
    title: str
    u_min: float
    u_max: float
    v_min: float
    v_max: float

class SurfaceInfo(CatalogueEntry):
    closed: bool

class Ranges(TypedDict, total=False):
    """The sampling ranges of ``AnalyticSurface.sample`` and its kin, the surface's own where left
    out (or None)."""

    u_min: Optional[float]
    u_max: Optional[float]
    v_min: Optional[float]
    v_max: Optional[float]
    closed: Optional[bool]

class CurveOptions(TypedDict, total=False):
    """The keywords of ``subdivide_polygon`` and ``turning_angles`` besides ``scheme`` (None: the
    default)."""

    steps: Optional[int]
    w: Optional[float]
    degree: Optional[int]
    closed: Optional[bool]

class FormulaParameters(TypedDict, total=False):
    a: float
    b: float
    c: float

class SurfacePreset(TypedDict):
    name: str
    a: list[str]
    e: list[str]
    u: list[str]
    v: list[str]
    closed: bool
    parameters: FormulaParameters

class CongruenceInfo(CatalogueEntry):
    rows: int
    cols: int

class CongruencePreset(TypedDict):
    name: str
    p: list[str]
    e: list[str]
    u: list[str]
    v: list[str]
    rows: int
    cols: int
    parameters: FormulaParameters
    reach: float

class SamplingErrors(TypedDict):
    rulings: int
    parallel_pairs: int
    footpoint: float
    midpoint: float
    perpendicular_midpoint: float
    distribution_mean: float

class SamplingOrders(TypedDict):
    finer: int
    footpoint: float
    midpoint: float
    perpendicular_midpoint: float
    distribution_mean: float

class ConvergenceSeries(TypedDict):
    name: str
    expected_order: float
    errors: list[float]
    orders: list[float]
    fitted_order: float

class ConvergenceStudy(TypedDict):
    surface: str
    u: float
    steps: list[float]
    series: list[ConvergenceSeries]

class CongruenceErrors(TypedDict):
    distance: float
    angle: float

class Tool(TypedDict):
    radius: float
    length: float
    end: NotRequired[Literal["ball", "flat"]]

class PathQuality(TypedDict):
    angle_step: F64
    second_difference: F64
    max_angle_step: float
    max_second_difference: float

class EnvelopeResult(TypedDict):
    points: F64
    at: F64
    per_pose: F64
    worst: int
    worst_deviation: float
    worst_point: F64

class Deviation(TypedDict):
    tip: float
    axis: float

class PostWarning(TypedDict):
    pose: int
    line: NotRequired[int]
    reason: str
    args: dict[str, Union[str, float]]
    message: str

class PostDeviation(TypedDict):
    """The target's deviation from the sweep of the program as posted, program units."""

    gouge: float
    leave: float
    rms: float
    at: F64  # (3,)
    largest: float
    worst: int
    pose: float
    points: F64  # (M,)

class PostResult(TypedDict):
    text: str
    poses: int
    inserted: int
    tolerance: float
    before: Deviation
    after: Deviation
    block_tip: F64
    block_axis: F64
    origin: F64
    units: Literal["mm", "inch"]
    letters: list[str]
    axes: F64  # (P, 5)
    block_minutes: F64
    block_feed: F64
    block_rotary_speed: F64  # (B, 2)
    block_limit: NDArray[np.uint8]
    over_acceleration: int
    unwinds: list[int]
    adjusted: F64
    warnings: list[PostWarning]
    stock: list[list[float]]
    deviation: NotRequired[PostDeviation]

class Holder(TypedDict):
    radius: float
    length: float

class InputNumbering(TypedDict):
    stride: int
    lines: NotRequired[Sequence[int]]

class ImportedPoses(TypedDict):
    tips: F64
    axes: F64
    lines: NDArray[np.uint64]
    tool: NotRequired[Tool]
    units: NotRequired[Literal["mm", "inch"]]
    machine: NotRequired[str]

class ImportedTarget(TypedDict):
    points: F64
    units: NotRequired[Literal["mm", "inch"]]

MachineName = Literal["table-table-ac", "table-table-bc", "head-table-bc", "head-head-ac"]

class PostOptions(TypedDict, total=False):
    """The options of a program (``ToolPath.export("gcode", …)``, ``ToolPath.post``), each
    optional (None: the default); ``target``, the part's points (M, 3) in model units, adds the
    deviation of the program as posted to the result and the header."""

    dialect: Optional[Literal["linuxcnc", "heidenhain", "sinumerik"]]
    mode: Optional[Literal["machine", "tcp"]]
    machine: Union[MachineName, dict[str, Any], None]
    units: Optional[Literal["mm", "inch"]]
    feed: Optional[float]
    approach_feed: Optional[float]
    scale: Optional[float]
    tool: Optional[int]
    spindle: Optional[float]
    direction: Optional[Literal["cw", "ccw"]]
    coolant: Optional[Literal["flood", "mist", "off"]]
    work_offset: Optional[int]
    safe_height: Optional[float]
    clearance: Optional[float]
    tolerance: Optional[float]
    angular_tolerance: Optional[float]
    gauge: Optional[float]
    holder: Optional[Holder]
    shank: Optional[float]
    stock: Optional[ArrayLike]
    pole_cone: Optional[float]
    input: Optional[InputNumbering]
    name: Optional[str]
    target: Optional[ArrayLike]

# --- classes

class RuledSurface:
    """A discrete ruled surface: N ≥ 2 rulings a_i → b_i (Section 2)."""

    def __init__(self, segments: ArrayLike) -> None: ...
    @staticmethod
    def from_segments(a: ArrayLike, b: ArrayLike) -> RuledSurface: ...
    def __len__(self) -> int: ...
    def segments(self) -> F64: ...
    def directions(self) -> F64: ...
    def mean_length(self) -> float: ...
    def slide(self, amounts: ArrayLike) -> RuledSurface: ...
    def invariants(self, *, closed: Optional[bool] = None) -> Invariants: ...
    def max_edge_change(self, other: RuledSurface) -> float: ...
    def max_angle_to(self, other: RuledSurface) -> float: ...
    def hinge_angles(self) -> F64: ...
    def hinge(self, angles: ArrayLike) -> RuledSurface: ...
    def conoidal(self) -> RuledSurface: ...
    def bend(self, t: float) -> RuledSurface: ...
    def development(self) -> F64: ...
    def non_developability(self) -> float: ...
    def envelope_radii(self) -> F64: ...
    def reference_frame(self) -> F64: ...
    def development_in_space(self) -> F64: ...
    def development_striction(self) -> F64: ...
    def development_striction_in_space(self) -> F64: ...
    def development_envelope(self) -> F64: ...
    def development_envelope_in_space(self) -> F64: ...
    def subdivide(
        self,
        *,
        scheme: Scheme,
        steps: Optional[int] = None,
        w: Optional[float] = None,
        n: Optional[int] = None,
        variant: Optional[Literal["coupled", "literal", "averaged"]] = None,
        degree: Optional[int] = None,
        closed: Optional[bool] = None,
        space: Optional[Literal["points", "lines"]] = None,
        length: Optional[float] = None,
    ) -> RuledSurface: ...
    def recut(self, length: Optional[float] = None) -> RuledSurface: ...
    def division_point(self, i: int, k: int, n: int) -> F64: ...
    def triangulation(self, n: int, which: Literal[1, 2]) -> F64: ...
    def inserted(self, stride: int) -> F64: ...
    def linear_complex(self, *, tolerance: Optional[float] = None) -> LinearComplexFit: ...
    def export(
        self,
        format: Literal["csv", "json", "obj", "invariants-csv", "invariants-json"],
        *,
        name: Optional[str] = None,
    ) -> str: ...

class AnalyticSurface:
    """An analytic ruled surface x(u, v) = a(u) + v·d(u) with its exact invariants."""

    # (the catalogue's methods, list to title, as AnalyticCongruence's: two classes, one interface)
    @staticmethod
    def list() -> list[SurfaceInfo]: ...
    @staticmethod
    def by_name(name: str) -> AnalyticSurface: ...
    @staticmethod
    def formula_presets() -> builtins.list[SurfacePreset]: ...
    @staticmethod
    def from_formulas(
        a: Sequence[str],
        e: Sequence[str],
        u: Sequence[Bound],
        *,
        v: Optional[Sequence[Bound]] = None,
        closed: Optional[bool] = None,
        parameters: Optional[FormulaParameters] = None,
        decimal_comma: Optional[DecimalComma] = None,
    ) -> AnalyticSurface: ...
    @property
    def name(self) -> str: ...
    @property
    def title(self) -> str: ...
    def sample(
        self,
        count: int,
        **ranges: Unpack[Ranges],
    ) -> RuledSurface: ...
    def parameters(
        self,
        count: int,
        **ranges: Unpack[Ranges],
    ) -> F64: ...
    def striction(self, u: ArrayLike) -> F64: ...
    def distribution(self, u: ArrayLike) -> F64: ...
    def central_tangent(self, u: ArrayLike) -> F64: ...
    def distances(self, points: ArrayLike, u_min: float, u_max: float) -> F64: ...
    def inserted_distance(self, refined: RuledSurface, stride: int, u_min: float, u_max: float) -> float: ...
    def sampling_errors(
        self,
        count: int,
        **ranges: Unpack[Ranges],
    ) -> SamplingErrors: ...
    def sampling_orders(
        self,
        count: int,
        **ranges: Unpack[Ranges],
    ) -> SamplingOrders: ...
    def convergence(
        self, *, u: Optional[float] = None, h0: Optional[float] = None, levels: Optional[int] = None
    ) -> ConvergenceStudy: ...

class LineCongruence:
    """A discrete line congruence: a rows × cols grid of lines (Section 5)."""

    def __init__(self, lines: ArrayLike) -> None: ...
    @staticmethod
    def from_grid(p: ArrayLike, q: ArrayLike) -> LineCongruence: ...
    @property
    def rows(self) -> int: ...
    @property
    def cols(self) -> int: ...
    def segments(self) -> F64: ...
    def row(self, i: int) -> RuledSurface: ...
    def column(self, j: int) -> RuledSurface: ...
    def subdivide(
        self,
        *,
        scheme: Literal["butterfly", "variational"],
        steps: Optional[int] = None,
        w: Optional[float] = None,
        diagonal_only: Optional[bool] = None,
        K: Optional[int] = None,
        variant: Optional[Literal["coupled", "two-stage", "paper"]] = None,
        space: Optional[Literal["points", "lines"]] = None,
        length: Optional[float] = None,
    ) -> LineCongruence: ...
    def focal(self) -> FocalGeometry: ...
    def focal_sheet(self, sheet: Literal[1, 2]) -> FocalSheet: ...
    def torsal_strokes(self, scale: Optional[float] = None) -> F64: ...
    def inserted(self, stride: int) -> F64: ...
    def linear_complex(self, *, tolerance: Optional[float] = None) -> LinearComplexFit: ...
    def export(self, format: Literal["csv", "json", "obj"], *, name: Optional[str] = None) -> str: ...

class AnalyticCongruence:
    """An analytic line congruence p(u, v) + t·d(u, v) (Examples 4 and 5)."""

    @staticmethod
    def list() -> list[CongruenceInfo]: ...
    @staticmethod
    def by_name(name: str) -> AnalyticCongruence: ...
    @staticmethod
    def formula_presets() -> builtins.list[CongruencePreset]: ...
    @staticmethod
    def from_formulas(
        p: Sequence[str],
        e: Sequence[str],
        u: Sequence[Bound],
        v: Sequence[Bound],
        *,
        parameters: Optional[FormulaParameters] = None,
        rows: Optional[int] = None,
        cols: Optional[int] = None,
        decimal_comma: Optional[DecimalComma] = None,
    ) -> AnalyticCongruence: ...
    @property
    def name(self) -> str: ...
    @property
    def title(self) -> str: ...
    def grid(
        self, rows: Optional[int] = None, cols: Optional[int] = None, *, reach: Optional[float] = None
    ) -> LineCongruence: ...
    def errors(self, refined: LineCongruence) -> CongruenceErrors: ...
    def diagonal_errors(self, diagonal: LineCongruence) -> CongruenceErrors: ...
    def focal(self, rows: Optional[int] = None, cols: Optional[int] = None) -> FocalGeometry: ...

class ToolPath:
    """A five-axis tool path: tool tips and unit axes, and the tool (Example 6)."""

    @staticmethod
    def from_segments(tips: ArrayLike, ends: ArrayLike, tool: Tool) -> ToolPath: ...
    @staticmethod
    def from_poses(tips: ArrayLike, axes: ArrayLike, tool: Tool) -> ToolPath: ...
    @staticmethod
    def example(count: Optional[int] = None, tool: Optional[Tool] = None) -> ToolPath: ...
    @staticmethod
    def example_profile(count: int) -> F64: ...
    @staticmethod
    def example_part(nx: int, ny: int) -> Mesh: ...
    @staticmethod
    def machine(name: MachineName) -> dict[str, Any]: ...
    def __len__(self) -> int: ...
    @property
    def tool(self) -> Tool: ...
    def tips(self) -> F64: ...
    def axes(self) -> F64: ...
    def segments(self) -> F64: ...
    def barycentres(self) -> F64: ...
    def cutting_centres(self) -> F64: ...
    def refine(
        self,
        *,
        scheme: Optional[Scheme] = None,
        steps: Optional[int] = None,
        w: Optional[float] = None,
        n: Optional[int] = None,
        variant: Optional[Literal["coupled", "literal", "averaged"]] = None,
        degree: Optional[int] = None,
    ) -> ToolPath: ...
    def quality(self) -> PathQuality: ...
    def deviation(self, targets: ArrayLike) -> F64: ...
    def deviation_per_pose(self, targets: ArrayLike) -> F64: ...
    def envelope_deviation(self, targets: ArrayLike) -> EnvelopeResult: ...
    def envelope_mesh(self, sides: int) -> Mesh: ...
    def tool_mesh(self, index: int, sides: int) -> Optional[Mesh]: ...
    def inserted(self, stride: int) -> F64: ...
    def export(
        self,
        format: Literal["json", "csv", "gcode"],
        **options: Unpack[PostOptions],
    ) -> str: ...
    def post(
        self,
        *,
        on_progress: Optional[Callable[[float], object]] = None,
        **options: Unpack[PostOptions],
    ) -> PostResult: ...

# --- free functions

def linear_complex(a: ArrayLike, b: ArrayLike, *, tolerance: Optional[float] = None) -> LinearComplexFit: ...
def subdivide_polygon(points: ArrayLike, *, scheme: CurveScheme, **options: Unpack[CurveOptions]) -> F64: ...
def turning_angles(points: ArrayLike, *, scheme: CurveScheme, **options: Unpack[CurveOptions]) -> F64: ...
def fit_line(points: ArrayLike) -> LineFit: ...
def import_segments(text: str, format: Optional[Literal["csv", "json"]] = None) -> ImportedSegments: ...
def detect_import(text: str) -> Literal["poses", "target", "segments"]: ...
def evaluate_formulas(
    formulas: Sequence[str],
    at: ArrayLike,
    *,
    variable: Optional[Literal["u", "v", "t"]] = None,
    name: Optional[str] = None,
    parameters: Optional[FormulaParameters] = None,
    decimal_comma: Optional[DecimalComma] = None,
) -> F64: ...
def import_tool_poses(
    text: str, format: Optional[Literal["csv", "json"]] = None, *, machine: Optional[MachineName] = None
) -> ImportedPoses: ...
def import_target(text: str, format: Optional[Literal["csv", "json"]] = None) -> ImportedTarget: ...
