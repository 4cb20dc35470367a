"""Checks of textures when they are built or bound, the same in both backends, each error naming the texture:

* a texture larger than the device allows (OpenGL would draw it black, WebGPU fail with a bare validation error);
* a cube map in a material's 2-D slot, or the reverse (the error also names the material, shader and slot);
* a frame (render target) larger than the device allows.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..resources import CubeTextureData, ResourceError


def check_texture_kinds(material: str, shader: str, slots: Sequence[tuple[str, bool]],
                        textures: Sequence[tuple[str, Any]]) -> None:
    """``slots``: (slot name, wants a cube map) in binding order; ``textures``: (texture name, its data)."""
    for (slot, wants_cube), (texture, data) in zip(slots, textures):
        is_cube = isinstance(data, CubeTextureData)
        if is_cube != wants_cube:
            have = "a cube map" if is_cube else "a 2-D texture"
            want = "a cube map" if wants_cube else "a 2-D texture"
            raise ResourceError(f"material '{material}'", "textures",
                                f"texture '{texture}' is {have}, but shader '{shader}' samples {want} in slot "
                                f"'{slot}'")


def check_texture_size(name: str, data: Any, limit: int, what: str) -> None:
    """Raise when ``data``'s width or height (a cube face's side) exceeds the device's ``limit``."""
    if isinstance(data, CubeTextureData):
        width = height = data.size
    else:
        height, width = data.pixels.shape[:2]
    if max(width, height) > limit:
        raise ResourceError(f"texture '{name}'", "size", f"{width}x{height} is larger than this device's {what} "
                            f"({limit}): scale the image down")


def check_target_size(width: int, height: int, limit: int) -> None:
    """Raise when a frame of ``width`` x ``height`` exceeds the device's largest render target side ``limit``."""
    for field, value in (("width", width), ("height", height)):
        if value > limit:
            raise ValueError(f"frame {field} {value} is larger than this device's largest render target ({limit} "
                             f"pixels a side): ask for a smaller {field}")
