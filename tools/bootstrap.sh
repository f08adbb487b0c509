#!/usr/bin/env bash
# Create or reuse .venv and install what is missing. Called by `make demo` / `make test`.
# Safe to run repeatedly: each step checks before it acts.
set -euo pipefail
cd "$(dirname "$0")/.."

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
  command -v Xvfb >/dev/null || missing+=(xvfb)        # the real-window UI smoke test
  command -v xdotool >/dev/null || missing+=(xdotool)  # drives that window
  if [ ${#missing[@]} -gt 0 ]; then
    apt_install "${missing[@]}" ||
      echo "bootstrap: warning: missing ${missing[*]} (need root to install); rendering tests will fail" >&2
  fi
fi

# 3. Python packages, re-installed only when pyproject.toml changes
stamp="$VENV/.kge-installed"
if [ ! -f "$stamp" ] || [ pyproject.toml -nt "$stamp" ]; then
  "$VENV/bin/python" -m pip install -q --upgrade pip >/dev/null 2>&1 || true
  "$VENV/bin/python" -m pip install -q -e ".[dev]"
  touch "$stamp"
fi
