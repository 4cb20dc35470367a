"""step07 pbr_model on the reference solution (not graded; a student's release leaves this module out, since it
imports the solutions):

* Both APIs render the tour's scene alike: PSNR ≥ 35 dB at 320×240 (measured on llvmpipe / lavapipe: 75.8 dB
  at 320×240 after 3 frames, 79.0 dB at 640×480 after the tour's 60).
* Explicit cube-map mip levels reach the GPU level by level in both APIs (each level a different solid colour,
  picked by roughness).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_pbr_model import make_app, render, solid_cube, sphere_scene

from gandalf_tools import testing
from step07_advanced import solutions
from step07_advanced.pbr_model.scene import build_scene


# --- both APIs alike ------------------------------------------------------------------------------------
def test_both_apis_render_the_model_alike():
    images = {}
    for backend in ("opengl", "webgpu"):
        with make_app(backend, solutions, (320, 240)) as app:
            app.add_scene(build_scene(solutions))
            app.run(frames=3)
            images[backend] = app.capture()
    testing.compare_images(images["webgpu"], images["opengl"], "pbr_model-webgpu-vs-opengl", min_psnr=35.0)
    # The model covers the middle of the picture and is lit (not the sky's colour, not black, not magenta).
    middle = images["opengl"][100:140, 150:170, :3].astype(int)
    assert middle.mean() > 30 and not np.all(np.abs(middle - [255, 0, 255]).max(axis=-1) < 40)


# --- engine: explicit cube-map levels reach the GPU -------------------------------------------------------------------
LEVEL_COLOURS = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0)]


@pytest.mark.parametrize("backend_name", ["opengl", "webgpu"])
def test_explicit_cube_levels_reach_the_gpu(backend_name):
    levels = [np.full((6, s, s, 4), (*c, 255), np.uint8) for s, c in zip((4, 2, 1), LEVEL_COLOURS[1:])]
    prefiltered = solid_cube(LEVEL_COLOURS[0], 8, levels=levels)
    black = solid_cube((0, 0, 0), mipmaps=False)
    for k, colour in enumerate(LEVEL_COLOURS):
        scene = sphere_scene((1.0, 1.0, 1.0), 1.0, k / 3.0, black, prefiltered, 4)
        centre = render(backend_name, solutions, scene, (48, 36))[18, 24, :3].astype(int)
        want = np.asarray(colour) > 0
        assert np.all(centre[want] > 120) and np.all(centre[~want] < 40), (
            f"{backend_name}: roughness {k}/3 should read mip level {k} ({colour}), got {centre.tolist()}")
