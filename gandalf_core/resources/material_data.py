"""Backend-neutral material description: which shader, which textures, which uniform values and render state.

A material splits into two parts that the render systems treat differently:

* the **pipeline key** (:meth:`MaterialData.pipeline_key`): shader, culling, depth test/write and blending.
  Those are baked into a GPU pipeline object, so materials that differ here need different pipelines;
* the **uniform values** (:meth:`MaterialData.uniform_values`): colour and shader parameters. They are plain
  buffer data; changing them (e.g. animating a colour) never builds a new pipeline.

Textures are referred to by name (the key in a backend's texture library), in binding order; so are storage
buffers (``buffers``: names in a renderer's buffer library, which the app's own compute code fills).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

import numpy as np

from gandalf_core.resources.errors import ResourceError

CULL_MODES = ("back", "front", "none")
BLEND_MODES = ("opaque", "alpha", "additive")
# The largest uniform a parameter can fill is a mat4.
_MAX_PARAM_FLOATS = 16


def _choice(label: str, field_name: str, value: Any, allowed: tuple[str, ...]) -> None:
    if value not in allowed:
        raise ResourceError(label, field_name, f"{value!r} is not one of {', '.join(repr(a) for a in allowed)}")


def _floats(label: str, field_name: str, value: Any) -> np.ndarray:
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise ResourceError(label, field_name, f"{value!r} is not a number or a sequence of numbers") from exc
    if not np.all(np.isfinite(a)):
        raise ResourceError(label, field_name, f"values must be finite, got {value!r}")
    return a


@dataclass(frozen=True, eq=False)
class MaterialData:
    """How a mesh is drawn: shader name, texture names, colour, shader parameters and fixed-function state.

    ``color`` takes 3 or 4 floats (3 get alpha 1) as sRGB values, like every colour a scene sets (a colour picker
    shows them); the renderers decode them to linear light for the shaders. Values above 1 are allowed.
    ``params`` map uniform names to a float or a flat sequence of up to 16 floats (vec2..vec4, mat3, mat4,
    row-major when flattened from a matrix); the name ``"color"`` is reserved for ``color``.
    ``buffers`` name storage buffers of the renderer's buffer library (``renderer.buffers.build(name, data)``), bound
    in order: OpenGL binds the i-th to shader-storage binding point i, WebGPU to the i-th storage binding of
    ``@group(1)`` (for vertex pulling: a vertex shader reading mesh data, or a compute pass's output, by index).
    All fields are validated on construction and stored immutably; use :meth:`with_color` or
    :func:`dataclasses.replace` to derive variants.
    """

    shader: str
    textures: Sequence[str] = ()
    color: Sequence[float] = (1.0, 1.0, 1.0, 1.0)
    params: Mapping[str, float | Sequence[float]] = field(default_factory=dict)
    cull: str = "back"
    depth_test: bool = True
    depth_write: bool = True
    blend: str = "opaque"
    name: str = ""
    buffers: Sequence[str] = ()

    def __post_init__(self) -> None:
        if not isinstance(self.shader, str) or not self.shader:
            raise ResourceError(f"material '{self.name}'", "shader", f"expected a shader name, got {self.shader!r}")
        label = self._label
        for attr, kind in (("textures", "texture"), ("buffers", "buffer")):
            names = getattr(self, attr)
            if isinstance(names, str) or not isinstance(names, Sequence):
                raise ResourceError(label, attr, f"expected a sequence of {kind} names, got {names!r}")
            for i, name in enumerate(names):
                if not isinstance(name, str) or not name:
                    raise ResourceError(label, f"{attr}[{i}]", f"expected a {kind} name, got {name!r}")
            object.__setattr__(self, attr, tuple(names))

        c = _floats(label, "color", self.color).reshape(-1)
        if c.size not in (3, 4):
            raise ResourceError(label, "color", f"expected 3 or 4 components, got {c.size}")
        object.__setattr__(self, "color", tuple(float(x) for x in (np.append(c, 1.0) if c.size == 3 else c)))

        if not isinstance(self.params, Mapping):
            raise ResourceError(label, "params", f"expected a mapping of uniform names, got {self.params!r}")
        params: dict[str, float | tuple[float, ...]] = {}
        for key, value in self.params.items():
            if not isinstance(key, str) or not key.isidentifier():
                raise ResourceError(label, "params", f"key {key!r} is not a valid uniform name")
            if key == "color":
                raise ResourceError(label, "params['color']", "'color' is reserved; set the color field instead")
            a = _floats(label, f"params[{key!r}]", value)
            if a.ndim == 0:
                params[key] = float(a)
            elif a.ndim > 2 or not 1 <= a.size <= _MAX_PARAM_FLOATS:
                detail = f"expected a float or up to {_MAX_PARAM_FLOATS} floats, got shape {a.shape}"
                raise ResourceError(label, f"params[{key!r}]", detail)
            else:
                params[key] = tuple(float(x) for x in a.reshape(-1))
        object.__setattr__(self, "params", MappingProxyType(params))

        _choice(label, "cull", self.cull, CULL_MODES)
        _choice(label, "blend", self.blend, BLEND_MODES)
        for flag in ("depth_test", "depth_write"):
            if not isinstance(getattr(self, flag), (bool, np.bool_)):
                raise ResourceError(label, flag, f"expected True or False, got {getattr(self, flag)!r}")
            object.__setattr__(self, flag, bool(getattr(self, flag)))

    @property
    def _label(self) -> str:
        return f"material '{self.name or self.shader}'"

    def pipeline_key(self) -> tuple[str, str, bool, bool, str]:
        """The hashable state that selects a GPU pipeline: ``(shader, cull, depth_test, depth_write, blend)``.

        Colour, params and textures are not part of it: materials differing only there share a pipeline.
        """
        return (self.shader, self.cull, self.depth_test, self.depth_write, self.blend)

    def uniform_values(self) -> dict[str, float | tuple[float, ...]]:
        """The per-material uniform data: ``{"color": (r, g, b, a), **params}``."""
        return {"color": self.color, **self.params}

    def with_color(self, color: Sequence[float]) -> MaterialData:
        """A copy with another colour (same pipeline key)."""
        return replace(self, color=color)
