"""Texture read-back on OpenGL (see :mod:`.texture_readback`): ``glGetTexImage``, any level and cube face."""

from __future__ import annotations

import ctypes
from typing import Any

import numpy as np

from .texture_sources import FRAME_COLOR, FRAME_DEPTH, SHADOW_MAP, TextureSource

_GL_TEXTURE_2D, _GL_TEXTURE_CUBE_MAP, _GL_CUBE_FACE0 = 0x0DE1, 0x8513, 0x8515
_GL_BINDING = {_GL_TEXTURE_2D: 0x8069, _GL_TEXTURE_CUBE_MAP: 0x8514}
_GL_TEXTURE_WIDTH, _GL_TEXTURE_HEIGHT = 0x1000, 0x1001
_GL_RGBA, _GL_UNSIGNED_BYTE, _GL_DEPTH_COMPONENT, _GL_FLOAT = 0x1908, 0x1401, 0x1902, 0x1406
_GL_PACK_ALIGNMENT = 0x0D05


def read(renderer: Any, source: TextureSource, face: int, level: int) -> np.ndarray:
    """The texels of ``source`` at cube ``face`` and mip ``level``, with ``glGetTexImage``."""
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


def upload(renderer: Any, rgba: np.ndarray, texture: Any = None) -> tuple[Any, Any]:
    """``rgba`` in an RGBA8 texture (``texture`` written again when given): ``(texture, texture)``."""
    height, width = rgba.shape[:2]
    renderer.make_current()
    if texture is None:
        texture = renderer.ctx.texture((width, height), 4)
    texture.write(rgba.tobytes())
    return texture, texture
