"""ruledlab in notebooks: discrete ruled surfaces and line congruences (Odehnal & Pottmann).

``View`` shows a scene of ruledlab in a notebook (JupyterLab, Jupyter Notebook, VS Code, Colab,
marimo) as an anywidget: the ``<ruled-view>`` element of the one-file build, with the
WebAssembly core inlined and carried by this package, so nothing is fetched from a network.

>>> import numpy as np
>>> from ruledlab import View
>>> u = np.linspace(0, 2 * np.pi, 24, endpoint=False)
>>> a = np.stack([np.cos(u), np.sin(u), -np.ones_like(u)], axis=1)
>>> b = np.stack([np.cos(u + 1), np.sin(u + 1), np.ones_like(u)], axis=1)
>>> view = View.from_segments(a, b)
>>> view.scene
'data'
"""

from ._errors import RuledlabError
from ._figure import Figure
from ._view import View

__version__ = "0.1.0"
__all__ = ["Figure", "RuledlabError", "View", "__version__"]
