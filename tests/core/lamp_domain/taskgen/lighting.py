"""The lighting tasks: turn the lamp on (it starts off), or leave it on."""

from __future__ import annotations

from ewa_mcp.core.taskmodel import StartState, Task, ToolCall


def generate() -> list[Task]:
    tasks = []
    for number, lit in enumerate((False, True)):
        oracle = [] if lit else [ToolCall(tool="lamp_switch", args={"state": "on"})]
        tasks.append(Task(
            id=f"lighting-{number:03d}",
            domain="lighting",
            difficulty="easy",
            intent="Make sure the lamp is on, then finish.",
            start=StartState.model_validate({"environment": "embodied", "embodied": {"kind": "lamp", "lit": lit}}),
            embodied_goals=[{"kind": "lamp_lit", "lit": True}],
            step_limit=5,
            oracle=[*oracle, ToolCall(tool="finish_episode", args={})],
        ))
    return tasks
