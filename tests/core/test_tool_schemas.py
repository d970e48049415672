"""Every published tool schema is portable: self-contained (no $ref/$defs) and, for arguments, within
OpenAI strict mode's rules (closed objects; each property required, nullable or defaulted).

A defaulted property is allowed: strict converters (the OpenAI Agents SDK's) list every property as
required, and a model that must send a value for, say, ``limit`` sends a valid one; nothing is lost."""

from __future__ import annotations

import json

import pytest

from ewa_mcp.core.schemas import SchemaError, close_objects, inline_refs

from .fixtures import listed_tools



def _nullable(prop: dict) -> bool:
    kinds = prop.get("type")
    if kinds == "null" or (isinstance(kinds, list) and "null" in kinds):
        return True
    return any(_nullable(alt) for alt in prop.get("anyOf", []) + prop.get("oneOf", []))


def _strict_problems(schema: dict, where: str) -> list[str]:
    problems = []
    if isinstance(schema, dict):
        if schema.get("type") == "object" or "properties" in schema:
            if schema.get("additionalProperties") is not False:
                problems.append(f"{where}: object is not closed (additionalProperties: false)")
            required = set(schema.get("required", []))
            for name, prop in schema.get("properties", {}).items():
                if name not in required and not _nullable(prop) and "default" not in prop:
                    problems.append(f"{where}.{name}: optional but neither nullable nor defaulted")
        for key, value in schema.items():
            if isinstance(value, dict):
                problems += _strict_problems(value, f"{where}.{key}")
            elif isinstance(value, list):
                for i, item in enumerate(value):
                    problems += _strict_problems(item, f"{where}.{key}[{i}]")
    return problems


def test_no_tool_schema_uses_refs(tmp_path):
    tools = listed_tools(tmp_path)
    assert len(tools) > 20
    for tool in tools:
        for kind, schema in (("input", tool.input_schema), ("output", tool.output_schema)):
            text = json.dumps(schema or {})
            assert "$ref" not in text and "$defs" not in text, f"{tool.name} {kind} schema: {text[:200]}"


def test_every_input_schema_meets_openai_strict_rules(tmp_path):
    problems = []
    for tool in listed_tools(tmp_path):
        problems += _strict_problems(tool.input_schema, tool.name)
    assert not problems, "\n".join(problems)


def test_start_episode_options_are_inlined_and_still_validated(tmp_path):
    start = next(t for t in listed_tools(tmp_path) if t.name == "start_episode")
    options = start.input_schema["properties"]["options"]
    model = next(alt for alt in options["anyOf"] if alt.get("type") == "object")
    assert "observation" in model["properties"] and model["additionalProperties"] is False


def test_inline_refs_resolves_nested_definitions_and_refuses_recursion():
    schema = {"type": "object", "properties": {"a": {"$ref": "#/$defs/A"}},
              "$defs": {"A": {"type": "object", "properties": {"b": {"$ref": "#/$defs/B"}}},
                        "B": {"type": "string"}}}
    assert inline_refs(schema) == {"type": "object", "properties": {
        "a": {"type": "object", "properties": {"b": {"type": "string"}}}}}
    with pytest.raises(SchemaError, match="refers to itself"):
        inline_refs({"$ref": "#/$defs/N", "$defs": {"N": {"properties": {"next": {"$ref": "#/$defs/N"}}}}})
    assert close_objects({"type": "object", "properties": {}})["additionalProperties"] is False
