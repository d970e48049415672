"""The street-view drawing toolkit shared by the two worlds that draw streets with Pillow.

``outdoor/street_view.py`` (the walked cities) and ``geo/view_images.py`` (the geolocation
standpoints) compose their pictures from these parts:

- ``camera``: the pinhole camera (90° field of view, eye height, horizon) both project with;
- ``sky``: the sky gradient above the horizon;
- ``colour``: hex colours to RGB, shading;
- ``shapes``: rectangles from any two corners;
- ``fonts`` and ``text``: fonts for any script at fixed paths, text fitted and centred in a box;
- ``trees``: street trees by kind;
- ``png``: deterministic PNG bytes (optionally quantised).

Everything is deterministic: the same inputs give the same pixels and the same bytes.
"""
