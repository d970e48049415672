"""MCP tool groups: one module per group, each with ``register(mcp, episodes)``."""
