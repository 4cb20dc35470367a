"""A shader's Material block, declared in Python when the shader is built, and the varyings between its stages.

A material's values live in one ``Material`` block, the same bytes in both APIs (the layout rule of
:mod:`gandalf_core.resources.layout`; binding points in :mod:`gandalf_core.resources.blocks`). The shader is built
with its declaration, ``shaders.build(..., material=[("color", "vec4"), ("shininess", "float")])`` (by default the
colour alone), and its stages ``#include "material.glsl"`` or ``"material.wgsl"``, which the engine writes from it:

* GLSL: ``layout(std140) uniform Material { vec4 color; float shininess; } material;`` read as ``material.color``;
* WGSL: ``struct Material { color: vec4<f32>, shininess: f32, };`` ``@group(1) @binding(0) var<uniform> material:
  Material;``.

Each field takes the material's value of the same name (``color`` is the material's colour, linear RGBA; the
others come from ``params``). A field with a default (padding) need not be set; everything else must be, or the
material is an error when it is built.
"""

from __future__ import annotations

import re
from typing import Any

from ..resources.blocks import MATERIAL_INCLUDES, MaterialDeclaration, material_layout, material_snippets
from ..resources.layout import BlockLayout, LayoutError
from ..resources.shader_source import ShaderSource
from .errors import ShaderCompileError

MATERIAL_BLOCK = "Material"


def _strip_comments(text: str) -> str:
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def declared_block(shader: str, material: MaterialDeclaration | None) -> tuple[BlockLayout, dict[str, str]]:
    """The shader's Material layout from its declaration, and the generated includes that declare it."""
    try:
        layout = material_layout(material)
    except LayoutError as exc:
        raise ShaderCompileError(f"shader '{shader}': material=: {exc}") from None
    return layout, material_snippets(layout)


def used_block(shader: str, layout: BlockLayout, sources: list[ShaderSource], declared: bool) -> BlockLayout | None:
    """``layout`` when a stage includes the generated Material block, else None (a shader without material values);
    a block declared with ``material=`` that no stage includes is an error."""
    if any(name in src.files for src in sources for name in MATERIAL_INCLUDES):
        return layout
    if declared:
        files = ", ".join(src.filename for src in sources)
        raise ShaderCompileError(f"shader '{shader}' ({files}): material= declares a Material block, but no stage "
                                 'includes it (#include "material.glsl" / "material.wgsl")')
    return None


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


# --- the block as text, read back (a shader editor edits the declaration as the shader sees it) ------------------
_GLSL_BLOCK = re.compile(r"\buniform\s+Material\s*\{(?P<body>[^}]*)\}", re.S)
_WGSL_BLOCK = re.compile(r"\bstruct\s+Material\s*\{(?P<body>[^}]*)\}", re.S)
_GLSL_MEMBER = re.compile(r"^\s*([A-Za-z_]\w*)\s+([A-Za-z_]\w*)\s*(?:\[\s*(\d+)\s*\])?\s*$")
_WGSL_MEMBER = re.compile(r"^\s*([A-Za-z_]\w*)\s*:\s*(?:array<\s*([\w<>]+)\s*,\s*(\d+)u?\s*>|([\w<>]+))\s*$")


def parse_material_block(text: str, lang: str, previous: BlockLayout | None = None,
                         filename: str | None = None) -> BlockLayout:
    """The Material block declared by ``text`` (what ``#include "material.glsl"`` / ``"material.wgsl"`` holds):
    GLSL's ``uniform Material { vec4 color; float glow; } material;`` or WGSL's ``struct Material { color:
    vec4<f32>, glow: f32, };``. A field of ``previous`` with the same name and type keeps its default (text cannot
    state one). An error names the file and line (``filename``, by default the include's name)."""
    filename = filename or f"material.{lang}"
    blank = re.sub(r"/\*.*?\*/|//[^\n]*", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)
    match = (_GLSL_BLOCK if lang == "glsl" else _WGSL_BLOCK).search(blank)
    if match is None:
        what = "uniform Material { ... }" if lang == "glsl" else "struct Material { ... }"
        raise ShaderCompileError(f"{filename}:1: no '{what}' declaration found")
    fields: list[tuple[Any, ...]] = []
    for pos, part in _members(match.group("body"), match.start("body"), ";" if lang == "glsl" else ","):
        line = blank.count("\n", 0, pos + len(part) - len(part.lstrip())) + 1
        if not part.strip():
            continue
        if lang == "glsl":
            m = _GLSL_MEMBER.match(part)
            name, kind, count = (m.group(2), m.group(1), m.group(3)) if m else ("", "", None)
        else:
            m = _WGSL_MEMBER.match(part)
            name, kind, count = (m.group(1), m.group(2) or m.group(4), m.group(3)) if m else ("", "", None)
        if m is None:
            raise ShaderCompileError(f"{filename}:{line}: cannot read Material member '{' '.join(part.split())}'")
        declared: Any = kind if count is None else (kind, int(count))
        old = next((f for f in (previous.fields if previous is not None else ()) if f.name == name), None)
        keeps = old is not None and old.has_default and _same_type(previous, name, declared)
        fields.append((name, declared, old.default) if keeps else (name, declared))
        try:
            BlockLayout(MATERIAL_BLOCK, [fields[-1]])
        except (LayoutError, ValueError) as exc:
            raise ShaderCompileError(f"{filename}:{line}: {exc}") from None
    try:
        return BlockLayout(MATERIAL_BLOCK, fields)
    except (LayoutError, ValueError) as exc:
        line = blank.count("\n", 0, match.start()) + 1
        raise ShaderCompileError(f"{filename}:{line}: {exc}") from None


def _members(body: str, start: int, separator: str) -> list[tuple[int, str]]:
    """``body`` cut at each ``separator`` outside ``<...>`` (WGSL's ``array<vec4<f32>, 3>``): (offset, text)."""
    parts, depth, begin = [], 0, 0
    for i, ch in enumerate(body):
        depth += (ch == "<") - (ch == ">")
        if ch == separator and depth == 0:
            parts.append((start + begin, body[begin:i]))
            begin = i + 1
    parts.append((start + begin, body[begin:]))
    return parts


def _same_type(layout: BlockLayout | None, name: str, kind: Any) -> bool:
    """Whether field ``name`` of ``layout`` has type ``kind``."""
    if layout is None:
        return False
    try:
        return _type_key(BlockLayout(MATERIAL_BLOCK, [(name, kind)]).field(name).type) == \
            _type_key(layout.field(name).type)
    except (LayoutError, ValueError):
        return False


def _type_key(t: Any) -> Any:
    """A type without its spelling (``vec3`` and ``vec3<f32>`` are one type)."""
    if hasattr(t, "elem"):
        return (_type_key(t.elem), t.count)
    return (getattr(t, "kind", None), getattr(t, "rows", None), getattr(t, "columns", None), getattr(t, "name", None)
            if not hasattr(t, "kind") else None)
