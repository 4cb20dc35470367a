"""The filters on WebGPU: WGSL compute pipelines over storage textures, on the renderer's wgpu device.

The source image is an ``rgba8unorm`` texture read with ``textureLoad`` (a sampled texture: WebGPU's storage
textures are write-only unless a feature is enabled, and there is no ``rgba8unorm-srgb`` storage format); a pass
writes a ``texture_storage_2d`` of format ``rgba32float`` (the separable blur's intermediate, read by the next
pass as an unfilterable-float texture) or ``rgba8unorm`` (the result). All passes of one filter are recorded in
one command encoder: WebGPU orders the passes and their texture accesses by itself (no barrier calls).
"""

from __future__ import annotations

from types import ModuleType
from typing import Any

import numpy as np
import wgpu

from gandalf_core.render.webgpu.device import request_device

from .kernels import MAX_RADIUS, check_image, check_op, check_radius, check_shared_memory, check_weights, groups
from .shaders import FORMATS, PARAMS_LAYOUT, PROGRAMS, explain_error, kernel_source, pass_params


class WGPUImageFilter:
    """Runs :data:`~.kernels.OPERATIONS` on RGBA8 images: ``run(image, op, radius)`` returns the filtered image."""

    backend = "webgpu"

    def __init__(self, device: Any, impl: ModuleType) -> None:
        self.device = device
        self.owns_device = False
        adapter = getattr(device, "adapter", None)
        self.device_name = str(getattr(adapter, "info", {}).get("device", "?")) if adapter is not None else "?"
        self.max_size = int(device.limits["max-texture-dimension-2d"])
        self.max_size_name = "maxTextureDimension2D"
        check_shared_memory(int(device.limits["max-compute-workgroup-storage-size"]),
                            "maxComputeWorkgroupStorageSize")
        fmt = FORMATS["webgpu"]
        stage = wgpu.ShaderStage.COMPUTE
        self.layouts = {
            kind: device.create_bind_group_layout(entries=[
                {"binding": 0, "visibility": stage, "buffer": {"type": "uniform"}},
                {"binding": 1, "visibility": stage, "texture": {"sample_type": "unfilterable-float"}},
                {"binding": 2, "visibility": stage, "buffer": {"type": "read-only-storage"}},
                {"binding": 3, "visibility": stage,
                 "storage_texture": {"access": "write-only", "format": fmt[kind], "view_dimension": "2d"}},
            ], label=f"filter {kind}") for kind in ("float", "unorm8")}
        self.layouts["weights"] = device.create_bind_group_layout(entries=[
            {"binding": 0, "visibility": stage, "buffer": {"type": "uniform"}},
            {"binding": 2, "visibility": stage, "buffer": {"type": "storage"}},
        ], label="filter weights")
        self.impl = impl
        self.pipelines: dict[str, Any] = {}
        usage = wgpu.BufferUsage
        self.weights = device.create_buffer(size=(2 * MAX_RADIUS + 2) * 4,
                                            usage=usage.STORAGE | usage.COPY_SRC | usage.COPY_DST)
        self.params = {d: device.create_buffer(size=PARAMS_LAYOUT.size, usage=usage.UNIFORM | usage.COPY_DST)
                       for d in ((1, 0), (0, 1))}
        self.size: tuple[int, int] | None = None
        self.textures: dict[str, Any] = {}
        self.bind_groups: dict[str, Any] = {}

    @classmethod
    def standalone(cls, impl: ModuleType) -> WGPUImageFilter:
        """A filter on its own device (the high-performance adapter, default limits), for the study and the tests."""
        flt = cls(request_device()[1], impl)
        flt.owns_device = True
        return flt

    def _pipeline(self, name: str) -> Any:
        """The compute pipeline ``name`` of :data:`~.shaders.PROGRAMS`, built on first use."""
        if name not in self.pipelines:
            kernel, kind = PROGRAMS[name]
            self.pipelines[name] = self._build_pipeline(kernel, kind, "weights" if kind is None else None)
        return self.pipelines[name]

    def _build_pipeline(self, kernel: str, kind: str | None, layout: str | None = None) -> Any:
        src = kernel_source("webgpu", kernel, self.impl, None if kind is None else FORMATS["webgpu"][kind])
        try:
            module = self.device.create_shader_module(code=src.text, label=src.filename)
        except wgpu.GPUError as exc:
            raise RuntimeError(explain_error(src, str(exc))) from None
        return self.device.create_compute_pipeline(
            layout=self.device.create_pipeline_layout(bind_group_layouts=[self.layouts[layout or kind]]),
            compute={"module": module, "entry_point": "cs_main"}, label=f"filter {kernel}")

    # --- steps (the study times dispatch + finish) ------------------------------------------------------
    def upload(self, image: np.ndarray) -> None:
        """Check ``image`` (RGBA8, (H, W, 4) uint8, within maxTextureDimension2D) and make it the source."""
        image = check_image(image, self.max_size, self.max_size_name)
        h, w = image.shape[:2]
        if self.size != (w, h):
            self._make_textures(w, h)
        self.device.queue.write_texture({"texture": self.textures["src"], "origin": (0, 0, 0), "mip_level": 0},
                                        image.tobytes(), {"offset": 0, "bytes_per_row": w * 4, "rows_per_image": h},
                                        (w, h, 1))

    def _make_textures(self, w: int, h: int) -> None:
        for tex in self.textures.values():
            tex.destroy()
        usage = wgpu.TextureUsage
        fmt = FORMATS["webgpu"]

        def texture(format: str, extra: int) -> Any:
            return self.device.create_texture(size=(w, h, 1), format=format, usage=usage.TEXTURE_BINDING | extra)

        self.textures = {
            "src": texture(fmt["unorm8"], usage.COPY_DST),
            "mid": texture(fmt["float"], usage.STORAGE_BINDING),
            "dst": texture(fmt["unorm8"], usage.STORAGE_BINDING | usage.COPY_SRC),
        }
        views = {k: t.create_view() for k, t in self.textures.items()}

        def group(kind: str, direction: tuple[int, int], src: str, dst: str) -> Any:
            return self.device.create_bind_group(layout=self.layouts[kind], entries=[
                {"binding": 0, "resource": {"buffer": self.params[direction]}},
                {"binding": 1, "resource": views[src]},
                {"binding": 2, "resource": {"buffer": self.weights}},
                {"binding": 3, "resource": views[dst]},
            ])

        self.bind_groups = {
            "horizontal": group("float", (1, 0), "src", "mid"),
            "vertical": group("unorm8", (0, 1), "mid", "dst"),
            "direct": group("unorm8", (1, 0), "src", "dst"),
            "direct_vertical": group("unorm8", (0, 1), "src", "dst"),
            "weights": self.device.create_bind_group(layout=self.layouts["weights"], entries=[
                {"binding": 0, "resource": {"buffer": self.params[(1, 0)]}},
                {"binding": 2, "resource": {"buffer": self.weights}},
            ]),
        }
        self.size = (w, h)

    def dispatch(self, op: str, radius: int = 0, weights: np.ndarray | None = None) -> None:
        """Record ``op`` on the uploaded image into the result texture and submit it (no wait).

        The weight table comes from the student's ``gaussian_weight`` on the GPU, or from ``weights`` when given
        (the tests of ``blur_pass`` use the reference table, so they do not depend on the other exercise).
        """
        check_op(op)
        r = check_radius(radius)
        table = None if weights is None else check_weights(weights, r)
        if self.size is None:
            raise RuntimeError("upload an image before dispatching a filter")
        w, h = self.size
        queue = self.device.queue
        for direction, buffer in self.params.items():
            queue.write_buffer(buffer, 0, pass_params(direction, r))
        if table is not None:
            queue.write_buffer(self.weights, 0, table.tobytes())
        encoder = self.device.create_command_encoder()
        compute = encoder.begin_compute_pass()
        if op != "sobel" and table is None:
            compute.set_pipeline(self._pipeline("weights"))
            compute.set_bind_group(0, self.bind_groups["weights"])
            compute.dispatch_workgroups(-(-(2 * r + 1) // 64))
        if op in ("horizontal", "vertical"):
            compute.set_pipeline(self._pipeline("pass_unorm8"))
            compute.set_bind_group(0, self.bind_groups["direct" if op == "horizontal" else "direct_vertical"])
            compute.dispatch_workgroups(*groups(w, h, op))
        elif op in ("sobel", "naive"):
            compute.set_pipeline(self._pipeline(op))
            compute.set_bind_group(0, self.bind_groups["direct"])
            compute.dispatch_workgroups(*groups(w, h, op))
        else:
            # --8<-- [start:dispatch]
            kind = "pass" if op == "separable" else "tiled"
            for name, direction, fmt in (("horizontal", (1, 0), "float"), ("vertical", (0, 1), "unorm8")):
                compute.set_pipeline(self._pipeline(f"{kind}_{fmt}"))
                compute.set_bind_group(0, self.bind_groups[name])
                compute.dispatch_workgroups(*groups(w, h, op, direction))
        compute.end()
        queue.submit([encoder.finish()])
        # --8<-- [end:dispatch]

    def finish(self) -> None:
        """Wait until the GPU has done everything submitted so far (a 4-byte read-back: F4 in STACK.md)."""
        self.device.queue.read_buffer(self.weights, 0, 4)

    def read(self) -> np.ndarray:
        """The result image, (H, W, 4) uint8, top row first."""
        w, h = self.size
        data = self.device.queue.read_texture(
            {"texture": self.textures["dst"], "origin": (0, 0, 0), "mip_level": 0},
            {"offset": 0, "bytes_per_row": w * 4, "rows_per_image": h}, (w, h, 1))
        return np.frombuffer(data, dtype=np.uint8).reshape(h, w, 4).copy()

    # --- one call --------------------------------------------------------------------------------------------
    def run(self, image: np.ndarray, op: str, radius: int = 0, weights: np.ndarray | None = None) -> np.ndarray:
        """``op`` (one of :data:`~.kernels.OPERATIONS`) of ``image`` with ``radius``: the RGBA8 result."""
        check_op(op)
        check_radius(radius)
        self.upload(image)
        self.dispatch(op, radius, weights)
        return self.read()

    def weight_table(self, radius: int) -> np.ndarray:
        """The weight table the student's ``gaussian_weight`` computes on the GPU, float32 (2·radius + 1,)."""
        r = check_radius(radius)
        if self.size is None:
            self._make_textures(1, 1)
        self.device.queue.write_buffer(self.params[(1, 0)], 0, pass_params((1, 0), r))
        encoder = self.device.create_command_encoder()
        compute = encoder.begin_compute_pass()
        compute.set_pipeline(self._pipeline("weights"))
        compute.set_bind_group(0, self.bind_groups["weights"])
        compute.dispatch_workgroups(-(-(2 * r + 1) // 64))
        compute.end()
        self.device.queue.submit([encoder.finish()])
        data = self.device.queue.read_buffer(self.weights, 0, (2 * r + 2) * 4)
        return np.frombuffer(data, dtype=np.float32)[:2 * r + 1].copy()

    def release(self) -> None:
        for tex in self.textures.values():
            tex.destroy()
        for buffer in (self.weights, *self.params.values()):
            buffer.destroy()
        self.textures, self.bind_groups, self.size = {}, {}, None
        if self.owns_device:
            self.device.destroy()
