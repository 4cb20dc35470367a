"""Storage buffers, checked the same way for both backends' buffer libraries: what one is built from
(:func:`buffer_bytes`) and for (:func:`buffer_uses`), what building a name again does and what a use of it must
match (:class:`StorageBufferLib`), and the bytes a shader's storage block or variable needs
(:func:`glsl_storage_layouts`, :func:`wgsl_storage_layouts`), against which a material's buffers are checked when
it is built (:func:`check_material_buffer`)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..resources import ResourceError
from ..resources.layout import parse_type


def buffer_bytes(name: str, data: Any) -> tuple[bytes | None, int]:
    """``(content, size)`` for ``renderer.buffers.build(name, data)``: the bytes of a numpy array, or ``None``
    and a size for an int (a zero-filled buffer). Sizes must be positive multiples of 4 bytes (both APIs'
    storage bindings address 4-byte words)."""
    label = f"buffer '{name}'"
    if isinstance(data, (int, np.integer)) and not isinstance(data, bool):
        content, size = None, int(data)
    elif isinstance(data, np.ndarray):
        if data.dtype.kind not in "iuf" or data.dtype.itemsize != 4:
            raise ResourceError(label, "data", f"expected 32-bit numbers (float32, int32, uint32), got {data.dtype}")
        content = np.ascontiguousarray(data).tobytes()
        size = len(content)
    else:
        raise ResourceError(label, "data", f"expected a numpy array or a size in bytes, got {type(data).__name__}")
    if size <= 0 or size % 4:
        raise ResourceError(label, "size", f"{size} bytes: a storage buffer needs a positive multiple of 4 bytes")
    return content, size


#: What a named buffer may be used for, in words both APIs share. WebGPU's buffer usage flags follow from them
#: (copies to and from it are always allowed); OpenGL's buffers carry no such flags, so the library keeps the words
#: and every engine use of a buffer is checked against them in both APIs, before the driver sees it.
BUFFER_USES = ("storage", "vertex", "index", "indirect", "uniform")
#: What ``buffers.build(name, data)`` allows unless told otherwise: read and written by shaders (materials, compute
#: passes), drawn from as vertices or indices, and drawn indirectly.
DEFAULT_USES = ("storage", "vertex", "index", "indirect")


def buffer_uses(name: str, usage: Any) -> tuple[str, ...]:
    """The checked ``usage`` of buffer ``name``: one or more words of :data:`BUFFER_USES`."""
    words = (usage,) if isinstance(usage, str) else tuple(usage) if isinstance(usage, (tuple, list, set)) else None
    if not words or not all(isinstance(w, str) for w in words):
        raise ResourceError(f"buffer '{name}'", "usage", f"expected one or more of {BUFFER_USES}, got {usage!r}")
    unknown = [w for w in words if w not in BUFFER_USES]
    if unknown:
        raise ResourceError(f"buffer '{name}'", "usage", f"{unknown[0]!r} is not one of {BUFFER_USES}")
    return tuple(w for w in BUFFER_USES if w in words)


# --- what a shader declares -----------------------------------------------------------------------
@dataclass(frozen=True)
class StorageLayout:
    """The bytes a shader's storage binding needs: ``fixed`` bytes of members before a runtime-sized array (or
    the whole size of a sized type), and that array's element ``stride`` (0: no runtime array). A buffer must
    hold the fixed part and at least one element, and end on a whole element."""

    slot: str  # the block's or variable's name in the shader
    fixed: int
    stride: int

    @property
    def minimum(self) -> int:
        return self.fixed + self.stride

    def problem(self, size: int, shader: str) -> str | None:
        """Why a buffer of ``size`` bytes does not fit ``shader``'s slot (None: it fits)."""
        if size < self.minimum:
            what = f"one element of {self.stride} bytes" if self.stride else "its type"
            extra = f"{self.fixed} bytes + " if self.stride and self.fixed else ""
            return (f"is {size} bytes, smaller than the {self.minimum} bytes shader '{shader}' reads from "
                    f"'{self.slot}' ({extra}{what})")
        if self.stride and (size - self.fixed) % self.stride:
            return (f"is {size} bytes, not a whole number of the elements shader '{shader}' reads from "
                    f"'{self.slot}' ({self.fixed} + n × {self.stride} bytes)")
        return None


def _strip(text: str) -> str:
    return re.sub(r"//[^\n]*", " ", re.sub(r"/\*.*?\*/", " ", text, flags=re.S))


def _round(align: int, n: int) -> int:
    return -(-n // align) * align


class _Types:
    """Sizes and alignments under std430 / WGSL's storage rules (the same for the course's types): structs by
    name from the source; None for a type it cannot lay out (then nothing is checked)."""

    def __init__(self, structs: dict[str, list[tuple[str, int | None]]]) -> None:
        self.structs = structs

    def layout(self, type_name: str, count: int | None = None) -> tuple[int, int] | None:
        """(align, size) of ``type_name``, or of a sized array of ``count`` of them."""
        if type_name in self.structs:
            members = [self.layout(t, n) for t, n in self.structs[type_name]]
            if any(m is None for m in members) or not members:
                return None
            offset, align = 0, 1
            for m_align, m_size in members:  # type: ignore[misc]
                offset = _round(m_align, offset) + m_size
                align = max(align, m_align)
            base = (align, _round(align, offset))
        else:
            try:
                leaf = parse_type(type_name)
            except ValueError:
                return None
            if leaf.columns:
                base = (16 if leaf.rows > 2 else 8, leaf.columns * (16 if leaf.rows > 2 else 8))
            else:
                base = ({1: 4, 2: 8, 3: 16, 4: 16}[leaf.rows], 4 * leaf.rows)
        if count is None:
            return base
        return base[0], count * _round(base[0], base[1])

    def block(self, slot: str, members: list[tuple[str, int | None, bool]]) -> StorageLayout | None:
        """The layout of members ``(type, count, runtime-sized)``, the last of which may be runtime-sized."""
        offset = 0
        for i, (type_name, count, runtime) in enumerate(members):
            one = self.layout(type_name)
            if one is None:
                return None
            align, size = one
            offset = _round(align, offset)
            if runtime:
                return StorageLayout(slot, offset, _round(align, size)) if i == len(members) - 1 else None
            sized = self.layout(type_name, count)
            offset += sized[1] if sized else 0
        return StorageLayout(slot, offset, 0) if members else None


_GLSL_MEMBER = re.compile(r"(?:\b(?:readonly|writeonly|coherent|volatile|restrict|highp|mediump|lowp)\s+)*"
                          r"([A-Za-z_]\w*)\s+[A-Za-z_]\w*\s*(\[\s*(\d*)\s*\])?\s*;")


def _glsl_members(body: str) -> list[tuple[str, int | None, bool]] | None:
    """The members of a block or struct body; None when one is beyond this reader (a layout qualifier, an array
    of arrays): then nothing is checked rather than something wrong."""
    statements = [part.strip() for part in body.split(";") if part.strip()]
    found = [(m.group(1), int(m.group(3)) if m.group(3) else None, m.group(2) is not None and not m.group(3))
             for m in _GLSL_MEMBER.finditer(body)]
    return found if len(found) == len(statements) and "layout" not in body else None


def glsl_storage_layouts(texts: list[str]) -> dict[str, StorageLayout]:
    """Each ``buffer Name { ... }`` block of GLSL stage ``texts`` (std430) by block name, where it can be laid out."""
    structs, blocks = {}, []
    for text in map(_strip, texts):
        for m in re.finditer(r"\bstruct\s+([A-Za-z_]\w*)\s*\{([^}]*)\}", text):
            members = _glsl_members(m.group(2))
            if members is not None:  # else unknown: blocks that use it are not checked
                structs[m.group(1)] = [(t, n) for t, n, _ in members]
        blocks += re.findall(r"\bbuffer\s+([A-Za-z_]\w*)\s*\{([^}]*)\}", text)
    types = _Types(structs)
    out = {}
    for name, body in blocks:
        members = _glsl_members(body)
        layout = types.block(name, members) if members is not None else None
        if layout is not None:
            out.setdefault(name, layout)
    return out


_WGSL_ARRAY = re.compile(r"^array<(.+?)(?:,(\d+)u?)?>$")


def _wgsl_member(type_text: str) -> tuple[str, int | None, bool]:
    t = type_text.replace(" ", "")
    if m := _WGSL_ARRAY.match(t):
        return m.group(1), int(m.group(2)) if m.group(2) else None, m.group(2) is None
    return t, None, False


def _wgsl_fields(body: str) -> list[tuple[str, int | None, bool]]:
    """The member types of a WGSL struct body (``name: type,`` each; commas inside ``<...>`` kept)."""
    parts, depth, current = [], 0, ""
    for ch in body:
        depth += (ch == "<") - (ch == ">")
        if ch == "," and depth == 0:
            parts.append(current)
            current = ""
        else:
            current += ch
    parts.append(current)
    return [_wgsl_member(p.split(":", 1)[1]) for p in parts if ":" in p]


def wgsl_storage_layouts(text: str, group: int) -> dict[int, StorageLayout]:
    """Each ``@group(group) @binding(N) var<storage, ...> name: T;`` of WGSL ``text`` by binding, where it can be
    laid out (WGSL's storage rules)."""
    text = _strip(text)
    # A struct with attributes (@align, @size) is beyond this reader: left unknown, so not checked.
    fields = {m.group(1): _wgsl_fields(m.group(2)) for m in re.finditer(r"\bstruct\s+([A-Za-z_]\w*)\s*\{([^}]*)\}",
                                                                         text) if "@" not in m.group(2)}
    types = _Types({name: [(t, n) for t, n, _ in members] for name, members in fields.items()})
    out = {}
    for m in re.finditer(rf"@group\(\s*{group}\s*\)\s*@binding\(\s*(\d+)\s*\)\s*var<\s*storage[^>]*>\s*"
                         r"([A-Za-z_]\w*)\s*:\s*([^;]+);", text):
        member = _wgsl_member(m.group(3))
        # A struct of its own may end in a runtime-sized array: lay out its members as a block.
        members = fields[member[0]] if member[0] in fields and member[1:] == (None, False) else [member]
        layout = types.block(m.group(2), members)
        if layout is not None:
            out[int(m.group(1))] = layout
    return out


def check_material_buffer(material: str, shader: str, buffer: str, size: int, layout: StorageLayout | None) -> None:
    """A material's storage buffer against the shader's declaration: an error naming both and both sizes."""
    problem = layout.problem(size, shader) if layout is not None else None
    if problem is not None:
        raise ResourceError(f"material '{material}'", "buffers", f"buffer '{buffer}' {problem}")


# --- building a name again, and using a buffer ---------------------------------------------------
class StorageBufferLib:
    """``build(name, data, usage=DEFAULT_USES)`` for storage buffers: the first call creates the buffer for the
    ``usage`` words; a later call under the same name writes the new data into it (an int: zeros) when the size and
    usage are the same, so materials and compute passes bound to it see the new contents, and is an error otherwise
    (never the old buffer silently). :meth:`get_for` hands a buffer to a use (``"storage"`` for a material,
    ``"indirect"`` for a draw) only when it was built for it."""

    _items: dict[str, Any]
    _data: dict[str, Any]

    @property
    def _uses(self) -> dict[str, tuple[str, ...]]:
        return self.__dict__.setdefault("_buffer_uses", {})

    def build(self, name: str, data: Any, usage: Any = DEFAULT_USES) -> Any:
        uses = buffer_uses(name, usage)
        if name not in self._items:
            self.building_uses = uses  # what _create makes the buffer for
            buffer = super().build(name, data)  # type: ignore[misc]
            self._uses[name] = uses
            return buffer
        content, size = buffer_bytes(name, data)
        buffer = self._items[name]
        if size != buffer.size:
            raise ResourceError(f"buffer '{name}'", "size",
                                f"was built with {buffer.size} bytes and is built again with {size}: materials and "
                                "passes bound to it would keep the old buffer; give the new one another name (or "
                                "build it again with the same size, which writes the new data into it)")
        if uses != self.uses_of(name):
            raise ResourceError(f"buffer '{name}'", "usage",
                                f"was built for {', '.join(self.uses_of(name))} and is built again for "
                                f"{', '.join(uses)}: give the new one another name")
        self._write(buffer, content if content is not None else bytes(size))
        self._data[name] = data
        return buffer

    def uses_of(self, name: str) -> tuple[str, ...]:
        """What buffer ``name`` was built for."""
        return self._uses.get(name, DEFAULT_USES)

    def get_for(self, name: str, use: str, referrer: str = "the caller") -> Any:
        """Buffer ``name`` for ``use`` (a word of :data:`BUFFER_USES`) by ``referrer``: a ResourceError naming the
        buffer, the use and what it was built for when it was not built for this use."""
        buffer = self.get(name, referrer)  # type: ignore[attr-defined]
        if use not in self.uses_of(name):
            built = ", ".join(self.uses_of(name))
            raise ResourceError(f"buffer '{name}'", "usage",
                                f"{referrer} uses it for '{use}', but it was built for {built} only: build it "
                                f"with usage=({', '.join(repr(u) for u in (*self.uses_of(name), use))})")
        return buffer

    def forget(self, name: str) -> None:
        self._uses.pop(name, None)
        super().forget(name)  # type: ignore[misc]

    def _write(self, buffer: Any, content: bytes) -> None:
        raise NotImplementedError
