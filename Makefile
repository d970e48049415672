# Two commands on a fresh machine: `make run` (the main job on the embedded defaults) and
# `make test`. Both create .venv, install the project and make sure a Chromium and OpenGL through EGL exist.
SHELL := /bin/bash
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.ewa-installed

LOCK := requirements.lock
# Installed without their dependencies (their versions are in the lock): openenv-core 0.3 requires Gradio for an
# optional web UI, and Gradio requires pillow<13; verifiers 0.4 pins mcp==2.0.0 and openai<3. The `openenv` and
# `verifiers` extras (both in `test`) list the dependencies they do need.
NODEPS := openenv-core verifiers

.PHONY: run test test-slow lint install lock chromium egl bench clean

# The main job on the embedded defaults: the oracle plays a deterministic sample of every domain
# through the real MCP server, then the run is graded and the paper-shaped table printed.
run: install chromium egl
	$(BIN)/ewa-mcp eval --agent oracle --sample 3 --workers 2

# The suite but its end-to-end tests (marked slow: wheels built and installed, every Inspect task, workers killed,
# training runs), which `make test-slow` runs; CI runs both (.ci/run).
test: install chromium egl lint
	$(BIN)/pytest -m "not slow"

test-slow: install chromium egl
	$(BIN)/pytest -m slow

# Bug-finding lint rules, the type checker and the import contracts, all configured in pyproject.toml.
# The contracts and the type checker run on the installed layout (websites/ and graders/ inside ewa_mcp/, as the
# wheel installs them), mirrored into .lint/; mypy's paths are mapped back to the checkout's.
lint: install
	$(BIN)/ruff check --quiet .
	$(BIN)/python scripts/installed_layout.py .lint >/dev/null
	cd .lint && PYTHONPATH=. ../$(BIN)/lint-imports --config ../pyproject.toml --no-cache
	cd .lint && ../$(BIN)/mypy --config-file ../pyproject.toml --cache-dir ../.mypy_cache ewa_mcp \
	  | sed -e 's#^ewa_mcp/websites/#websites/#' -e 's#^ewa_mcp/graders/#graders/#'; exit $${PIPESTATUS[0]}

install: $(STAMP)

$(BIN)/python:
	$(PYTHON) -c 'import sys; sys.exit(0 if sys.version_info >= (3, 11) else "ewa-mcp needs Python >= 3.11; set PYTHON=python3.11")'
	$(PYTHON) -m venv $(VENV)

# pyproject.toml declares compatible ranges; requirements.lock holds the exact versions installed here and in CI.
$(STAMP): pyproject.toml $(LOCK) | $(BIN)/python
	$(BIN)/python -m pip install -q --disable-pip-version-check -c $(LOCK) -e ".[test,ai2thor]"
	$(BIN)/python -m pip install -q --disable-pip-version-check --no-deps -c $(LOCK) $(NODEPS)
	touch $(STAMP)

# Re-resolve the newest versions the ranges allow, in a fresh environment, and write them to requirements.lock.
# Then run `make test` and commit the lock (docs/architecture.md, "Dependencies").
lock:
	rm -rf .venv-lock
	$(PYTHON) -m venv .venv-lock
	.venv-lock/bin/python -m pip install -q --disable-pip-version-check -e ".[test,ai2thor]"
	.venv-lock/bin/python -m pip install -q --disable-pip-version-check --no-deps $(NODEPS)
	( echo "# Exact versions for \`make install\` and CI: pip install -c requirements.lock -e '.[test,ai2thor]'"; \
	  echo "# Written by \`make lock\` from the ranges in pyproject.toml; do not edit by hand."; \
	  .venv-lock/bin/python -m pip freeze --disable-pip-version-check --exclude-editable ) > $(LOCK)
	rm -rf .venv-lock

chromium:
	@scripts/ensure-chromium.sh
	@scripts/ensure-fonts.sh

# Mesa's EGL and OpenGL drivers for the first-person kitchen camera (CPU rendering where no GPU driver is).
egl:
	@scripts/ensure-egl.sh

bench: install chromium egl
	for script in benchmarks/bench_*.py; do echo "== $$script"; $(BIN)/python $$script || exit 1; done

clean:
	rm -rf $(VENV) .venv-lock runs .pytest_cache .mypy_cache .ruff_cache .import_linter_cache .lint
