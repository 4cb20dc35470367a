"""The API lesson of step 06 (``lights/lights_gl.py`` / ``lights/lights_wgpu.py``): a uniform block of lights.

Tolerance: in each picture, every pixel away from the silhouette (|r² − 1| > 0.03) is within 2 steps of a
numpy Lambert reference (ambient 0.05 + the first ``COUNT`` lights only, clamped to 1, on a black background);
the two pictures agree to 2 steps on ≥ 99.5 % of pixels (measured: identical on llvmpipe/lavapipe). The fourth,
magenta light lies beyond the count: if it were read, the front of the sphere would turn magenta.
``--help`` only prints help.
"""

from __future__ import annotations

import numpy as np
import pytest
from cli_checks import check_main_writes_a_png_and_help_only_helps

from step06_lighting.lights import lights_gl, lights_wgpu
from step06_lighting.lights.light_block import AMBIENT, COUNT, LIGHTS, MAX_LIGHTS, light_block

SIZE = 64


def reference(size: int) -> tuple[np.ndarray, np.ndarray]:
    """The expected linear colour per pixel (float64, 0..255) and the mask of pixels to compare."""
    centres = (np.arange(size) + 0.5) / size * 2 - 1
    x, y = np.meshgrid(centres, -centres)
    px, py = x / 0.9, y / 0.9
    r2 = px * px + py * py
    normal = np.stack([px, py, np.sqrt(np.clip(1 - r2, 0, None))], axis=-1)
    color = np.full(r2.shape + (3,), AMBIENT)
    for direction, light in LIGHTS[:COUNT]:
        d = np.asarray(direction) / np.linalg.norm(direction)
        color += np.clip(normal @ d, 0, None)[..., None] * np.asarray(light)
    color = np.where((r2 <= 1)[..., None], np.minimum(color, 1.0), 0.0)
    return 255 * color, np.abs(r2 - 1) > 0.03


@pytest.mark.parametrize("module", [lights_gl, lights_wgpu], ids=["gl", "wgpu"])
def test_the_sphere_is_lit_by_the_counted_lights(module):
    image = module.render(SIZE, SIZE)[..., :3].astype(float)
    expected, mask = reference(SIZE)
    error = np.abs(image - expected).max(axis=2) * mask
    row, col = np.unravel_index(error.argmax(), error.shape)
    assert error.max() <= 2, (f"pixel (row {row}, col {col}): expected {np.round(expected[row, col])}, got "
                              f"{image[row, col]} (hint: std140 offsets, the light count, normalising the direction)")


def test_both_apis_give_the_same_picture():
    gl, wg = lights_gl.render(SIZE, SIZE).astype(int), lights_wgpu.render(SIZE, SIZE).astype(int)
    same = (np.abs(gl - wg).max(axis=2) <= 2).mean()
    assert same >= 0.995, f"only {100 * same:.2f} % of pixels agree to 2 steps (allowed ≥ 99.5 %)"


def test_both_apis_upload_the_same_block_of_count_then_vec4_pairs():
    assert lights_gl.light_block is lights_wgpu.light_block is light_block
    data = light_block()
    assert len(data) == 16 + 32 * MAX_LIGHTS
    assert np.frombuffer(data[:16], np.uint32).tolist() == [COUNT, 0, 0, 0]
    rows = np.frombuffer(data[16:], np.float32).reshape(2 * MAX_LIGHTS, 4)
    for i, (direction, color) in enumerate(LIGHTS):
        np.testing.assert_allclose(rows[2 * i], [*direction, 0.0], err_msg=f"light {i}'s direction")
        np.testing.assert_allclose(rows[2 * i + 1], [*color, 0.0], err_msg=f"light {i}'s colour")


@pytest.mark.parametrize("module", [lights_gl, lights_wgpu], ids=["gl", "wgpu"])
def test_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys):
    check_main_writes_a_png_and_help_only_helps(module, tmp_path, capsys)
