"""Builds the package with the one-file script of <ruled-view> inside it.

The script (``dist/ruledlab-embed.js``: the element with the wasm core inlined) is made by the
repository's build (``npm run build``); it is copied into ``ruledlab/static/`` of the wheel here,
so an installed package fetches nothing when it runs.
"""

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = Path(__file__).resolve().parent
SCRIPT = HERE.parent / "dist" / "ruledlab-embed.js"


class BuildWithScript(build_py):
    def run(self):
        super().run()
        if not SCRIPT.is_file():
            raise SystemExit(f"ruledlab: {SCRIPT} is missing: run `npm run build` in the repository first")
        target = Path(self.build_lib) / "ruledlab" / "static" / SCRIPT.name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(SCRIPT, target)


setup(cmdclass={"build_py": BuildWithScript})
