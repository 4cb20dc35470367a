"""What a part needs from the GPU beyond the course's floor, stated once and checked when its app starts.

The floor every part fits: OpenGL 3.3 core, and a WebGPU device with the limits every implementation guarantees
(:data:`WEBGPU_DEFAULT_LIMITS`, the WebGPU specification's defaults) and no optional feature a part relies on (the
device asks for ``indirect-first-instance`` where offered, which only an indirect draw of a batch that does not start
at the frame's first row uses, and without which that draw is refused with an error that says so). A part that needs
more says so in its :class:`Needs` (tessellation: OpenGL 4.0; compute shaders, storage buffers and image
load/store: OpenGL 4.3; a WebGPU feature such as ``float32-filterable``; a limit above its default). The renderer
compares the needs with what the context or adapter offers (:class:`Offer`) before building anything, and a gap
becomes a :class:`CapabilityError` that says in one sentence what is missing and what to run instead.

A WebGPU device is requested with the default limits plus what the part declares, never with all the adapter
has: a part that silently used more would run here and fail on a student's laptop or in a browser.
No GPU library is imported here.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

#: The OpenGL version every part runs on (core profile), as moderngl's ``version_code``.
GL_FLOOR = 330

#: The WebGPU specification's default limits: what every implementation guarantees, and what a device is
#: requested with unless a part declares more. ``max-*`` limits are upper bounds, ``min-*`` alignments lower ones.
WEBGPU_DEFAULT_LIMITS: dict[str, int] = {
    "max-texture-dimension-1d": 8192,
    "max-texture-dimension-2d": 8192,
    "max-texture-dimension-3d": 2048,
    "max-texture-array-layers": 256,
    "max-bind-groups": 4,
    "max-bindings-per-bind-group": 1000,
    "max-dynamic-uniform-buffers-per-pipeline-layout": 8,
    "max-dynamic-storage-buffers-per-pipeline-layout": 4,
    "max-sampled-textures-per-shader-stage": 16,
    "max-samplers-per-shader-stage": 16,
    "max-storage-buffers-per-shader-stage": 8,
    "max-storage-textures-per-shader-stage": 4,
    "max-uniform-buffers-per-shader-stage": 12,
    "max-uniform-buffer-binding-size": 65536,
    "max-storage-buffer-binding-size": 134217728,
    "min-uniform-buffer-offset-alignment": 256,
    "min-storage-buffer-offset-alignment": 256,
    "max-vertex-buffers": 8,
    "max-buffer-size": 268435456,
    "max-vertex-attributes": 16,
    "max-vertex-buffer-array-stride": 2048,
    "max-inter-stage-shader-variables": 16,
    "max-color-attachments": 8,
    "max-color-attachment-bytes-per-sample": 32,
    "max-compute-workgroup-storage-size": 16384,
    "max-compute-invocations-per-workgroup": 256,
    "max-compute-workgroup-size-x": 256,
    "max-compute-workgroup-size-y": 256,
    "max-compute-workgroup-size-z": 64,
    "max-compute-workgroups-per-dimension": 65535,
}


def _gl_name(code: int) -> str:
    return f"OpenGL {code // 100}.{code % 100 // 10}"


@dataclass(frozen=True)
class Offer:
    """What one implementation offers: ``api``, a ``name`` (renderer or adapter), the OpenGL ``version`` code
    (OpenGL), the ``features`` and ``limits`` (WebGPU)."""

    api: str
    name: str = ""
    version: int = 0
    features: frozenset[str] = frozenset()
    limits: Mapping[str, int] = field(default_factory=dict)

    def __str__(self) -> str:
        if self.api == "opengl":
            return f"{_gl_name(self.version)} on {self.name}" if self.name else _gl_name(self.version)
        return f"WebGPU on {self.name}" if self.name else "WebGPU"


@dataclass(frozen=True)
class Needs:
    """What a part needs beyond the floor: ``opengl`` (a version code, 330 by default) and what for
    (``opengl_for``: "compute shaders"), WebGPU ``features`` and ``limits`` above the defaults and what for
    (``webgpu_for``)."""

    opengl: int = GL_FLOOR
    opengl_for: str = ""
    features: tuple[str, ...] = ()
    limits: Mapping[str, int] = field(default_factory=dict)
    webgpu_for: str = ""

    def __post_init__(self) -> None:
        if self.opengl < GL_FLOOR:
            raise ValueError(f"Needs: opengl={self.opengl} is below the course's floor {GL_FLOOR} (OpenGL 3.3)")
        unknown = sorted(set(self.limits) - set(WEBGPU_DEFAULT_LIMITS))
        if unknown:
            raise ValueError(f"Needs: unknown WebGPU limit(s) {unknown}; known: {sorted(WEBGPU_DEFAULT_LIMITS)}")

    def required(self, api: str) -> str:
        """What this part needs in ``api``, beyond the floor, in words ("" when nothing)."""
        if api == "opengl":
            if self.opengl == GL_FLOOR:
                return ""
            return f"{_gl_name(self.opengl)}{' ' + self.opengl_for if self.opengl_for else ''}"
        wanted = [f"the WebGPU feature '{f}'" for f in self.features]
        wanted += [f"WebGPU's {name} of {value}" for name, value in self.limits.items()]
        what = ", ".join(wanted)
        return f"{what} ({self.webgpu_for})" if what and self.webgpu_for else what

    def missing(self, offer: Offer) -> str:
        """What ``offer`` lacks of these needs, in words ("" when it has everything)."""
        if offer.api == "opengl":
            return self.required("opengl") if offer.version < self.opengl else ""
        gaps = [f"the WebGPU feature '{f}'" for f in self.features if f not in offer.features]
        for name, value in self.limits.items():
            have = offer.limits.get(name)
            short = have is None or (have > value if name.startswith("min-") else have < value)
            if short:
                gaps.append(f"WebGPU's {name} of {value} (this adapter: {have})")
        return ", ".join(gaps)

    def device_limits(self, adapter_limits: Mapping[str, int]) -> dict[str, int]:
        """The limits to request a WebGPU device with: the defaults, raised where this part needs more, and
        never beyond what the adapter offers (a weaker adapter keeps its own value)."""
        out = {}
        for name, default in {**WEBGPU_DEFAULT_LIMITS, **self.limits}.items():
            have = adapter_limits.get(name)
            if have is None or have == 0:
                continue
            out[name] = max(default, have) if name.startswith("min-") else min(default, have)
        return out


#: No needs beyond the floor.
FLOOR = Needs()


class CapabilityError(RuntimeError):
    """A part needs what this implementation lacks: ``what`` (the part) needs ``missing``; ``offer`` is what the
    machine has; ``instead``, a command that runs here (the other API's variant), when known."""

    def __init__(self, missing: str, offer: Offer, what: str = "this program", instead: str = "",
                 needs: Needs = FLOOR) -> None:
        self.missing, self.offer, self.what, self.instead, self.needs = missing, offer, what, instead, needs
        go = f": run `{instead}` instead" if instead else ""
        super().__init__(f"{what} needs {missing} (this machine has {offer}){go}")

    def naming(self, what: str, instead: str = "") -> CapabilityError:
        """The same gap told about ``what`` (unless the error already names a piece of it) with the command to
        run ``instead``."""
        return CapabilityError(self.missing, self.offer, what if self.what == "this program" else self.what,
                               self.instead or instead, self.needs)


def check(needs: Needs, offer: Offer, what: str = "this program") -> None:
    """Raise :class:`CapabilityError` when ``offer`` lacks something ``needs`` states."""
    gap = needs.missing(offer)
    if gap:
        raise CapabilityError(gap, offer, what, needs=needs)


def opengl_offer(ctx: Any) -> Offer:
    """What a moderngl context offers."""
    return Offer("opengl", str(ctx.info.get("GL_RENDERER", "")), int(ctx.version_code))


def webgpu_offer(adapter: Any) -> Offer:
    """What a wgpu adapter offers."""
    info = adapter.info
    name = f"{info.get('device', '?')} via {info.get('backend_type', '?')}"
    return Offer("webgpu", name, 0, frozenset(adapter.features), dict(adapter.limits))


def require_opengl(ctx: Any, version: int, purpose: str, what: str = "this program") -> None:
    """Raise :class:`CapabilityError` unless the moderngl context ``ctx`` is OpenGL ``version`` or later
    (``purpose``: what the version brings, "compute shaders")."""
    check(Needs(opengl=version, opengl_for=purpose), opengl_offer(ctx), what)


def standalone_opengl(version: int, purpose: str, what: str = "this program") -> Any:
    """A headless (EGL) moderngl context of OpenGL ``version`` or later, or a :class:`CapabilityError` naming the
    version the driver does give."""
    import moderngl

    try:
        return moderngl.create_standalone_context(backend="egl", require=version)
    except Exception as exc:  # noqa: BLE001 - glcontext raises a plain Exception ("eglCreateContext failed")
        try:
            probe = moderngl.create_standalone_context(backend="egl", require=GL_FLOOR)
        except Exception:  # noqa: BLE001 - no OpenGL at all: the original error says why
            raise exc from None
        try:
            offer = opengl_offer(probe)
        finally:
            probe.release()
        needs = Needs(opengl=version, opengl_for=purpose)
        raise CapabilityError(needs.required("opengl"), offer, what, needs=needs) from None

