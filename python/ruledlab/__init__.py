"""ruledlab in Python: discrete ruled surfaces and line congruences (Odehnal & Pottmann).

Two parts in one package:

- **the core** (``ruledlab._core``, compiled from the Rust workspace): the invariants of
  Section 2, the isometries and development of Section 3, the curve and strip schemes of
  Section 4, congruences and their schemes (Section 5), focal geometry, linear complexes,
  subdivision in the space of lines, formulas, and five-axis tool paths with their G-code posts —
  the computations of the JavaScript API on NumPy float64 arrays, headless (no view, no browser),
  the GIL released while they run, every error a ``RuledlabError`` with the core's ``code``;
- **the view** (``View``): a scene of ruledlab in a notebook as an anywidget, the ``<ruled-view>``
  element with the WebAssembly core inlined and carried by this package, so nothing is fetched
  from a network.

>>> import numpy as np
>>> import ruledlab
>>> u = np.linspace(0, 2 * np.pi, 24, endpoint=False)
>>> a = np.stack([np.cos(u), np.sin(u), -np.ones_like(u)], axis=1)
>>> b = np.stack([np.cos(u + 1), np.sin(u + 1), np.ones_like(u)], axis=1)
>>> surface = ruledlab.RuledSurface.from_segments(a, b)
>>> inv = surface.invariants()
>>> inv["striction"].shape
(22, 3)
>>> view = ruledlab.View.from_segments(a, b)
>>> view.scene
'data'
"""

from typing import TYPE_CHECKING

from ._core import (
    AnalyticCongruence,
    AnalyticSurface,
    LineCongruence,
    RuledSurface,
    ToolPath,
    detect_import,
    evaluate_formulas,
    fit_line,
    import_segments,
    import_target,
    import_tool_poses,
    linear_complex,
    subdivide_polygon,
    turning_angles,
)
from ._errors import RuledlabError
from ._figure import Figure
from ._view import View

if TYPE_CHECKING:  # the result types exist in the stubs only (the core returns plain dicts)
    from ._core import CongruenceErrors as CongruenceErrors
    from ._core import ConvergenceStudy as ConvergenceStudy
    from ._core import FocalGeometry as FocalGeometry
    from ._core import FocalSheet as FocalSheet
    from ._core import ImportedPoses as ImportedPoses
    from ._core import ImportedSegments as ImportedSegments
    from ._core import ImportedTarget as ImportedTarget
    from ._core import Invariants as Invariants
    from ._core import LinearComplexFit as LinearComplexFit
    from ._core import LineFit as LineFit
    from ._core import Mesh as Mesh
    from ._core import PathQuality as PathQuality
    from ._core import PostResult as PostResult
    from ._core import SamplingErrors as SamplingErrors
    from ._core import SamplingOrders as SamplingOrders
    from ._core import Tool as Tool


__version__ = "0.1.0"
__all__ = [
    "AnalyticCongruence",
    "AnalyticSurface",
    "Figure",
    "LineCongruence",
    "RuledSurface",
    "RuledlabError",
    "ToolPath",
    "View",
    "__version__",
    "detect_import",
    "evaluate_formulas",
    "fit_line",
    "import_segments",
    "import_target",
    "import_tool_poses",
    "linear_complex",
    "subdivide_polygon",
    "turning_angles",
]
