"""The step07 terrain on the reference solution (not graded; a student's release leaves this module out, since it
imports the solutions): OpenGL and WebGPU agree on the tour's 640×480 picture, PSNR ≥ 35 dB (measured 45.7 dB on
llvmpipe/lavapipe: the two triangulations differ only where a patch's outer levels differ from its inner one; the
shading comes per fragment from the uv in both). The graded pictures and the rest of the engine side are in
``test_terrain_render.py``.
"""

from __future__ import annotations

from test_terrain_render import render

from gandalf_tools.testing import psnr
from step07_advanced import solutions
from step07_advanced.terrain import scene


def test_both_apis_agree_on_the_tour_picture():
    gl = render("opengl", solutions, size=(640, 480), frames=scene.TOUR_FRAMES)
    wg = render("webgpu", solutions, size=(640, 480), frames=scene.TOUR_FRAMES)
    value = psnr(gl, wg)
    assert value >= 35.0, f"OpenGL and WebGPU pictures differ: PSNR {value:.1f} dB < 35 dB"
