# Two commands on a fresh machine: `make run` (the main job on the embedded defaults) and
# `make test`. Both create .venv, install the project and make sure a Chromium exists.
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.ewa-installed

.PHONY: run test lint install chromium bench clean

# The main job on the embedded defaults: the oracle plays a deterministic sample of every domain
# through the real MCP server, then the run is graded and the paper-shaped table printed.
run: install chromium
	$(BIN)/ewa-mcp eval --agent oracle --sample 3 --workers 2

test: install chromium lint
	$(BIN)/pytest

# Bug-finding lint rules, the type checker and the import contracts, all configured in pyproject.toml.
lint: install
	$(BIN)/ruff check --quiet .
	$(BIN)/lint-imports --no-cache
	$(BIN)/mypy

install: $(STAMP)

$(BIN)/python:
	$(PYTHON) -c 'import sys; sys.exit(0 if sys.version_info >= (3, 11) else "ewa-mcp needs Python >= 3.11; set PYTHON=python3.11")'
	$(PYTHON) -m venv $(VENV)

$(STAMP): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install -q --disable-pip-version-check -e ".[test,ai2thor]"
	touch $(STAMP)

chromium:
	@scripts/ensure-chromium.sh
	@scripts/ensure-fonts.sh

bench: install chromium
	for script in benchmarks/bench_*.py; do echo "== $$script"; $(BIN)/python $$script || exit 1; done

clean:
	rm -rf $(VENV) runs .pytest_cache
