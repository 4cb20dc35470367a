"""The API lesson of step 02 (``vertex_buffer_gl.py`` / ``vertex_buffer_wgpu.py``): one interleaved buffer.

Tolerance: the two pictures agree to ±2 steps on every pixel (rasterisers may interpolate the last bit
differently; measured: identical on llvmpipe/lavapipe), the pixel at the centroid has the colour
interpolated at its centre (about the mean of the three, 85 each) ±2, each corner region has its vertex's
colour dominant, the background stays black, and ``--help`` only prints help.
"""

from __future__ import annotations

import numpy as np
import pytest
from cli_checks import check_main_writes_a_png_and_help_only_helps

from step02_triangle import vertex_buffer_gl, vertex_buffer_wgpu

SIZE = 64


def _pixel(image: np.ndarray, x: float, y: float) -> np.ndarray:
    """The pixel at NDC (x, y)."""
    col = int((x + 1) / 2 * SIZE)
    row = int((1 - y) / 2 * SIZE)
    return image[row, col, :3].astype(int)


def test_both_apis_draw_the_same_triangle():
    gl, wg = vertex_buffer_gl.render(SIZE, SIZE), vertex_buffer_wgpu.render(SIZE, SIZE)
    diff = np.abs(gl.astype(int) - wg.astype(int)).max()
    assert diff <= 2, f"the pictures differ by up to {diff} steps (allowed 2)"
    # The pixel holding the centroid, against the colour interpolated at that pixel's centre (about 85 each).
    col, row = SIZE // 2, int((1 + 0.8 / 3) / 2 * SIZE)
    centre = np.array([(col + 0.5) / SIZE * 2 - 1, 1 - (row + 0.5) / SIZE * 2])
    corners = vertex_buffer_gl.VERTICES[:, :2]
    weights = np.linalg.solve(np.vstack([corners.T, np.ones(3)]), np.append(centre, 1.0))
    expected = np.round(255 * weights @ vertex_buffer_gl.VERTICES[:, 2:])
    got = gl[row, col, :3].astype(int)
    assert np.abs(got - expected).max() <= 2, f"centroid pixel {col, row}: expected {expected} ±2, got {got}"
    for (x, y), channel in [((-0.7, -0.75), 0), ((0.7, -0.75), 1), ((0.0, 0.7), 2)]:
        pixel = _pixel(gl, x, y)
        assert pixel.argmax() == channel and pixel[channel] > 200, f"near corner ({x}, {y}): got {pixel}"
    assert (_pixel(gl, -0.95, 0.95) == 0).all(), "the background should stay black"


@pytest.mark.parametrize("module", [vertex_buffer_gl, vertex_buffer_wgpu], ids=["gl", "wgpu"])
def test_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys):
    check_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys)
