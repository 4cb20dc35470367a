"""What a texture viewer can read from a renderer (see :mod:`.texture_readback`): every texture of its library
(2-D or cube, every level), the frame's colour and depth targets, and the shadow map once a shadow pass drew it."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

FRAME_COLOR, FRAME_DEPTH, SHADOW_MAP = "frame colour", "frame depth", "shadow map"
CUBE_FACES = ("+X", "-X", "+Y", "-Y", "+Z", "-Z")


@dataclass(frozen=True)
class TextureSource:
    """A readable texture: ``name``, ``kind`` ("2d", "cube", "color target" or "depth"), size of level 0, levels."""

    name: str
    kind: str
    size: tuple[int, int]
    levels: int = 1

    @property
    def faces(self) -> int:
        return 6 if self.kind == "cube" else 1


def texture_sources(renderer: Any) -> list[TextureSource]:
    """What :func:`read_source` can read now."""
    out = [TextureSource(FRAME_COLOR, "color target", (renderer.width, renderer.height)),
           TextureSource(FRAME_DEPTH, "depth", (renderer.width, renderer.height))]
    if getattr(renderer, "_shadow", None) is not None:
        from gandalf_core.render.frame import SHADOW_MAP_SIZE

        out.append(TextureSource(SHADOW_MAP, "depth", (SHADOW_MAP_SIZE, SHADOW_MAP_SIZE)))
    for name in renderer.textures.names():
        data = renderer.textures.data_of(name)
        cube = not hasattr(data, "width")
        size = (data.size, data.size) if cube else (data.width, data.height)
        out.append(TextureSource(name, "cube" if cube else "2d", size, data.mip_levels))
    return out
