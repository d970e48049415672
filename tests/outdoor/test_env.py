"""The street environment: moves, refused moves, stop, the final state, no goal leakage."""

import json

import pytest

from ewa_mcp.environment import EnvError
from ewa_mcp.outdoor.env import StreetEnvironment
from ewa_mcp.outdoor.geo import angle_diff
from ewa_mcp.services import Services
from ewa_mcp.taskmodel import Task


def make_task(world, start_query="5th Ave & W 23rd St", heading=29.0, goal="store-target-herald-square"):
    start = world.search(start_query, city="manhattan")[0]
    target = world.place(goal)
    return Task.model_validate({
        "id": "nav-test", "domain": "navigation", "intent": "Walk to the store.",
        "start": {"environment": "embodied",
                  "embodied": {"kind": "street", "city": "manhattan", "node": start.node, "heading": heading}},
        "embodied_goals": [{"kind": "reached_place", "city": "manhattan", "node": target.node,
                            "lat": target.lat, "lng": target.lng, "place_id": goal}],
    })


async def started(world, **kw):
    env = StreetEnvironment(episode=None, services=Services())
    await env.reset(make_task(world, **kw), {"observation": "text"})
    return env


@pytest.mark.anyio
async def test_forward_follows_the_heading_and_updates_state(world):
    env = await started(world)
    before = env.graph.ids[env.node]
    obs = env.move(direction="forward")
    assert env.graph.ids[env.node] != before
    assert abs(angle_diff(env.heading, 29.0)) < 10
    assert obs.data["moves"] == 1 and obs.data["distance_walked_m"] > 5
    state = await env.final_state()
    assert state["path"] == [before, state["node"]] and state["stopped"] is False
    assert set(state) >= {"city", "node", "lat", "lng", "heading", "stopped", "path", "distance_walked_m"}


@pytest.mark.anyio
async def test_turning_at_an_intersection_and_moving_by_neighbour_id(world):
    env = await started(world)
    right = [n for n in env.observation().data["neighbours"] if n["direction"] == "right"]
    assert right and right[0]["street"] == "East 23rd Street"
    env.move(direction="right")
    assert "East 23rd Street" in env.graph.node_streets[env.node]
    back = next(n for n in env.observation().data["neighbours"] if n["direction"] == "back")
    env.move(neighbour=back["node"])
    assert env.graph.ids[env.node] == (await env.final_state())["path"][0]


@pytest.mark.anyio
async def test_refused_moves_name_the_choices_and_change_nothing(world):
    env = await started(world)
    env.move(direction="forward")  # now mid-block on 5th Avenue: no street to the left or right
    snapshot = json.dumps(await env.final_state())
    with pytest.raises(EnvError, match="valid directions here: forward, back"):
        env.move(direction="left")
    with pytest.raises(EnvError, match="not a neighbour.*valid neighbour ids"):
        env.move(neighbour="mn-0000000000")
    with pytest.raises(EnvError, match="exactly one"):
        env.move(direction="forward", neighbour=env.graph.ids[env.node])
    assert json.dumps(await env.final_state()) == snapshot


@pytest.mark.anyio
async def test_stop_ends_the_walk(world):
    env = await started(world)
    env.stop()
    node = env.node
    with pytest.raises(EnvError, match="already stopped"):
        env.move(direction="forward")
    with pytest.raises(EnvError, match="already stopped"):
        env.stop()
    assert env.node == node and (await env.final_state())["stopped"] is True


@pytest.mark.anyio
async def test_observation_never_leaks_the_goal(world):
    task = make_task(world)
    goal = task.embodied_goals[0]
    env = StreetEnvironment(episode=None, services=Services())
    await env.reset(task, {"observation": "text"})
    for _ in range(3):
        text = json.dumps(env.observation().data) + env.observation().text
        assert goal.node not in text and f"{goal.lat:.4f}" not in text and f"{goal.lng:.4f}" not in text
        assert "lat" not in env.observation().data  # no own coordinates either (ids are opaque too)
        env.move(direction="forward")
    assert env.heading != 0 and (await env.final_state())["path"][0] == task.start.embodied.node


@pytest.mark.anyio
async def test_vision_mode_returns_four_cached_pngs(world):
    env = StreetEnvironment(episode=None, services=Services())
    await env.reset(make_task(world), {"observation": "vision"})
    obs = env.observation()
    assert len(obs.images) == 4 and all(png.startswith(b"\x89PNG") for png in obs.images)
    assert env.observation().images == obs.images
    assert [v["view"] for v in env.observation("absolute").data["views"]] == ["north", "east", "south", "west"]


@pytest.mark.anyio
async def test_bad_start_is_refused_clearly(world):
    task = make_task(world)
    task.start.embodied.node = "mn-doesnotexist"
    env = StreetEnvironment(episode=None, services=Services())
    with pytest.raises(EnvError, match="unknown node id"):
        await env.reset(task, {})
    task.start.embodied.node = world.search("Broad St & Market St", city="philadelphia")[0].node
    with pytest.raises(EnvError, match="is in philadelphia, not in manhattan"):
        await env.reset(task, {})
