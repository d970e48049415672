#!/usr/bin/env sh
# Claude Code: add ewa-mcp as a stdio server for this user (every project), run with uvx from PyPI.
# The domains' prompts then appear as /mcp__ewa-mcp__cooking, /mcp__ewa-mcp__navigation, ...
claude mcp add --scope user ewa-mcp --env EWA_RUNS_DIR="$HOME/ewa-runs" -- uvx ewa-mcp serve
# Without uv: claude mcp add --scope user ewa-mcp -- pipx run ewa-mcp serve
