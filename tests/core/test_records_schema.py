"""The record formats are declared once (ewa_mcp/core/records.py), exported to docs/records.schema.json, and what
the server writes fits them: the committed schema is current, and a real episode's every record validates against
the exported JSON Schema (not only the pydantic models it was made from)."""

from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import pytest
from mcp import Client

from ewa_mcp.core.records import FinalState, TrajectoryLine, export_records_schema
from ewa_mcp.server import ServerConfig, build_server

ROOT = Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.anyio


def test_the_committed_schema_is_current():
    committed = json.loads((ROOT / "docs" / "records.schema.json").read_text(encoding="utf-8"))
    assert committed == export_records_schema(), "regenerate: python -m ewa_mcp.core.records > docs/records.schema.json"


def test_required_fields_are_required():
    assert {"step", "tool", "args", "ok", "error", "counted", "observation", "t", "time", "duration_ms",
            "environment"} <= set(TrajectoryLine.model_json_schema()["required"])
    assert {"schema_version", "episode_id", "task_id", "domain", "status", "end_reason"} <= set(
        FinalState.model_json_schema()["required"])


async def test_a_real_episodes_records_fit_the_exported_schema(tmp_path):
    schema = export_records_schema()

    def check(kind: str, record: dict) -> None:
        jsonschema.validate(record, {"$defs": schema["$defs"], "$ref": f"#/$defs/{kind}"})

    mcp, _ = build_server(ServerConfig(run_dir=tmp_path))
    async with Client(mcp) as client:
        started = await client.call_tool("start_episode", {"task_id": "navigation-boston-000"})
        episode_id = started.structured_content["episode_id"]
        await client.call_tool("switch_environment", {"episode_id": episode_id, "target": "embodied"})
        await client.call_tool("street_move", {"episode_id": episode_id, "direction": "sideways"})  # refused
        await client.call_tool("finish_episode", {"episode_id": episode_id})
    folder = tmp_path / episode_id
    lines = [json.loads(line) for line in (folder / "trajectory.jsonl").read_text().splitlines()]
    assert len(lines) == 4
    for line in lines:
        check("trajectory_line", line)
    for line in (folder / "web_events.jsonl").read_text().splitlines():
        check("web_event", json.loads(line))
    check("final_state", json.loads((folder / "final_state.json").read_text()))
    with pytest.raises(jsonschema.ValidationError):
        check("final_state", {"status": "finished"})
