"""The Skybox component: a cube texture drawn behind everything (the renderer adds a sky pass only then)."""

from __future__ import annotations

from ..ecs import Component
from .fields import Name


class SkyboxComponent(Component):
    """Names a cube texture in the scene's assets (or the renderer's texture library)."""

    texture = Name("a cube texture name")

    def __init__(self, texture: str) -> None:
        self.texture = texture
