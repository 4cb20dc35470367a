"""The API lesson of step 03 (``texture_gl.py`` / ``texture_wgpu.py``): a 2×2 texture, nearest, repeated twice.

Tolerance: the two pictures are identical (nearest sampling of 8-bit texels is exact), every pixel equals the
texel the repeat/nearest rule picks for its centre (a 4×4 grid of cells, red/green over blue/white, red at the
top left), and ``--help`` only prints help.
"""

from __future__ import annotations

import numpy as np
import pytest
from cli_checks import check_main_writes_a_png_and_help_only_helps

from step03_textures import texture_gl, texture_wgpu

SIZE = 64


def test_both_apis_tile_the_texture_the_same_way():
    gl, wg = texture_gl.render(SIZE, SIZE), texture_wgpu.render(SIZE, SIZE)
    assert np.array_equal(gl, wg), f"the pictures differ by up to {np.abs(gl.astype(int) - wg).max()} steps"
    # uv = 2 * (pixel centre) / size; nearest picks texel floor(uv * 2) mod 2.
    index = (np.floor(2 * (np.arange(SIZE) + 0.5) / SIZE * 2).astype(int)) % 2
    expected = texture_gl.TEXELS[index[:, None], index[None, :]]
    wrong = np.argwhere((gl != expected).any(axis=2))
    assert not len(wrong), (f"{len(wrong)} pixels differ, e.g. (row, col) {tuple(wrong[0])}: expected "
                            f"{expected[tuple(wrong[0])]}, got {gl[tuple(wrong[0])]}")


@pytest.mark.parametrize("module", [texture_gl, texture_wgpu], ids=["gl", "wgpu"])
def test_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys):
    check_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys)
