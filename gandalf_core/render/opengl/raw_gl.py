"""The few OpenGL calls moderngl does not wrap, made through ctypes: clip control and a float depth buffer for
real reverse-Z, a colour-only blit to the window, the buffer texture through which shaders read the instance
rows (:class:`BufferTexture`), and cube maps whose mip levels are allocated at once (:class:`CubeTexture`).

Clip control (OpenGL 4.5) sets clip-space depth to [0, 1] as in WebGPU.
With OpenGL's default [-1, 1] clip depth, reverse-Z gains nothing: the mapping to the depth buffer adds 1 and
halves, which rounds away the tiny depths near the far plane where reverse-Z keeps its precision. With
``glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)`` and a float depth buffer, the clip depth is stored as it is, so
one camera gives the same depths, and the same picture, in both APIs. The functions are loaded from the GL
library (libglvnd dispatches them to the current context, EGL or GLX).
"""

from __future__ import annotations

import ctypes
import ctypes.util
import functools
from collections.abc import Callable
from typing import Any

GL_LOWER_LEFT = 0x8CA1
GL_NEGATIVE_ONE_TO_ONE = 0x935E
GL_ZERO_TO_ONE = 0x935F
GL_TEXTURE_2D = 0x0DE1
GL_TEXTURE_BINDING_2D = 0x8069
GL_DEPTH_COMPONENT = 0x1902
GL_DEPTH_COMPONENT32F = 0x8CAC
GL_FLOAT = 0x1406
GL_READ_FRAMEBUFFER = 0x8CA8
GL_DRAW_FRAMEBUFFER = 0x8CA9
GL_COLOR_BUFFER_BIT = 0x4000
GL_NEAREST = 0x2600
GL_TEXTURE0 = 0x84C0
GL_MAX_TEXTURE_BUFFER_SIZE = 0x8C2B
GL_TEXTURE_BUFFER = 0x8C2A
GL_RGBA32F = 0x8814
#: The sampler types of buffer textures (float, int, uint): moderngl does not set their uniform's unit.
GL_BUFFER_SAMPLER_TYPES = frozenset({0x8DC2, 0x8DD0, 0x8DD8})


@functools.cache
def gl_function(name: str, argtypes: tuple[type, ...]) -> Callable[..., None]:
    """The GL library's function ``name`` with its argument types (one moderngl does not wrap), or RuntimeError."""
    errors = []
    for library in ("libGL.so.1", "libOpenGL.so.0", ctypes.util.find_library("GL")):
        if not library:
            continue
        try:
            function = getattr(ctypes.CDLL(library), name)
        except (OSError, AttributeError) as exc:
            errors.append(f"{library}: {exc}")
            continue
        function.argtypes = list(argtypes)
        function.restype = None
        return function
    raise RuntimeError(f"the OpenGL renderer needs {name}, which no GL library here exports "
                       f"({'; '.join(errors) or 'no libGL found'})")


def _gl_clip_control() -> Callable[[int, int], None]:
    return gl_function("glClipControl", (ctypes.c_uint, ctypes.c_uint))


def make_float_depth(glo: int, width: int, height: int) -> None:
    """Give the 2-D depth texture ``glo`` (made by moderngl, which only makes 24-bit ones) 32-bit float storage.

    Reverse-Z keeps its precision only in a float depth buffer: fixed-point depth has the same steps everywhere.
    """
    get = gl_function("glGetIntegerv", (ctypes.c_uint, ctypes.POINTER(ctypes.c_int)))
    bind = gl_function("glBindTexture", (ctypes.c_uint, ctypes.c_uint))
    image = gl_function("glTexImage2D", (ctypes.c_uint, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_int,
                                          ctypes.c_int, ctypes.c_uint, ctypes.c_uint, ctypes.c_void_p))
    previous = ctypes.c_int()
    get(GL_TEXTURE_BINDING_2D, ctypes.byref(previous))
    bind(GL_TEXTURE_2D, glo)
    image(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, width, height, 0, GL_DEPTH_COMPONENT, GL_FLOAT, None)
    bind(GL_TEXTURE_2D, previous.value)


def get_integer(name: int) -> int:
    """``glGetIntegerv(name)`` for the current context."""
    value = ctypes.c_int()
    gl_function("glGetIntegerv", (ctypes.c_uint, ctypes.POINTER(ctypes.c_int)))(name, ctypes.byref(value))
    return value.value


def set_sampler_unit(program_glo: int, location: int, unit: int) -> None:
    """Point the sampler uniform at ``location`` of program ``program_glo`` at texture unit ``unit``: for sampler
    types moderngl does not set (``samplerBuffer``). Leaves the program in use (moderngl binds its own per draw)."""
    gl_function("glUseProgram", (ctypes.c_uint,))(program_glo)
    gl_function("glUniform1i", (ctypes.c_int, ctypes.c_int))(location, unit)


def supported(version_code: int, extensions: set[str]) -> bool:
    """True when the context has clip control (OpenGL 4.5, or the ARB_clip_control extension)."""
    return version_code >= 450 or "GL_ARB_clip_control" in extensions


def set_zero_to_one(on: bool) -> None:
    """Clip depth in [0, 1] (``on``) or OpenGL's default [-1, 1], for the context current on this thread."""
    _gl_clip_control()(GL_LOWER_LEFT, GL_ZERO_TO_ONE if on else GL_NEGATIVE_ONE_TO_ONE)


def blit_color(source_glo: int, target_glo: int, size: tuple[int, int], target_size: tuple[int, int]) -> None:
    """Copy only the colour of framebuffer ``source_glo`` onto ``target_glo`` (0: the window).

    moderngl's ``copy_framebuffer`` copies depth too, which fails (GL_INVALID_OPERATION, nothing copied) when the
    two depth formats differ, as the float depth target and a window's 24-bit depth buffer do.
    """
    bind = gl_function("glBindFramebuffer", (ctypes.c_uint, ctypes.c_uint))
    blit = gl_function("glBlitFramebuffer", (ctypes.c_int,) * 8 + (ctypes.c_uint, ctypes.c_uint))
    bind(GL_READ_FRAMEBUFFER, source_glo)
    bind(GL_DRAW_FRAMEBUFFER, target_glo)
    blit(0, 0, *size, 0, 0, *target_size, GL_COLOR_BUFFER_BIT, GL_NEAREST)


GL_TEXTURE_CUBE_MAP = 0x8513
GL_TEXTURE_CUBE_MAP_POSITIVE_X = 0x8515
GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL = 0x813C, 0x813D
GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER = 0x2801, 0x2800
GL_LINEAR = 0x2601
GL_UNPACK_ALIGNMENT, GL_PACK_ALIGNMENT = 0x0CF5, 0x0D05
GL_RGBA = 0x1908
GL_UNSIGNED_BYTE = 0x1401


def has_texture_storage(version_code: int, extensions: set[str]) -> bool:
    """True when the context can give a texture all its levels at once (glTexStorage2D: OpenGL 4.2, or the
    ARB_texture_storage extension)."""
    return version_code >= 420 or "GL_ARB_texture_storage" in extensions


class CubeTexture:
    """A cube texture of RGBA8 faces whose levels are all allocated at once (``glTexStorage2D``), for a cube map
    with mip levels made on the GPU. moderngl's ``texture_cube`` allocates level 0 alone, and making the levels
    then reallocates the texture while level 0 is still held: for a 2048² sky on llvmpipe, where texture memory is
    the process's own, 96 + 128 MiB at once instead of 128. It offers what the engine uses of moderngl's
    ``TextureCube``: ``write``, ``read``, ``build_mipmaps``, ``use``, ``filter``, ``release``, ``glo`` and ``size``
    (a cube map has no anisotropy setting in the engine)."""

    def __init__(self, size: int, levels: int, internal_format: int) -> None:
        name = ctypes.c_uint()
        gl_function("glGenTextures", (ctypes.c_int, ctypes.POINTER(ctypes.c_uint)))(1, ctypes.byref(name))
        self.glo = name.value
        self.size = (size, size)
        self.use(0)
        gl_function("glTexStorage2D", (ctypes.c_uint, ctypes.c_int, ctypes.c_uint, ctypes.c_int, ctypes.c_int))(
            GL_TEXTURE_CUBE_MAP, levels, internal_format, size, size)
        self.filter = (GL_LINEAR, GL_LINEAR)  # as moderngl's textures start

    def _parameter(self, name: int, value: int) -> None:
        self.use(0)
        gl_function("glTexParameteri", (ctypes.c_uint, ctypes.c_uint, ctypes.c_int))(GL_TEXTURE_CUBE_MAP, name, value)

    def write(self, face: int, pixels: Any) -> None:
        """Level 0 of cube face ``face`` (0-5: +X, -X, +Y, -Y, +Z, -Z) from a C-contiguous (size, size, 4) uint8
        array."""
        if pixels.shape != (*self.size, 4) or pixels.dtype.itemsize != 1 or not pixels.flags.c_contiguous:
            raise ValueError(f"a face of this cube texture is a C-contiguous {self.size[0]}x{self.size[1]}x4 uint8 "
                             f"array, got {pixels.shape} {pixels.dtype}")
        self.use(0)
        gl_function("glPixelStorei", (ctypes.c_uint, ctypes.c_int))(GL_UNPACK_ALIGNMENT, 1)
        gl_function("glTexSubImage2D", (ctypes.c_uint,) + (ctypes.c_int,) * 5 + (ctypes.c_uint, ctypes.c_uint,
                                                                                  ctypes.c_void_p))(
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, 0, 0, self.size[0], self.size[1], GL_RGBA, GL_UNSIGNED_BYTE,
            pixels.ctypes.data)

    def read(self, face: int, alignment: int = 1, level: int = 0) -> bytes:
        """The RGBA8 texels of cube face ``face`` at mip ``level``, rows packed to ``alignment`` bytes."""
        side = max(1, self.size[0] >> level)
        row = -(-side * 4 // alignment) * alignment
        out = ctypes.create_string_buffer(row * side)
        self.use(0)
        gl_function("glPixelStorei", (ctypes.c_uint, ctypes.c_int))(GL_PACK_ALIGNMENT, alignment)
        gl_function("glGetTexImage", (ctypes.c_uint, ctypes.c_int, ctypes.c_uint, ctypes.c_uint, ctypes.c_void_p))(
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, level, GL_RGBA, GL_UNSIGNED_BYTE, out)
        return out.raw

    def build_mipmaps(self, base: int, max_level: int) -> None:
        """Make levels ``base + 1`` to ``max_level`` from level ``base`` (``glGenerateMipmap``)."""
        self._parameter(GL_TEXTURE_BASE_LEVEL, base)
        self._parameter(GL_TEXTURE_MAX_LEVEL, max_level)
        gl_function("glGenerateMipmap", (ctypes.c_uint,))(GL_TEXTURE_CUBE_MAP)

    @property
    def filter(self) -> tuple[int, int]:
        return self._filter

    @filter.setter
    def filter(self, value: tuple[int, int]) -> None:
        self._filter = (int(value[0]), int(value[1]))
        self._parameter(GL_TEXTURE_MIN_FILTER, self._filter[0])
        self._parameter(GL_TEXTURE_MAG_FILTER, self._filter[1])

    def use(self, location: int = 0) -> None:
        """Bind to texture unit ``location``."""
        gl_function("glActiveTexture", (ctypes.c_uint,))(GL_TEXTURE0 + location)
        gl_function("glBindTexture", (ctypes.c_uint, ctypes.c_uint))(GL_TEXTURE_CUBE_MAP, self.glo)

    def release(self) -> None:
        name = ctypes.c_uint(self.glo)
        gl_function("glDeleteTextures", (ctypes.c_int, ctypes.POINTER(ctypes.c_uint)))(1, ctypes.byref(name))


GL_ACTIVE_UNIFORMS = 0x8B86
GL_UNIFORM_BLOCK_INDEX = 0x8A3A
GL_UNIFORM_OFFSET = 0x8A3B
GL_UNIFORM_ARRAY_STRIDE = 0x8A3C


def block_members(program_glo: int) -> dict[str, dict[str, tuple[int, int]]]:
    """Every uniform block of a linked program as the driver lays it out: ``{block: {member: (offset, array
    stride)}}`` (arrays named ``member[0]``, as GL names them), for the context current on this thread.

    moderngl reports a block's size but not its members' offsets; the layout checks compare these with
    :class:`~gandalf_core.resources.layout.BlockLayout`'s.
    """
    i32p = ctypes.POINTER(ctypes.c_int)
    get_program = gl_function("glGetProgramiv", (ctypes.c_uint, ctypes.c_uint, i32p))
    uniform_name = gl_function("glGetActiveUniformName", (ctypes.c_uint, ctypes.c_uint, ctypes.c_int, i32p,
                                                           ctypes.c_char_p))
    uniforms_iv = gl_function("glGetActiveUniformsiv", (ctypes.c_uint, ctypes.c_int, ctypes.POINTER(ctypes.c_uint),
                                                         ctypes.c_uint, i32p))
    block_name = gl_function("glGetActiveUniformBlockName", (ctypes.c_uint, ctypes.c_uint, ctypes.c_int, i32p,
                                                              ctypes.c_char_p))
    count = ctypes.c_int()
    get_program(program_glo, GL_ACTIVE_UNIFORMS, ctypes.byref(count))
    n = count.value
    if n == 0:
        return {}
    indices = (ctypes.c_uint * n)(*range(n))
    blocks, offsets, strides = (ctypes.c_int * n)(), (ctypes.c_int * n)(), (ctypes.c_int * n)()
    uniforms_iv(program_glo, n, indices, GL_UNIFORM_BLOCK_INDEX, blocks)
    uniforms_iv(program_glo, n, indices, GL_UNIFORM_OFFSET, offsets)
    uniforms_iv(program_glo, n, indices, GL_UNIFORM_ARRAY_STRIDE, strides)
    out: dict[str, dict[str, tuple[int, int]]] = {}
    buffer, length = ctypes.create_string_buffer(512), ctypes.c_int()
    names: dict[int, str] = {}
    for i in range(n):
        if blocks[i] < 0:
            continue
        if blocks[i] not in names:
            block_name(program_glo, blocks[i], 512, ctypes.byref(length), buffer)
            names[blocks[i]] = buffer.value.decode()
        uniform_name(program_glo, i, 512, ctypes.byref(length), buffer)
        member = buffer.value.decode()
        out.setdefault(names[blocks[i]], {})[member] = (offsets[i], strides[i])
    return out


class BufferTexture:
    """A buffer texture (OpenGL 3.1, ``samplerBuffer`` in GLSL) over a moderngl buffer: the vertex shader fetches
    the instance rows from it by index (``texelFetch``), as WebGPU's reads them from a storage buffer. moderngl
    makes no buffer textures, so the texture object is made and bound here."""

    def __init__(self) -> None:
        name = ctypes.c_uint()
        gl_function("glGenTextures", (ctypes.c_int, ctypes.POINTER(ctypes.c_uint)))(1, ctypes.byref(name))
        self.glo = name.value
        # Bound once now, so that the name is a buffer texture from the start.
        gl_function("glBindTexture", (ctypes.c_uint, ctypes.c_uint))(GL_TEXTURE_BUFFER, self.glo)

    def attach(self, buffer_glo: int) -> None:
        """Read ``buffer_glo``'s data store (RGBA32F texels) from now on."""
        gl_function("glBindTexture", (ctypes.c_uint, ctypes.c_uint))(GL_TEXTURE_BUFFER, self.glo)
        gl_function("glTexBuffer", (ctypes.c_uint, ctypes.c_uint, ctypes.c_uint))(GL_TEXTURE_BUFFER, GL_RGBA32F,
                                                                                 buffer_glo)

    def use(self, unit: int) -> None:
        """Bind the texture to texture unit ``unit`` (the unit the shaders' sampler reads)."""
        gl_function("glActiveTexture", (ctypes.c_uint,))(GL_TEXTURE0 + unit)
        gl_function("glBindTexture", (ctypes.c_uint, ctypes.c_uint))(GL_TEXTURE_BUFFER, self.glo)

    def release(self) -> None:
        name = ctypes.c_uint(self.glo)
        gl_function("glDeleteTextures", (ctypes.c_int, ctypes.POINTER(ctypes.c_uint)))(1, ctypes.byref(name))
