"""The render system: the last system of a frame; clears to the scene's background and draws.

It is backend-neutral: it reads components and hands the renderer what to draw.
"""

from __future__ import annotations

import numpy as np

from ..components import ClearColorComponent
from ..ecs import System
from .base import Renderer
from .color import srgb_rgba_to_linear

DEFAULT_CLEAR = (0.0, 0.0, 0.0, 1.0)


class RenderSystem(System):
    """Draws the scene with ``renderer`` once per frame."""

    def __init__(self, renderer: Renderer) -> None:
        super().__init__([])
        self.renderer = renderer

    def on_create_system(self) -> None:
        self._backgrounds = self.scene.query(ClearColorComponent)

    def clear_color(self) -> np.ndarray:
        """The first ClearColorComponent's colour in linear light (black when the scene has none)."""
        comps = self._backgrounds.components
        return srgb_rgba_to_linear(comps[0][0].color if comps else DEFAULT_CLEAR)

    def on_update_system(self, ts: float) -> None:
        self.renderer.begin_frame(self.clear_color())
        self.renderer.end_frame()
