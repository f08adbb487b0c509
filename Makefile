# The two commands of the README. Each bootstraps .venv (and headless GL
# libraries on Debian when run as root) before it runs.
.PHONY: demo test lint bench

PY := .venv/bin/python

demo:
	@tools/bootstrap.sh
	$(PY) -m kge demo

test:
	@tools/bootstrap.sh
	PYGLET_HEADLESS=1 PYGLET_AUDIO=silent $(PY) -m pytest

bench:
	@tools/bootstrap.sh
	@$(PY) -c "import Box2D" 2>/dev/null || $(PY) -m pip install -q -e ".[bench]" || \
	  echo "make bench: could not install pybox2d (box2d 2.3.10); its column is skipped"
	PYGLET_HEADLESS=1 PYGLET_AUDIO=silent $(PY) -m kge bench --breakdown $(BENCH_ARGS)

lint:
	@tools/bootstrap.sh
	$(PY) -m ruff check kge tests examples benchmarks
	$(PY) -m mypy
	.venv/bin/lint-imports
