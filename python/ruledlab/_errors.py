"""The error of a view: the core's (or the element's) code, message and details."""

from __future__ import annotations

from typing import Any


class RuledlabError(ValueError):
    """An error of ruledlab: ``code`` says what kind (the book's "Errors and their codes":
    ``invalid-argument``, ``not-finite``, ``degenerate``, ``too-large``, …), the message says it
    in the view's language, ``details`` points at it (``reason``, ``args``, ``index``,
    ``param``, …) as the core gives them."""

    def __init__(self, message: str, code: str | None = None, details: dict[str, Any] | None = None):
        super().__init__(message)
        self.message = message
        self.code = code
        self.details = details or {}

    @classmethod
    def from_detail(cls, detail: dict[str, Any]) -> RuledlabError:
        """The error a view reported (the element's ``error`` event detail)."""
        return cls(str(detail.get("message", "")), detail.get("code"), detail.get("details"))

    def __repr__(self) -> str:
        return f"RuledlabError({self.message!r}, code={self.code!r})"
