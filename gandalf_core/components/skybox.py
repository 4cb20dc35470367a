"""The Skybox component: a cube texture drawn behind everything (the renderer adds a sky pass only then)."""

from __future__ import annotations

from ..ecs import Component


class SkyboxComponent(Component):
    """Names a cube texture in the scene's assets (or the renderer's texture library)."""

    def __init__(self, texture: str) -> None:
        if not isinstance(texture, str) or not texture:
            raise TypeError(f"SkyboxComponent.texture must be a cube texture name, got {texture!r}")
        self.texture = texture
