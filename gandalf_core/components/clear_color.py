"""The ClearColor component: the background colour a frame starts from."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..ecs import Component


class ClearColorComponent(Component):
    """Background colour as sRGB values in [0, 1] (what a colour picker shows); alpha defaults to 1.

    The renderer converts it to linear light; an sRGB framebuffer encodes it back, so a colour of
    (0.2, 0.4, 0.8) reads back as bytes (51, 102, 204) in both backends.
    """

    def __init__(self, color: Sequence[float] = (0.1, 0.1, 0.12, 1.0)) -> None:
        self.color = color

    @property
    def color(self) -> np.ndarray:
        return self._color

    @color.setter
    def color(self, value: Sequence[float]) -> None:
        rgba = np.asarray(value, dtype=np.float64).ravel()
        if rgba.shape == (3,):
            rgba = np.append(rgba, 1.0)
        if rgba.shape != (4,) or not np.all(np.isfinite(rgba)):
            raise ValueError(f"ClearColorComponent.color must be 3 or 4 finite floats, got {value!r}")
        self._color = np.clip(rgba, 0.0, 1.0)
