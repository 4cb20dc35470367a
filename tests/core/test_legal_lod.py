"""The pixels ``legal_lod`` leaves open follow the level-of-detail rules: none where every legal scale factor
rounds to one mip level, all where the legal range holds a level boundary d + 1/2. Checked on a plane seen
straight from above through an orthographic camera, where a pixel's texel footprint is known exactly: ``tx``
texels a pixel across, ``ty`` down, so λ may lie anywhere in [log2 max(tx, ty), log2 (tx + ty)] ± 1/16."""

from __future__ import annotations

import numpy as np
import pytest
from legal_lod import mip_flip_pixels, plane_texels

from gandalf_core.math import orthographic


def _top_down(tx: float, ty: float) -> np.ndarray:
    """Texel coordinates of a 16 × 16 picture of a plane of 64 texels over edge 8, seen from y = 5 looking down
    -Y (+X to the right, +Z towards the bottom of the picture)."""
    half_x, half_y = 16 * tx / 64 * 8 / 2, 16 * ty / 64 * 8 / 2
    view = np.array([[1.0, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, -5], [0, 0, 0, 1]])
    return plane_texels(view, orthographic(-half_x, half_x, -half_y, half_y, 0.1, 10.0), (16, 16), 0.0, 8.0, 64)


def test_the_texel_coordinates_step_by_the_footprint():
    texel = _top_down(2.0, 0.5)
    assert np.allclose(np.diff(texel[..., 0], axis=1), 2.0) and np.allclose(np.diff(texel[..., 1], axis=0), 0.5)


@pytest.mark.parametrize(("tx", "ty", "open_level"), [
    (1.0, 1.0, True),         # λ in [0, 1]: holds 1/2
    (0.5, 0.5, False),        # magnified: λ ≤ 0 (+ 1/16)
    (0.6, 0.6, False),        # λ in [-0.74, 0.26]: below 1/2
    (2.0**1.7, 2.0**1.7, True),  # λ in [1.7, 2.7]: holds 2.5
    (2.0, 0.1, False),        # anisotropic: λ in [1, 1.07], level 1 whatever the approximation
    (2.0**1.45, 0.1, True),   # λ in [1.45, 1.5]: 1.5 is the boundary between levels 1 and 2
])
def test_open_levels_follow_the_scale_factor_bounds(tx, ty, open_level):
    found = mip_flip_pixels(_top_down(tx, ty))
    assert found.all() == open_level and found.any() == open_level, (tx, ty, found.mean())
