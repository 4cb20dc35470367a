"""The lights both API lessons draw (``lights_gl.py``, ``lights_wgpu.py``) and their bytes.

The block is a count, then up to ``MAX_LIGHTS`` (direction, colour) pairs. OpenGL's std140 rules and WGSL's
uniform rules give it the same layout: the count padded to 16 bytes (the array starts at byte 16), then one vec4
per direction and per colour. Only how the buffer is bound differs between the APIs.
"""

from __future__ import annotations

import numpy as np

MAX_LIGHTS = 4
#: (direction towards the light, linear RGB colour); the fourth slot is beyond ``count`` and must not show.
LIGHTS = [((-1.0, 1.0, 1.0), (0.8, 0.6, 0.3)), ((1.0, 0.0, 0.5), (0.1, 0.2, 0.6)),
          ((0.0, 0.0, -1.0), (1.0, 1.0, 1.0)), ((0.0, 0.0, 1.0), (5.0, 0.0, 5.0))]
COUNT, AMBIENT = 3, 0.05


def light_block() -> bytes:
    """The block's bytes: the count (u32, padded to 16 bytes), then the (direction, colour) vec4 pairs."""
    rows = np.zeros((2 * MAX_LIGHTS, 4))
    for i, (direction, color) in enumerate(LIGHTS):
        rows[2 * i, :3], rows[2 * i + 1, :3] = direction, color
    return np.array([COUNT, 0, 0, 0], np.uint32).tobytes() + rows.astype("f4").tobytes()
