"""Correct alternatives of step 03: the brick wall built with plain loops and a different draw of the factors
(any uniform draw from [1 - variation, 1 + variation] per brick is allowed)."""

from __future__ import annotations

import numpy as np

from gandalf_core.resources import TextureData
from gandalf_tools.grading.fairness import alternative
from gandalf_tools.grading.mutants import Mutant, patch

STEP = "step03_textures"
ALTERNATIVES: list[Mutant] = []


@alternative(ALTERNATIVES, STEP, "brick_texture", "loops-and-uniform",
             "texel loops; factors drawn with rng.uniform per (course, column) in a dict; np.minimum to clip")
def _(pkg):
    original = pkg.bricks.brick_texture

    def brick_texture(width=128, height=128, brick_size=(32, 16), mortar=2, brick_color=(0.62, 0.27, 0.18),
                      mortar_color=(0.80, 0.78, 0.72), variation=0.1, seed=0, **settings):
        original(width, height, brick_size, mortar, brick_color, mortar_color, variation, seed)  # the checks
        bw, bh = brick_size
        rng = np.random.default_rng(seed)
        columns = -(-width // bw)
        factors: dict[tuple[int, int], float] = {}
        rgb = np.zeros((height, width, 3))
        for y in range(height):
            course = y // bh
            shift = bw // 2 if course % 2 else 0
            for x in range(width):
                if y % bh < mortar or (x - shift) % bw < mortar:
                    rgb[y, x] = mortar_color
                    continue
                key = (course, ((x - shift) // bw) % columns)
                if key not in factors:
                    factors[key] = rng.uniform(1.0 - variation, 1.0 + variation)
                rgb[y, x] = np.maximum(np.minimum(np.asarray(brick_color) * factors[key], 1.0), 0.0)
        settings.setdefault("name", "bricks")
        return TextureData.from_array(rgb, **settings)

    patch(pkg, "bricks.brick_texture", brick_texture)
