"""What both backends' renderers offer the app and the render system.

A renderer owns a GPU context, an offscreen sRGB colour target plus depth, and (optionally) a window
to present to. Every frame is drawn offscreen first, in a window too, so captures, tests and windows
share one render path.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections import Counter
from collections.abc import Callable
from contextlib import nullcontext
from pathlib import Path
from typing import Any

import numpy as np

from ..resources.assets import Assets
from .frame import INSTANCE_STRIDE, PASS_SHADERS, DrawBatch, FrameData, instance_capacity
from .library import ResourceLib
from .patches import check_patch_draw
from .shader_files import engine_shader_files

BACKENDS = ("opengl", "webgpu")
#: Each backend's shading language.
SHADING_LANGUAGES = {"opengl": "glsl", "webgpu": "wgsl"}
#: What the pass and draw loops enter when no :attr:`Renderer.recorder` is set (reusable, costs one attribute test).
NOT_RECORDING = nullcontext()


class UnknownBackendError(ValueError):
    """A backend name that is neither 'opengl' nor 'webgpu'."""


def check_backend(name: str) -> str:
    """Return the canonical backend name or raise UnknownBackendError listing the valid ones."""
    key = str(name).lower().replace("-", "").replace("_", "")
    aliases = {"opengl": "opengl", "gl": "opengl", "moderngl": "opengl", "webgpu": "webgpu", "wgpu": "webgpu"}
    if key not in aliases:
        raise UnknownBackendError(f"unknown backend {name!r}: choose one of {', '.join(BACKENDS)}")
    return aliases[key]


class Renderer(ABC):
    """Backend-neutral face of a render context."""

    backend: str
    #: The buffer of the frame's instance rows (grown by :meth:`_instance_capacity`).
    _instance_buffer: Any = None
    #: The frame-capture hook: None, or while a frame is captured a recorder (the editor's frame inspector installs
    #: its ``FrameRecorder``, :mod:`step07_advanced.editor.frame_inspector`). The pass and draw loops call its
    #: ``begin_frame``/``end_frame``, ``begin_target``/``end_target`` and ``with draw(...)``/``with overlay()``, so a
    #: frame that is not captured pays one test of a local variable per draw.
    recorder: Any = None
    #: ``instances_version`` of the rows the instance buffer holds (see :meth:`_instance_span`).
    _instances_uploaded: tuple[object, int] | None = None
    #: The lights block the lights buffer holds (see :meth:`_lights_changed`).
    _lights_in_buffer: bytes | None = None

    def __init__(self, width: int, height: int, window: Any = None) -> None:
        if int(width) <= 0 or int(height) <= 0:
            raise ValueError(f"render target size must be positive, got {width}x{height}")
        self.width, self.height = int(width), int(height)
        #: A :class:`gandalf_core.app.window.Window`, or None (headless).
        self.window = window
        #: Counters the tests and benchmarks read: draw calls of the last frame, objects created.
        self.stats: Counter[str] = Counter()
        #: Drawn over each finished frame, in order (a GUI layer such as the editor). OpenGL calls
        #: ``overlay(renderer)`` with the frame's framebuffer bound; WebGPU calls ``overlay(renderer,
        #: render_pass)`` at the end of the scene's render pass (colour ``renderer.color_view``, depth
        #: ``renderer.depth_view``), so that an overlay draws into the frame without a pass of its own.
        self.overlays: list[Callable[..., None]] = []
        #: GPU objects that code outside the engine keeps with this renderer (a frame's ``instance_pass``, step 07's
        #: GPU-driven motion), by name: each has ``release()``, called when the renderer is released.
        self.attachments: dict[str, Any] = {}

    @property
    def aspect(self) -> float:
        return self.width / self.height

    @property
    def depth_range(self) -> str:
        """NDC depth range of this API, passed to the projection functions (named by the backend)."""
        return self.backend

    @property
    def shading_language(self) -> str:
        """The language of its shaders: ``"glsl"`` or ``"wgsl"``."""
        return SHADING_LANGUAGES[self.backend]

    def depth_range_for(self, reverse_z: bool) -> str:
        """The NDC depth range a camera's projection must target (OpenGL switches to [0, 1] for reverse-Z)."""
        return self.depth_range

    @abstractmethod
    def render(self, data: FrameData, assets: Assets) -> None:
        """Draw one frame: clear, upload the frame and light uniforms and the instance data once, draw
        each batch with one instanced call (and the sky, if any), then present (in a window)."""

    @abstractmethod
    def read_pixels(self) -> np.ndarray:
        """The last frame as a ``(height, width, 4)`` uint8 array, top row first, sRGB-encoded."""

    @abstractmethod
    def read_pixel(self, x: int, y: int) -> np.ndarray:
        """One pixel of the last frame (``x`` from the left, ``y`` from the top) as 4 uint8 values.

        Also the cheapest way to wait until the GPU has finished the frame (benchmarks use it).
        """

    @abstractmethod
    def resize(self, width: int, height: int) -> None:
        """Recreate the size-dependent targets."""

    @abstractmethod
    def release(self) -> None:
        """Free every GPU object this renderer created."""

    # --- resources on first use (the same for both backends) ------------------------------------
    # Each renderer has ``textures``, ``shaders``, ``meshes`` and ``materials`` libraries (ResourceLib).
    textures: ResourceLib[Any]
    shaders: ResourceLib[Any]
    meshes: ResourceLib[Any]
    materials: ResourceLib[Any]

    def collect(self, all_assets: list[Assets]) -> None:
        """Release the GPU objects built from assets that none of ``all_assets`` (every scene of the app) has any
        more: materials first (they refer to textures), then meshes and textures."""
        self.materials.collect(name for a in all_assets for name in a.materials)
        self.meshes.collect(name for a in all_assets for name in a.meshes)
        self.textures.collect(name for a in all_assets for name in a.textures)

    def _forget_materials_using(self, texture: str) -> None:
        """A texture is going (released or replaced): the materials that bind it go too (rebuilt on next use)."""
        for name in [n for n in self.materials.names() if texture in self.materials.get(n).data.textures]:
            self.materials.forget(name)

    def resolve_material(self, name: str, assets: Assets) -> Any:
        """The material a MaterialComponent names, built (with its textures) from the scene's assets."""
        data = assets.materials.get(name)
        if data is not None:
            # Every frame, so a texture replaced under its name is seen (and its materials rebuilt with it).
            for texture in data.textures:
                self.textures.resolve(texture, assets.textures, f"material '{name}'")
        return self.materials.resolve(name, assets.materials, "a MaterialComponent")

    def resolve_mesh(self, name: str, assets: Assets) -> Any:
        return self.meshes.resolve(name, assets.meshes, "a MeshComponent")

    def resolve_texture(self, name: str, assets: Assets, referrer: str) -> Any:
        return self.textures.resolve(name, assets.textures, referrer)

    def resolve_sky(self, name: str, assets: Assets) -> Any:
        """The cube texture a SkyboxComponent names; a 2-D texture there is an error naming it."""
        from ..resources import CubeTextureData, ResourceError

        texture = self.resolve_texture(name, assets, "a SkyboxComponent")
        if not isinstance(self.textures.data_of(name), CubeTextureData):
            raise ResourceError(f"texture '{name}'", "kind", "a SkyboxComponent needs a cube texture "
                                "(CubeTextureData, six faces); this one is 2-D")
        return texture

    # --- what both backends do the same way in a frame -----------------------------------------
    def resolve_draws(self, data: FrameData, assets: Assets) -> list[tuple[DrawBatch, Any, Any]]:
        """Every batch with its material and mesh, built on first use and checked before any pass is drawn:
        a patch mesh needs a program that tessellates patches of its size (and cannot cast shadows)."""
        draws = []
        indirect_counts: dict[str, int] = {}
        for batch in data.batches:
            material = self.resolve_material(batch.material, assets)
            mesh = self.resolve_mesh(batch.mesh, assets)
            # A GL program with a tessellation control stage has patch_vertices; WebGPU's shaders never do.
            check_patch_draw(batch.material, material.shader.name, getattr(material.shader, "patch_vertices", None),
                             batch.mesh, mesh.data, self.backend)
            if mesh.data.indirect is not None:
                self.indirect_buffer(batch.mesh, mesh.data)  # built and large enough, before any pass
                # WebGPU writes a buffer's instance count once per frame, before the passes run.
                if indirect_counts.setdefault(mesh.data.indirect, batch.count) != batch.count:
                    raise ValueError(f"mesh '{batch.mesh}' is drawn indirectly from buffer '{mesh.data.indirect}' by "
                                     "batches of different instance counts in one frame; give each its own buffer")
            if data.shadows and mesh.data.patch_size is not None and not batch.transparent:
                raise ValueError(f"mesh '{batch.mesh}' (material '{batch.material}') is a patch mesh, which the "
                                 "shadow pass cannot draw: turn off cast_shadows, or draw it with a blended material")
            draws.append((batch, material, mesh))
        return draws

    def indirect_buffer(self, mesh_name: str, mesh: Any) -> Any:
        """The buffer an indirectly drawn mesh reads its draw from (``MeshData.indirect``): it must be built in this
        renderer's buffer library and hold the four ``uint32`` of a draw (16 bytes)."""
        from ..resources import ResourceError

        buffer = self.buffers.get_for(mesh.indirect, "indirect", f"mesh '{mesh_name}' (indirect)")
        if buffer.size < 16:
            raise ResourceError(f"mesh '{mesh_name}'", "indirect", f"buffer '{mesh.indirect}' has {buffer.size} "
                                "bytes; an indirect draw reads 16 (vertex count, instance count, first vertex, "
                                "first instance)")
        return buffer

    def pass_shader(self, kind: str) -> Any:
        """The shader of one of the engine's own passes (``"sky"``, ``"shadow"``: :data:`.frame.PASS_SHADERS`),
        built from ``render/shaders`` in this renderer's language on first use."""
        name, stem = PASS_SHADERS[kind]
        return self.shaders.build(name, *engine_shader_files(stem, self.shading_language))

    def _instance_span(self, data: FrameData) -> tuple[int, int] | None:
        """The rows of ``data.instances`` to upload when the instance buffer already holds the frame they are
        counted from (``data.instances_since``); None: upload them all. Remembers the version uploaded."""
        uploaded, self._instances_uploaded = self._instances_uploaded, data.instances_version
        if (data.instance_span is None or uploaded is None or uploaded != data.instances_since
                or self._instance_buffer is None or self._instance_buffer.size < data.instances.nbytes):
            return None
        return data.instance_span

    def _instance_capacity(self, nbytes: int) -> int | None:
        """The size of a new instance buffer when the current one cannot hold ``nbytes`` (None: it can)."""
        if self._instance_buffer is not None and self._instance_buffer.size >= nbytes:
            return None
        self.stats["buffers_created"] += 1
        return instance_capacity(nbytes)

    def _lights_changed(self, lights: bytes) -> bool:
        """Whether the lights buffer must be written with ``lights`` this frame: not when it holds those bytes
        already (lights that did not move or change, seen from a camera that did not move, cost no upload).
        Counts ``stats["lights_uploaded"]`` (1 or 0 for the frame)."""
        changed = lights != self._lights_in_buffer
        if changed:
            self._lights_in_buffer = lights
        self.stats["lights_uploaded"] = int(changed)
        return changed

    def _upload_instances(self, data: FrameData) -> None:
        """Write the frame's instance rows: only the span that changed when the buffer holds the previous frame's
        rows, else all of them (into a new buffer when they do not fit)."""
        instances = data.instances
        span = self._instance_span(data)
        if span is not None:
            lo, hi = span
            self.stats["instances_uploaded"] = hi - lo
            if hi > lo:
                self._write_instances(instances[lo:hi], lo * INSTANCE_STRIDE)
            return
        self.stats["instances_uploaded"] = len(instances)
        self._renew_instance_buffer(self._instance_capacity(instances.nbytes))
        self._write_instances(instances, 0)

    def _renew_instance_buffer(self, capacity: int | None) -> None:
        """Before a whole upload: a new instance buffer of ``capacity`` bytes (None: the current one is kept)."""
        raise NotImplementedError

    def _write_instances(self, rows: np.ndarray, offset: int) -> None:
        """Write ``rows`` into the instance buffer at byte ``offset``."""
        raise NotImplementedError

    def gpu_memory(self) -> dict[str, int]:
        """Bytes of GPU memory this renderer holds, by kind, and their ``"total"``: what was asked of the API for its
        buffers and textures (:mod:`.gpu_memory`), the same way in both backends.

        Kinds: ``textures``, ``meshes`` (vertex and index buffers), ``storage buffers``, ``material blocks``,
        ``frame targets`` (colour and depth), ``shadow map``, ``instances`` (the instance buffer's capacity),
        ``frame uniforms`` (frame and lights blocks, and WebGPU's stand-ins for an absent shadow map or instance
        buffer); then each of :attr:`attachments` that reports its own (``gpu_bytes()``), by its name.
        """
        held = {"textures": self.textures.gpu_bytes(), "meshes": self.meshes.gpu_bytes(),
                "storage buffers": self.buffers.gpu_bytes(), "material blocks": self.materials.gpu_bytes(),
                **self._frame_gpu_memory()}
        for name, attached in self.attachments.items():
            if hasattr(attached, "gpu_bytes"):
                held[name] = int(attached.gpu_bytes())
        held["total"] = sum(held.values())
        return held

    def _frame_gpu_memory(self) -> dict[str, int]:
        """The bytes of the renderer's own objects: ``frame targets``, ``shadow map``, ``instances``,
        ``frame uniforms``."""
        raise NotImplementedError

    def save_png(self, path: str | Path) -> Path:
        """Write the last frame to a PNG file."""
        from PIL import Image

        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        Image.fromarray(self.read_pixels(), "RGBA").save(path)
        return path
