"""The street environment: moves, refused moves, stop, the final state, no goal leakage."""

import json
import re

import pytest

from ewa_mcp.core.environment import EnvError
from ewa_mcp.envs.street.env import StreetEnvironment
from ewa_mcp.geometry import angle_diff
from ewa_mcp.core.services import Services
from ewa_mcp.core.taskmodel import Task


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
    with pytest.raises(EnvError, match=r"valid directions here: forward \(5th Avenue, .*\), back \(5th Avenue"):
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
    with pytest.raises(EnvError, match="the walk is over.*finish_episode"):
        env.move(direction="forward")
    with pytest.raises(EnvError, match="the walk is over.*finish_episode"):
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


HERALD_SQUARE = "mn-1a5b7f7603"  # 6th Avenue, Broadway and West 34th Street: six streets, two pairs close together


async def started_at(world, node, heading, city="manhattan"):
    task = Task.model_validate({
        "id": "nav-test", "domain": "navigation", "intent": "Walk.",
        "start": {"environment": "embodied", "embodied": {"kind": "street", "city": city, "node": node,
                                                          "heading": heading}}})
    env = StreetEnvironment(episode=None, services=Services())
    await env.reset(task, {"observation": "text"})
    return env


@pytest.mark.anyio
@pytest.mark.parametrize("heading", range(0, 360, 5))
async def test_every_listed_direction_names_one_street(world, heading):
    env = await started_at(world, HERALD_SQUARE, float(heading))
    listed = env.observation().data["neighbours"]
    labels = [n["direction"] for n in listed]
    assert len(listed) == 6 and len(set(labels)) == 6 and None not in labels
    for n in listed:  # each label walks to exactly the neighbour it is listed with
        probe = await started_at(world, HERALD_SQUARE, float(heading))
        probe.move(direction=n["direction"])
        assert probe.path[-1] == n["node"]


@pytest.mark.anyio
async def test_a_plain_direction_matching_several_streets_is_refused_with_the_choices(world):
    env = await started_at(world, HERALD_SQUARE, 60.0)
    listed = env.observation().data["neighbours"]
    right = [n for n in listed if 45 <= n["relative_heading"] <= 135]
    assert len(right) == 2 and "right" not in {n["direction"] for n in listed}
    with pytest.raises(EnvError, match="'right' is ambiguous here: 2 streets") as refused:
        env.move(direction="right")
    for n in right:
        assert n["node"] in str(refused.value) and repr(n["direction"]) in str(refused.value)
    assert env.path == [HERALD_SQUARE]


@pytest.mark.anyio
async def test_landmark_distances_are_measured_from_where_the_agent_stands(world):
    # Walking up North 12th Street towards Reading Terminal Market: the market's distance shrinks at
    # every move, and at its node it is announced as right here on the right.
    market = world.place("poi-philadelphia-reading-terminal-market")
    route = world.directions(world.search("Market St & 12th St", city="philadelphia")[0].node, market.id)
    env = await started_at(world, route.nodes[0], route.steps[0].heading, city="philadelphia")
    seen = []
    for node in route.nodes[1:]:
        obs = env.move(neighbour=node)
        for line in obs.text.splitlines():
            for m in re.finditer(r'(\d+) m away: a sign reading "Reading Terminal Market"', line):
                seen.append((node, int(m.group(1))))
    front = [d for _, d in dict(seen).items()]
    assert len(front) >= 4 and all(a > b for a, b in zip(front, front[1:])), seen
    assert front[-1] <= 15
    assert 'Right here: on your right, a sign reading "Reading Terminal Market"' in obs.text


@pytest.mark.anyio
async def test_stop_ends_the_walk_and_says_so(world):
    env = await started(world)
    env.move(direction="forward")
    obs = env.stop()
    assert obs.data["walk_stopped"] is True
    assert "Walk stopped at 5th Avenue; call finish_episode to end the episode." in obs.text
    assert "Walk stopped at" in env.observation().text
    with pytest.raises(EnvError, match="the walk is over: it stopped at 5th Avenue.*Call finish_episode"):
        env.move(direction="back")
    state = await env.final_state()
    assert state["walk_stopped"] is True and state["walk_end"]["by"] == "street_stop"
    assert state["walk_end"]["node"] == state["node"] == state["path"][-1]
    assert len(state["path_points"]) == len(state["path"]) == 2
    fresh = await started(world)
    assert fresh.observation().data["walk_stopped"] is False
    assert (await fresh.final_state())["walk_end"]["by"] == "episode_end"


@pytest.mark.anyio
async def test_two_places_at_one_node_read_as_two_sentences(world):
    # A play-tester read "Right here: on your right, a … tower … . on your right, a rugged church …" at
    # Boylston & Clarendon, where two landmarks share a node: each place now gets its own line.
    from ewa_mcp.envs.street.scene import places_here

    graph = world.city("boston")
    node = next(n for n in graph.ids if len(places_here(world, graph, graph.index[n], 0.0)) >= 2)
    env = await started_at(world, node, 0.0, city="boston")
    lines = [ln for ln in env.observation("relative").text.splitlines() if ln.startswith(("Right here:", "Also here:"))]
    assert len(lines) >= 2 and lines[0].startswith("Right here: ") and lines[1].startswith("Also here: ")
    assert all(ln.endswith(".") and ln.count(". ") == 0 for ln in lines), lines  # one sentence per line
