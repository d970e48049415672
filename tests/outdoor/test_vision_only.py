"""Observation "vision" in the walked cities: the four views as images plus only what a camera cannot give
(the neighbour list with headings and distances); "both" keeps the text too."""

from __future__ import annotations

import io
import json

import pytest
from PIL import Image

from ewa_mcp.core.environment import EnvError
from ewa_mcp.core.services import Services
from ewa_mcp.core.taskmodel import Task
from ewa_mcp.envs.street.env import StreetEnvironment
from ewa_mcp.envs.street.scene import places_here
from ewa_mcp.envs.street.street_view import render
from ewa_mcp.envs.street.scene import compute_scene
from ewa_mcp.street_drawing.compass import STRIP_H

pytestmark = pytest.mark.anyio
TARGET = "store-target-herald-square"


async def at_place(world, mode: str, heading: float = 29.0) -> StreetEnvironment:
    """An environment started on the node of a place, so the text has a "Right here:" line to leave out."""
    place = world.place(TARGET)
    task = Task.model_validate({
        "id": "nav-test", "domain": "navigation", "intent": "Walk.",
        "start": {"environment": "embodied",
                  "embodied": {"kind": "street", "city": "manhattan", "node": place.node, "heading": heading}}})
    env = StreetEnvironment(episode=None, services=Services())
    await env.reset(task, {"observation": mode})
    return env


def words_to_hide(env: StreetEnvironment, world) -> set[str]:
    g = env.graph
    names = set(g.node_streets[env.node]) | {g.streets[s] for _, _, s, _ in g.adj[env.node]}
    return names | {world.place(TARGET).name, g.name}


async def test_vision_only_observation_has_no_names_or_descriptions(world):
    env = await at_place(world, "vision")
    assert places_here(world, env.graph, env.node, env.heading)  # the text mode would say "Right here:"
    hidden = words_to_hide(env, world)
    for obs in (env.observation(), env.move(neighbour=env._neighbours()[0]["node"]), env.stop()):
        everything = obs.text + json.dumps(obs.data)
        assert len(obs.images) == 4 and all(png.startswith(b"\x89PNG") for png in obs.images)
        for word in hidden | set(words_to_hide(env, world)):
            assert word not in everything, word
        assert "Right here" not in obs.text and "Street signs" not in obs.text and "Cross streets" not in obs.text
        assert all(set(v) == {"view", "heading", "image_index"} for v in obs.data["views"])
        assert "streets" not in obs.data and all("street" not in n for n in obs.data["neighbours"])
        # what the action space needs stays: every neighbour's id, direction, headings and distance
        assert all({"node", "direction", "heading", "relative_heading", "distance_m"} <= set(n)
                   for n in obs.data["neighbours"])
    # error messages keep the secret too
    with pytest.raises(EnvError) as err:
        env.move(direction="forward")
    assert not any(word in str(err.value) for word in hidden)


async def test_vision_only_choices_name_no_streets(world):
    env = await at_place(world, "vision")
    with pytest.raises(EnvError) as err:
        env.move(neighbour="mn-nope")
    assert "valid neighbour ids" in str(err.value)
    assert not any(word in str(err.value) for word in words_to_hide(env, world))


async def test_both_keeps_the_text_and_adds_the_images(world):
    both, text = await at_place(world, "both"), await at_place(world, "text")
    ob, ot = both.observation(), text.observation()
    assert ob.text.startswith(ot.text.rsplit("\nWalked", 1)[0]) and "Right here" in ob.text
    assert len(ob.images) == 4 and not ot.images
    assert ob.data["views"][0]["description"] == ot.data["views"][0]["description"]


async def test_compass_strip_shows_the_heading(world):
    env = await at_place(world, "vision")
    g = env.graph
    strips = []
    for heading in (0.0, 90.0, 180.0):
        img = render(compute_scene(world, g, env.node, heading, "front"))
        strips.append(img.crop((0, img.height - STRIP_H, img.width, img.height)).tobytes())
        assert Image.open(io.BytesIO(env.observation().images[0])).size == img.size
    assert len(set(strips)) == 3  # a different bearing draws a different strip


def test_every_cue_the_text_names_is_drawn_in_a_sample_of_views(world):
    """scene.text_cues (what describe names that a camera shows) must be among the ids render_cues draws,
    for a sample of views in every city, biased to nodes with places (the views that name the most)."""
    import random

    from ewa_mcp.envs.street.scene import text_cues
    from ewa_mcp.envs.street.street_view import render_cues

    rng = random.Random(27)
    missing: dict[str, str] = {}
    kinds: set[str] = set()
    for city in sorted(world.cities_by_name):
        g = world.city(city)
        placed = sorted({p.node for p in world.places.values() if p.city == g.city and p.node in g.index})
        for node in rng.sample(placed, min(8, len(placed))) + rng.sample(g.ids, 2):
            for heading in (0.0, 90.0, 180.0, 270.0):
                scene = compute_scene(world, g, g.index[node], heading, "front")
                said = text_cues(scene)
                kinds |= {c.split(":", 1)[0] for c in said}
                for cue in said - render_cues(scene)[1]:
                    missing.setdefault(cue, f"{node} at {heading:.0f}°")
    assert not missing, f"named in the text but not drawn: {sorted(missing.items())[:10]}"
    assert {"road_ahead", "opening", "sign", "facade", "detail", "skyline", "street_sign"} <= kinds
