"""A material's uniform block, read from its shader in either language, and the varyings between its stages.

A material's values live in one ``Material`` block, the same bytes in both APIs (the layout rule of
:mod:`gandalf_core.resources.layout`; binding points in :mod:`gandalf_core.resources.blocks`):

* GLSL: ``layout(std140) uniform Material { vec4 color; float shininess; } material;`` read as ``material.color``;
* WGSL: ``struct Material { color: vec4<f32>, shininess: f32 };`` ``@group(1) @binding(0) var<uniform> material:
  Material;``.

Each field takes the material's value of the same name (``color`` is the material's colour, linear RGBA; the
others come from ``params``). A field whose name starts with ``_`` is padding: it has a stated default (zero) and
the material need not set it. Everything else must be set, or the material is an error when it is built.
"""

from __future__ import annotations

import re
from typing import Any

from ..resources.layout import BlockLayout, LayoutError

MATERIAL_BLOCK = "Material"


def _strip_comments(text: str) -> str:
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


_GLSL_BLOCK = re.compile(r"\buniform\s+Material\s*\{(?P<body>[^}]*)\}\s*(?P<instance>\w+)?\s*;")
_GLSL_MEMBER = re.compile(r"^\s*(?:(?:highp|mediump|lowp)\s+)?(?P<type>\w+)\s+(?P<names>[^;]+)$")
_DECLARATOR = re.compile(r"^\s*(?P<name>[A-Za-z_]\w*)\s*(?:\[\s*(?P<count>\d+)\s*\])?\s*$")


def glsl_material_fields(text: str, filename: str) -> list[tuple[Any, ...]] | None:
    """The fields of the stage's ``uniform Material { ... }`` block (None when it has none)."""
    match = _GLSL_BLOCK.search(_strip_comments(text))
    if match is None:
        return None
    fields: list[tuple[Any, ...]] = []
    for statement in match.group("body").split(";"):
        if not statement.strip():
            continue
        member = _GLSL_MEMBER.match(statement.strip())
        if member is None:
            raise LayoutError(f"{filename}: cannot read the Material block's member '{statement.strip()}'")
        for declarator in member.group("names").split(","):
            d = _DECLARATOR.match(declarator)
            if d is None:
                raise LayoutError(f"{filename}: cannot read the Material block's member '{statement.strip()}'")
            kind: Any = member.group("type") if d.group("count") is None else (member.group("type"),
                                                                                int(d.group("count")))
            fields.append(_with_default(d.group("name"), kind))
    return fields


def glsl_material_layout(stages: dict[str, Any], shader: str) -> BlockLayout | None:
    """The std140 layout of the Material block the program's stages declare (the same in each, as GL requires)."""
    found: list[tuple[str, list[tuple[Any, ...]]]] = []
    for src in stages.values():
        fields = glsl_material_fields(src.text, src.filename)
        if fields is not None:
            found.append((src.filename, fields))
    if not found:
        return None
    first_file, first = found[0]
    for filename, fields in found[1:]:
        if [f[:2] for f in fields] != [f[:2] for f in first]:
            raise LayoutError(f"shader '{shader}': {filename} declares the Material block differently from "
                              f"{first_file}; declare it once in an #include file, or the same in every stage")
    try:
        return BlockLayout(MATERIAL_BLOCK, first, rules="std140")
    except LayoutError as exc:
        raise LayoutError(f"shader '{shader}' ({first_file}): {exc}") from None


def _wgsl_type(text: str) -> Any:
    t = text.replace(" ", "")
    if m := re.fullmatch(r"array<(.+),(\d+)u?>", t):
        return (_wgsl_type(m.group(1)), int(m.group(2)))
    return t


def wgsl_material_layout(struct: Any, shader: str, filename: str) -> BlockLayout:
    """The WGSL uniform layout of a reflected ``Material`` struct, checked against the reflector's offsets."""
    fields = [_with_default(f.name, _wgsl_type(f.type)) for f in struct.fields]
    try:
        layout = BlockLayout(MATERIAL_BLOCK, fields, rules="wgsl")
    except LayoutError as exc:
        raise LayoutError(f"shader '{shader}' ({filename}): {exc}") from None
    for f in struct.fields:
        if layout.offset(f.name) != f.offset:
            raise LayoutError(f"shader '{shader}' ({filename}): struct Material field '{f.name}' is at offset "
                              f"{f.offset} (an @align or @size attribute?); materials use the plain layout, which "
                              f"puts it at {layout.offset(f.name)}")
    return layout


def _with_default(name: str, kind: Any) -> tuple[Any, ...]:
    return (name, kind, 0) if name.startswith("_") else (name, kind)


def block_values(layout: BlockLayout, values: dict[str, Any]) -> dict[str, Any]:
    """The material's values for the block's fields: the colour only when the block has a ``color`` field (a vec3
    one takes its rgb)."""
    out = {k: v for k, v in values.items() if k != "color"}
    if "color" in values and "color" in layout.names():
        color = values["color"]
        out["color"] = color[:3] if layout.field("color").size == 12 else color
    return out


# --- varyings --------------------------------------------------------------------------------------
_IO = re.compile(r"(?:layout\s*\([^)]*\)\s*)?(?:(?:flat|smooth|noperspective|centroid)\s+)*\b(in|out)\s+"
                 r"(?:(?:highp|mediump|lowp)\s+)?(\w+)\s+(\w+)\s*(\[[^\]]*\])?\s*;")


def glsl_stage_io(text: str) -> tuple[dict[str, str], dict[str, str]]:
    """(inputs, outputs) of a GLSL stage: loose ``in``/``out`` variables (not interface blocks) -> type."""
    ins: dict[str, str] = {}
    outs: dict[str, str] = {}
    for m in _IO.finditer(_strip_comments(text)):
        (ins if m.group(1) == "in" else outs)[m.group(3)] = m.group(2)
    return ins, outs


def _written(text: str, name: str) -> bool:
    """Whether the stage's code assigns ``name`` (``name = ...``, ``name.x += ...``, ``name[i] = ...``)."""
    pattern = rf"\b{re.escape(name)}\b\s*(?:\[[^\]]*\]\s*)?(?:\.\w+\s*)?(?:[-+*/]?=(?!=))"
    return re.search(pattern, _strip_comments(text)) is not None


def check_glsl_varyings(shader: str, stages: dict[str, Any]) -> str | None:
    """A message when the fragment stage reads a varying the stage before it never writes, else None.

    Only a plain vertex → fragment program is checked here (a geometry or tessellation stage passes its own
    blocks); the driver's link still checks the others.
    """
    if set(stages) != {"vertex_shader", "fragment_shader"}:
        return None
    vertex, fragment = stages["vertex_shader"], stages["fragment_shader"]
    ins, _ = glsl_stage_io(fragment.text)
    _, outs = glsl_stage_io(vertex.text)
    for name, kind in ins.items():
        if not re.search(rf"\b{re.escape(name)}\b", _main_and_functions(fragment.text, name)):
            continue  # declared but never read
        if name not in outs:
            have = ", ".join(sorted(outs)) or "none"
            return (f"shader '{shader}' ({fragment.filename}): the fragment stage reads varying '{name}' ({kind}), "
                    f"which the vertex stage ({vertex.filename}) never declares as 'out' (its outputs: {have})")
        if outs[name] != kind:
            return (f"shader '{shader}' ({fragment.filename}): varying '{name}' is {kind} here but {outs[name]} in "
                    f"the vertex stage ({vertex.filename})")
        if not _written(vertex.text, name):
            return (f"shader '{shader}' ({fragment.filename}): the fragment stage reads varying '{name}', which the "
                    f"vertex stage ({vertex.filename}) declares but never writes (it would be undefined)")
    return None


def _main_and_functions(text: str, name: str) -> str:
    """The stage's code without the declaration of ``name`` (to see whether anything else names it)."""
    return _IO.sub(lambda m: "" if m.group(3) == name else m.group(0), _strip_comments(text))


def check_wgsl_varyings(shader: str, filename: str, reflection: Any, vertex_entry: str,
                        fragment_entry: str) -> str | None:
    """A message when the fragment entry point takes a ``@location`` the vertex entry point does not return."""
    vs, fs = reflection.entry_points[vertex_entry], reflection.entry_points[fragment_entry]
    outs = {o.location: o for o in vs.location_outputs}
    for i in fs.location_inputs:
        o = outs.get(i.location)
        if o is None:
            have = ", ".join(f"@location({o.location}) {o.name}" for o in vs.location_outputs) or "none"
            return (f"shader '{shader}' ({filename}): fragment entry point '{fragment_entry}' reads @location"
                    f"({i.location}) '{i.name}' ({i.type}), which vertex entry point '{vertex_entry}' never returns "
                    f"(it returns: {have})")
        if o.type != i.type:
            return (f"shader '{shader}' ({filename}): @location({i.location}) is {i.type} '{i.name}' in "
                    f"'{fragment_entry}' but {o.type} '{o.name}' in '{vertex_entry}'")
    return None
