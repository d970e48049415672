"""Shared by the training tests: embodied-only variants of suite tasks (no browser), and a task per domain."""

from __future__ import annotations

from ewa_mcp.task_variants import embodied_only  # noqa: F401  (the tests' import path)

# One task per domain (the first of its domain in id order has each domain's usual shape).
ONE_PER_DOMAIN = {
    "navigation": "navigation-boston-000",
    "cooking": "cooking-buy-0001",
    "shopping": "shopping-calories-000",
    "traveling": "traveling-boston-005",
    "geolocation": "geo-0018-baseline",
}
