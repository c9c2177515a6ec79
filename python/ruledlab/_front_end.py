"""Whether a front end holds a view: what ``View.wait()`` and the figures need, and what a notebook
run headless (``jupyter nbconvert --execute``, papermill, a batch job) does not have.

A widget front end (JupyterLab, Jupyter Notebook, VS Code, Colab, marimo) creates each view's
model when the kernel opens it, and the widget's module then says hello (``widget.js``'s
``initialize``), before anything is drawn. Without a front end nobody does: the kernel's
messages go nowhere. So a view that has heard no hello ``GRACE`` seconds after it was made has no
front end — unless one has spoken for another view of this kernel, when it is given up to
``TIMEOUT`` (the front end is there, busy). Computations never wait for a view: they are the core's
(``ruledlab.RuledSurface`` …); only what the view itself does (what it shows, its figures, what the
reader did) needs one.
"""

from __future__ import annotations

import asyncio
import time

from ._errors import RuledlabError

#: how long a figure or a view's outcome is waited for, once a front end holds the view
TIMEOUT = 30.0

#: how long after a view is made its front end has to say hello before the view counts as headless
GRACE = 3.0

#: whether a front end has spoken for any view of this kernel
_any_front_end = False


class FrontEnd:
    """What is known of the front end of one view: whether one said hello, whether the view was
    displayed (its output published), when it was made."""

    def __init__(self) -> None:
        self.made = time.monotonic()
        self.spoke = False
        self.displayed = False

    def heard(self) -> None:
        """A message from the view's front end arrived."""
        global _any_front_end
        self.spoke = True
        _any_front_end = True

    async def present(self, grace: float | None = None) -> bool:
        """Whether a front end holds the view: at once if one has spoken, else after waiting until
        ``grace`` seconds after the view was made (``GRACE``; ``TIMEOUT`` when a front end has
        spoken for another view) for its hello. The kernel handles the front end's messages while
        this waits."""
        if grace is None:
            grace = TIMEOUT if _any_front_end else GRACE
        deadline = self.made + grace
        while not self.spoke and time.monotonic() < deadline:
            await asyncio.sleep(0.02)
        return self.spoke

    async def needed(self, what: str) -> None:
        """Raises RuledlabError unless a front end holds the view and it is displayed: ``no-view``
        (a notebook run headless: nothing draws it), ``not-displayed`` (made but never shown)."""
        if not await self.present():
            raise RuledlabError(
                f"ruledlab: no front end shows this view (a notebook run headless, by nbconvert or "
                f"papermill, or a kernel without a notebook), so there is no {what}; computations "
                "need no view: ruledlab.RuledSurface and the other classes compute in Python",
                "no-view",
                {"reason": "no-view"},
            )
        if not self.displayed:
            raise RuledlabError(
                f"ruledlab: the view is not displayed, so there is no {what}: show it first (the last "
                "line of a cell, or display(view))",
                "not-displayed",
                {"reason": "not-displayed"},
            )


def no_answer(what: str, timeout: float) -> RuledlabError:
    """The error of a view that did not answer in `timeout` seconds (its front end gone or busy)."""
    return RuledlabError(
        f"ruledlab: no {what} from the view in {timeout:g} s: is its output still shown (the notebook "
        "open, the cell not cleared)?",
        "no-answer",
        {"reason": "no-answer", "limit": timeout},
    )
