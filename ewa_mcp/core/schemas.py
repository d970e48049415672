"""Tool schemas every MCP client can use: no ``$ref``/``$defs``, closed argument objects.

pydantic writes nested models as ``$ref`` into ``$defs``; several clients (the OpenAI Agents SDK's strict
mode, some Gemini and LangChain converters) reject or mangle that. The server inlines every reference once,
at start, so the published input and output schemas are self-contained. Argument objects are closed
(``additionalProperties: false``), as OpenAI strict mode requires; the SDK's validation is unchanged.
"""

from __future__ import annotations

import copy
from typing import Any


class SchemaError(ValueError):
    """A schema that cannot be made portable (a recursive model); the message names the definition."""


def inline_refs(schema: dict[str, Any]) -> dict[str, Any]:
    """A copy of ``schema`` with every local ``#/$defs/...`` reference replaced by the definition itself."""
    defs = schema.get("$defs", {}) or schema.get("definitions", {})

    def walk(node: Any, seen: tuple[str, ...]) -> Any:
        if isinstance(node, list):
            return [walk(item, seen) for item in node]
        if not isinstance(node, dict):
            return node
        ref = node.get("$ref")
        if isinstance(ref, str):
            name = ref.rsplit("/", 1)[-1]
            if name not in defs:
                raise SchemaError(f"schema reference {ref[:200]!r} has no definition")
            if name in seen:
                raise SchemaError(f"{name} refers to itself; a recursive model cannot be inlined")
            merged = {**copy.deepcopy(defs[name]), **{k: v for k, v in node.items() if k != "$ref"}}
            return walk(merged, (*seen, name))
        return {k: walk(v, seen) for k, v in node.items() if k not in ("$defs", "definitions")}

    return walk(schema, ())


def close_objects(schema: Any) -> Any:
    """Set ``additionalProperties: false`` on every object schema with named properties that leaves it open."""
    if isinstance(schema, list):
        return [close_objects(item) for item in schema]
    if not isinstance(schema, dict):
        return schema
    out = {k: close_objects(v) for k, v in schema.items()}
    if (out.get("type") == "object" or "properties" in out) and "additionalProperties" not in out:
        out["additionalProperties"] = False
    return out


def make_portable(mcp: Any) -> None:
    """Rewrite the published schemas of every tool registered on ``mcp`` (an MCPServer) in place."""
    for tool in mcp._tool_manager.list_tools():  # the SDK keeps no public setter for a tool's schemas
        tool.parameters = close_objects(inline_refs(tool.parameters))
        meta = tool.fn_metadata
        if meta.output_schema is not None:
            meta.output_schema = inline_refs(meta.output_schema)
