# The two commands of the README. Each bootstraps .venv (and headless GL
# libraries on Debian when run as root) before it runs.
.PHONY: demo test lint check bench

PY := .venv/bin/python

demo:
	@tools/bootstrap.sh demo
	$(PY) -m kge demo

test:
	@tools/bootstrap.sh test
	@$(MAKE) --no-print-directory check
	PYGLET_HEADLESS=1 PYGLET_AUDIO=silent $(PY) -m pytest

bench:
	@tools/bootstrap.sh test
	@$(PY) -c "import Box2D" 2>/dev/null || $(PY) -m pip install -q -e ".[bench]" || \
	  echo "make bench: could not install pybox2d (box2d 2.3.10); its column is skipped"
	@# Arcade 3 pins pymunk 6.9 (kge needs 7.3): its animation row runs in a venv of its own
	@[ -x .venv-arcade/bin/python ] || { python3 -m venv .venv-arcade && \
	  .venv-arcade/bin/python -m pip install -q "arcade>=3,<4"; } || \
	  echo "make bench: could not make .venv-arcade (Arcade 3); its animation column is skipped"
	PYGLET_HEADLESS=1 PYGLET_AUDIO=silent $(PY) -m kge bench --breakdown $(BENCH_ARGS)

lint:
	@tools/bootstrap.sh test
	@$(MAKE) --no-print-directory check

# The static gates `make test` runs before the suite: ruff, mypy, the import floors.
check:
	@echo "check: ruff"; $(PY) -m ruff check -q kge tests examples benchmarks tools
	@echo "check: mypy"; $(PY) -m mypy
	@echo "check: import contracts"; .venv/bin/lint-imports
