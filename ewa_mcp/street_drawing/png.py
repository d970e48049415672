"""Deterministic PNG bytes: a fixed compression level and no metadata, so identical pixels give
identical bytes."""

from __future__ import annotations

import io

from PIL import Image


def encode_png(image: Image.Image, colours: int | None = None, compress_level: int = 6) -> bytes:
    """PNG bytes of ``image``; with ``colours``, first reduced to an adaptive palette of that many colours
    (no dithering), which keeps a street view around 10-20 KB without visible banding."""
    if colours is not None:
        image = image.quantize(colors=colours, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE)
    buf = io.BytesIO()
    image.save(buf, format="PNG", optimize=False, compress_level=compress_level)
    return buf.getvalue()
