"""A view's still: what a notebook shows of it where no widget front end runs — a notebook saved
and opened without a kernel, ``jupyter nbconvert --to html``, GitHub's viewer, a plain IPython.

A widget's output holds only a reference to a model that lives in the kernel (and in the front
end that made it): without them nothing draws. So a view, when displayed, puts a second output
below it, plain HTML with an id (a display id): first a sentence saying what the view shows,
then, each time the front end has drawn a change (a second after it settles), the picture it
drew, as a PNG, put into that output by ``update_display``. The notebook saves it with the cell;
where the widget runs, the widget's module hides it (the view itself is there). Nothing of the
view's data is in it but the picture.
"""

from __future__ import annotations

import base64
import html
from typing import Any

#: the class of the still's element: the widget's module hides its outputs where it runs
CLASS = "ruledlab-still"


def describe(scene: str, params: dict[str, Any], source: dict[str, Any] | None, task: str, paper: str) -> str:
    """One line saying what a view shows: its scene (or your rulings, or your congruence), its
    parameters, the exercise or the paper's figure."""
    if source and source.get("rows"):
        what = f"a congruence of {source['rows']} × {source['cols']} lines"
    elif source:
        what = f"{len(source['segments']) // 6} rulings"
    elif task:
        what = f"the exercise {task}"
    elif paper:
        what = f"the paper's {paper}"
    else:
        what = f"the scene {scene or '(the first)'}"
    shown = ", ".join(f"{k}={v!r}" for k, v in sorted(params.items()))
    return f"ruledlab view of {what}" + (f" ({shown})" if shown else "")


def html_of(text: str, png: bytes | None) -> str:
    """The still's HTML: the picture the view last drew with `text` as its alternative, or only
    `text` while there is no picture."""
    said = html.escape(text)
    if png is None:
        body = f"<p style=\"margin:0;font:13px system-ui,sans-serif;color:#555\">{said} — drawn where a notebook front end runs its widget</p>"
    else:
        data = base64.b64encode(png).decode("ascii")
        body = f'<img alt="{said}" title="{said}" src="data:image/png;base64,{data}" style="max-width:100%">'
    return f'<div class="{CLASS}">{body}</div>'


def bundle(text: str, png: bytes | None) -> dict[str, Any]:
    """The still's output: HTML, and its text for front ends that show no HTML."""
    return {"text/html": html_of(text, png), "text/plain": text}
