# The two commands of the README. Each bootstraps .venv (and headless GL
# libraries on Debian when run as root) before it runs.
.PHONY: demo test lint bench fuzz soak

PY := .venv/bin/python

demo:
	@tools/bootstrap.sh
	$(PY) -m kge demo

test:
	@tools/bootstrap.sh
	PYGLET_HEADLESS=1 PYGLET_AUDIO=silent $(PY) -m pytest

lint:
	@tools/bootstrap.sh
	$(PY) -m ruff check kge tests examples benchmarks
	$(PY) -m mypy
