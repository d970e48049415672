"""The street-view drawing toolkit: one camera, one sky, one way to load fonts and encode PNGs,
used by both street worlds (walked cities and geolocation views)."""

import io
from pathlib import Path

import pytest
from PIL import Image, ImageDraw

from ewa_mcp.street_drawing.camera import Camera
from ewa_mcp.street_drawing.colour import rgb, shade
from ewa_mcp.street_drawing.png import encode_png
from ewa_mcp.street_drawing.sky import sky_gradient

ROOT = Path(__file__).resolve().parents[2]


def test_camera_depth_and_inverse_depth_forms_agree():
    cam = Camera(width=600, height=400, horizon=175, eye_height=0.75)
    for x, y, z in ((0.8, 0.0, 2.0), (-0.5, 1.2, 7.5), (0.0, 0.75, 3.0)):
        assert cam.project(x, y, z) == pytest.approx(cam.project_u(x, y, 1 / z))
    assert cam.project(0, 0.75, 10.0) == (300.0, 175.0)  # a point at eye height lies on the horizon
    assert cam.screen_x(45.0) == pytest.approx(600.0)  # 90 degree field of view: 45 degrees is the edge


def test_sky_gradient_blends_from_zenith_to_horizon_in_bands():
    img = Image.new("RGB", (40, 60), (0, 0, 0))
    sky_gradient(ImageDraw.Draw(img), 40, 50, (100, 100, 200), (200, 220, 250), band=4)
    assert img.getpixel((5, 0)) == (100, 100, 200)
    assert img.getpixel((5, 3)) == img.getpixel((5, 0))  # one band is 4 rows
    assert img.getpixel((5, 48)) != img.getpixel((5, 0))
    assert img.getpixel((5, 55)) == (0, 0, 0)  # nothing below the horizon band


def test_colours_and_png_encoding_are_deterministic():
    assert rgb("#ff8000") == (255, 128, 0) and shade("#ff8000", 0.5) == (127, 64, 0) and shade("#808080", 3) == (
        255, 255, 255)
    img = Image.new("RGB", (32, 32), (10, 120, 200))
    ImageDraw.Draw(img).ellipse([4, 4, 28, 28], fill=(250, 40, 40))
    assert encode_png(img) == encode_png(img.copy())
    quantised = encode_png(img, colours=16)
    assert Image.open(io.BytesIO(quantised)).mode == "P"


def test_street_views_load_fonts_and_project_only_through_the_toolkit():
    """No street renderer keeps its own font loading, camera or PNG encoder beside the toolkit's."""
    offenders = []
    for folder in ("outdoor", "geo"):
        for path in (ROOT / "ewa_mcp" / folder).rglob("*.py"):
            text = path.read_text(encoding="utf-8")
            for needle in ("ImageFont.load_default", "ImageFont.truetype", "class Camera", "format=\"PNG\"",
                           "def _sky"):
                if needle in text and not (needle == "def _sky" and "sky_gradient(" in text):
                    offenders.append(f"{path.relative_to(ROOT)}: {needle}")
    assert not offenders, offenders


def test_ascii_runs_in_a_script_line_are_drawn_in_the_latin_font():
    from PIL import Image, ImageDraw

    from ewa_mcp.street_drawing import fonts
    from ewa_mcp.street_drawing.text import draw_centred_lines, runs

    assert runs("ฎข 2169", "thai") == [("ฎข ", "thai"), ("2169", "latin")]
    assert runs("ABC 123", "latin") == [("ABC 123", "latin")]
    assert runs("ب 12", "arabic") == [("ب 12", "arabic")]  # right-to-left lines stay whole (bidi order)
    if not fonts.has_font("thai"):
        pytest.skip("no Thai font on this machine")

    def plate(text: str) -> bytes:
        img = Image.new("RGB", (200, 40), (255, 255, 255))
        draw_centred_lines(ImageDraw.Draw(img), (0, 0, 200, 40), [(text, "thai")], (0, 0, 0))
        return img.tobytes()

    # A font without digits draws every digit as the same empty box: different digits must differ.
    assert plate("ฎข 2169") != plate("ฎข 8888")
