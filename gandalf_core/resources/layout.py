"""One layout rule for every uniform block: GLSL's std140 and WGSL's uniform address space, packed by field name.

A block is declared once, as a list of fields::

    LIGHT = Struct("Light", [("position", "vec4"), ("color", "vec4")])
    layout = BlockLayout("Lights", [("count", "u32"), ("ambient", "vec3"), ("lights", (LIGHT, 8))])
    layout.offset("lights[1].color"), layout.size, layout.pack({"count": 1, "ambient": (0.1, 0.1, 0.1), ...})

Types are the course's: scalars (``f32``/``float``, ``i32``/``int``, ``u32``/``uint``), vectors (``vec3``,
``vec3<f32>``, ``vec3f``, ``ivec4``, ``vec4<u32>`` ...), square matrices (``mat3``, ``mat4x4<f32>`` ...; stored as
columns, each padded like a ``vec4`` for mat3), fixed-size arrays ``(type, count)`` and structs (:class:`Struct`, or
its name when ``structs=`` maps names to them). A field is ``(name, type)`` or ``(name, type, default)``.

``rules`` picks the layout: ``"std140"`` (GLSL), ``"wgsl"`` (WGSL's uniform address space: natural alignment,
with its extra rules checked) or ``"both"`` (the default): the block must lay out the same way under both, so the
same bytes feed a GLSL ``layout(std140) uniform`` block and a WGSL ``var<uniform>`` struct. Where they differ
(``mat2``, an array of scalars, a struct not padded to 16 bytes) the error names the block and the field.

Values: scalars a number; vectors N numbers; matrices an ``(n, n)`` array in maths convention (row, column) or
``n·n`` floats row-major (written column by column); arrays a leading axis (structs: a sequence of dicts); structs
a dict. Floats become float32, integers int32/uint32, only here (CPU maths stays float64).
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

RULES = ("std140", "wgsl", "both")
_FLOAT32_MAX = float(np.finfo(np.float32).max)
_MISSING = object()


class LayoutError(ValueError):
    """A block declaration or a value that does not fit it; the message names the block and the field."""


def _round_up(align: int, n: int) -> int:
    return -(-n // align) * align


# --- types ------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Leaf:
    """A scalar, vector or square matrix: ``kind`` 'f', 'i' or 'u'; ``columns`` 0 for scalars and vectors."""

    name: str
    kind: str
    rows: int  # 1 for a scalar
    columns: int = 0  # matrices: number of columns (= rows)

    @property
    def dtype(self) -> np.dtype:
        return np.dtype({"f": "<f4", "i": "<i4", "u": "<u4"}[self.kind])

    @property
    def shape(self) -> tuple[int, ...]:
        if self.columns:
            return (self.rows, self.columns)
        return () if self.rows == 1 else (self.rows,)


@dataclass(frozen=True)
class Struct:
    """A struct type: its name and fields (``(name, type)`` or ``(name, type, default)``)."""

    name: str
    fields: Sequence[tuple[Any, ...]]


@dataclass(frozen=True)
class Array:
    elem: Any  # Leaf | Array | Struct
    count: int


_SCALARS = {"f32": "f", "float": "f", "i32": "i", "int": "i", "u32": "u", "uint": "u"}
_GLSL_VEC = re.compile(r"^([iu]?)vec([234])$")
_WGSL_VEC = re.compile(r"^vec([234])(?:<(f32|i32|u32)>|([fiu]))$")
_GLSL_MAT = re.compile(r"^mat([234])(?:x([234]))?$")
_WGSL_MAT = re.compile(r"^mat([234])x([234])(?:<f32>|f)$")


def parse_type(text: str) -> Leaf:
    """A scalar, vector or matrix type named in GLSL or WGSL (``vec3``, ``vec3<f32>``, ``vec3f``, ``mat4``)."""
    t = text.replace(" ", "")
    if t in _SCALARS:
        return Leaf(t, _SCALARS[t], 1)
    if m := _GLSL_VEC.match(t):
        return Leaf(t, {"": "f", "i": "i", "u": "u"}[m.group(1)], int(m.group(2)))
    if m := _WGSL_VEC.match(t):
        kind = (m.group(2) or m.group(3))[0]
        return Leaf(t, kind, int(m.group(1)))
    if (m := _GLSL_MAT.match(t)) or (m := _WGSL_MAT.match(t)):
        columns, rows = int(m.group(1)), int(m.group(2) or m.group(1))
        if columns != rows:
            raise ValueError(f"type '{text}': only square matrices are supported")
        return Leaf(t, "f", rows, columns)
    raise ValueError(f"unknown type '{text}' (expected a scalar, vector or square matrix, e.g. float, vec3, mat4)")


# --- sizes and alignments under each rule ---------------------------------------------------------
def _leaf_layout(leaf: Leaf, rules: str) -> tuple[int, int]:
    """(align, size) of a leaf."""
    if leaf.columns:  # a matrix: an array of column vectors
        col_align, col_size = _leaf_layout(Leaf("", "f", leaf.rows), rules)
        if rules == "std140":
            return 16, 16 * leaf.columns
        return col_align, leaf.columns * _round_up(col_align, col_size)
    n = leaf.rows
    return {1: 4, 2: 8, 3: 16, 4: 16}[n], 4 * n


@dataclass(frozen=True)
class FieldInfo:
    """A laid-out field: byte ``offset``, ``size``, ``align``; ``stride`` for arrays (0 otherwise)."""

    name: str
    type: Any
    offset: int
    size: int
    align: int
    stride: int = 0
    default: Any = _MISSING
    members: tuple[FieldInfo, ...] = ()  # a struct's fields (of one element, for an array of structs)

    @property
    def has_default(self) -> bool:
        return self.default is not _MISSING


def _type_name(t: Any) -> str:
    if isinstance(t, Leaf):
        return t.name
    if isinstance(t, Struct):
        return t.name
    if isinstance(t, Array):
        return f"{_type_name(t.elem)}[{t.count}]"
    return str(t)


class BlockLayout:
    """A uniform block's layout, declared once by field list; :meth:`pack` makes its bytes by field name."""

    def __init__(self, name: str, fields: Sequence[tuple[Any, ...]], *, rules: str = "both",
                 structs: Mapping[str, Struct | Sequence[tuple[Any, ...]]] | None = None) -> None:
        if rules not in RULES:
            raise ValueError(f"block '{name}': rules must be one of {RULES}, got {rules!r}")
        self.name, self.rules = name, rules
        self._structs = {k: v if isinstance(v, Struct) else Struct(k, v) for k, v in (structs or {}).items()}
        if not fields:
            raise LayoutError(f"block '{name}': no fields")
        if rules == "both":
            std140 = self._lay_struct(name, fields, "std140", name)
            wgsl = self._lay_struct(name, fields, "wgsl", name)
            _compare(name, std140[2], wgsl[2], name)
            self.align, self.size, self.fields = std140
            self.size = max(self.size, wgsl[1])
        else:
            self.align, self.size, self.fields = self._lay_struct(name, fields, rules, name)
        self._by_name = {f.name: f for f in self.fields}
        self._pack_cache: bytes | None = None
        self._views: dict[str, tuple[tuple[int, ...], np.dtype, int, tuple[int, ...]]] = {}

    # --- laying out -----------------------------------------------------------------------------
    def _resolve(self, t: Any, path: str) -> Any:
        if isinstance(t, (Leaf, Struct, Array)):
            return t
        if isinstance(t, tuple) and len(t) == 2 and isinstance(t[1], (int, np.integer)):
            if int(t[1]) < 1:
                raise LayoutError(f"block '{self.name}' field '{path}': array count must be ≥ 1, got {t[1]}")
            return Array(self._resolve(t[0], path), int(t[1]))
        if isinstance(t, str):
            if t in self._structs:
                return self._structs[t]
            try:
                return parse_type(t)
            except ValueError as exc:
                raise LayoutError(f"block '{self.name}' field '{path}': {exc}") from None
        raise LayoutError(f"block '{self.name}' field '{path}': cannot read type {t!r}")

    def _lay(self, t: Any, rules: str, path: str) -> tuple[int, int, int, tuple[FieldInfo, ...]]:
        """(align, size, stride, members) of a resolved type."""
        if isinstance(t, Leaf):
            align, size = _leaf_layout(t, rules)
            return align, size, 0, ()
        if isinstance(t, Struct):
            align, size, members = self._lay_struct(t.name, t.fields, rules, path)
            return align, size, 0, members
        elem_align, elem_size, _, members = self._lay(t.elem, rules, path + "[]")
        if rules == "std140":
            align = _round_up(16, elem_align)
            stride = _round_up(align, elem_size)
        else:
            align, stride = elem_align, _round_up(elem_align, elem_size)
            if stride % 16:
                raise LayoutError(f"block '{self.name}' field '{path}': an array in a WGSL uniform block needs an "
                                  f"element stride that is a multiple of 16, {_type_name(t.elem)} has {stride} "
                                  "(use vec4 elements, or pad the struct)")
        return align, stride * t.count, stride, members

    def _lay_struct(self, name: str, fields: Sequence[tuple[Any, ...]], rules: str,
                    path: str) -> tuple[int, int, tuple[FieldInfo, ...]]:
        offset, max_align, out, min_next = 0, 4 if rules == "wgsl" else 16, [], 0
        seen: set[str] = set()
        for spec in fields:
            if not isinstance(spec, tuple) or len(spec) not in (2, 3) or not isinstance(spec[0], str):
                raise LayoutError(f"block '{self.name}' ({path}): a field is (name, type) or (name, type, default), "
                                  f"got {spec!r}")
            fname = spec[0]
            if fname in seen:
                raise LayoutError(f"block '{self.name}' field '{_join(path, self.name, fname)}': declared twice")
            seen.add(fname)
            fpath = _join(path, self.name, fname)
            t = self._resolve(spec[1], fpath)
            align, size, stride, members = self._lay(t, rules, fpath)
            start = _round_up(align, max(offset, min_next))
            if rules == "wgsl":
                needs16 = isinstance(t, (Struct, Array))
                if needs16 and start % 16:
                    raise LayoutError(f"block '{self.name}' field '{fpath}': WGSL's uniform address space puts a "
                                      f"{'struct' if isinstance(t, Struct) else 'array'} at a multiple of 16 bytes, "
                                      f"here it falls at {start} (add padding before it)")
                if min_next and offset < min_next:
                    raise LayoutError(f"block '{self.name}' field '{fpath}': WGSL's uniform address space needs "
                                      f"{min_next - offset} more bytes after the struct before it (pad that struct "
                                      "to a multiple of 16 bytes)")
                min_next = start + _round_up(16, size) if isinstance(t, Struct) else 0
            default = spec[2] if len(spec) == 3 else _MISSING
            out.append(FieldInfo(fname, t, start, size, align, stride, default, members))
            offset = start + size
            max_align = max(max_align, align)
        if rules == "std140":
            max_align = _round_up(16, max_align)
        return max_align, _round_up(max_align, offset), tuple(out)

    # --- queries --------------------------------------------------------------------------------
    def field(self, path: str) -> FieldInfo:
        """The field at ``path`` (``"ambient"``, ``"lights[2].color"``), offsets from the block's start."""
        fields, base, found = self.fields, 0, None
        for part in path.split("."):
            m = re.fullmatch(r"(\w+)(?:\[(\d+)\])?", part)
            named = {f.name: f for f in fields}
            if m is None or m.group(1) not in named:
                raise LayoutError(f"block '{self.name}' has no field '{path}' (fields: {', '.join(named)})")
            f = named[m.group(1)]
            offset = base + f.offset
            if m.group(2) is not None:
                if not isinstance(f.type, Array) or int(m.group(2)) >= f.type.count:
                    raise LayoutError(f"block '{self.name}' field '{path}': index out of range or not an array")
                offset += int(m.group(2)) * f.stride
                elem = f.type.elem
                size = f.stride if isinstance(elem, Struct) else f.size // f.type.count
                f = FieldInfo(f"{f.name}[{m.group(2)}]", elem, 0, size, f.align, 0, _MISSING, f.members)
            found = FieldInfo(f.name, f.type, offset, f.size, f.align, f.stride, f.default, f.members)
            fields, base = f.members, offset
        assert found is not None
        return found

    def offset(self, path: str) -> int:
        """Byte offset of the field at ``path`` (see :meth:`field`)."""
        return self.field(path).offset

    def names(self) -> list[str]:
        return [f.name for f in self.fields]

    def leaves(self) -> list[tuple[str, int, str]]:
        """Every scalar/vector/matrix in the block as ``(path, offset, type)``; arrays as their first element
        ``name[0]`` (then the array stride gives the others) — how GL's introspection names block members."""
        out: list[tuple[str, int, str]] = []

        def walk(fields: tuple[FieldInfo, ...], prefix: str, base: int) -> None:
            for f in fields:
                t, path = f.type, prefix + f.name
                if isinstance(t, Array):
                    elem = t.elem
                    if isinstance(elem, Struct):
                        for i in range(t.count):
                            walk(f.members, f"{path}[{i}].", base + f.offset + i * f.stride)
                    else:
                        out.append((f"{path}[0]", base + f.offset, _type_name(elem)))
                elif isinstance(t, Struct):
                    walk(f.members, path + ".", base + f.offset)
                else:
                    out.append((path, base + f.offset, t.name))

        walk(self.fields, "", 0)
        return out

    # --- shader text ----------------------------------------------------------------------------
    def glsl(self, instance: str | None = None, members: Mapping[str, str] | None = None, *,
             binding: int | None = None, struct: bool = False) -> str:
        """The block as GLSL declares it: ``layout(std140) uniform Name { ... } instance;`` (members renamed by
        ``members``; no instance name: the members are global names; ``binding``: the block's binding point,
        GLSL 4.20 and later).

        ``struct=True`` declares ``struct Name { ... };`` and the block ``uniform NameBlock { Name instance; }``:
        the same bytes, for a shader that passes the whole block to a function as one value (WGSL's struct)."""
        if any(isinstance(_array_elem(f.type), Struct) for f in self.fields):
            raise LayoutError(f"block '{self.name}': shader text is written for blocks of numbers, vectors and "
                              "matrices (and arrays of them)")
        qualifier = "std140" if binding is None else f"std140, binding = {binding}"
        lines = []
        for f in self.fields:
            name = (members or {}).get(f.name, f.name)
            if isinstance(f.type, Array):
                lines.append(f"    {_glsl_type(f.type.elem)} {name}[{f.type.count}];")
            else:
                lines.append(f"    {_glsl_type(f.type)} {name};")
        if struct:
            if not instance:
                raise LayoutError(f"block '{self.name}': a block declared as a struct needs an instance name")
            return (f"struct {self.name} {{\n" + "\n".join(lines) + "\n};\n"
                    f"layout({qualifier}) uniform {self.name}Block {{ {self.name} {instance}; }};\n")
        tail = f" {instance}" if instance else ""
        return f"layout({qualifier}) uniform {self.name} {{\n" + "\n".join(lines) + f"\n}}{tail};\n"

    def wgsl(self, variable: str, group: int, binding: int) -> str:
        """The block as WGSL declares it: ``struct Name { ... };`` and its ``var<uniform>`` at (group, binding)."""
        if any(isinstance(_array_elem(f.type), Struct) for f in self.fields):
            raise LayoutError(f"block '{self.name}': shader text is written for blocks of numbers, vectors and "
                              "matrices (and arrays of them)")
        lines = [f"    {f.name}: {_wgsl_type(f.type)}," for f in self.fields]
        return (f"struct {self.name} {{\n" + "\n".join(lines) + "\n};\n"
                f"@group({group}) @binding({binding}) var<uniform> {variable}: {self.name};\n")

    def __repr__(self) -> str:
        inner = ", ".join(f"{f.name}: {_type_name(f.type)} @{f.offset}" for f in self.fields)
        return f"BlockLayout({self.name!r}, {self.rules}, size {self.size}: {inner})"

    # --- packing --------------------------------------------------------------------------------
    def pack(self, values: Mapping[str, Any]) -> bytes:
        """The block's bytes, each field from ``values`` by name (a field with a default may be left out)."""
        if self._pack_cache is None:
            self._prepare()
        if not isinstance(values, Mapping):
            raise LayoutError(f"block '{self.name}': expected a dict of fields, got {type(values).__name__}")
        out = self._template.copy()  # float32 words; integer fields keep their bits
        buf = memoryview(out).cast("B")
        by_name, fast = self._by_name, self._fast
        written: list[str] = []
        with np.errstate(over="ignore", invalid="ignore"):  # float32 overflow is caught below, naming the field
            for key, value in values.items():
                plan = fast.get(key)
                if plan is not None:
                    start, stop, shape = plan
                    try:
                        arr = np.asarray(value, dtype=np.float64)
                    except (TypeError, ValueError):
                        arr = None
                    if arr is not None and arr.size == stop - start:
                        if shape is not None:  # matrices: maths (row, column) in, column by column out
                            arr = arr.reshape(shape).swapaxes(-1, -2)
                        out[start:stop] = arr.ravel()
                        written.append(key)
                        continue
                f = by_name.get(key)
                if f is None:
                    raise LayoutError(f"block '{self.name}' has no field '{key}' (fields: {', '.join(by_name)})")
                self._write(buf, f.offset, f, f.type, value, key)
        if written and not np.isfinite(out[self._float_words]).all():
            for key in written:  # find the field, for the message
                f = by_name[key]
                leaf = f.type.elem if isinstance(f.type, Array) else f.type
                _numbers(self.name, key, values[key], leaf, f.type.count if isinstance(f.type, Array) else None)
        if len(values) < len(by_name):
            for f in self.fields:
                if f.name not in values and not f.has_default:
                    raise LayoutError(f"block '{self.name}' field '{f.name}': no value given and no default")
        return out.tobytes()

    def new(self) -> np.ndarray:
        """A fresh block (bytes as a ``uint8`` array) holding the defaults, to fill through :meth:`view`."""
        if self._pack_cache is None:
            self._prepare()
        return np.frombuffer(self._pack_cache, dtype=np.uint8).copy()

    def view(self, block: np.ndarray, path: str) -> np.ndarray:
        """A typed numpy view of field ``path`` inside ``block`` (from :meth:`new`), in the shape :meth:`pack` takes:
        writing ``view[...] = values`` fills it with the layout's offsets and strides (matrices in maths
        convention, written column by column). The engine's per-frame blocks are filled this way, with no checks
        (their values come from validated components); :meth:`pack` checks each value."""
        plan = self._views.get(path)
        if plan is None:
            f = self.field(path)
            t = f.type
            leaf = t.elem if isinstance(t, Array) else t
            if not isinstance(leaf, Leaf):
                raise LayoutError(f"block '{self.name}' field '{path}': view() takes a number, vector, matrix or "
                                  "array of them")
            shape, strides = leaf.shape, _leaf_strides(leaf, self.rules)
            if isinstance(t, Array):
                shape, strides = (t.count, *shape), (f.stride, *strides)
            plan = self._views[path] = (shape, leaf.dtype, f.offset, strides)
        shape, dtype, offset, strides = plan
        return np.ndarray(shape, dtype, buffer=block, offset=offset, strides=strides)

    def unpack(self, data: bytes | np.ndarray) -> dict[str, Any]:
        """The values of a block's bytes by field name, as :meth:`pack` takes them (the inverse of :meth:`pack`):
        numbers, lists for vectors and arrays, ``(n, n)`` nested lists for matrices (maths convention), dicts for
        structs. What a frame inspector shows of a block as written."""
        raw = np.frombuffer(bytes(data), dtype=np.uint8)
        if len(raw) < self.size:
            raise LayoutError(f"block '{self.name}': {len(raw)} bytes given, the block has {self.size}")
        block = raw[: _round_up(4, self.size)].copy()
        return self._unpack_fields(block, self.fields, 0)

    def _unpack_fields(self, block: np.ndarray, fields: tuple[FieldInfo, ...], base: int) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for f in fields:
            t, offset = f.type, base + f.offset
            if isinstance(t, Struct):
                out[f.name] = self._unpack_fields(block, f.members, offset)
            elif isinstance(t, Array) and isinstance(t.elem, Struct):
                out[f.name] = [self._unpack_fields(block, f.members, offset + i * f.stride) for i in range(t.count)]
            else:
                leaf = t.elem if isinstance(t, Array) else t
                shape, strides = leaf.shape, _leaf_strides(leaf, self.rules)
                if isinstance(t, Array):
                    shape, strides = (t.count, *shape), (f.stride, *strides)
                value = np.ndarray(shape, leaf.dtype, buffer=block, offset=offset, strides=strides)
                out[f.name] = value.item() if value.ndim == 0 else value.tolist()
        return out

    def _prepare(self) -> None:
        """The defaults, written once (fields without one stay zero until given), and the fields that can be
        written straight into the block's float32 words: float leaves and arrays with no padding inside."""
        template = bytearray(_round_up(4, self.size))
        for f in self.fields:
            if f.has_default:
                self._write(template, f.offset, f, f.type, self._default_value(f), f.name)
        self._pack_cache = bytes(template)
        self._template = np.frombuffer(self._pack_cache, dtype=np.float32).copy()
        self._fast: dict[str, tuple[int, int, tuple[int, ...] | None]] = {}
        float_words = np.zeros(len(self._template), dtype=bool)
        for f in self.fields:
            t = f.type
            leaf = t.elem if isinstance(t, Array) else t
            if not isinstance(leaf, Leaf) or leaf.kind != "f":
                continue
            strides = _leaf_strides(leaf, self.rules)
            if leaf.columns and strides[1] != 4 * leaf.rows:
                continue  # mat3: padded columns
            if isinstance(t, Array) and f.stride != 4 * _flat_count(leaf):
                continue  # padded elements (vec3[], float[] in std140)
            start = f.offset // 4
            stop = start + _flat_count(t)
            shape = None
            if leaf.columns:
                shape = leaf.shape if not isinstance(t, Array) else (t.count, *leaf.shape)
            self._fast[f.name] = (start, stop, shape)
            float_words[start:stop] = True
        self._float_words = float_words

    @staticmethod
    def _default_value(f: FieldInfo) -> Any:
        if np.ndim(f.default) == 0 and not isinstance(f.type, Struct):  # a scalar default fills the field
            return np.full(_flat_count(f.type), f.default)
        return f.default

    def _write_struct(self, buf: bytearray, base: int, fields: tuple[FieldInfo, ...], values: Any,
                      prefix: str) -> None:
        if not isinstance(values, Mapping):
            raise LayoutError(f"block '{self.name}' field '{prefix.rstrip('.') or self.name}': expected a dict of "
                              f"fields, got {type(values).__name__}")
        names = {f.name for f in fields}
        for key in values:
            if key not in names:
                raise LayoutError(f"block '{self.name}' has no field '{prefix}{key}' "
                                  f"(fields: {', '.join(f.name for f in fields)})")
        for f in fields:
            value = values.get(f.name, _MISSING)
            if value is _MISSING:
                if not f.has_default:
                    raise LayoutError(f"block '{self.name}' field '{prefix}{f.name}': no value given and no default")
                value = self._default_value(f)
            self._write(buf, base + f.offset, f, f.type, value, prefix + f.name)

    def _write(self, buf: bytearray, offset: int, f: FieldInfo, t: Any, value: Any, path: str) -> None:
        if isinstance(t, Struct):
            self._write_struct(buf, offset, f.members, value, path + ".")
            return
        if isinstance(t, Array) and isinstance(t.elem, Struct):
            items = list(value) if not isinstance(value, Mapping) else [value]
            if len(items) != t.count:
                raise LayoutError(f"block '{self.name}' field '{path}': expected {t.count} elements "
                                  f"({_type_name(t)}), got {len(items)}")
            for i, item in enumerate(items):
                self._write_struct(buf, offset + i * f.stride, f.members, item, f"{path}[{i}].")
            return
        count = t.count if isinstance(t, Array) else None
        leaf = t.elem if isinstance(t, Array) else t
        if not isinstance(leaf, Leaf):
            raise LayoutError(f"block '{self.name}' field '{path}': arrays of arrays are not supported")
        arr = _numbers(self.name, path, value, leaf, count)
        strides = _leaf_strides(leaf, self.rules)
        dense = not leaf.columns or strides[1] == 4 * leaf.rows  # no padding inside an element
        if dense and (count is None or f.stride == 4 * _flat_count(leaf)):
            # One copy of the bytes (matrices column by column): the common vec4 / mat4 / vec4[] case.
            if leaf.columns:
                arr = arr.swapaxes(-1, -2)
            data = arr.tobytes()
            buf[offset:offset + len(data)] = data
            return
        shape = leaf.shape
        if count is not None:
            shape, strides = (count, *shape), (f.stride, *strides)
        np.ndarray(shape, leaf.dtype, buffer=buf, offset=offset, strides=strides)[...] = arr


def _array_elem(t: Any) -> Any:
    return t.elem if isinstance(t, Array) else t


_SCALAR_NAMES = {"f": ("float", "f32"), "i": ("int", "i32"), "u": ("uint", "u32")}


def _glsl_type(leaf: Leaf) -> str:
    if leaf.columns:
        return f"mat{leaf.columns}"
    if leaf.rows == 1:
        return _SCALAR_NAMES[leaf.kind][0]
    return f"{'' if leaf.kind == 'f' else leaf.kind}vec{leaf.rows}"


def _wgsl_type(t: Any) -> str:
    if isinstance(t, Array):
        return f"array<{_wgsl_type(t.elem)}, {t.count}>"
    scalar = _SCALAR_NAMES[t.kind][1]
    if t.columns:
        return f"mat{t.columns}x{t.rows}<{scalar}>"
    return scalar if t.rows == 1 else f"vec{t.rows}<{scalar}>"


def _join(path: str, block: str, name: str) -> str:
    return name if path == block else f"{path}.{name}"


def _flat_count(t: Any) -> int:
    if isinstance(t, Array):
        return t.count * _flat_count(t.elem)
    return int(np.prod(t.shape)) if t.shape else 1


def _leaf_strides(leaf: Leaf, rules: str) -> tuple[int, ...]:
    if leaf.columns:  # (row, column): rows 4 bytes apart, columns one padded column vector apart
        col = 16 if rules in ("std140", "both") or leaf.rows != 2 else 8
        return (4, col)
    return () if leaf.rows == 1 else (4,)


def _numbers(block: str, path: str, value: Any, leaf: Leaf, count: int | None) -> np.ndarray:
    want = leaf.shape if count is None else (count, *leaf.shape)
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise LayoutError(f"block '{block}' field '{path}': expected numbers for {leaf.name}, got {value!r}") from None
    if arr.dtype.kind not in "biuf":
        raise LayoutError(f"block '{block}' field '{path}': expected numbers for {leaf.name}, got {value!r}")
    if arr.shape != want:
        n = 1
        for d in want:
            n *= d
        if arr.size != n:
            what = f"{count} × {leaf.name}" if count is not None else leaf.name
            raise LayoutError(f"block '{block}' field '{path}': expected {n} value(s) ({what}), got {arr.size} "
                              f"(shape {arr.shape})")
        arr = arr.reshape(want)  # flat: a matrix's n·n floats row-major, an array's elements one after another
    if leaf.kind == "f":
        # One reduction catches NaN, infinities and values float32 cannot hold (NaN fails every comparison).
        if arr.size and not float(np.abs(arr).max()) <= _FLOAT32_MAX:
            if not np.isfinite(arr).all():
                raise LayoutError(f"block '{block}' field '{path}': values must be finite, got {value!r}")
            raise LayoutError(f"block '{block}' field '{path}': values beyond float32's range, got {value!r}")
        return arr.astype(np.float32)
    if arr.dtype.kind == "f" and not np.array_equal(arr, np.trunc(arr)):
        raise LayoutError(f"block '{block}' field '{path}': {leaf.name} holds integers, got {value!r}")
    info = np.iinfo(leaf.dtype)
    if arr.size and (arr.min() < info.min or arr.max() > info.max):
        raise LayoutError(f"block '{block}' field '{path}': out of {leaf.name}'s range [{info.min}, {info.max}], "
                          f"got {value!r}")
    return arr.astype(leaf.dtype)


def _compare(block: str, a: tuple[FieldInfo, ...], b: tuple[FieldInfo, ...], path: str) -> None:
    """Raise when the std140 (``a``) and WGSL (``b``) layouts of the same fields differ."""
    for fa, fb in zip(a, b):
        where = fa.name if path == block else f"{path}.{fa.name}"
        if (fa.offset, fa.size, fa.stride) != (fb.offset, fb.size, fb.stride):
            hint = ("mat2's columns are 16 bytes apart in std140 and 8 in WGSL: use vec4 or mat4"
                    if isinstance(fa.type, Leaf) and fa.type.columns == 2 else
                    "pad it so both rules agree (vec4 elements, structs padded to 16 bytes)")
            raise LayoutError(f"block '{block}' field '{where}': std140 puts it at offset {fa.offset} (size {fa.size}"
                              f"{f', stride {fa.stride}' if fa.stride else ''}), WGSL at {fb.offset} (size {fb.size}"
                              f"{f', stride {fb.stride}' if fb.stride else ''}): {hint}")
        if fa.members:
            _compare(block, fa.members, fb.members, where)
