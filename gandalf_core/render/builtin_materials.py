"""Ready materials: ``gandalf.unlit`` and ``gandalf.blinn_phong``, in both APIs, with no shader to write.

Use them by name, like any shader::

    MaterialData("gandalf.blinn_phong", ["bricks"], color=(1, 1, 1), params={"shininess": 16})
    MaterialData("gandalf.unlit", color=(1.0, 0.5, 0.0))

Each takes the material colour and, optionally, one 2D texture (the albedo, multiplied by the colour).
``gandalf.unlit`` shows that colour as it is (no light). ``gandalf.blinn_phong`` lights it with the scene's
lights (ambient, directional and point lights of the engine's lights block) with the Blinn-Phong model:
``ambient · albedo + Σ (albedo + specular · max(n·h, 0)^shininess) · radiance · max(n·l, 0)``. Its
params are ``specular`` (≥ 0, default 0.25) and ``shininess`` (≥ 0, default 32). It casts shadows but does
not receive them. Meshes need normals for ``gandalf.blinn_phong`` and texture coordinates with a texture.

A material library calls :func:`prepare` on every material it builds: for a built-in name it checks the
material (unknown params, bad values, more than one texture, storage buffers are errors that name the
material), builds the shader variant it needs on first use (``gandalf.blinn_phong`` or
``gandalf.blinn_phong+texture``) from ``render/shaders/builtin_*``, and fills in the default params.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from ..resources import MaterialData, ResourceError
from .shader_files import engine_shader_files

#: The built-in materials: their params with (default, lowest allowed value).
BUILTIN_MATERIALS: dict[str, dict[str, tuple[float, float]]] = {
    "gandalf.unlit": {},
    "gandalf.blinn_phong": {"specular": (0.25, 0.0), "shininess": (32.0, 0.0)},
}
TEXTURED_SUFFIX = "+texture"
#: The Material block of the Blinn-Phong shaders (``gandalf.unlit``'s is the colour alone).
BLINN_PHONG_MATERIAL = [("color", "vec4"), ("specular", "float"), ("shininess", "float")]


def is_builtin(shader: str) -> bool:
    """Whether ``shader`` names a built-in material."""
    return shader in BUILTIN_MATERIALS


def check(name: str, data: MaterialData) -> None:
    """Raise a ResourceError naming the material if ``data`` does not fit its built-in shader."""
    label = f"material '{name}'"
    allowed = BUILTIN_MATERIALS[data.shader]
    for key, value in data.params.items():
        if key not in allowed:
            known = ", ".join(repr(k) for k in allowed) or "none (only the colour and a texture)"
            raise ResourceError(label, f"params[{key!r}]", f"{data.shader} has no param {key!r}; its params: {known}")
        if not isinstance(value, float):
            raise ResourceError(label, f"params[{key!r}]", f"{data.shader} expects one number, got {value!r}")
        low = allowed[key][1]
        if value < low:
            raise ResourceError(label, f"params[{key!r}]", f"must be ≥ {low:g}, got {value:g}")
    if len(data.textures) > 1:
        raise ResourceError(label, "textures", f"{data.shader} takes at most one texture (the albedo), "
                                               f"got {len(data.textures)}: {list(data.textures)}")
    if data.buffers:
        raise ResourceError(label, "buffers", f"{data.shader} reads no storage buffers, got {list(data.buffers)}")


def _build(shaders: Any, variant: str, stem: str, lang: str) -> None:
    material = BLINN_PHONG_MATERIAL if "blinn_phong" in stem else None
    shaders.build(variant, *engine_shader_files(stem, lang), material=material)


def prepare(shaders: Any, name: str, data: MaterialData, lang: str) -> MaterialData:
    """``data`` itself, or for a built-in material: checked, its shader variant built in ``shaders`` (a
    backend's shader library, ``lang`` its language) and named, and its default params filled in."""
    if not is_builtin(data.shader):
        return data
    check(name, data)
    textured = len(data.textures) == 1
    variant = data.shader + (TEXTURED_SUFFIX if textured else "")
    if variant not in shaders:
        stem = "builtin_" + data.shader.split(".", 1)[1] + ("_textured" if textured else "")
        _build(shaders, variant, stem, lang)
    params = {key: default for key, (default, _low) in BUILTIN_MATERIALS[data.shader].items()}
    return replace(data, shader=variant, params={**params, **data.params})
