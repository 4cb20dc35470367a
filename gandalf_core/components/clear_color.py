"""The ClearColor component: the background colour a frame starts from."""

from __future__ import annotations

from collections.abc import Sequence

from ..ecs import Component
from .fields import Color


class ClearColorComponent(Component):
    """Background colour as sRGB values in [0, 1] (what a colour picker shows); alpha defaults to 1.

    The renderer converts it to linear light; an sRGB framebuffer encodes it back, so a colour of
    (0.2, 0.4, 0.8) reads back as bytes (51, 102, 204) in both backends. Values above 1 are clipped.
    """

    color = Color(alpha=True, clip=True)

    def __init__(self, color: Sequence[float] = (0.1, 0.1, 0.12, 1.0)) -> None:
        self.color = color
