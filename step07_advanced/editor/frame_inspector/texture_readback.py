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

import ctypes
from dataclasses import dataclass
from typing import Any

import numpy as np

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
        return _read_gl(renderer, source, face, level)
    return _read_wgpu(renderer, source, face, level)


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
    height, width = rgba.shape[:2]
    if renderer.backend == "opengl":
        renderer.make_current()
        if texture is None:
            texture = renderer.ctx.texture((width, height), 4)
        texture.write(np.ascontiguousarray(rgba).tobytes())
        return texture, texture
    import wgpu

    if texture is None:
        texture = renderer.device.create_texture(size=(width, height, 1), format="rgba8unorm", label="texture viewer",
                                                 usage=wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST)
    renderer.device.queue.write_texture({"texture": texture, "mip_level": 0, "origin": (0, 0, 0)},
                                        np.ascontiguousarray(rgba), {"offset": 0, "bytes_per_row": 4 * width},
                                        (width, height, 1))
    return texture, texture.create_view()


def release_display(texture: Any) -> None:
    """Free a texture :func:`upload_display` made."""
    if hasattr(texture, "release"):
        texture.release()
    else:
        texture.destroy()


# --- OpenGL ---------------------------------------------------------------------------------------
_GL_TEXTURE_2D, _GL_TEXTURE_CUBE_MAP, _GL_CUBE_FACE0 = 0x0DE1, 0x8513, 0x8515
_GL_BINDING = {_GL_TEXTURE_2D: 0x8069, _GL_TEXTURE_CUBE_MAP: 0x8514}
_GL_TEXTURE_WIDTH, _GL_TEXTURE_HEIGHT = 0x1000, 0x1001
_GL_RGBA, _GL_UNSIGNED_BYTE, _GL_DEPTH_COMPONENT, _GL_FLOAT = 0x1908, 0x1401, 0x1902, 0x1406
_GL_PACK_ALIGNMENT = 0x0D05


def _read_gl(renderer: Any, source: TextureSource, face: int, level: int) -> np.ndarray:
    from gandalf_core.render.opengl.raw_gl import gl_function

    renderer.make_current()
    if source.name == FRAME_COLOR:
        texture, target, flip = renderer._color, _GL_TEXTURE_2D, True
    elif source.name == FRAME_DEPTH:
        texture, target, flip = renderer._depth, _GL_TEXTURE_2D, True
    elif source.name == SHADOW_MAP:
        texture, target, flip = renderer._shadow[0], _GL_TEXTURE_2D, True
    else:  # library textures are written top row first: read back in the same order
        texture, flip = renderer.textures.get(source.name), False
        target = _GL_TEXTURE_CUBE_MAP if source.kind == "cube" else _GL_TEXTURE_2D
    int_p = ctypes.POINTER(ctypes.c_int)
    get = gl_function("glGetIntegerv", (ctypes.c_uint, int_p))
    bind = gl_function("glBindTexture", (ctypes.c_uint, ctypes.c_uint))
    level_iv = gl_function("glGetTexLevelParameteriv", (ctypes.c_uint, ctypes.c_int, ctypes.c_uint, int_p))
    image = gl_function("glGetTexImage", (ctypes.c_uint, ctypes.c_int, ctypes.c_uint, ctypes.c_uint,
                                           ctypes.c_void_p))
    pixel_store = gl_function("glPixelStorei", (ctypes.c_uint, ctypes.c_int))
    previous, width, height = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
    get(_GL_BINDING[target], ctypes.byref(previous))
    bind(target, texture.glo)
    face_target = _GL_CUBE_FACE0 + face if target == _GL_TEXTURE_CUBE_MAP else target
    try:
        level_iv(face_target, level, _GL_TEXTURE_WIDTH, ctypes.byref(width))
        level_iv(face_target, level, _GL_TEXTURE_HEIGHT, ctypes.byref(height))
        depth = source.kind == "depth"
        out = np.empty((height.value, width.value) + (() if depth else (4,)), dtype=np.float32 if depth else np.uint8)
        pixel_store(_GL_PACK_ALIGNMENT, 1)
        image(face_target, level, _GL_DEPTH_COMPONENT if depth else _GL_RGBA, _GL_FLOAT if depth else _GL_UNSIGNED_BYTE,
              out.ctypes.data)
    finally:
        bind(target, previous.value)
    return np.ascontiguousarray(out[::-1]) if flip else out


# --- WebGPU ---------------------------------------------------------------------------------------
def _read_wgpu(renderer: Any, source: TextureSource, face: int, level: int) -> np.ndarray:
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
