#!/usr/bin/env bash
# Create or reuse .venv and install what is missing. Called by `make demo` (profile
# `demo`: kge and its runtime dependencies only) and `make test` (profile `test`: also
# the test tools and every extra the suite exercises). Safe to run repeatedly: each
# step checks before it acts, and says what it installs and how long it took.
set -euo pipefail
cd "$(dirname "$0")/.."
PROFILE=${1:-test}
case "$PROFILE" in demo|test) ;; *) echo "bootstrap: unknown profile $PROFILE (demo or test)" >&2; exit 2;; esac

PY=${PYTHON:-python3}
VENV=.venv

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then sudo "$@"; else return 1; fi; }
apt_install() {
  command -v apt-get >/dev/null || return 1
  echo "bootstrap: installing Debian packages: $*"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq >/dev/null &&
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@" >/dev/null
}

"$PY" -c 'import sys; sys.exit(sys.version_info < (3, 11))' || {
  echo "bootstrap: kge needs Python >= 3.11 (found $("$PY" --version 2>&1))" >&2; exit 1; }

# 1. virtual environment (Debian's python3 needs python3-venv for ensurepip)
if [ ! -x "$VENV/bin/python" ]; then
  if ! "$PY" -m venv "$VENV" 2>/dev/null; then
    rm -rf "$VENV"
    ver=$("$PY" -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")')
    apt_install "python${ver}-venv" || apt_install python3-venv || {
      echo "bootstrap: cannot create a venv; install python3-venv" >&2; exit 1; }
    "$PY" -m venv "$VENV"
  fi
fi

# 2. system libraries for headless GL and text (only when missing, only when we can)
missing=()
have_lib() { ldconfig -p 2>/dev/null | grep -q "$1"; }
if command -v ldconfig >/dev/null && command -v apt-get >/dev/null; then
  have_lib 'libGL.so.1' || missing+=(libgl1)
  have_lib 'libEGL.so.1' || missing+=(libegl1)
  have_lib 'libfontconfig.so.1' || missing+=(libfontconfig1)
  if [ "$PROFILE" = test ]; then
    command -v Xvfb >/dev/null || missing+=(xvfb)        # the real-window tests
    command -v xdotool >/dev/null || missing+=(xdotool)  # drives those windows
  fi
  if [ ${#missing[@]} -gt 0 ]; then
    apt_install "${missing[@]}" ||
      echo "bootstrap: warning: missing ${missing[*]} (need root to install); rendering tests will fail" >&2
  fi
fi

# 3. Python packages, re-installed only when pyproject.toml changes. The test profile
#    includes the demo's, so a venv made by `make test` serves `make demo` as it is.
fresh() { [ -f "$1" ] && [ ! pyproject.toml -nt "$1" ]; }
pip_step() {  # pip_step WHAT STAMP SPEC
  local start=$SECONDS
  echo "bootstrap: installing $1..."
  "$VENV/bin/python" -m pip install -q -e "$3"
  touch "$2"
  echo "bootstrap: installed in $((SECONDS - start)) s"
}
demo_stamp="$VENV/.kge-installed-demo"
test_stamp="$VENV/.kge-installed-test"
if ! fresh "$test_stamp" && ! fresh "$demo_stamp"; then
  "$VENV/bin/python" -m pip install -q --upgrade pip >/dev/null 2>&1 || true
  pip_step "kge and its runtime dependencies (pymunk, esper, pyglet, numpy, Pillow, soundfile, zstandard)" \
    "$demo_stamp" "."
fi
if [ "$PROFILE" = test ] && ! fresh "$test_stamp"; then
  pip_step "the test tools and extras (pytest, ruff, mypy, Gymnasium, pygame, pybox2d, Ray/RLlib, PyTorch CPU: about 2 GB, a few minutes the first time)" \
    "$test_stamp" ".[dev]"
fi
