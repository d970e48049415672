"""The eval runner: agents that play tasks through the real MCP server, and the run orchestration."""
