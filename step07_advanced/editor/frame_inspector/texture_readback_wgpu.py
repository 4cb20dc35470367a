"""Texture read-back on WebGPU (see :mod:`.texture_readback`): ``queue.read_texture`` (the engine's textures and
targets carry ``COPY_SRC``; a depth texture is read whole at level 0, WebGPU's rule)."""

from __future__ import annotations

from typing import Any

import numpy as np
import wgpu

from .texture_sources import FRAME_COLOR, FRAME_DEPTH, SHADOW_MAP, TextureSource


def read(renderer: Any, source: TextureSource, face: int, level: int) -> np.ndarray:
    """The texels of ``source`` at cube ``face`` and mip ``level``, with ``queue.read_texture``."""
    if source.name == FRAME_COLOR:
        texture = renderer._color
    elif source.name == FRAME_DEPTH:
        texture = renderer._depth
    elif source.name == SHADOW_MAP:
        texture = renderer._shadow[0]
    else:
        texture = renderer.textures.get(source.name).texture
    width, height = max(1, source.size[0] >> level), max(1, source.size[1] >> level)
    depth = source.kind == "depth"
    where: dict[str, Any] = {"texture": texture, "mip_level": level, "origin": (0, 0, face)}
    if depth:
        where["aspect"] = "depth-only"
    data = renderer.device.queue.read_texture(where, {"offset": 0, "bytes_per_row": 4 * width,
                                                      "rows_per_image": height}, (width, height, 1))
    if depth:
        return np.frombuffer(data, dtype=np.float32).reshape(height, width).copy()
    return np.frombuffer(data, dtype=np.uint8).reshape(height, width, 4).copy()


def upload(renderer: Any, rgba: np.ndarray, texture: Any = None) -> tuple[Any, Any]:
    """``rgba`` in an RGBA8 texture (``texture`` written again when given): ``(texture, its view)``."""
    height, width = rgba.shape[:2]
    if texture is None:
        texture = renderer.device.create_texture(size=(width, height, 1), format="rgba8unorm", label="texture viewer",
                                                 usage=wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST)
    renderer.device.queue.write_texture({"texture": texture, "mip_level": 0, "origin": (0, 0, 0)}, rgba,
                                        {"offset": 0, "bytes_per_row": 4 * width}, (width, height, 1))
    return texture, texture.create_view()
