"""The picture carries every cue the text names: the describer and the renderer both report the cue ids
of a view (``describe_view_cues`` and ``render_view_cues``, from the one ViewSpec), and every id the
text names must be one the image draws, at every standpoint and heading of every location."""

from __future__ import annotations

import dataclasses
import itertools

import pytest
from PIL import Image, ImageDraw

from ewa_mcp.envs.geo.describe import SHOP_KIND_LOOKS, describe_view, describe_view_cues
from ewa_mcp.envs.geo.graph import build_graph
from ewa_mcp.envs.geo.locations import LOCATIONS_LIST
from ewa_mcp.envs.geo.scene import compose_view
from ewa_mcp.envs.geo.styles import TREE_WORDS
from ewa_mcp.envs.geo.view_images import render_view, render_view_cues, shop_pictogram
from ewa_mcp.geometry import FOUR_DIRECTIONS
from ewa_mcp.street_drawing import fonts
from ewa_mcp.street_drawing.trees import KINDS, draw_tree


def test_every_cue_the_text_names_is_drawn_at_every_view_of_every_location():
    missing: dict[str, list[str]] = {}
    kinds_seen: set[str] = set()
    for loc in LOCATIONS_LIST:
        for sp in build_graph(loc):
            for heading in FOUR_DIRECTIONS:
                spec = compose_view(loc, sp, heading)
                text, said = describe_view_cues(spec)
                _, drawn = render_view_cues(spec)
                kinds_seen |= {c.split(":", 1)[0] for c in said}
                for cue in sorted(said - drawn):
                    if cue.startswith(("sign_text:", "street_sign_text:")) and not fonts.has_font(
                            fonts.script_of(cue.split(":", 1)[1])):
                        continue  # no font for this script on this machine: drawn transliterated (test_views)
                    missing.setdefault(cue, []).append(f"{loc.id}/{sp}/{heading}")
    assert not missing, "named in the text but not drawn: " + "; ".join(
        f"{cue} ({len(where)} views, e.g. {where[0]})" for cue, where in sorted(missing.items())[:20])
    # the check covers every kind of cue the describer names
    assert {"composition", "arch", "sky", "drive", "centre_line", "plate_colours", "plate_text", "vehicle", "tree",
            "shop", "sign_text", "phone", "street_sign_text", "street_sign_style", "landmark", "tram_tracks",
            "wires", "pedestrian"} <= kinds_seen


def test_the_cue_ids_follow_the_words():
    loc = LOCATIONS_LIST[0]
    spec = compose_view(loc, "p0", "north")
    text, said = describe_view_cues(spec)
    assert text == describe_view(spec)
    for sign in spec.shops:
        assert f"shop:{sign.kind}" in said and SHOP_KIND_LOOKS[sign.kind] in text
        assert all(f"sign_text:{t.native}" in said and t.native in text for t in sign.lines)
    for kind, _side, _depth in spec.trees:
        assert f"tree:{kind}" in said and TREE_WORDS[kind] in text


def test_recording_cues_does_not_change_the_picture():
    spec = compose_view(LOCATIONS_LIST[3], "p1", "east")
    assert render_view_cues(spec)[0].tobytes() == render_view(spec).tobytes()


def test_a_cue_the_spec_drops_is_no_longer_drawn():
    """The renderer reports what it draws, not what the spec lists: a spec without trees draws no tree cue."""
    spec = next(s for loc in LOCATIONS_LIST for s in (compose_view(loc, "p0", h) for h in FOUR_DIRECTIONS)
                if s.trees)
    bare = dataclasses.replace(spec, trees=())
    assert any(c.startswith("tree:") for c in render_view_cues(spec)[1])
    assert not any(c.startswith("tree:") for c in render_view_cues(bare)[1])
    assert render_view(spec).tobytes() != render_view(bare).tobytes()


def _drawn(fn) -> bytes:
    img = Image.new("RGB", (240, 260), (200, 220, 240))
    fn(ImageDraw.Draw(img))
    return img.tobytes()


def test_every_tree_kind_has_its_own_drawing():
    assert set(TREE_WORDS) <= set(KINDS)  # every kind the text can name is drawn as that kind
    pictures = {kind: _drawn(lambda d, k=kind: draw_tree(d, k, 120, 250, 1.0)) for kind in TREE_WORDS}
    for a, b in itertools.combinations(sorted(pictures), 2):
        assert pictures[a] != pictures[b], f"{a} and {b} look the same"
    generic = _drawn(lambda d: draw_tree(d, "no-such-tree", 120, 250, 1.0))
    assert generic not in pictures.values()


@pytest.mark.parametrize("kind", sorted(SHOP_KIND_LOOKS))
def test_every_shop_kind_has_its_own_pictogram(kind):
    mine = _drawn(lambda d: shop_pictogram(d, kind, 120, 120, 40))
    others = {k: _drawn(lambda d, k=k: shop_pictogram(d, k, 120, 120, 40)) for k in SHOP_KIND_LOOKS if k != kind}
    assert mine not in others.values() and mine != _drawn(lambda d: None)
