"""The one-file script of ``<ruled-view>`` (the wasm core inlined) that the package carries."""

from __future__ import annotations

import gzip
from functools import lru_cache
from pathlib import Path

HERE = Path(__file__).resolve().parent
NAME = "ruledlab-embed.js"


def script_path() -> Path:
    """Where the script is: in the installed package (``static/``), or, run from a checkout of
    the repository, the build's ``dist/``."""
    for path in (HERE / "static" / NAME, HERE.parent.parent / "dist" / NAME):
        if path.is_file():
            return path
    raise FileNotFoundError(
        f"ruledlab: {NAME} is not in the package (build it with `npm run build` in the repository, "
        "then install the package again)"
    )


@lru_cache(maxsize=1)
def script_gzip() -> bytes:
    """The script gzipped, as the widget's first view asks for it (read and packed once)."""
    return gzip.compress(script_path().read_bytes(), compresslevel=6, mtime=0)
