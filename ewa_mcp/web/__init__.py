"""The web environment: a Playwright-driven Chromium with WebArena's action grammar.

Importing this package does not import Playwright; ``ewa_mcp.web.env`` does.
``find_chromium`` (in ``ewa_mcp.web.chromium``) is the browser discovery other parts may reuse.
"""
