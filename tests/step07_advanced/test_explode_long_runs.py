"""The explosion after a long run: its clock reaches the shaders wrapped to one period in float64, so at
t = 1e7 s + 1.3 s the bunny is drawn exactly as at 1.3 s (a float32 clock there steps by 1 s), in both APIs."""

from __future__ import annotations

import numpy as np
from test_explode_render import render_bunny

from step07_advanced import solutions
from step07_advanced.explode.scene import PERIOD


def test_a_long_run_explodes_like_a_short_one(backend):
    short, _, _ = render_bunny(backend, solutions, 1.3)
    long, _, _ = render_bunny(backend, solutions, 1e7 + 1.3)
    assert 1e7 % PERIOD == 0.0
    worst = int(np.abs(short.astype(int) - long.astype(int)).max())
    assert worst <= 1, f"{backend}: the bunny at t = 1e7 + 1.3 s differs from t = 1.3 s by up to {worst}/255"
