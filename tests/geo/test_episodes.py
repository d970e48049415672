"""Geolocation episodes through a real in-process MCP client: the oracle scores 100 % on all
levels, settings and options behave, and bad input is refused without changing anything."""

from __future__ import annotations

import json
from typing import Any

import pytest
from ewa_mcp.envs.geo.checks import grade_geolocation
from mcp import Client

from ewa_mcp.core.environment import Environment, Observation
from ewa_mcp.envs.geo.taskgen.geolocation import generate_tasks
from ewa_mcp.server import ServerConfig, build_server

pytestmark = pytest.mark.anyio

SAMPLE = ["geo-0018", "geo-0003", "geo-0122", "geo-0042", "geo-0102", "geo-0066", "geo-0158", "geo-0026",
          "geo-0164"]


class WikiStandIn(Environment):
    """The web side of embodied tasks is the browser engineer's; these tests exercise the
    geolocation world only, so the web environment is a minimal stand-in."""

    side = "web"
    name = "browser"

    def __init__(self, episode: Any, services: Any):
        pass

    async def reset(self, task, options):
        return None

    async def observe(self) -> Observation:
        return Observation(text="(wiki)")

    async def final_state(self) -> dict[str, Any]:
        return {}


@pytest.fixture(scope="module")
def task_dir(tmp_path_factory):
    directory = tmp_path_factory.mktemp("geo-tasks")
    generate_tasks(directory)
    return directory


@pytest.fixture
def server(task_dir, tmp_path):
    mcp, episodes = build_server(ServerConfig(task_dirs=[task_dir], run_dir=tmp_path / "run",
                                              environments={"browser": WikiStandIn}))
    return mcp, episodes, tmp_path / "run"


def text_of(result) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


async def start(client, task_id: str, options: dict | None = None) -> tuple[str, Any]:
    args: dict[str, Any] = {"task_id": task_id}
    if options:
        args["options"] = options
    r = await client.call_tool("start_episode", args)
    assert not r.is_error, text_of(r)
    return r.structured_content["episode_id"], r


async def status(client, episode_id: str) -> dict:
    return (await client.call_tool("episode_status", {"episode_id": episode_id})).structured_content


@pytest.mark.parametrize("setting", ["baseline", "embodied"])
async def test_oracle_scores_100_percent_on_every_level(server, setting):
    mcp, episodes, run_dir = server
    async with Client(mcp) as client:
        for prefix in SAMPLE:
            task = episodes.tasks.get(f"{prefix}-{setting}")
            episode_id, _ = await start(client, task.id)
            for call in task.oracle:
                r = await client.call_tool(call.tool, {"episode_id": episode_id, **call.args})
                assert not r.is_error, f"{task.id} {call.tool}: {text_of(r)}"
            final = json.loads((run_dir / episode_id / "final_state.json").read_text(encoding="utf-8"))
            assert final["status"] == "finished"
            assert final["environments"]["embodied"]["setting"] == setting
            result = grade_geolocation(task.answer, final["submission"])
            assert result["all_levels"] is True, (task.id, result)
            assert result["distance_km"] == 0 and result["score"] == 5000 and all(result["bands"].values())


async def test_embodied_moves_views_and_neighbours(server):
    mcp, _, run_dir = server
    async with Client(mcp) as client:
        episode_id, r = await start(client, "geo-0122-embodied")
        obs = r.structured_content["observation"]
        assert [v["heading"] for v in obs["views"]] == ["north", "east", "south", "west"]
        assert {n["id"] for n in obs["neighbours"]} == {"p1", "p2"} and obs["can_move"]
        assert not any(c.type == "image" for c in r.content)  # text mode: descriptions only
        r = await client.call_tool("geo_move", {"episode_id": episode_id, "neighbour": "p1"})
        assert r.structured_content["observation"]["standpoint"] == "p1"
        facing = r.structured_content["observation"]["facing"]
        r = await client.call_tool("geo_move", {"episode_id": episode_id, "direction": "forward"})  # on to p3
        assert not r.is_error and r.structured_content["observation"]["standpoint"] == "p3"
        assert r.structured_content["observation"]["facing"] == facing
        r = await client.call_tool("geo_look", {"episode_id": episode_id, "direction": "south"})
        views = r.structured_content["observation"]["views"]
        assert [v["heading"] for v in views] == ["south"] and r.structured_content["observation"]["facing"] == "south"
        # Observations carry no coordinates and no place names.
        def keys(obj):
            if isinstance(obj, dict):
                for k, v in obj.items():
                    yield k
                    yield from keys(v)
            elif isinstance(obj, list):
                for v in obj:
                    yield from keys(v)
        assert not {"lat", "lng", "location_id", "city", "country"} & set(keys(r.structured_content))
        state = await status(client, episode_id)
        assert state["steps"] == 4  # every call counts: two moves, a look and this status call
    trajectory = (run_dir / episode_id / "trajectory.jsonl").read_text(encoding="utf-8").splitlines()
    assert [json.loads(line)["tool"] for line in trajectory][-4:] == ["geo_move", "geo_move", "geo_look", "episode_status"]


async def test_bad_moves_and_looks_change_nothing(server):
    mcp, _, _ = server
    async with Client(mcp) as client:
        episode_id, _ = await start(client, "geo-0057-embodied")  # a north-south street: nothing to the left
        for args, expected in (({"neighbour": "p3"}, "not adjacent"), ({"neighbour": "zz"}, "unknown neighbour"),
                               ({"direction": "left"}, "no neighbour left"), ({}, "exactly one"),
                               ({"direction": "north", "neighbour": "p1"}, "exactly one")):
            r = await client.call_tool("geo_move", {"episode_id": episode_id, **args})
            assert r.is_error and expected in text_of(r) and "p1" in text_of(r), text_of(r)
        r = await client.call_tool("get_observation", {"episode_id": episode_id})
        assert r.structured_content["observation"]["standpoint"] == "p0"
        assert r.structured_content["observation"]["facing"] == "north"
        assert (await status(client, episode_id))["status"] == "running"

        base_id, r = await start(client, "geo-0122-baseline")
        assert [v["heading"] for v in r.structured_content["observation"]["views"]] == ["north"]
        assert r.structured_content["observation"]["neighbours"] == []
        r = await client.call_tool("geo_move", {"episode_id": base_id, "neighbour": "p1"})
        assert r.is_error and "baseline" in text_of(r)
        r = await client.call_tool("geo_look", {"episode_id": base_id, "direction": "east"})
        assert r.is_error and "north" in text_of(r)


async def test_setting_option_overrides_the_task_and_vision_mode_sends_images(server):
    mcp, _, run_dir = server
    async with Client(mcp) as client:
        episode_id, r = await start(client, "geo-0003-embodied", {"geolocation_setting": "baseline",
                                                                 "observation": "vision"})
        obs = r.structured_content["observation"]
        assert obs["setting"] == "baseline" and len(obs["views"]) == 1 and "description" not in obs["views"][0]
        images = [c for c in r.content if c.type == "image"]
        assert len(images) == 1 and images[0].mime_type == "image/png"

        episode_id, r = await start(client, "geo-0003-baseline", {"geolocation_setting": "embodied",
                                                                 "observation": "both"})
        obs = r.structured_content["observation"]
        assert obs["setting"] == "embodied" and obs["can_move"] and len(obs["views"]) == 4
        assert all("description" in v for v in obs["views"])
        assert sum(c.type == "image" for c in r.content) == 4
        r = await client.call_tool("geo_move", {"episode_id": episode_id, "neighbour": "p2"})
        assert not r.is_error
        # each image is linked as a resource that reads back the same PNG, for clients that drop inline images
        links = [c for c in r.content if c.type == "resource_link"]
        inline = [c for c in r.content if c.type == "image"]
        assert len(links) == 4 and [str(c.uri).rsplit("-", 1)[-1] for c in links] == ["0.png", "1.png", "2.png",
                                                                                        "3.png"]
        fetched = await client.read_resource(str(links[2].uri))
        assert fetched.contents[0].blob == inline[2].data


@pytest.mark.parametrize("args,expected", [
    ({"lat": 91.0, "lng": 0.0}, "latitude must be a number from -90"),
    ({"lat": -90.5, "lng": 0.0}, "latitude must be a number from -90"),
    ({"lat": 10.0, "lng": 180.01}, "longitude must be a number from -180"),
    ({"lat": 10.0, "lng": 20.0, "continent": "Atlantis"}, "North America"),
    ({"lat": 10.0, "lng": 20.0, "continent": "America"}, "South America"),
    ({"lat": 10.0, "lng": 20.0, "country": "Narnia"}, "ISO 3166"),
    ({"lat": 10.0, "lng": 20.0, "country": "Frnace"}, "France"),
])
async def test_invalid_submissions_are_refused_and_the_episode_stays_open(server, args, expected):
    mcp, _, run_dir = server
    async with Client(mcp) as client:
        episode_id, _ = await start(client, "geo-0018-baseline")
        r = await client.call_tool("submit_location", {"episode_id": episode_id, **args})
        assert r.is_error and expected in text_of(r), text_of(r)
        state = await status(client, episode_id)
        # the refused submission and this status call are steps, like every call
        assert state["status"] == "running" and state["steps"] == 2 and state["answer"] is None
        r = await client.call_tool("submit_location", {"episode_id": episode_id, "lat": 48.86, "lng": 2.32,
                                                      "country": "FR", "continent": "EU"})
        assert not r.is_error
        assert r.structured_content["submission"]["country"] == "FR"
        final = json.loads((run_dir / episode_id / "final_state.json").read_text(encoding="utf-8"))
        assert final["submission"]["lat"] == 48.86 and final["answer"].startswith("48.86000, 2.32000")
        r = await client.call_tool("submit_location", {"episode_id": episode_id, "lat": 1.0, "lng": 1.0})
        assert r.is_error and "has ended" in text_of(r)


async def test_geo_tools_refuse_other_domains(server, tmp_path):
    mcp, episodes, _ = server
    async with Client(mcp) as client:
        r = await client.call_tool("geo_look", {"episode_id": "ep-nonexistent"})
        assert r.is_error and "unknown episode" in text_of(r)
        tools = {t.name: t for t in (await client.list_tools()).tools}
        for name in ("geo_look", "geo_move", "submit_location"):
            assert tools[name].output_schema, name
        assert set(tools["submit_location"].input_schema["required"]) == {"episode_id", "lat", "lng"}


async def test_completion_is_the_fraction_of_levels_right(server):
    # Issue 15 item 7: a submission right at continent and country but wrong at city and street
    # completes half the task; overall success stays "every level right".
    from ewa_mcp.graders.aggregate import domain_aggregate
    from ewa_mcp.graders.episode import grade_episode

    mcp, episodes, run_dir = server
    task = episodes.tasks.get("geo-0018-baseline")
    async with Client(mcp) as client:
        half, _ = await start(client, task.id)
        r = await client.call_tool("submit_location", {
            "episode_id": half, "lat": 0.0, "lng": 0.0, "continent": task.answer.continent,
            "country": task.answer.country, "city": "Nowhere", "street": "No Street"})
        assert not r.is_error, text_of(r)
        full, _ = await start(client, task.id)
        for call in task.oracle:
            await client.call_tool(call.tool, {"episode_id": full, **call.args})
    half_result, full_result = grade_episode(run_dir / half), grade_episode(run_dir / full)
    assert half_result.completion == 0.5 and half_result.overall_success is False
    assert half_result.geolocation["completion"] == 0.5
    assert full_result.completion == 1.0 and full_result.overall_success is True
    aggregate = domain_aggregate("geolocation", [half_result, full_result])
    assert aggregate.completion_rate.value == 0.75 and aggregate.overall_accuracy.value == 0.5
