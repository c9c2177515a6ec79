#!/usr/bin/env bash
# Builds the Python package for notebooks (python/) into dist/python/ruledlab-<version>-py3-none-any.whl
# with the one-file script dist/ruledlab-embed.js inside (python/setup.py copies it: run
# scripts/build.sh first) and installs that wheel into .venv/ (scripts/setup.sh --browser makes it),
# where the pytest tests and the JupyterLab test (tests/page/notebook.test.mjs) use it.
set -euo pipefail
cd "$(dirname "$0")/.."

[ -x .venv/bin/python ] || { echo "wheel: .venv/ is missing: run bash scripts/setup.sh --browser" >&2; exit 1; }
[ -f dist/ruledlab-embed.js ] || { echo "wheel: dist/ruledlab-embed.js is missing: run bash scripts/build.sh" >&2; exit 1; }
rm -rf dist/python python/build python/ruledlab.egg-info
.venv/bin/python -m pip wheel -q --disable-pip-version-check --no-deps --no-build-isolation -w dist/python ./python
rm -rf python/build python/ruledlab.egg-info
wheel=$(ls dist/python/ruledlab-*.whl)
.venv/bin/python -m pip install -q --disable-pip-version-check --force-reinstall --no-deps "$wheel"
echo "wheel: $wheel ($(( $(stat -c %s "$wheel") / 1024 )) KiB), installed into .venv/"
