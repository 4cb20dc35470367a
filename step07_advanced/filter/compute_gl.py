"""The filters on OpenGL: GLSL 4.30 compute shaders with image load/store, on the renderer's moderngl context.

The source image is an ``rgba8`` texture read with ``texelFetch`` (a sampler, no filtering); a pass writes an
image unit (``imageStore``) of format ``rgba32f`` (the separable blur's intermediate, so the 8-bit result is rounded
once) or ``rgba8`` (the result). ``ctx.memory_barrier()`` makes one dispatch's writes visible to the next.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from types import ModuleType
from typing import Any, TypeVar

import moderngl
import numpy as np

from gandalf_core.render.capabilities import require_opengl, standalone_opengl

from .kernels import MAX_RADIUS, check_image, check_op, check_radius, check_shared_memory, check_weights, groups
from .shaders import FORMATS, PARAMS_BINDING, PARAMS_LAYOUT, PROGRAMS, explain_error, kernel_source, pass_params

#: Compute shaders and image load/store arrived in OpenGL 4.3.
REQUIRED_VERSION = 430
PURPOSE = "compute shaders and image load/store"
#: GL 4.3's guaranteed GL_MAX_COMPUTE_SHARED_MEMORY_SIZE (moderngl does not report the driver's value).
GL_MIN_SHARED_MEMORY = 32768

_F = TypeVar("_F", bound=Callable[..., Any])


def _current(method: _F) -> _F:
    """Make the context current before ``method``: another library in the process (wgpu probing EGL, a second
    app) may have made its own context current since, and GL calls go to the current one. It stays current
    (the renderer draws with it next), so this is ``__enter__`` without the ``__exit__`` that would release it."""

    @functools.wraps(method)
    def wrapper(self: GLImageFilter, *args: Any, **kwargs: Any) -> Any:
        self.ctx.__enter__()
        return method(self, *args, **kwargs)

    return wrapper  # type: ignore[return-value]


class GLImageFilter:
    """Runs :data:`~.kernels.OPERATIONS` on RGBA8 images: ``run(image, op, radius)`` returns the filtered image."""

    backend = "opengl"

    def __init__(self, ctx: moderngl.Context, impl: ModuleType) -> None:
        require_opengl(ctx, REQUIRED_VERSION, PURPOSE, "the image filter")
        self.ctx = ctx
        self.owns_context = False
        self.device_name = str(ctx.info.get("GL_RENDERER", "?"))
        self.max_size = int(ctx.info["GL_MAX_TEXTURE_SIZE"])
        self.max_size_name = "GL_MAX_TEXTURE_SIZE"
        check_shared_memory(int(ctx.info.get("GL_MAX_COMPUTE_SHARED_MEMORY_SIZE", GL_MIN_SHARED_MEMORY)),
                            "GL_MAX_COMPUTE_SHARED_MEMORY_SIZE")
        self._build(impl)
        self.size: tuple[int, int] | None = None
        self.textures: dict[str, moderngl.Texture] = {}

    @classmethod
    def standalone(cls, impl: ModuleType) -> GLImageFilter:
        """A filter on its own headless EGL context of OpenGL 4.3 or later (for the study and the tests).

        Some drivers (NVIDIA's) give exactly the version asked for, so a context made for GL 3.3 drawing has no
        compute shaders there; this one asks for 4.3.
        """
        ctx = standalone_opengl(REQUIRED_VERSION, PURPOSE, "the image filter")
        flt = cls(ctx, impl)
        flt.owns_context = True
        return flt

    def _build(self, impl: ModuleType) -> None:
        self.ctx.__enter__()  # current, and left current (see _current)
        self.impl = impl
        self.programs: dict[str, moderngl.ComputeShader] = {}
        self.weights = self.ctx.buffer(reserve=(2 * MAX_RADIUS + 1) * 4)
        self.params = self.ctx.buffer(reserve=PARAMS_LAYOUT.size)

    def _program(self, name: str) -> moderngl.ComputeShader:
        """The compiled program ``name`` of :data:`~.shaders.PROGRAMS`, built on first use."""
        if name not in self.programs:
            kernel, kind = PROGRAMS[name]
            self.programs[name] = self._compile(kernel, None if kind is None else FORMATS["opengl"][kind])
        return self.programs[name]

    def _compile(self, kernel: str, out_format: str | None = None) -> moderngl.ComputeShader:
        src = kernel_source("opengl", kernel, self.impl, out_format)
        try:
            return self.ctx.compute_shader(src.text)
        except moderngl.Error as exc:
            raise RuntimeError(explain_error(src, str(exc))) from None

    # --- steps (the study times dispatch + finish) ------------------------------------------------------
    @_current
    def upload(self, image: np.ndarray) -> None:
        """Check ``image`` (RGBA8, (H, W, 4) uint8, within GL_MAX_TEXTURE_SIZE) and make it the source."""
        image = check_image(image, self.max_size, self.max_size_name)
        h, w = image.shape[:2]
        if self.size != (w, h):
            for tex in self.textures.values():
                tex.release()
            self.textures = {
                "src": self.ctx.texture((w, h), 4, dtype="f1"),
                "mid": self.ctx.texture((w, h), 4, dtype="f4"),
                "dst": self.ctx.texture((w, h), 4, dtype="f1"),
            }
            for tex in self.textures.values():
                tex.filter = (moderngl.NEAREST, moderngl.NEAREST)
            self.size = (w, h)
        self.textures["src"].write(image.tobytes())  # row 0 (the top) first, as TextureData stores it

    @_current
    def dispatch(self, op: str, radius: int = 0, weights: np.ndarray | None = None) -> None:
        """Run ``op`` on the uploaded image into the result texture (no wait).

        The weight table comes from the student's ``gaussian_weight`` on the GPU, or from ``weights`` when given
        (the tests of ``blur_pass`` use the reference table, so they do not depend on the other exercise).
        """
        check_op(op)
        r = check_radius(radius)
        table = None if weights is None else check_weights(weights, r)
        if self.size is None:
            raise RuntimeError("upload an image before dispatching a filter")
        w, h = self.size
        tex = self.textures
        if op == "sobel":
            self._run("sobel", tex["src"], tex["dst"], (1, 0), r, groups(w, h, op))
            return
        if table is None:
            self._fill_weights(r)
        else:
            self.weights.write(table.tobytes())
        if op in ("horizontal", "vertical"):
            direction = (1, 0) if op == "horizontal" else (0, 1)
            self._run("pass_unorm8", tex["src"], tex["dst"], direction, r, groups(w, h, op))
            return
        if op == "naive":
            self._run("naive", tex["src"], tex["dst"], (1, 0), r, groups(w, h, op))
            return
        kind = "pass" if op == "separable" else "tiled"
        self._run(f"{kind}_float", tex["src"], tex["mid"], (1, 0), r, groups(w, h, op, (1, 0)))
        self._run(f"{kind}_unorm8", tex["mid"], tex["dst"], (0, 1), r, groups(w, h, op, (0, 1)))

    def _fill_weights(self, radius: int) -> None:
        program = self._program("weights")
        self.params.write(pass_params((1, 0), radius))
        self.params.bind_to_uniform_block(PARAMS_BINDING)
        self.weights.bind_to_storage_buffer(0)
        program.run(group_x=-(-(2 * radius + 1) // 64))
        self.ctx.memory_barrier()

    # --8<-- [start:dispatch]
    def _run(self, name: str, src: moderngl.Texture, dst: moderngl.Texture, direction: tuple[int, int],
             radius: int, group_count: tuple[int, int]) -> None:
        program = self._program(name)
        self.params.write(pass_params(direction, radius))
        self.params.bind_to_uniform_block(PARAMS_BINDING)
        src.use(location=0)
        dst.bind_to_image(0, read=False, write=True)
        self.weights.bind_to_storage_buffer(0)
        program.run(group_x=group_count[0], group_y=group_count[1])
        # The next pass samples what this one stored: make the image writes visible first.
        self.ctx.memory_barrier()
    # --8<-- [end:dispatch]

    @_current
    def finish(self) -> None:
        """Wait until the GPU has done everything dispatched so far."""
        self.ctx.finish()

    @_current
    def read(self) -> np.ndarray:
        """The result image, (H, W, 4) uint8, top row first."""
        w, h = self.size
        return np.frombuffer(self.textures["dst"].read(), dtype=np.uint8).reshape(h, w, 4).copy()

    # --- one call --------------------------------------------------------------------------------------------
    def run(self, image: np.ndarray, op: str, radius: int = 0, weights: np.ndarray | None = None) -> np.ndarray:
        """``op`` (one of :data:`~.kernels.OPERATIONS`) of ``image`` with ``radius``: the RGBA8 result."""
        check_op(op)
        check_radius(radius)
        self.upload(image)
        self.dispatch(op, radius, weights)
        return self.read()

    @_current
    def weight_table(self, radius: int) -> np.ndarray:
        """The weight table the student's ``gaussian_weight`` computes on the GPU, float32 (2·radius + 1,)."""
        r = check_radius(radius)
        self._fill_weights(r)
        return np.frombuffer(self.weights.read(size=(2 * r + 1) * 4), dtype=np.float32).copy()

    @_current
    def release(self) -> None:
        for obj in (*self.textures.values(), *self.programs.values(), self.weights, self.params):
            obj.release()
        self.textures = {}
        self.size = None
        if self.owns_context:
            self.ctx.release()
