"""The example notebook runs headless: ``jupyter nbconvert --execute examples/notebook.ipynb``,
no front end, every cell passing — its numbers computed by the core in Python, its views made
(nothing draws them), what only a view gives asked for where a front end shows the view. In a
real JupyterLab the same notebook runs cell by cell with its views drawn
(tests/page/notebook.test.mjs)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def test_the_example_notebook_runs_headless_under_nbconvert(tmp_path):
    jupyter = Path(sys.executable).with_name("jupyter")
    out = subprocess.run(
        [jupyter, "nbconvert", "--to", "notebook", "--execute", "--ExecutePreprocessor.timeout=120",
         str(REPO / "examples" / "notebook.ipynb"), "--output-dir", str(tmp_path), "--output", "run.ipynb"],
        cwd=tmp_path, capture_output=True, text=True,
    )  # fmt: skip
    assert out.returncode == 0, out.stderr[-3000:]
    notebook = json.loads((tmp_path / "run.ipynb").read_text())
    code = [c for c in notebook["cells"] if c["cell_type"] == "code"]
    assert all(c["execution_count"] for c in code), "every cell ran"
    printed = {}
    for i, cell in enumerate(notebook["cells"]):
        for output in cell.get("outputs", []):
            assert output["output_type"] != "error", f"cell {i}: {output.get('ename')}: {output.get('evalue')}"
            text = output.get("text") or ""
            printed[i] = printed.get(i, "") + ("".join(text) if isinstance(text, list) else text)
    text = "\n".join(printed.values())
    # the numbers are the core's, computed headless
    assert "δ = -1.463709 ± " in text and "striction points on z = 0 to " in text
    assert "t = 0.9  n = 40" in text
    assert "degenerate | View.from_segments: ruling 0 has zero length" in text
    assert "not-finite 2 | RuledSurface.from_segments: coordinate b[2, 1] (ruling 2, b.y) is NaN" in text
    # the views were made and displayed; nothing drew them, and nothing waited long for them
    widget = "application/vnd.jupyter.widget-view+json"
    views = [c for c in code if any(widget in o.get("data", {}) for o in c["outputs"])]
    assert len(views) >= 4
    # below each view its still: what a notebook without a kernel shows (headless: the sentence)
    stills = [
        o for c in code for o in c["outputs"] if "ruledlab-still" in "".join(o.get("data", {}).get("text/html", ""))
    ]
    assert len(stills) == len(views), "a still for every view"
    assert any("ruledlab view of 24 rulings" in "".join(o["data"]["text/plain"]) for o in stills)
    for c in views:
        kinds = [list(o.get("data", {})) for o in c["outputs"]]
        assert ["text/html", "text/plain"] in [sorted(k) for k in kinds], "the view's still is in its cell"
    # nbconvert's HTML of the run notebook names every view where no widget runs
    html = subprocess.run(
        [jupyter, "nbconvert", "--to", "html", str(tmp_path / "run.ipynb"), "--stdout"],
        cwd=tmp_path, capture_output=True, text=True, check=True,
    ).stdout  # fmt: skip
    assert html.count('class="ruledlab-still"') == len(views)
    assert "ruledlab view of a congruence of 9 × 9 lines" in html
    assert "&lt;ruledlab._view.View object" not in html and "<ruledlab._view.View object" not in html
