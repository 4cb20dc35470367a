"""A second render target of its own size that a renderer draws whole frames into: the editor's viewport.

``target = OffscreenTarget(renderer, w, h)``; ``with target.drawing(): renderer.render(data, assets)`` draws one
frame (at the target's size and aspect) into the target instead of the renderer's own frame: no overlay runs and
nothing is presented; the renderer's own targets are untouched and back in place after the ``with``. Build the
frame data inside the ``with`` too, so that the camera's projection takes the target's aspect.

The colour target is sRGB like the renderer's frame (same bytes). ``display_texture`` is what a GUI shows: the
target's bytes read as they are, so a GUI that treats bytes as colours shows the frame as it is. On OpenGL that
is the target itself, sampled without sRGB decoding (EXT_texture_sRGB_decode; a copy where the extension is
missing); on WebGPU a plain ``rgba8unorm`` copy, refreshed after each frame drawn (wgpu-py has no view formats).
Nothing in the renderers changes: the target swaps their size and target attributes for the duration.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import Any

import numpy as np

_GL_FRAMEBUFFER_SRGB = 0x8DB9
_GL_SWAPPED = ("width", "height", "_fbo", "_color", "_depth", "_target", "window", "overlays", "_pending_swap",
               "present_direct")
_WGPU_SWAPPED = ("width", "height", "_color", "_depth", "color_view", "depth_view", "_surface", "overlays")


_GL_TEXTURE_2D = 0x0DE1
_GL_TEXTURE_BINDING_2D = 0x8069
_GL_TEXTURE_SRGB_DECODE_EXT = 0x8A48
_GL_SKIP_DECODE_EXT = 0x8A4A


def _skip_srgb_decode(glo: int) -> None:
    """Make sampling the sRGB texture ``glo`` return its stored bytes (EXT_texture_sRGB_decode)."""
    import ctypes

    from .opengl.raw_gl import gl_function

    get = gl_function("glGetIntegerv", (ctypes.c_uint, ctypes.POINTER(ctypes.c_int)))
    bind = gl_function("glBindTexture", (ctypes.c_uint, ctypes.c_uint))
    parameter = gl_function("glTexParameteri", (ctypes.c_uint, ctypes.c_uint, ctypes.c_int))
    previous = ctypes.c_int()
    get(_GL_TEXTURE_BINDING_2D, ctypes.byref(previous))
    bind(_GL_TEXTURE_2D, glo)
    parameter(_GL_TEXTURE_2D, _GL_TEXTURE_SRGB_DECODE_EXT, _GL_SKIP_DECODE_EXT)
    bind(_GL_TEXTURE_2D, previous.value)


class OffscreenTarget:
    """Colour + depth of ``width`` x ``height`` for ``renderer`` (either backend); :meth:`release` frees them."""

    def __init__(self, renderer: Any, width: int, height: int) -> None:
        self.renderer = renderer
        self.size = (0, 0)
        self._saved: dict[str, Any] = {}
        self._own: dict[str, Any] = {}
        self.display_texture: Any = None
        self._display_fbo: Any = None
        self._display: Any = None
        self.resize(width, height)

    @property
    def width(self) -> int:
        return self.size[0]

    @property
    def height(self) -> int:
        return self.size[1]

    def resize(self, width: int, height: int) -> bool:
        """Recreate the targets at ``width`` x ``height`` (at least 1x1); False when the size did not change."""
        size = (max(int(width), 1), max(int(height), 1))
        if size == self.size:
            return False
        self.release()
        self.size = size
        if self.renderer.backend == "opengl":
            self._create_gl()
        else:
            self._create_wgpu()
        return True

    # --- OpenGL -----------------------------------------------------------------------------------------------
    def _create_gl(self) -> None:
        r = self.renderer
        r.make_current()
        keep = {name: getattr(r, name) for name in ("width", "height", "_fbo", "_color", "_depth")}
        try:
            r.width, r.height = self.size
            r._create_targets()  # the renderer's own recipe: sRGB colour, float depth
            self._own = {"_fbo": r._fbo, "_color": r._color, "_depth": r._depth}
        finally:
            for name, value in keep.items():
                setattr(r, name, value)
        if "GL_EXT_texture_sRGB_decode" in r.ctx.extensions:
            # Sampled without sRGB decoding, the target itself gives its bytes: no copy at all. Only a GUI samples
            # this texture (the renderer draws into it), so the switch changes nothing else.
            _skip_srgb_decode(self._own["_color"].glo)
            self.display_texture = self._own["_color"]
        else:
            self.display_texture = r.ctx.texture(self.size, 4)
            self._display_fbo = r.ctx.framebuffer([self.display_texture])

    # --- WebGPU -----------------------------------------------------------------------------------------------
    def _create_wgpu(self) -> None:
        import wgpu

        from .webgpu.renderer import COLOR_FORMAT, DEPTH_FORMAT

        device, usage = self.renderer.device, wgpu.TextureUsage
        color = device.create_texture(
            size=(*self.size, 1), format=COLOR_FORMAT,
            usage=usage.RENDER_ATTACHMENT | usage.COPY_SRC | usage.TEXTURE_BINDING, label="offscreen colour",
        )
        depth = device.create_texture(size=(*self.size, 1), format=DEPTH_FORMAT,
                                      usage=usage.RENDER_ATTACHMENT | usage.COPY_SRC, label="offscreen depth")
        self._own = {"_color": color, "_depth": depth, "color_view": color.create_view(),
                     "depth_view": depth.create_view()}
        # The same bytes in a plain rgba8unorm texture (read without sRGB decoding): what a GUI that blends bytes
        # as colours must sample. wgpu-py 0.32 has no view_formats, so the bytes are copied after each frame.
        self._display = device.create_texture(size=(*self.size, 1), format="rgba8unorm",
                                              usage=usage.COPY_DST | usage.TEXTURE_BINDING, label="offscreen display")
        self.display_texture = self._display.create_view()

    # --- drawing ----------------------------------------------------------------------------------------------
    @contextlib.contextmanager
    def drawing(self) -> Iterator[OffscreenTarget]:
        """Frames rendered inside the ``with`` go into this target (no overlays, no presenting)."""
        r = self.renderer
        names = _GL_SWAPPED if r.backend == "opengl" else _WGPU_SWAPPED
        saved = {name: getattr(r, name) for name in names}
        try:
            r.width, r.height = self.size
            r.overlays = []
            for name, value in self._own.items():
                setattr(r, name, value)
            if r.backend == "opengl":
                r.window, r._pending_swap, r.present_direct, r._target = None, False, False, None
            else:
                r._surface = None
            yield self
        finally:
            for name, value in saved.items():
                setattr(r, name, value)
            if r.backend == "opengl":
                r._state = None  # the frame changed GL state under the renderer's cache
        self.refresh_display()

    def refresh_display(self) -> None:
        """Copy the target's bytes into the display texture (no sRGB conversion on the way)."""
        r = self.renderer
        if not self._own:
            return
        if r.backend == "webgpu":
            encoder = r.device.create_command_encoder()
            encoder.copy_texture_to_texture({"texture": self._own["_color"], "mip_level": 0, "origin": (0, 0, 0)},
                                            {"texture": self._display, "mip_level": 0, "origin": (0, 0, 0)},
                                            (*self.size, 1))
            r.device.queue.submit([encoder.finish()])
            return
        if self._display_fbo is None:  # the target is its own display texture
            return
        ctx = r.ctx
        ctx.disable_direct(_GL_FRAMEBUFFER_SRGB)
        ctx.copy_framebuffer(self._display_fbo, self._own["_fbo"])
        ctx.enable_direct(_GL_FRAMEBUFFER_SRGB)

    def read_pixels(self) -> np.ndarray:
        """The target's last frame as a ``(height, width, 4)`` uint8 array, top row first."""
        r = self.renderer
        w, h = self.size
        if r.backend == "opengl":
            r.make_current()
            data = self._own["_fbo"].read(components=4, attachment=0)
            return np.ascontiguousarray(np.frombuffer(data, np.uint8).reshape(h, w, 4)[::-1])
        data = r.device.queue.read_texture(
            {"texture": self._own["_color"], "origin": (0, 0, 0), "mip_level": 0},
            {"offset": 0, "bytes_per_row": w * 4, "rows_per_image": h}, (w, h, 1),
        )
        return np.frombuffer(data, np.uint8).reshape(h, w, 4).copy()

    def release(self) -> None:
        """Free the targets (the object can be resized again afterwards)."""
        if not self._own:
            return
        if self.renderer.backend == "opengl":
            self.renderer.make_current()
            if self._display_fbo is not None:
                self._display_fbo.release()
                self.display_texture.release()
            for obj in (self._own["_fbo"], self._own["_color"], self._own["_depth"]):
                obj.release()
        else:
            for texture in (self._own["_color"], self._own["_depth"], self._display):
                texture.destroy()
        self._own, self.display_texture, self._display_fbo, self.size = {}, None, None, (0, 0)
