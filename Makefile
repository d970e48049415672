# Two commands on a fresh machine: `make run` (the main job on the embedded defaults) and
# `make test`. Both create .venv, install the project and make sure a Chromium exists.
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.ewa-installed

.PHONY: run test install chromium bench clean

run: install chromium
	$(BIN)/ewa-mcp demo

test: install chromium
	$(BIN)/pytest

install: $(STAMP)

$(BIN)/python:
	$(PYTHON) -c 'import sys; sys.exit(0 if sys.version_info >= (3, 11) else "ewa-mcp needs Python >= 3.11; set PYTHON=python3.11")'
	$(PYTHON) -m venv $(VENV)

$(STAMP): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install -q --disable-pip-version-check -e ".[test,ai2thor]"
	touch $(STAMP)

chromium:
	@scripts/ensure-chromium.sh

bench: install chromium
	for script in benchmarks/bench_*.py; do echo "== $$script"; $(BIN)/python $$script || exit 1; done

clean:
	rm -rf $(VENV) runs .pytest_cache
