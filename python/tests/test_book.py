"""The book's chapters on Python run as printed: "In Python" (docs/src/guide/python.md) block by
block in one namespace, headless."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def blocks(chapter: str) -> list[str]:
    text = (REPO / "docs" / "src" / "guide" / chapter).read_text()
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def test_the_python_chapter_runs_as_printed():
    code = blocks("python.md")
    assert len(code) >= 2
    namespace: dict[str, object] = {}
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        for k, block in enumerate(code):
            exec(compile(block, f"python.md block {k}", "exec"), namespace)
    printed = out.getvalue().splitlines()
    # what the comments say it prints
    assert printed[1] == "800 (800, 6)"
    assert printed[2] == "gouge -0.0112 leave 0.0047"
    assert printed[3] == "not-finite 2 [2, 1]"
    assert printed[4].startswith("RuledSurface.from_segments: coordinate b[2, 1] (ruling 2, b.y) is NaN")


def run_in_kernel(cells: list[str], tmp_path: Path) -> list[dict]:
    """Runs `cells` in order in a fresh kernel, headless (nbclient, as `nbconvert --execute` does),
    and gives each cell's outputs."""
    import nbclient
    import nbformat

    notebook = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    notebook.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    client = nbclient.NotebookClient(
        notebook, timeout=120, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    )
    client.execute()
    return [cell["outputs"] for cell in notebook.cells]


def test_the_notebooks_chapter_runs_in_a_kernel_as_printed(tmp_path):
    """"In notebooks" (docs/src/guide/notebooks.md): its Python blocks in order in one kernel,
    headless, every block passes and shows nothing it should not (a bound method's repr …)."""
    code = blocks("notebooks.md")
    assert len(code) >= 8
    outputs = run_in_kernel(code, tmp_path)
    text = []
    for k, cell in enumerate(outputs):
        for out in cell:
            assert out["output_type"] != "error", f"block {k}: {out.get('ename')}: {out.get('evalue')}"
            plain = out.get("text") or out.get("data", {}).get("text/plain", "")
            assert not plain.startswith(("<function", "<built-in", "<bound")), f"block {k} shows {plain!r}"
            text.append(plain)
    printed = "".join(text)
    assert "(22, 3)" in printed  # the striction polygon of 24 rulings
    assert "degenerate | View.from_segments: ruling 0 has zero length" in printed
    assert "0.9 40" in printed
    assert "<ruledlab view of 24 rulings>" in printed  # a view as text, where no widget runs
