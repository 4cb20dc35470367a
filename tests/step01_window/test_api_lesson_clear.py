"""The API lesson of step 01 (``clear_gl.py`` / ``clear_wgpu.py``): both run headless and clear to one colour.

Tolerance: the two pictures are identical (a clear writes the colour exactly), every pixel is the clear colour
(0.2, 0.4, 0.8) = (51, 102, 204) to the step, and ``--help`` only prints help.
"""

from __future__ import annotations

import numpy as np
import pytest
from cli_checks import check_main_writes_a_png_and_help_only_helps

from step01_window import clear_gl, clear_wgpu


def test_both_apis_clear_to_the_same_colour():
    gl, wg = clear_gl.render(40, 30), clear_wgpu.render(40, 30)
    assert gl.shape == wg.shape == (30, 40, 4)
    assert np.array_equal(gl, wg), f"the pictures differ by up to {np.abs(gl.astype(int) - wg).max()} steps"
    assert (gl.reshape(-1, 4) == (51, 102, 204, 255)).all(), f"expected (51, 102, 204, 255), got {gl[0, 0]}"


@pytest.mark.parametrize("module", [clear_gl, clear_wgpu], ids=["gl", "wgpu"])
def test_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys):
    check_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys)
