"""server.json (the MCP registry entry) agrees with the package: name line in the README, versions, the command."""

from __future__ import annotations

import json
import re
import tomllib

from ewa_mcp.core.paths import REPO_ROOT


def test_server_json_matches_the_package_and_the_readme():
    server = json.loads((REPO_ROOT / "server.json").read_text(encoding="utf-8"))
    project = tomllib.loads((REPO_ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    [package] = server["packages"]
    assert package["registryType"] == "pypi" and package["identifier"] == project["name"]
    assert server["version"] == package["version"] == project["version"]
    assert package["runtimeHint"] == "uvx" and package["transport"] == {"type": "stdio"}
    assert [a["value"] for a in package["packageArguments"]] == ["serve"]
    assert server["$schema"].startswith("https://static.modelcontextprotocol.io/schemas/")
    assert re.fullmatch(r"io\.github\.[A-Za-z0-9-]+/[A-Za-z0-9._-]+", server["name"])
    assert len(server["description"]) <= 100  # the registry's limit
    readme = (REPO_ROOT / "README.md").read_text(encoding="utf-8")
    assert f"mcp-name: {server['name']}" in readme  # the registry's PyPI ownership check reads this line
