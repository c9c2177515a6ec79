"""Unit tests of the package: what a View sends and how it takes the view's answers.

The view's side is played here by calling the messages it sends (``_message``) and reading what
the widget sends (its ``_send`` and ``send`` captured); the real view is exercised in a real
JupyterLab by tests/page/notebook.test.mjs.
"""

from __future__ import annotations

import asyncio
import gzip
import json
import time
from pathlib import Path

import numpy as np
import pytest
from ipywidgets.widgets.widget import _remove_buffers

import ruledlab
from ruledlab import RuledlabError, View
from ruledlab import _front_end as front_end
from ruledlab._script import script_path

REPO = Path(__file__).resolve().parents[2]


def hyperboloid(n: int = 8, phi: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    u = np.linspace(0, 2 * np.pi, n, endpoint=False)
    a = np.stack([np.cos(u), np.sin(u), -np.ones(n)], axis=1)
    b = np.stack([np.cos(u + phi), np.sin(u + phi), np.ones(n)], axis=1)
    return a, b


class Wire:
    """What a view sends: state updates (``_send``) and custom messages (``send``)."""

    def __init__(self, view: View):
        self.updates: list[tuple[dict, list]] = []
        self.messages: list[tuple[dict, list]] = []
        view._send = lambda msg, buffers=None: self.updates.append((msg, list(buffers or [])))
        view.send = lambda content, buffers=None: self.messages.append((content, list(buffers or [])))


def answer(view: View, content: dict, buffers: list | None = None) -> None:
    """A message of the view's front end to the kernel."""
    view._message(view, content, buffers or [])


def shown(view: View) -> View:
    """The view displayed (its output published) and held by a front end (which said hello)."""
    view._repr_mimebundle_()
    answer(view, {"kind": "hello"})
    return view


@pytest.fixture(autouse=True)
def headless(monkeypatch):
    """Each test starts in a kernel no front end has spoken to, with a short grace period."""
    monkeypatch.setattr(front_end, "_any_front_end", False)
    monkeypatch.setattr(front_end, "GRACE", 0.2)


def test_segments_go_as_one_binary_buffer_of_doubles():
    a, b = hyperboloid(8)
    view = View.from_segments(a, b)
    assert view.scene == "data"
    state, paths, buffers = _remove_buffers(view.get_state())
    assert ["_source", "segments"] in paths
    raw = bytes(buffers[paths.index(["_source", "segments"])])
    assert len(raw) == 8 * 6 * 8
    sent = np.frombuffer(raw, dtype="<f8").reshape(8, 6)
    assert np.array_equal(sent[:, :3], a) and np.array_equal(sent[:, 3:], b)
    # nothing of the data is a JSON list
    assert "segments" not in json.dumps(state["_source"])


def test_a_million_rulings_go_as_one_buffer_of_48_mb_in_well_under_a_second():
    """What the view gets of 10⁶ rulings: one buffer of doubles (the page draws them at a level of
    detail: tests/page/million.test.mjs), made without a list in between."""
    n = 1_000_000
    u = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    a = np.stack([np.cos(u), np.sin(u), -np.ones(n)], axis=1)
    b = np.stack([np.cos(u + 1.2), np.sin(u + 1.2), np.ones(n)], axis=1)
    t0 = time.perf_counter()
    view = View.from_segments(a, b)
    state, paths, buffers = _remove_buffers(view.get_state())
    seconds = time.perf_counter() - t0
    raw = buffers[paths.index(["_source", "segments"])]
    assert memoryview(raw).nbytes == n * 6 * 8
    sent = np.frombuffer(raw, dtype="<f8").reshape(n, 6)
    assert np.array_equal(sent[::9973, :3], a[::9973]) and np.array_equal(sent[-1, 3:], b[-1])
    print(f"10⁶ rulings: the view's state in {seconds:.2f} s")
    assert "segments" not in json.dumps(state["_source"])


def test_a_grid_goes_row_by_row_with_its_size():
    s, t = np.meshgrid(np.arange(3.0), np.arange(4.0), indexing="ij")
    p = np.stack([s, t, np.zeros_like(s)], axis=2)
    q = p + np.array([0.0, 0.0, 1.0])
    view = View.from_grid(p, q)
    state, paths, buffers = _remove_buffers(view.get_state())
    assert (state["_source"]["rows"], state["_source"]["cols"]) == (3, 4)
    lines = np.frombuffer(bytes(buffers[paths.index(["_source", "segments"])]), dtype="<f8").reshape(3, 4, 6)
    assert np.array_equal(lines[..., :3], p) and np.array_equal(lines[..., 3:], q)


@pytest.mark.parametrize(
    ("a", "b", "option"),
    [
        (np.zeros((4, 2)), np.zeros((4, 2)), "a"),
        (np.zeros((4, 3)), np.zeros((5, 3)), "b"),
        ([["x", 1, 2]], [[0, 1, 2]], "a"),
        (np.zeros(3), np.zeros(3), "a"),
    ],
)
def test_arrays_of_the_wrong_shape_are_refused_with_a_code(a, b, option):
    with pytest.raises(RuledlabError) as e:
        View.from_segments(a, b)
    assert e.value.code == "invalid-argument"
    assert e.value.details["option"] == option
    with pytest.raises(RuledlabError):
        View.from_grid(np.zeros((2, 3)), np.zeros((2, 3)))


def test_a_change_of_pythons_goes_with_its_revision_in_one_message():
    view = View(scene="isometry", params={"t": 0.5})
    wire = Wire(view)
    rev = view._rev
    view.params = {"t": np.float64(0.75), "n": np.int64(30), "ghost": np.bool_(False)}
    assert view._rev == rev + 1
    assert len(wire.updates) == 1
    state = wire.updates[0][0]["state"]
    assert state["params"] == {"t": 0.75, "n": 30, "ghost": False}
    assert state["_rev"] == rev + 1
    assert type(view.params["n"]) is int and type(view.params["ghost"]) is bool
    view.camera = (0.5, 0.25, 4, 0, 0, 1)
    view.height = 560
    assert (view.camera, view.height, view._rev) == ("0.5,0.25,4,0,0,1", "560", rev + 3)
    with pytest.raises(RuledlabError) as e:
        view.params = {"t": [1, 2]}
    assert (e.value.code, e.value.details["param"]) == ("invalid-argument", "t")


def test_what_the_view_reports_becomes_the_traits_without_a_revision():
    a, b = hyperboloid(4)
    view = View.from_segments(a, b)
    wire = Wire(view)
    rev = view._rev
    ends = np.hstack([a, b]).reshape(-1, 3)
    readouts = [{"key": "readout.rulings", "label": "rulings", "value": 4}]
    answer(
        view,
        {
            "kind": "state",
            "state": {"scene": "data", "params": {"strip": False}, "readouts": readouts, "_rev": 99},
            "input": ["rulings"],
        },
        [memoryview(ends.astype("<f8").tobytes())],
    )
    assert view.params == {"strip": False} and view.readouts == readouts
    assert np.array_equal(view.data["rulings"], ends)
    assert view._rev == rev, "the view's state is not a change of Python's (and cannot set the revision)"
    # (ipywidgets tells other front ends; never the data back to the view that sent it)
    assert all("data" not in msg["state"] and "_rev" not in msg["state"] for msg, _ in wire.updates)
    # a camera moved by the reader
    answer(view, {"kind": "state", "state": {"camera": "1,0.5,5,0,0,0"}, "input": None})
    assert view.camera == "1,0.5,5,0,0,0" and view._rev == rev


def test_setting_data_moves_the_handles_and_is_checked():
    view = View(scene="data")
    wire = Wire(view)
    view.data = {"rulings": np.zeros((4, 3))}
    msg, buffers = wire.updates[-1]
    assert msg["buffer_paths"] == [["data", "rulings"]] and len(bytes(buffers[0])) == 4 * 3 * 8
    assert msg["state"]["_rev"] == view._rev
    with pytest.raises(RuledlabError):
        view.data = {"rulings": np.zeros((4, 2))}


def test_what_the_core_refuses_is_refused_at_once_without_a_view():
    a, b = hyperboloid(6)
    with pytest.raises(RuledlabError) as e:
        View.from_segments(a, a)
    assert e.value.code == "degenerate" and e.value.details["index"] == 0
    assert str(e.value).startswith("View.from_segments: ruling 0 has zero length")
    b[3, 2] = np.nan
    view = View.from_segments(*hyperboloid(6))
    with pytest.raises(RuledlabError) as e:
        view.set_segments(a, b)
    assert (e.value.code, e.value.details["index"], e.value.details["at"]) == ("not-finite", 3, [3, 2])
    assert "b[3, 2] (ruling 3, b.z) is NaN" in str(e.value) and str(e.value).startswith("View.set_segments:")
    # the view keeps what it showed
    assert np.array_equal(view._source["segments"].reshape(6, 6), np.hstack(hyperboloid(6)))


def test_wait_raises_the_views_error_and_the_view_works_on():
    async def run():
        view = shown(View(scene="isometry"))
        said = []
        view.on_error(said.append)
        view.params = {"t": "half"}
        rev = view._rev
        error = {
            "message": "ruled-view: parameter t must be a number, got \"half\"",
            "code": "invalid-argument",
            "details": {"param": "t"},
        }
        asyncio.get_running_loop().call_later(0.05, answer, view, {"kind": "shown", "rev": rev, "errors": [error]})
        with pytest.raises(RuledlabError) as e:
            await view.wait(timeout=5)
        assert e.value.code == "invalid-argument" and e.value.details["param"] == "t"
        assert str(e.value) == error["message"]
        assert view.error is not None and view.error.code == "invalid-argument"
        assert [s.code for s in said] == ["invalid-argument"]
        # a good value: the same view shows it, the error is gone
        view.params = {"t": 0.5}
        assert view._rev == rev + 1
        loop = asyncio.get_running_loop()
        loop.call_later(0.05, answer, view, {"kind": "shown", "rev": rev + 1, "errors": []})
        assert await view.wait(timeout=5) is view
        assert view.error is None
        # an error the view finds later (a computation in a worker) is kept and said
        answer(view, {"kind": "error", "error": {"message": "too many", "code": "too-large"}})
        assert view.error.code == "too-large" and said[-1].code == "too-large"

    asyncio.run(run())


def test_without_a_front_end_wait_returns_at_once_and_figures_say_why_not():
    """A notebook run headless: nothing draws the view; computations never needed it."""

    async def run():
        view = View(scene="striction")
        view._repr_mimebundle_()
        view.params = {"n": 30}
        start = asyncio.get_running_loop().time()
        assert await view.wait(timeout=30) is view
        assert asyncio.get_running_loop().time() - start < 1
        assert not await view.has_front_end()
        with pytest.raises(RuledlabError) as e:
            await view.svg()
        assert e.value.code == "no-view" and "headless" in str(e.value)

    asyncio.run(run())


def test_with_a_front_end_wait_needs_the_view_displayed_and_says_when_none_answers():
    async def run():
        view = View(scene="striction")
        answer(view, {"kind": "hello"})
        assert await view.has_front_end()
        view.params = {"n": 30}
        with pytest.raises(RuledlabError) as e:
            await view.wait(timeout=0.1)
        assert e.value.code == "not-displayed"
        view._repr_mimebundle_()
        with pytest.raises(RuledlabError) as e:
            await view.wait(timeout=0.1)
        assert e.value.code == "no-answer" and e.value.details["limit"] == 0.1
        # once a front end has spoken, another view waits for its hello longer than the grace
        later = View(scene="striction")
        loop = asyncio.get_running_loop()
        loop.call_later(0.4, answer, later, {"kind": "hello"})
        assert await later.has_front_end()

    asyncio.run(run())


def test_figures_arrive_as_text_bytes_and_files(tmp_path):
    view = shown(View(scene="striction"))
    wire = Wire(view)

    async def run():
        svg = view.svg(tmp_path / "fig.svg", bw=True)
        png = view.png(tmp_path / "fig.png", scale=2)
        tikz = view.tikz(width=8)
        asks = [m for m, _ in wire.messages]
        assert [(m["kind"], m["format"]) for m in asks] == [("export", "svg"), ("export", "png"), ("export", "tikz")]
        assert asks[0]["options"] == {"bw": True} and asks[1]["options"] == {"scale": 2, "legend": True}
        assert not svg.done()
        with pytest.raises(RuntimeError):
            svg.result()
        loop = asyncio.get_running_loop()
        loop.call_later(0.02, answer, view, {"kind": "export", "id": asks[0]["id"], "text": "<svg/>"})
        loop.call_later(0.02, answer, view, {"kind": "export", "id": asks[1]["id"]}, [memoryview(b"\x89PNG..")])
        error = {"message": "ruled-view: not connected", "code": "invalid-argument"}
        loop.call_later(0.02, answer, view, {"kind": "export", "id": asks[2]["id"], "error": error})
        assert await svg == "<svg/>"
        assert await png == b"\x89PNG.."
        with pytest.raises(RuledlabError, match="not connected"):
            await tikz
        # a second answer (the view shown twice) changes nothing
        answer(view, {"kind": "export", "id": asks[0]["id"], "text": "<other/>"})
        assert svg.result() == "<svg/>"

    asyncio.run(run())
    assert (tmp_path / "fig.svg").read_text() == "<svg/>"
    assert (tmp_path / "fig.png").read_bytes() == b"\x89PNG.."


def test_the_first_view_gets_the_bundled_script_gzipped():
    view = View()
    wire = Wire(view)
    answer(view, {"kind": "embed"})
    content, buffers = wire.messages[-1]
    assert content == {"kind": "embed"}
    script = gzip.decompress(bytes(buffers[0]))
    assert script == script_path().read_bytes()
    assert b"ruled-view" in script and len(buffers[0]) < len(script) / 2
    # the installed package carries it
    assert script_path().parent.name == "static"


def test_exercise_checks_reach_python():
    view = View(task="striction-accuracy")
    checks = []

    @view.on_check
    def heard(report):
        checks.append(report)

    report = {"task": "striction-accuracy", "solved": True, "passed": 1, "of": 1, "conditions": []}
    answer(view, {"kind": "task", "type": "check", "report": report})
    answer(view, {"kind": "task", "type": "solved", "report": report})
    assert [(c["event"], c["solved"], c["task"]) for c in checks] == [
        ("check", True, "striction-accuracy"),
        ("solved", True, "striction-accuracy"),
    ]


def test_the_version_is_the_npm_packages():
    npm = json.loads((REPO / "package.json").read_text())
    assert ruledlab.__version__ == npm["version"]
    assert f'version = "{npm["version"]}"' in (REPO / "python" / "pyproject.toml").read_text()


def python_snippets() -> list[tuple[str, str]]:
    """The Python of the book's chapter and the code cells of the example notebook."""
    import re

    chapter = (REPO / "docs" / "src" / "guide" / "notebooks.md").read_text()
    out = [("notebooks.md", m) for m in re.findall(r"^```python\n(.*?)^```", chapter, flags=re.S | re.M)]
    notebook = json.loads((REPO / "examples" / "notebook.ipynb").read_text())
    cells = [(i, c) for i, c in enumerate(notebook["cells"]) if c["cell_type"] == "code"]
    return out + [(f"notebook.ipynb cell {i}", "".join(c["source"])) for i, c in cells]


def test_the_books_and_the_notebooks_python_reads_and_names_what_exists():
    """Every snippet compiles (top-level await, as in a notebook) and uses only what a View has;
    the notebook's cells run for real in the JupyterLab test."""
    import ast

    snippets = python_snippets()
    assert len(snippets) >= 20
    views = {"view", "surface", "bending", "flat", "exercise", "lines"}
    for where, code in snippets:
        tree = compile(code, where, "exec", flags=ast.PyCF_ONLY_AST | ast.PyCF_ALLOW_TOP_LEVEL_AWAIT)
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
                if node.value.id in views or node.value.id == "View":
                    assert hasattr(View, node.attr), f"{where}: View has no {node.attr}"


def test_the_layers_the_view_draws_arrive_as_arrays():
    view = shown(View(scene="striction"))
    wire = Wire(view)

    async def run():
        layers = view.layers()
        ask = wire.messages[-1][0]
        assert (ask["kind"], ask["format"]) == ("export", "layers")
        striction = np.array([[0, 0, 0], [1, 0.5, 0.25]], dtype="<f4")
        rulings = np.arange(12, dtype="<f4")
        kinds = [{"kind": "polyline", "style": "striction"}, {"kind": "segments", "style": "ruling"}]
        buffers = [memoryview(striction.tobytes()), memoryview(rulings.tobytes())]
        asyncio.get_running_loop().call_later(0.02, answer, view, {**ask, "layers": kinds}, buffers)
        got = await layers
        assert [(g["kind"], g["style"], g["points"].shape) for g in got] == [
            ("polyline", "striction", (2, 3)),
            ("segments", "ruling", (4, 3)),
        ]
        assert np.array_equal(got[0]["points"], striction.astype(float))

    asyncio.run(run())


class Handle:
    """An IPython display handle that records its updates."""

    def __init__(self) -> None:
        self.updates: list[dict] = []

    def update(self, obj: dict, raw: bool = False) -> None:
        assert raw
        self.updates.append(obj)


def test_a_view_says_what_it_shows_as_text_and_leaves_a_still_for_notebooks_without_a_kernel(monkeypatch):
    """Outside a widget front end (a plain IPython, print, a notebook saved and opened without a
    kernel, nbconvert's HTML) a view is a sentence, then the picture its front end drew last."""
    import base64

    import IPython.display

    a, b = hyperboloid(8)
    view = View.from_segments(a, b, params={"strip": False})
    assert repr(view) == "<ruledlab view of 8 rulings (strip=False)>"
    assert str(view) == repr(view)
    s, t = np.meshgrid(np.arange(3.0), np.arange(4.0), indexing="ij")
    p = np.stack([s, t, np.zeros_like(s)], axis=2)
    assert repr(View.from_grid(p, p + [0.0, 0.0, 1.0])) == "<ruledlab view of a congruence of 3 × 4 lines>"
    assert repr(View(task="striction-accuracy")) == "<ruledlab view of the exercise striction-accuracy>"
    assert repr(View(scene="isometry", params={"t": 0.5})) == "<ruledlab view of the scene isometry (t=0.5)>"
    data = view._repr_mimebundle_()
    data = data[0] if isinstance(data, tuple) else data
    assert data["text/plain"] == "ruledlab view of 8 rulings (strip=False)"
    assert data["application/vnd.jupyter.widget-view+json"]["model_id"] == view.model_id

    shown: list[tuple[dict, dict]] = []
    handles: list[Handle] = []

    def display(obj, metadata=None, raw=False, display_id=None):
        assert raw
        shown.append((obj, {"display_id": display_id}))
        if display_id:
            handles.append(Handle())
            return handles[-1]
        return None

    monkeypatch.setattr(IPython.display, "display", display)
    view._ipython_display_()
    assert len(shown) == 2 and "application/vnd.jupyter.widget-view+json" in shown[0][0]
    still, how = shown[1]
    assert how["display_id"] is True
    assert 'class="ruledlab-still"' in still["text/html"] and "ruledlab view of 8 rulings" in still["text/html"]
    assert still["text/plain"] == "ruledlab view of 8 rulings (strip=False)"
    # the front end drew it: its picture goes into the still (escaped text as its alternative)
    png = b"\x89PNG\r\n\x1a\n" + bytes(range(256))
    answer(view, {"kind": "still"}, [memoryview(png)])
    (update,) = handles[0].updates
    assert f'src="data:image/png;base64,{base64.b64encode(png).decode()}"' in update["text/html"]
    assert 'alt="ruledlab view of 8 rulings (strip=False)"' in update["text/html"]
    # a view displayed again starts with the picture it has
    view._ipython_display_()
    assert base64.b64encode(png).decode() in shown[3][0]["text/html"]
    answer(view, {"kind": "still"}, [png[:20]])
    assert len(handles[0].updates) == 2 and len(handles[1].updates) == 1
    # text that HTML would read is escaped
    odd = View(scene="<b>x</b>")
    monkeypatch.setattr(IPython.display, "display", display)
    odd._ipython_display_()
    assert "<b>x</b>" not in shown[-1][0]["text/html"] and "&lt;b&gt;" in shown[-1][0]["text/html"]
