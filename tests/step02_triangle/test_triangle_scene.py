"""Non-graded checks of step 02's own code (run on the solutions): colours, the index buffer, both APIs.

Tolerances: a flat sRGB vertex colour c reads back as round(255 * c) within 1 step in both APIs; OpenGL and
WebGPU pictures of the whole scene agree with PSNR >= 45 dB and no channel more than 2 steps apart; each
matches its committed reference in ``references/`` with PSNR >= 40 dB (a few edge pixels may differ on
another rasteriser).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from per_api import PerAPI

from gandalf_core.resources import MeshData, linear_to_srgb, srgb_to_linear
from gandalf_tools.testing import compare_images, compare_to_reference, render_frames
from step02_triangle import opengl, webgpu
from step02_triangle.meshes import quad_mesh, triangle_mesh
from step02_triangle.preview import render_mesh
from step02_triangle.scene import TOUR_FRAMES

REFERENCES = Path(__file__).resolve().parent / "references"
WIDTH, HEIGHT = 160, 120
# One triangle larger than the screen: every pixel shows its colour.
FULL_SCREEN = [(-1.0, -1.0, 0.0), (3.0, -1.0, 0.0), (-1.0, 3.0, 0.0)]


@pytest.mark.parametrize("color", [(0.2, 0.5, 0.8), (1.0, 1.0, 1.0), (0.0, 0.0, 0.0), (0.04, 0.3, 0.999)])
def test_flat_vertex_colour_reads_back_as_itself(backend, color):
    mesh = MeshData(FULL_SCREEN, colors=np.tile([*color, 1.0], (3, 1)))
    image = render_mesh(backend, mesh, 16, 12, clear_color=(0.5, 0.1, 0.3)).astype(int)
    expected = np.round(255 * np.array(color)).astype(int)
    assert np.abs(image[..., :3] - expected).max() <= 1


def test_colours_blend_in_linear_light(backend):
    # Red, green and blue corners: at the centroid each is 1/3 in *linear* light, i.e. sRGB 0.613 (156), not 85.
    mesh = triangle_mesh()
    big = MeshData(np.array(mesh.positions) * 2, colors=mesh.colors)
    # The centroid (0, -1/3) falls on a pixel corner at 60x60: average the four pixels around it in linear light.
    image = render_mesh(backend, big, 60, 60).astype(float) / 255
    patch = srgb_to_linear(image[39:41, 29:31, :3]).reshape(-1, 3).mean(axis=0)
    assert np.abs(np.round(255 * linear_to_srgb(patch)) - 156).max() <= 2


def test_quad_uses_an_index_buffer():
    quad = quad_mesh()
    assert (quad.vertex_count, quad.index_count, quad.triangle_count) == (4, 6, 2)
    assert triangle_mesh().index_count == 0


def test_quad_fills_its_square(backend):
    image = render_mesh(backend, MeshData(quad_mesh().positions, colors=np.ones((4, 4)), indices=quad_mesh().indices),
                        64, 64)
    # The quad spans clip [-0.5, 0.5]^2: pixels 16..47 in both directions are covered, the rest is not.
    covered = image[..., 0] > 127
    assert covered[16:48, 16:48].all() and covered.sum() == 32 * 32


@pytest.fixture(scope="module")
def pictures() -> PerAPI:
    variants = {"opengl": opengl, "webgpu": webgpu}
    return PerAPI(lambda api: render_frames(variants[api].create_app, TOUR_FRAMES, width=WIDTH, height=HEIGHT))


def test_opengl_and_webgpu_agree(pictures):
    compare_images(pictures["webgpu"], pictures["opengl"], "step02-webgpu-vs-opengl", min_psnr=45.0, max_diff=2)


@pytest.mark.parametrize("name", ["opengl", "webgpu"])
def test_matches_reference(pictures, name):
    compare_to_reference(pictures[name], REFERENCES / f"step02_triangle-{name}.png", min_psnr=40.0)
