#!/usr/bin/env bash
# Installs what ruledlab needs to build (and, with --browser, to test), skipping whatever
# is already there: the wasm32 target, wasm-bindgen-cli at exactly Cargo.lock's version,
# the npm packages, and with --browser Debian's chromium and chromium-driver, firefox-esr with
# xvfb, geckodriver, cargo-fuzz, LinuxCNC's G-code interpreter rs274 (Debian's linuxcnc-uspace
# without its recommends: just under a minute and ~85 packages, Tcl/Tk and Python among them; with
# the recommends it would pull a realtime kernel), and the programs the figure exports are checked
# with: LaTeX (pdflatex and lualatex with TikZ), poppler's pdftoppm and librsvg's rsvg-convert, and
# libxml2-utils' xmllint, which validates the SCORM manifests.
# With --browser or --docs also mdBook, which builds the book (scripts/docs.sh). With --browser
# also a Python virtual environment .venv/ (JupyterLab, anywidget, NumPy, pytest, setuptools, ezdxf
# from PyPI) for the notebook widget in python/ and its test in a real JupyterLab.
# Only package registries are used; nothing downloads a binary or a browser of its own.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

say() { printf '\033[1msetup:\033[0m %s\n' "$*"; }

command -v cargo >/dev/null || { echo "setup: cargo not found; install Rust with rustup first" >&2; exit 1; }
command -v npm >/dev/null || { echo "setup: npm not found; install Node.js 20+ first" >&2; exit 1; }
# building and testing need Node.js 20 (the package's own "engines" is what it needs to run: 16.4)
node -e 'process.exit(Number(process.versions.node.split(".")[0]) >= 20 ? 0 : 1)' ||
  { echo "setup: Node.js $(node --version) is too old to build ruledlab; install Node.js 20+ (the built package runs from 16.4)" >&2; exit 1; }

if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
  say "adding the wasm32-unknown-unknown target"
  rustup target add wasm32-unknown-unknown
fi

# wasm-bindgen-cli must equal the wasm-bindgen crate in Cargo.lock.
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}' || true)
if [ "$have" != "$want" ]; then
  say "installing wasm-bindgen-cli $want (found '${have:-none}'; takes about 3 minutes once)"
  cargo install wasm-bindgen-cli --version "$want" --force
fi

# npm packages: reinstall only when package-lock.json changed since the last install.
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  say "installing npm packages"
  if [ -f package-lock.json ]; then npm ci --no-audit --no-fund; else npm install --no-audit --no-fund; fi
fi

# mdBook builds the book (docs/, scripts/docs.sh): from crates.io, compiled like the other tools
if [ "${1:-}" = "--browser" ] || [ "${1:-}" = "--docs" ]; then
  if [ "$(mdbook --version 2>/dev/null || true)" != "mdbook v0.5.4" ]; then
    say "installing mdBook 0.5.4 from crates.io (about ten minutes once on 2 cores)"
    cargo install mdbook --version 0.5.4 --locked
  fi
fi

if [ "${1:-}" = "--browser" ]; then
  if ! command -v cargo-fuzz >/dev/null; then
    say "installing cargo-fuzz (about a minute once)"
    cargo install cargo-fuzz --version 0.13.2
  fi
  if ! command -v chromium >/dev/null || ! command -v chromedriver >/dev/null; then
    say "installing Debian's chromium and chromium-driver"
    sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium chromium-driver >/dev/null
  fi
  # The second engine: Debian's Firefox ESR, headed under Xvfb (headless Firefox has no WebGL2
  # here), driven through geckodriver built from crates.io.
  if ! command -v firefox-esr >/dev/null || ! command -v xvfb-run >/dev/null || ! command -v xauth >/dev/null; then
    say "installing Debian's firefox-esr, xvfb and xauth"
    sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq firefox-esr xvfb xauth >/dev/null
  fi
  # LinuxCNC's own interpreter reads the LinuxCNC programs of the G-code post (tests/controller.rs)
  if ! command -v rs274 >/dev/null; then
    say "installing Debian's linuxcnc-uspace for rs274, LinuxCNC's G-code interpreter (just under a minute once)"
    sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends linuxcnc-uspace >/dev/null
  fi
  # The readers of the figure exports (tests/page/print.test.mjs): pdflatex and lualatex with
  # TikZ, pdftoppm to look at a PDF's pages, rsvg-convert to turn the SVG into PDF. Without
  # recommends: 24 packages, 49 s once (measured 2026-12-02, apt-get update included).
  if ! command -v pdflatex >/dev/null || ! command -v lualatex >/dev/null || ! command -v pdftoppm >/dev/null \
    || ! command -v rsvg-convert >/dev/null || ! kpsewhich tikz.sty >/dev/null 2>&1; then
    say "installing Debian's LaTeX (texlive-latex-base, -pictures, -luatex, -latex-recommended), poppler-utils, librsvg2-bin"
    sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends -o DPkg::Lock::Timeout=900 \
      texlive-latex-base texlive-pictures texlive-luatex texlive-latex-recommended poppler-utils librsvg2-bin >/dev/null
  fi
  # xmllint validates the SCORM manifests against the ADL/IMS schemas they carry (tests/node/course.test.mjs)
  if ! command -v xmllint >/dev/null; then
    say "installing Debian's libxml2-utils (xmllint)"
    sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends -o DPkg::Lock::Timeout=900 libxml2-utils >/dev/null
  fi
  if ! command -v geckodriver >/dev/null; then
    say "installing geckodriver 0.37 from crates.io (about two minutes once)"
    cargo install geckodriver --version 0.37.0 --locked
  fi
fi

# The notebook widget (python/): its wheel is built and tested with these, and JupyterLab runs the
# example notebook (tests/page/notebook.test.mjs); ezdxf reads the flat patterns' DXF back
# (tests/paper_models.rs). Remade only when the list below changes.
if [ "${1:-}" = "--browser" ]; then
  PY_PACKAGES="jupyterlab==4.6.6 notebook==7.6.5 anywidget==0.11.0 numpy==2.4.6 pytest==9.2.0 mypy==2.4.1 maturin==1.16.0 nbconvert==7.17.2 nbclient==0.11.0 ipykernel==7.4.0 ezdxf==1.4.5"
  if [ "$(cat .venv/ruledlab-packages 2>/dev/null || true)" != "$PY_PACKAGES" ]; then
    if ! python3 -c 'import venv, ensurepip' 2>/dev/null; then
      say "installing Debian's python3-venv"
      sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
      $sudo apt-get update -qq
      DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq python3-venv >/dev/null
    fi
    say "making the Python environment .venv/ (JupyterLab, anywidget, NumPy, pytest; about a minute once)"
    python3 -m venv .venv
    .venv/bin/python -m pip install -q --disable-pip-version-check $PY_PACKAGES
    echo "$PY_PACKAGES" > .venv/ruledlab-packages
  fi
fi
