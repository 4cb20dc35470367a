"""The API lesson of step 04 (``uniforms_gl.py`` / ``uniforms_wgpu.py``): per-draw uniforms and the depth range.

Tolerance: the two pictures agree on ≥ 99.5 % of pixels exactly (the rest are triangle-edge pixels, where the
rasterisers may decide a sample differently; measured: identical on llvmpipe/lavapipe). Content, checked in
each picture: the red triangle's centroid is red; the green triangle's centroid, which lies behind the red one,
is red too (the depth test works although red is drawn first); a point only the green triangle covers is green;
the corner is black. The near plane is at 1.5, so a projection with the other API's depth range would clip the
red triangle (z = −2) away in WebGPU. ``--help`` only prints help.
"""

from __future__ import annotations

import numpy as np
import pytest
from cli_checks import check_main_writes_a_png_and_help_only_helps

from step04_camera import uniforms_gl, uniforms_wgpu

SIZE = 64
F = 1.0 / np.tan(np.radians(30.0))
#: NDC points and the colour each must show.
PROBES = [
    ((F * -0.25 / 2, F * -0.8 / 3 / 2), (255, 0, 0), "the red (front) triangle's centroid"),
    ((F * 0.25 / 3, F * -0.8 / 3 / 3), (255, 0, 0), "the green triangle's centroid, behind the red one"),
    ((0.5, -0.4), (0, 255, 0), "a point only the green (back) triangle covers"),
    ((0.9, 0.9), (0, 0, 0), "the background"),
]


@pytest.mark.parametrize("module", [uniforms_gl, uniforms_wgpu], ids=["gl", "wgpu"])
def test_uniforms_place_and_colour_each_draw(module):
    image = module.render(SIZE, SIZE)
    for (x, y), colour, what in PROBES:
        col, row = int((x + 1) / 2 * SIZE), int((1 - y) / 2 * SIZE)
        got = tuple(int(v) for v in image[row, col, :3])
        assert got == colour, (f"{what} at NDC ({x:.3f}, {y:.3f}): expected {colour}, got {got}"
                               " (hint: depth test, depth range of the projection, matrix layout)")


def test_both_apis_give_the_same_picture():
    gl, wg = uniforms_gl.render(SIZE, SIZE), uniforms_wgpu.render(SIZE, SIZE)
    same = (gl == wg).all(axis=2).mean()
    assert same >= 0.995, f"only {100 * same:.2f} % of pixels agree (allowed ≥ 99.5 %)"


def test_the_projections_differ_only_in_the_depth_range():
    gl, wg = uniforms_gl.perspective(1.0), uniforms_wgpu.perspective(1.0)
    for z in (-uniforms_gl.NEAR, -uniforms_gl.FAR):
        clip_gl, clip_wg = gl @ (0, 0, z, 1), wg @ (0, 0, z, 1)
        assert np.allclose(clip_gl[[0, 1, 3]], clip_wg[[0, 1, 3]])
        assert np.isclose(clip_gl[2] / clip_gl[3], -1 if z == -uniforms_gl.NEAR else 1)
        assert np.isclose(clip_wg[2] / clip_wg[3], 0 if z == -uniforms_gl.NEAR else 1)


@pytest.mark.parametrize("module", [uniforms_gl, uniforms_wgpu], ids=["gl", "wgpu"])
def test_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys):
    check_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys)
