"""examples/mcp_call.py keeps every image of a play-through: each call's images get a number of their own."""

from __future__ import annotations

import importlib.util
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "examples" / "mcp_call.py"


def _load():
    spec = importlib.util.spec_from_file_location("mcp_call_example", SCRIPT)
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_repeated_calls_of_one_tool_keep_every_image_in_call_order(tmp_path: Path) -> None:
    save_images = _load().save_images
    folder = tmp_path / "images"
    first = save_images(folder, "browser_scroll", [(1, b"first")])
    second = save_images(folder, "browser_scroll", [(1, b"second")])
    both = save_images(folder, "get_observation", [(1, b"a"), (2, b"b")])
    assert [p.name for p in first + second + both] == [
        "0001-browser_scroll-1.png", "0002-browser_scroll-1.png",
        "0003-get_observation-1.png", "0003-get_observation-2.png"]
    assert [p.read_bytes() for p in first + second + both] == [b"first", b"second", b"a", b"b"]
    assert sorted(p.name for p in folder.iterdir()) == [p.name for p in first + second + both]
    assert save_images(folder, "browser_click", []) == []  # a result without images writes nothing


def test_numbering_goes_on_after_the_images_already_there(tmp_path: Path) -> None:
    save_images = _load().save_images
    (tmp_path / "0041-street_move-1.png").write_bytes(b"old")
    (tmp_path / "notes.txt").write_text("not an image of ours")
    [path] = save_images(tmp_path, "street_move", [(1, b"new")])
    assert path.name == "0042-street_move-1.png"
    assert (tmp_path / "0041-street_move-1.png").read_bytes() == b"old"
