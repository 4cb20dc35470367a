"""The WebGPU renderer: a wgpu device, an ``rgba8unorm-srgb`` offscreen target, optional window surface."""

from __future__ import annotations

from importlib import resources
from typing import Any

import numpy as np
import wgpu

from ..base import Renderer
from .device import request_device

COLOR_FORMAT = "rgba8unorm-srgb"
DEPTH_FORMAT = "depth32float"


class WebGPURenderer(Renderer):
    """wgpu render context. ``window`` is a :class:`gandalf_core.app.window.Window` or None (headless)."""

    backend = "webgpu"
    depth_range = "webgpu"

    def __init__(self, width: int, height: int, window: Any = None) -> None:
        super().__init__(width, height)
        self.window = window
        self._surface = None
        if window is not None:
            from wgpu.utils.glfw_present_info import get_glfw_present_info

            self._surface = wgpu.gpu.get_canvas_context(get_glfw_present_info(window.handle, vsync=False))
        self.adapter, self.device = request_device(self._surface)
        if self._surface is not None:
            self._surface_format = self._surface.get_preferred_format(self.adapter)
            self._surface.configure(device=self.device, format=self._surface_format)
            self._present = _PresentBlit(self.device, self._surface_format)
        self.encoder: Any = None
        self.render_pass: Any = None
        self._create_targets()

    def _create_targets(self) -> None:
        usage = wgpu.TextureUsage
        self._color = self.device.create_texture(
            size=(self.width, self.height, 1),
            format=COLOR_FORMAT,
            usage=usage.RENDER_ATTACHMENT | usage.COPY_SRC | usage.TEXTURE_BINDING,
        )
        self._depth = self.device.create_texture(
            size=(self.width, self.height, 1), format=DEPTH_FORMAT, usage=usage.RENDER_ATTACHMENT
        )
        self.color_view = self._color.create_view()
        self.depth_view = self._depth.create_view()

    def begin_frame(self, clear_color_linear: np.ndarray) -> None:
        self.stats["draw_calls"] = 0
        self.encoder = self.device.create_command_encoder()
        self.render_pass = self.encoder.begin_render_pass(
            color_attachments=[
                {
                    "view": self.color_view,
                    "clear_value": tuple(float(x) for x in clear_color_linear),
                    "load_op": "clear",
                    "store_op": "store",
                }
            ],
            depth_stencil_attachment={
                "view": self.depth_view,
                "depth_clear_value": 1.0,
                "depth_load_op": "clear",
                "depth_store_op": "store",
            },
        )

    def end_frame(self) -> None:
        self.render_pass.end()
        if self._surface is not None:
            self._present.draw(self.encoder, self.color_view, self._surface.get_current_texture().create_view())
        self.device.queue.submit([self.encoder.finish()])
        self.render_pass = self.encoder = None
        if self._surface is not None:
            self._surface.present()

    def read_pixels(self) -> np.ndarray:
        data = self.device.queue.read_texture(
            {"texture": self._color, "origin": (0, 0, 0), "mip_level": 0},
            {"offset": 0, "bytes_per_row": self.width * 4, "rows_per_image": self.height},
            (self.width, self.height, 1),
        )
        return np.frombuffer(data, dtype=np.uint8).reshape(self.height, self.width, 4).copy()

    def resize(self, width: int, height: int) -> None:
        if (width, height) == (self.width, self.height) or width <= 0 or height <= 0:
            return
        self._color.destroy()
        self._depth.destroy()
        self.width, self.height = int(width), int(height)
        self._create_targets()
        if self._surface is not None:
            self._surface.configure(device=self.device, format=self._surface_format)

    def release(self) -> None:
        self._color.destroy()
        self._depth.destroy()
        self.device.destroy()


class _PresentBlit:
    """Draws the offscreen target onto the window's surface texture with a full-screen triangle."""

    def __init__(self, device: Any, surface_format: str) -> None:
        code = resources.files(__package__).joinpath("present.wgsl").read_text()
        module = device.create_shader_module(code=code, label="present.wgsl")
        self.device = device
        self.pipeline = device.create_render_pipeline(
            layout="auto",
            vertex={"module": module, "entry_point": "vs_main"},
            fragment={"module": module, "entry_point": "fs_main", "targets": [{"format": surface_format}]},
            primitive={"topology": "triangle-list"},
        )
        self.sampler = device.create_sampler()

    def draw(self, encoder: Any, source_view: Any, target_view: Any) -> None:
        bind_group = self.device.create_bind_group(
            layout=self.pipeline.get_bind_group_layout(0),
            entries=[{"binding": 0, "resource": source_view}, {"binding": 1, "resource": self.sampler}],
        )
        rpass = encoder.begin_render_pass(
            color_attachments=[{"view": target_view, "load_op": "clear", "store_op": "store", "clear_value": (0, 0, 0, 1)}]
        )
        rpass.set_pipeline(self.pipeline)
        rpass.set_bind_group(0, bind_group)
        rpass.draw(3)
        rpass.end()
