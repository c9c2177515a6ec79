"""A figure a view draws for Python (SVG, TikZ or PNG): it arrives once the view has drawn it."""

from __future__ import annotations

import asyncio
import concurrent.futures
from pathlib import Path
from typing import Any, Callable, Generator

from ._errors import RuledlabError
from ._front_end import TIMEOUT, FrontEnd, no_answer


class Figure:
    """A figure on its way from the view: ``await`` it for its text (SVG, TikZ) or bytes (PNG),
    or let the notebook show it (the output updates when it arrives). Given a ``path``, it is
    written there when it arrives."""

    def __init__(self, kind: str, path: str | Path | None = None, front_end: FrontEnd | None = None):
        self.kind = kind
        self.path = Path(path) if path is not None else None
        self._front_end = front_end
        self._future: concurrent.futures.Future[Any] = concurrent.futures.Future()
        self._shown: list[Callable[[], None]] = []

    # called by the view with its answer
    def _resolve(self, content: dict[str, Any], buffers: list[Any]) -> None:
        if self._future.done():
            return  # the view shown twice answers twice
        if content.get("error"):
            self._future.set_exception(RuledlabError.from_detail(content["error"]))
        else:
            value: Any
            if self.kind == "layers":
                import numpy as np

                value = [
                    {**layer, "points": np.frombuffer(bytes(b), dtype="<f4").astype(float).reshape(-1, 3)}
                    for layer, b in zip(content.get("layers") or [], buffers)
                ]
            else:
                value = bytes(buffers[0]) if self.kind == "png" else str(content.get("text", ""))
            if self.path is not None and self.kind != "layers":
                if isinstance(value, bytes):
                    self.path.write_bytes(value)
                else:
                    self.path.write_text(value, encoding="utf-8")
            self._future.set_result(value)
        for update in self._shown:
            update()

    def done(self) -> bool:
        """Whether the view has answered."""
        return self._future.done()

    def result(self) -> str | bytes:
        """The figure (SVG or TikZ text, PNG bytes); raises RuledlabError if the view could not
        draw it, and RuntimeError if it has not arrived yet (``await`` the figure to wait)."""
        if not self._future.done():
            raise RuntimeError("ruledlab: the figure has not arrived yet; `await` it")
        value: str | bytes = self._future.result()
        return value

    async def _wait(self, timeout: float) -> str | bytes:
        if not self._future.done() and self._front_end is not None:
            # RuledlabError at once where no front end draws the view (a notebook run headless)
            await self._front_end.needed(f"{self.kind.upper()} figure")
        try:
            return await asyncio.wait_for(asyncio.wrap_future(self._future), timeout)
        except asyncio.TimeoutError:
            raise no_answer(f"{self.kind.upper()} figure", timeout) from None

    def __await__(self) -> Generator[Any, None, str | bytes]:
        return self._wait(TIMEOUT).__await__()

    def _display_object(self) -> Any:
        from IPython.display import SVG, Image, Pretty

        if not self._future.done():
            return Pretty(f"ruledlab: waiting for the view to draw the {self.kind.upper()} figure…")
        if self._future.exception() is not None:
            return Pretty(f"ruledlab: {self._future.exception()}")
        value = self._future.result()
        if self.kind == "png":
            return Image(data=value, format="png")
        if self.kind == "svg":
            return SVG(data=value)
        return Pretty(value)

    def _ipython_display_(self) -> None:
        from IPython.display import display

        handle = display(self._display_object(), display_id=True)
        if not self._future.done() and handle is not None:
            self._shown.append(lambda: handle.update(self._display_object()))

    def __repr__(self) -> str:
        state = "done" if self.done() else "pending"
        where = f", path={str(self.path)!r}" if self.path else ""
        return f"<ruledlab.Figure {self.kind} {state}{where}>"
