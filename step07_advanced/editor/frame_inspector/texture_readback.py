"""Any texture a renderer holds, read back as numpy, one face and mip level at a time: what a texture viewer shows.

Sources (:func:`texture_sources`): every texture of the renderer's library (2-D or cube, every level), the frame's
colour and depth targets (the ones it draws into now: inside an :class:`~gandalf_core.render.offscreen.
OffscreenTarget`'s ``drawing()``, that target's), and the shadow map once a shadow pass has drawn it.
:func:`read_source` returns colour as ``(h, w, 4)`` uint8 (the stored bytes: sRGB-encoded where the format is),
depth as ``(h, w)`` float32, top row first in both APIs. :func:`display_rgba` turns either into bytes to show
(depth stretched over its own range, so a shadow map's shapes are visible).

OpenGL reads with ``glGetTexImage`` (any level, any cube face); WebGPU with ``queue.read_texture`` (its textures
and targets carry ``COPY_SRC`` for it; a depth texture is read whole at level 0, WebGPU's rule).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .texture_sources import CUBE_FACES, FRAME_COLOR, FRAME_DEPTH, SHADOW_MAP, TextureSource, texture_sources

__all__ = ["CUBE_FACES", "FRAME_COLOR", "FRAME_DEPTH", "SHADOW_MAP", "TextureSource", "display_rgba", "read_source",
           "release_display", "texture_sources", "upload_display"]


def read_source(renderer: Any, name: str, face: int = 0, level: int = 0) -> np.ndarray:
    """The texels of source ``name`` (see :func:`texture_sources`) at cube ``face`` and mip ``level``."""
    sources = {s.name: s for s in texture_sources(renderer)}
    source = sources.get(name)
    if source is None:
        raise ValueError(f"texture viewer: no texture '{name}' (sources: {', '.join(sources)})")
    if not (0 <= face < source.faces and 0 <= level < source.levels):
        raise ValueError(f"texture viewer: '{name}' has {source.faces} face(s) and {source.levels} level(s); "
                         f"asked for face {face}, level {level}")
    if renderer.backend == "opengl":
        from .texture_readback_gl import read
    else:
        from .texture_readback_wgpu import read
    return read(renderer, source, face, level)


def display_rgba(texels: np.ndarray) -> np.ndarray:
    """``(h, w, 4)`` uint8 to show: colour as stored, depth stretched over its own range to grey."""
    if texels.ndim == 3:
        return np.ascontiguousarray(texels)
    finite = texels[np.isfinite(texels)]
    lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    grey = np.zeros(texels.shape) if hi <= lo else (np.nan_to_num(texels, nan=lo) - lo) / (hi - lo)
    grey8 = (np.clip(grey, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)
    return np.ascontiguousarray(np.dstack([grey8, grey8, grey8, np.full_like(grey8, 255)]))


def upload_display(renderer: Any, rgba: np.ndarray, texture: Any = None) -> tuple[Any, Any]:
    """``rgba`` (from :func:`display_rgba`) in a plain RGBA8 texture a GUI can show: ``(texture, shown)``, where
    ``shown`` is what a GUI renderer registers (the GL texture, the wgpu texture's view). ``texture`` (one this
    function made, of the same size) is written again instead of making a new one."""
    if renderer.backend == "opengl":
        from .texture_readback_gl import upload
    else:
        from .texture_readback_wgpu import upload
    return upload(renderer, np.ascontiguousarray(rgba), texture)


def release_display(texture: Any) -> None:
    """Free a texture :func:`upload_display` made."""
    if hasattr(texture, "release"):
        texture.release()
    else:
        texture.destroy()
