"""The OpenGL renderer: a moderngl context (EGL offscreen, or a glfw window) and an sRGB offscreen target."""

from __future__ import annotations

from typing import Any

import moderngl
import numpy as np

from ..base import Renderer

GL_FRAMEBUFFER_SRGB = 0x8DB9
GL_SRGB8_ALPHA8 = 0x8C43


class OpenGLRenderer(Renderer):
    """moderngl render context. ``window`` is a :class:`gandalf_core.app.window.Window` or None (headless)."""

    backend = "opengl"
    depth_range = "opengl"

    def __init__(self, width: int, height: int, window: Any = None) -> None:
        super().__init__(width, height)
        self.window = window
        if window is None:
            self.ctx = moderngl.create_standalone_context(backend="egl", require=330)
        else:
            self.ctx = moderngl.create_context(require=330)
        self._fbo: moderngl.Framebuffer | None = None
        self._create_targets()

    def _create_targets(self) -> None:
        size = (self.width, self.height)
        # An sRGB colour target: shaders work in linear light and GL encodes on write, as WebGPU's
        # rgba8unorm-srgb does, so both backends store the same bytes.
        self._color = self.ctx.texture(size, 4, internal_format=GL_SRGB8_ALPHA8)
        self._depth = self.ctx.depth_texture(size)
        self._fbo = self.ctx.framebuffer([self._color], self._depth)

    def _release_targets(self) -> None:
        for obj in (self._fbo, self._color, self._depth):
            obj.release()

    def begin_frame(self, clear_color_linear: np.ndarray) -> None:
        self.stats["draw_calls"] = 0
        self._fbo.use()
        self.ctx.enable_direct(GL_FRAMEBUFFER_SRGB)
        self.ctx.depth_mask = True
        r, g, b, a = (float(x) for x in clear_color_linear)
        self._fbo.clear(r, g, b, a, depth=1.0)

    def end_frame(self) -> None:
        if self.window is not None:
            # Copy the already-encoded bytes as they are: no second sRGB conversion on the way out.
            self.ctx.disable_direct(GL_FRAMEBUFFER_SRGB)
            self.ctx.copy_framebuffer(self.ctx.screen, self._fbo)
            self.window.swap_buffers()
        else:
            self.ctx.finish()

    @property
    def framebuffer(self) -> moderngl.Framebuffer:
        return self._fbo

    def read_pixels(self) -> np.ndarray:
        data = self._fbo.read(components=4, attachment=0)
        image = np.frombuffer(data, dtype=np.uint8).reshape(self.height, self.width, 4)
        return np.ascontiguousarray(image[::-1])  # GL rows are bottom-up

    def resize(self, width: int, height: int) -> None:
        if (width, height) == (self.width, self.height) or width <= 0 or height <= 0:
            return
        self._release_targets()
        self.width, self.height = int(width), int(height)
        self._create_targets()

    def release(self) -> None:
        self._release_targets()
        self.ctx.release()
