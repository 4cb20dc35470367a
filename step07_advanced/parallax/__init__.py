"""Step 07 technique: normal mapping and the parallax family compared on one brick wall.

Four tiles of the same brick material under the same light, seen at a grazing angle: normal mapping only,
simple parallax (offset) mapping, steep parallax mapping and parallax occlusion mapping. Only the texture
coordinates differ: each method moves the uv it samples the maps at by its own estimate of where the view ray
meets the height field. ``python -m step07_advanced.parallax.opengl`` / ``.webgpu``; the exercise is
``parallax`` (``parallax_offset``, ``parallax_steep``, ``parallax_occlusion``); the study is
``python -m step07_advanced.parallax.study``.
"""

#: The step package whose ``exercises`` / ``solutions`` hold this technique's shader functions.
STEP = "step07_advanced"
