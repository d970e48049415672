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


# The registry's server.json shape (its published schema, server.schema.json, as of the 2025-12-11 revision that
# server.json names), restated here for the fields this entry uses so the check runs offline.
_INPUT = {"type": "object", "properties": {
    "description": {"type": "string"}, "isRequired": {"type": "boolean"}, "isSecret": {"type": "boolean"},
    "format": {"enum": ["string", "number", "boolean", "filepath"]}, "value": {"type": "string"},
    "default": {"type": "string"}, "placeholder": {"type": "string"},
    "choices": {"type": "array", "items": {"type": "string"}}}}
_ARGUMENT = {"anyOf": [
    {"allOf": [_INPUT, {"required": ["type"], "properties": {"type": {"const": "positional"},
                                                             "valueHint": {"type": "string"},
                                                             "isRepeated": {"type": "boolean"}},
                        "anyOf": [{"required": ["value"]}, {"required": ["valueHint"]}]}]},
    {"allOf": [_INPUT, {"required": ["type", "name"], "properties": {"type": {"const": "named"},
                                                                     "name": {"type": "string"}}}]}]}
_KEY_VALUE = {"allOf": [_INPUT, {"required": ["name"], "properties": {"name": {"type": "string", "minLength": 1}}}]}
_VERSION = {"type": "string", "minLength": 1, "maxLength": 255, "not": {"anyOf": [
    {"const": "latest"}, {"pattern": r"^[\^~<>=]"}, {"pattern": r"(^|\.)[x*](\.|$)"}]}}
SERVER_SHAPE = {
    "type": "object",
    "required": ["name", "description", "version"],
    "additionalProperties": False,
    "properties": {
        "$schema": {"type": "string", "format": "uri"},
        "name": {"type": "string", "pattern": r"^[a-zA-Z0-9.-]+/[a-zA-Z0-9._-]+$", "minLength": 3, "maxLength": 200},
        "title": {"type": "string", "minLength": 1, "maxLength": 100},
        "description": {"type": "string", "minLength": 1, "maxLength": 100},
        "version": _VERSION,
        "websiteUrl": {"type": "string", "format": "uri"},
        "repository": {"type": "object", "required": ["url", "source"]},
        "packages": {"type": "array", "items": {
            "type": "object",
            "additionalProperties": False,
            "required": ["registryType", "identifier", "version", "transport"],
            "properties": {
                "registryType": {"enum": ["npm", "pypi", "oci", "nuget", "mcpb"]},
                "registryBaseUrl": {"type": "string", "format": "uri"},
                "identifier": {"type": "string", "minLength": 1},
                "version": _VERSION,
                "fileSha256": {"type": "string", "pattern": "^[a-f0-9]{64}$"},
                "runtimeHint": {"type": "string"},
                "transport": {"anyOf": [
                    {"type": "object", "required": ["type"], "properties": {"type": {"const": "stdio"}}},
                    {"type": "object", "required": ["type", "url"],
                     "properties": {"type": {"enum": ["streamable-http", "sse"]}, "url": {"type": "string"}}}]},
                "runtimeArguments": {"type": "array", "items": _ARGUMENT},
                "packageArguments": {"type": "array", "items": _ARGUMENT},
                "environmentVariables": {"type": "array", "items": _KEY_VALUE}}}},
        "remotes": {"type": "array"},
        "icons": {"type": "array"},
        "_meta": {"type": "object"},
    },
}


def test_server_json_has_the_registry_shape_and_a_reverse_dns_name():
    import copy

    import jsonschema

    server = json.loads((REPO_ROOT / "server.json").read_text(encoding="utf-8"))
    validator = jsonschema.Draft7Validator(SERVER_SHAPE)
    assert [e.message for e in validator.iter_errors(server)] == []
    # A reverse-DNS namespace (io.github.<owner>) that the README's mcp-name line names, not a placeholder.
    namespace, _, _ = server["name"].partition("/")
    assert namespace.split(".")[:2] == ["io", "github"] and "example" not in server["name"].lower()
    # The shape catches what the registry refuses.
    for field, bad in [("name", "ewa-mcp"), ("description", "x" * 101), ("version", "^0.1.0")]:
        broken = copy.deepcopy(server) | {field: bad}
        assert list(validator.iter_errors(broken)), field
    broken = copy.deepcopy(server)
    broken["packages"][0]["version"] = "latest"
    broken["packages"][0]["command"] = "uvx"
    assert len(list(validator.iter_errors(broken))) >= 2
