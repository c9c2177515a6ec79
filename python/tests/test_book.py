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
    assert printed[2] == "not-finite 2 [2, 1]"
    assert printed[3].startswith("RuledSurface.from_segments: coordinate b[2, 1] (ruling 2, b.y) is NaN")
