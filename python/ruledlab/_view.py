"""``View``: a scene of ruledlab in a notebook, as an anywidget showing ``<ruled-view>``."""

from __future__ import annotations

import asyncio
import concurrent.futures
import itertools
import numbers
from pathlib import Path
from typing import Any, Callable

import anywidget
import traitlets as t

from . import _data, _still
from ._errors import RuledlabError
from ._figure import Figure
from ._front_end import TIMEOUT, FrontEnd, no_answer
from ._script import script_gzip

#: the traits whose change from Python the view applies and answers with an outcome
APPLIED = (
    "scene",
    "paper",
    "params",
    "camera",
    "lang",
    "controls",
    "text",
    "editable",
    "autoplay",
    "height",
    "task",
    "_source",
    "data",
)

#: the traits the view reports (what the reader did, what it shows)
VIEWED = ("scene", "params", "readouts", "camera", "data")

_ids = itertools.count(1)


class View(anywidget.AnyWidget):
    """One scene of ruledlab, shown where the view is displayed (its last line of a cell, or
    ``display(view)``) and followed both ways: what Python sets is drawn, what the reader does
    comes back.

    ``View(scene=…, params=…, paper=…, camera=…, lang=…, controls=True, height=…, task=…,
    editable=…, text=…, autoplay=…)`` takes what ``<ruled-view>``'s attributes take (the book's
    "<ruled-view>"); ``View.from_segments(a, b)`` and ``View.from_grid(p, q)`` show your own rulings
    or congruence from NumPy arrays, sent as binary buffers.

    Traits: ``params`` (set the ones you name; the reader's sliders update it), ``data`` (the
    scene's input per handle set, an (n, 3) array each; a dragged handle updates it, and setting
    it moves the handles), ``readouts`` (the numbers the view shows, after every computation),
    ``camera``, ``scene``. A change from Python is drawn once the view has it; ``await
    view.wait()`` waits for that and raises :class:`RuledlabError` (the core's ``code`` and
    message) when it failed — the view keeps working, showing the last picture and the error.
    """

    _esm = Path(__file__).with_name("widget.js")

    scene = t.Unicode("", help="the scene's id (the first scene if empty)").tag(sync=True)
    paper = t.Unicode("", help="a figure or example of the paper: fig1 … fig18, ex1 … ex6").tag(sync=True)
    params = t.Dict(help="the scene's parameters, by key").tag(sync=True)
    camera = t.Unicode("", help="yaw, pitch, distance, target x, y, z (the page's cam value)").tag(sync=True)
    lang = t.Unicode("", help="'en' or 'de' (default: the page's)").tag(sync=True)
    controls = t.Bool(True, help="show the scene's sliders, menus and readouts").tag(sync=True)
    text = t.Bool(False, help="show the scene's explanation").tag(sync=True)
    editable = t.Bool(False, help="the reader may drag the scene's handles").tag(sync=True)
    autoplay = t.Bool(False, help="play the first playable parameter").tag(sync=True)
    height = t.Unicode("480", help="the view's height: CSS pixels or a CSS length").tag(sync=True)
    task = t.Unicode("", help="an exercise: a built-in one's id or the page's 'j.' value").tag(sync=True)
    readouts: t.List[Any] = t.List(help="the numbers the view shows: {key, label, value} each (read only)").tag(sync=True)
    data = t.Dict(help="the scene's input: an (n, 3) array per handle set").tag(
        sync=True, to_json=_data.input_to_json, from_json=_data.input_from_json, echo_update=False
    )
    _source = t.Dict(allow_none=True, default_value=None).tag(
        sync=True, to_json=_data.source_to_json, from_json=_data.source_from_json
    )
    _rev = t.Int(0).tag(sync=True)

    #: the last error the view reported (None once a change of Python's is shown without one)
    error: RuledlabError | None = None

    def __init__(self, **kwargs: Any) -> None:
        self._from_view = False
        self._shown_rev = -1
        self._outcome: list[dict[str, Any]] = []
        self._waiters: list[tuple[int, concurrent.futures.Future[None]]] = []
        self._figures: dict[str, Figure] = {}
        self._on_check: list[Callable[[dict[str, Any]], Any]] = []
        self._on_error: list[Callable[[RuledlabError], Any]] = []
        self._front = FrontEnd()
        self._stills: list[Any] = []
        self._still_png: bytes | None = None
        self.error = None
        super().__init__(**kwargs)
        self.on_msg(self._message)

    # --- making views of your data

    @classmethod
    def from_segments(cls, a: Any, b: Any, **kwargs: Any) -> View:
        """Your rulings, from ``a[i]`` to ``b[i]`` (N × 3 arrays): the "data" scene with its
        invariants, striction points and strip."""
        return cls(scene="data", _source=_data.segments(a, b), **kwargs)

    @classmethod
    def from_grid(cls, p: Any, q: Any, **kwargs: Any) -> View:
        """Your congruence: the line through ``p[i, j]`` and ``q[i, j]`` (rows × cols × 3 arrays)
        at each grid point, in the "data" scene (its focal geometry with ``params={'focal': True}``)."""
        return cls(scene="data", _source=_data.grid(p, q), **kwargs)

    def set_segments(self, a: Any, b: Any) -> None:
        """Shows other rulings (N × 3 arrays ``a`` and ``b``) in this view; what the core refuses
        raises RuledlabError at once, and the view keeps what it shows."""
        self._source = _data.segments(a, b, "View.set_segments")

    def set_grid(self, p: Any, q: Any) -> None:
        """Shows another congruence (rows × cols × 3 arrays ``p`` and ``q``) in this view; what the
        core refuses raises RuledlabError at once."""
        self._source = _data.grid(p, q, "View.set_grid")

    # --- checks of what Python sets

    @t.validate("params")
    def _valid_params(self, proposal: dict[str, Any]) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for key, value in proposal["value"].items():
            if isinstance(value, (bool, str)):
                out[str(key)] = value
            elif hasattr(value, "item") and not isinstance(value, (list, tuple)):
                out[str(key)] = value.item()  # a NumPy scalar
            elif isinstance(value, numbers.Real):
                out[str(key)] = float(value) if not isinstance(value, numbers.Integral) else int(value)
            else:
                raise RuledlabError(
                    f"the value of parameter {key!r} must be a number, a string or a bool, not {type(value).__name__}",
                    "invalid-argument",
                    {"option": "params", "param": str(key)},
                )
        return out

    @t.validate("data")
    def _valid_data(self, proposal: dict[str, Any]) -> dict[str, Any]:
        return proposal["value"] if self._from_view else _data.check_input(proposal["value"])

    def __setattr__(self, name: str, value: Any) -> None:
        # a tuple camera (yaw, pitch, distance, x, y, z) or a number height, as the element writes them
        if name == "camera" and isinstance(value, (list, tuple)):
            value = ",".join(f"{float(x):g}" for x in value)
        if name == "height" and isinstance(value, numbers.Real) and not isinstance(value, bool):
            value = f"{float(value):g}"
        super().__setattr__(name, value)

    # --- both ways: a change of Python's is a revision the view answers

    def set_state(self, sync_data: dict[str, Any]) -> None:
        """(ipywidgets) Takes the state the view sends: not a change of Python's."""
        self._from_view = True
        try:
            super().set_state(sync_data)
        finally:
            self._from_view = False

    def notify_change(self, change: Any) -> None:
        if change["name"] in APPLIED and not self._from_view and change["type"] == "change":
            # the trait and its revision go in one message
            with self.hold_sync():
                super().notify_change(change)
                self._rev += 1
            return
        super().notify_change(change)

    def _message(self, _widget: Any, content: dict[str, Any], buffers: list[Any]) -> None:
        kind = content.get("kind") if isinstance(content, dict) else None
        self._front.heard()
        if kind in ("shown", "state", "embed"):
            self._front.displayed = True  # (a front end that draws it displayed it, also where the kernel cannot tell)
        if kind == "hello":
            return
        if kind == "embed":
            self.send({"kind": "embed"}, buffers=[script_gzip()])
        elif kind == "state" and isinstance(content.get("state"), dict):
            state = {k: v for k, v in content["state"].items() if k in VIEWED}
            if isinstance(content.get("input"), list):
                state["data"] = dict(zip(content["input"], buffers))
            self.set_state(state)
        elif kind == "shown":
            self._shown_rev = max(self._shown_rev, int(content.get("rev", 0)))
            self._outcome = [e for e in content.get("errors") or [] if isinstance(e, dict)]
            self.error = RuledlabError.from_detail(self._outcome[-1]) if self._outcome else None
            for detail in self._outcome:
                self._said(RuledlabError.from_detail(detail))
            waiting = [(rev, f) for rev, f in self._waiters if rev <= self._shown_rev]
            self._waiters = [(rev, f) for rev, f in self._waiters if rev > self._shown_rev]
            for _, future in waiting:
                if not future.done():
                    future.set_result(None)
        elif kind == "error" and isinstance(content.get("error"), dict):
            self.error = RuledlabError.from_detail(content["error"])
            self._said(self.error)
        elif kind == "export":
            figure = self._figures.get(str(content.get("id")))
            if figure is not None:
                figure._resolve(content, buffers)
                if figure.done():
                    self._figures.pop(str(content.get("id")), None)
        elif kind == "still" and buffers:
            self._show_still(bytes(buffers[0]))
        elif kind == "task" and isinstance(content.get("report"), dict):
            report = {**content["report"], "event": content.get("type", "check")}
            for fn in list(self._on_check):
                fn(report)

    def _said(self, error: RuledlabError) -> None:
        for fn in list(self._on_error):
            fn(error)

    async def wait(self, timeout: float = TIMEOUT) -> View:
        """Waits until the view shows everything Python has set (``await view.wait()``) and
        returns the view; raises RuledlabError with the core's ``code`` and message when that
        failed (the view keeps the last picture and works on). It is for views only: where no
        front end holds the view (a notebook run headless) there is nothing to wait for, and it
        returns at once (``await view.has_front_end()`` tells); a view never displayed raises
        ``not-displayed``, one whose front end does not answer in ``timeout`` s ``no-answer``."""
        target = self._rev
        if self._shown_rev < target:
            if not await self._front.present():
                return self
            await self._front.needed("picture to wait for")
            future: concurrent.futures.Future[None] = concurrent.futures.Future()
            self._waiters.append((target, future))
            try:
                await asyncio.wait_for(asyncio.wrap_future(future), timeout)
            except asyncio.TimeoutError:
                raise no_answer("answer", timeout) from None
        if self._outcome:
            raise RuledlabError.from_detail(self._outcome[0])
        return self

    async def has_front_end(self, timeout: float | None = None) -> bool:
        """Whether a front end (JupyterLab, Jupyter Notebook, VS Code, …) holds this view, so that
        it draws, answers ``wait()``, makes figures and reports what the reader does: False in a
        notebook run headless (nbconvert, papermill). Found at once once the front end has said
        hello, else by waiting for it until ``timeout`` seconds after the view was made (default
        GRACE, 3 s; 30 s when a front end has spoken for another view of this kernel)."""
        return await self._front.present(timeout)

    def __repr__(self) -> str:
        return f"<{self._describe()}>"

    def _describe(self) -> str:
        return _still.describe(self.scene, dict(self.params), self._source, self.task, self.paper)

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        self._front.displayed = True
        bundle = super()._repr_mimebundle_(**kwargs)
        data = bundle[0] if isinstance(bundle, tuple) else bundle
        if isinstance(data, dict):
            data["text/plain"] = self._describe()
        return bundle

    def _ipython_display_(self) -> None:
        """Displays the view and, below it, its still (``_still``): what a notebook saved, or
        converted to HTML, shows of it without a kernel."""
        from IPython.display import display

        bundle = self._repr_mimebundle_()
        data, metadata = bundle if isinstance(bundle, tuple) else (bundle, {})
        display(data, metadata=metadata, raw=True)
        handle = display(_still.bundle(self._describe(), self._still_png), raw=True, display_id=True)
        if handle is not None:
            self._stills.append(handle)

    def _show_still(self, png: bytes) -> None:
        """The picture the front end drew last, into every still of the view."""
        self._still_png = png
        for handle in self._stills:
            handle.update(_still.bundle(self._describe(), png), raw=True)

    # --- figures

    def _figure(self, kind: str, path: str | Path | None, options: dict[str, Any]) -> Figure:
        figure = Figure(kind, path, self._front)
        key = str(next(_ids))
        self._figures[key] = figure
        self.send({"kind": "export", "id": key, "format": kind, "options": options})
        return figure

    def svg(self, path: str | Path | None = None, **options: Any) -> Figure:
        """The view as an SVG figure (``bw``, ``legend``, ``title``, ``labels``, ``hidden``: the
        book's "Figures for lecture notes"); ``await`` it for the text, or let the cell show it;
        with ``path``, it is written there."""
        return self._figure("svg", path, options)

    def tikz(self, path: str | Path | None = None, **options: Any) -> Figure:
        """The view as a TikZ picture for LaTeX (the SVG's options and ``width`` in cm)."""
        return self._figure("tikz", path, options)

    def png(self, path: str | Path | None = None, scale: int = 1, legend: bool = True) -> Figure:
        """The view as a PNG (``scale`` 1, 2 or 4 times its size); ``await`` it for the bytes."""
        return self._figure("png", path, {"scale": scale, "legend": legend})

    def layers(self) -> Figure:
        """What the view draws, as the core computed it: ``await view.layers()`` gives a list of
        ``{kind, style, points}`` (``points`` an (n, 3) array: a segments layer's ends in pairs, a
        polyline's points, a mesh's vertices), e.g. the striction polygon as style ``striction``.
        The points are float64 arrays holding the 32-bit floats the view draws (WebGL's): they agree
        with the core's float64 results (``RuledSurface.invariants()["striction"]``) to about 1e-7
        relative, not bit for bit."""
        return self._figure("layers", None, {})

    # --- callbacks

    def on_check(self, fn: Callable[[dict[str, Any]], Any]) -> Callable[[dict[str, Any]], Any]:
        """Calls ``fn(report)`` after every check of the exercise (``task``): ``task``, ``title``,
        ``solved``, ``passed``, ``of``, ``conditions``, ``answers``, and ``event`` ('check', or
        'solved' the first time it is solved). Returns ``fn`` (usable as a decorator)."""
        self._on_check.append(fn)
        return fn

    def on_error(self, fn: Callable[[RuledlabError], Any]) -> Callable[[RuledlabError], Any]:
        """Calls ``fn(error)`` for every error the view reports. Returns ``fn``."""
        self._on_error.append(fn)
        return fn
