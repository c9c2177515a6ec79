#!/usr/bin/env bash
# Builds the Python package — python/: the notebook widget and the compiled core (crates/ruledlab-py,
# ruledlab._core) — into one wheel, dist/python/ruledlab-<version>-cp39-abi3-<platform>.whl, with
# the one-file script dist/ruledlab-embed.js inside (run scripts/build.sh first), and installs it
# into .venv/ where there is one (scripts/setup.sh --browser makes it; the pytest, mypy, notebook
# and JupyterLab tests use it).
#
# Works from any Python ≥ 3.9 with pip, a plain `python3 -m venv` included: pip builds with
# isolation, fetching the build backend pinned in python/pyproject.toml (maturin 1.16.0) from
# PyPI; the Rust toolchain compiles the core (cargo, as for the rest of the workspace). The
# Python is $PYTHON, else .venv/bin/python, else python3.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

python=${PYTHON:-}
if [ -z "$python" ]; then
  if [ -x .venv/bin/python ]; then python=.venv/bin/python; else python=python3; fi
fi
[ -f dist/ruledlab-embed.js ] || { echo "wheel: dist/ruledlab-embed.js is missing: run bash scripts/build.sh" >&2; exit 1; }
# the script goes into the package's static/ (git ignores it), which the wheel carries whole
mkdir -p python/ruledlab/static
cp dist/ruledlab-embed.js python/ruledlab/static/
rm -rf dist/python
"$python" -m pip wheel -q --disable-pip-version-check --no-deps -w dist/python ./python
wheel=$(ls dist/python/ruledlab-*.whl)
echo "wheel: $wheel ($(( $(stat -c %s "$wheel") / 1024 )) KiB)"
if [ -x .venv/bin/python ]; then
  .venv/bin/python -m pip install -q --disable-pip-version-check --force-reinstall --no-deps "$wheel"
  echo "wheel: installed into .venv/"
fi
