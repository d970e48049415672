"""The built-in worlds, one package each (docs/extending.md, "Add a world").

Every world package has the same files: ``__init__.py`` (its ``EnvironmentSpec`` and the ``Domain``s it
declares, importing nothing heavy), ``env.py`` (the environment), ``actions.py`` (its action table),
``tools.py`` (its MCP tools, generated from the table), ``checks.py`` (the grader's checks of its goal
kinds), ``taskgen/`` (its task generators, one module per domain) and ``README.md`` (its documentation).

The kernel (``ewa_mcp.core``) names none of them: the registry reads the list below, one line per world,
in display order (the order of ``list_tasks``' domains and the report tables).
"""

from __future__ import annotations

from ewa_mcp.core.registry import Domain, load_object

PACKAGES = [
    "ewa_mcp.envs.street:DOMAINS",
    "ewa_mcp.envs.kitchen:DOMAINS",
    "ewa_mcp.envs.geo:DOMAINS",
    "ewa_mcp.envs.browser:DOMAINS",
]

DOMAINS: list[Domain] = [domain for path in PACKAGES for domain in load_object(path)]
