"""WGSL reflection: struct layouts, resource bindings and entry points read from the shader source.

The WebGPU backend builds uniform buffers and bind group layouts from what a shader declares, so a
shader edit can never silently disagree with the host code. This module tokenizes WGSL (comments and
formatting do not matter), parses only the module-scope declarations it needs (function bodies are
skipped by brace matching) and computes host-shareable memory layouts with the WGSL spec's rules
(AlignOf/SizeOf, ``@align``/``@size``), checking the extra uniform-buffer constraints that naga
enforces. Pure Python + numpy: no GPU library is imported.

    refl = reflect(source, "shaders/lit.wgsl")
    layout = refl.structs["Uniforms"]
    data = layout.pack({"model": m, "color": (1.0, 0.5, 0.0), "time": t})
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any, NamedTuple

import numpy as np

__all__ = [
    "Binding",
    "EntryPoint",
    "FieldLayout",
    "ShaderReflection",
    "StructLayout",
    "VertexInput",
    "WGSLReflectError",
    "reflect",
]


class WGSLReflectError(ValueError):
    """A WGSL source that cannot be reflected; the message starts with ``<file>:<line>:``."""


# ----------------------------------------------------------------------------------------------
# Tokenizer

class _Token(NamedTuple):
    kind: str  # "ident" | "number" | "punct" | "eof"
    text: str
    line: int


_TOKEN_RE = re.compile(
    r"""
    (?P<ws>\s+)
    | (?P<number>
        0[xX](?:[0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)(?:[pP][+-]?[0-9]+)?[iufh]?
      | (?:[0-9]+\.[0-9]*|\.[0-9]+|[0-9]+)(?:[eE][+-]?[0-9]+)?[iufh]?
      )
    | (?P<ident>[^\W\d]\w*)
    | (?P<punct>->|[@(){}<>\[\],:;=.+\-*/%&|^!~?])
    """,
    re.VERBOSE,
)


def _tokenize(source: str, filename: str) -> list[_Token]:
    """Split WGSL into tokens, dropping whitespace, ``//`` and (nested) ``/* */`` comments.

    ``<`` and ``>`` are always single tokens so that ``array<vec4<f32>>`` needs no special case.
    """
    tokens: list[_Token] = []
    pos, line, end = 0, 1, len(source)
    while pos < end:
        if source.startswith("//", pos):
            nl = source.find("\n", pos)
            pos = end if nl < 0 else nl
            continue
        if source.startswith("/*", pos):
            start_line, depth, pos = line, 1, pos + 2
            while depth:
                if pos >= end:
                    raise WGSLReflectError(f"{filename}:{start_line}: unterminated block comment")
                if source.startswith("/*", pos):
                    depth, pos = depth + 1, pos + 2
                elif source.startswith("*/", pos):
                    depth, pos = depth - 1, pos + 2
                else:
                    line += source[pos] == "\n"
                    pos += 1
            continue
        m = _TOKEN_RE.match(source, pos)
        if m is None:
            raise WGSLReflectError(f"{filename}:{line}: unexpected character {source[pos]!r}")
        if m.lastgroup != "ws":
            tokens.append(_Token(m.lastgroup, m.group(), line))
        line += m.group().count("\n")
        pos = m.end()
    tokens.append(_Token("eof", "", line))
    return tokens


# ----------------------------------------------------------------------------------------------
# Syntax tree (only what reflection needs)

@dataclass(frozen=True)
class _TypeRef:
    """A named type or identifier with an optional template list, e.g. ``array<Light, N>``."""

    name: str
    args: tuple[_Expr, ...]
    line: int


@dataclass(frozen=True)
class _BinOp:
    op: str
    lhs: _Expr
    rhs: _Expr


@dataclass(frozen=True)
class _Call:
    callee: _TypeRef
    args: tuple[_Expr, ...]


_Expr = int | float | _TypeRef | _BinOp | _Call


@dataclass(frozen=True)
class _Decl:
    """A struct member or function parameter: ``@attrs name: type``."""

    name: str
    type: _TypeRef
    attrs: dict[str, tuple[_Expr, ...]]
    line: int


@dataclass
class _Function:
    name: str
    attrs: dict[str, tuple[_Expr, ...]]
    params: list[_Decl]
    body_idents: set[str]
    line: int
    returns: _TypeRef | None = None


@dataclass
class _Var:
    name: str
    space: str | None
    access: str | None
    type: _TypeRef
    attrs: dict[str, tuple[_Expr, ...]]
    line: int


@dataclass
class _Module:
    structs: dict[str, list[_Decl]] = field(default_factory=dict)
    struct_lines: dict[str, int] = field(default_factory=dict)
    aliases: dict[str, _TypeRef] = field(default_factory=dict)
    consts: dict[str, _Expr | None] = field(default_factory=dict)  # None: not an integer expression
    vars: list[_Var] = field(default_factory=list)
    functions: dict[str, _Function] = field(default_factory=dict)


class _Parser:
    """Recursive-descent parser over module-scope WGSL declarations."""

    def __init__(self, tokens: list[_Token], filename: str) -> None:
        self.tokens = tokens
        self.filename = filename
        self.pos = 0

    # -- token helpers
    def peek(self, k: int = 0) -> _Token:
        return self.tokens[min(self.pos + k, len(self.tokens) - 1)]

    def next(self) -> _Token:
        tok = self.peek()
        self.pos = min(self.pos + 1, len(self.tokens) - 1)
        return tok

    def accept(self, text: str) -> bool:
        if self.peek().text == text and self.peek().kind != "eof":
            self.pos += 1
            return True
        return False

    def expect(self, text: str) -> _Token:
        tok = self.peek()
        if tok.text != text or tok.kind == "eof":
            raise self.error(f"expected '{text}', found {_describe(tok)}", tok)
        return self.next()

    def ident(self, what: str) -> _Token:
        tok = self.peek()
        if tok.kind != "ident":
            raise self.error(f"expected {what}, found {_describe(tok)}", tok)
        return self.next()

    def error(self, what: str, tok: _Token | None = None) -> WGSLReflectError:
        return WGSLReflectError(f"{self.filename}:{(tok or self.peek()).line}: {what}")

    # -- module scope
    def module(self) -> _Module:
        mod = _Module()
        while self.peek().kind != "eof":
            attrs = self.attributes()
            tok = self.peek()
            if tok.text == ";" and not attrs:
                self.next()
            elif tok.text in ("enable", "requires", "diagnostic", "const_assert", "override"):
                self.skip_statement()  # directives and pipeline overrides carry no layout
            elif tok.text == "alias":
                self.next()
                name = self.ident("an alias name").text
                self.expect("=")
                mod.aliases[name] = self.type()
                self.expect(";")
            elif tok.text == "struct":
                self.struct(mod)
            elif tok.text == "const":
                self.const(mod)
            elif tok.text == "var":
                mod.vars.append(self.var(attrs))
            elif tok.text == "fn":
                fn = self.function(attrs)
                mod.functions[fn.name] = fn
            else:
                raise self.error(f"unexpected {_describe(tok)} at module scope", tok)
        return mod

    def attributes(self) -> dict[str, tuple[_Expr, ...]]:
        attrs: dict[str, tuple[_Expr, ...]] = {}
        while self.accept("@"):
            name = self.ident("an attribute name").text
            args: list[_Expr] = []
            if self.accept("("):
                while not self.accept(")"):
                    args.append(self.expr())
                    if not self.accept(","):
                        self.expect(")")
                        break
            attrs[name] = tuple(args)
        return attrs

    def struct(self, mod: _Module) -> None:
        self.expect("struct")
        name_tok = self.ident("a struct name")
        if name_tok.text in mod.structs:
            raise self.error(f"struct '{name_tok.text}' is declared twice", name_tok)
        self.expect("{")
        members: list[_Decl] = []
        while not self.accept("}"):
            members.append(self.decl("a struct member name"))
            if not self.accept(","):
                self.expect("}")
                break
        if not members:
            raise self.error(f"struct '{name_tok.text}' has no members", name_tok)
        mod.structs[name_tok.text] = members
        mod.struct_lines[name_tok.text] = name_tok.line

    def decl(self, what: str) -> _Decl:
        attrs = self.attributes()
        name = self.ident(what)
        self.expect(":")
        return _Decl(name.text, self.type(), attrs, name.line)

    def const(self, mod: _Module) -> None:
        self.expect("const")
        name = self.ident("a constant name").text
        if self.accept(":"):
            self.type()
        self.expect("=")
        init = self.skip_statement()
        # Only integer expressions matter (array counts); anything else is kept as "unknown".
        sub = _Parser([*init[:-1], _Token("eof", "", init[-1].line)], self.filename)
        try:
            value: _Expr | None = sub.expr()
            if sub.peek().kind != "eof":
                value = None
        except WGSLReflectError:
            value = None
        mod.consts[name] = value

    def var(self, attrs: dict[str, tuple[_Expr, ...]]) -> _Var:
        var_tok = self.expect("var")
        space = access = None
        if self.accept("<"):
            space = self.ident("an address space").text
            if self.accept(","):
                access = self.ident("an access mode").text
            self.expect(">")
        name = self.ident("a variable name")
        if not self.accept(":"):
            raise self.error(f"module-scope variable '{name.text}' needs an explicit type", name)
        vtype = self.type()
        if self.peek().text == "=":
            self.skip_statement()
        else:
            self.expect(";")
        return _Var(name.text, space, access, vtype, attrs, var_tok.line)

    def function(self, attrs: dict[str, tuple[_Expr, ...]]) -> _Function:
        fn_tok = self.expect("fn")
        name = self.ident("a function name").text
        self.expect("(")
        params: list[_Decl] = []
        while not self.accept(")"):
            params.append(self.decl("a parameter name"))
            if not self.accept(","):
                self.expect(")")
                break
        returns = None
        if self.accept("->"):
            self.attributes()
            returns = self.type()
        open_tok = self.expect("{")
        idents: set[str] = set()
        depth = 1
        while depth:
            tok = self.next()
            if tok.kind == "eof":
                raise self.error(f"unterminated body of function '{name}' (opened at line {open_tok.line})", tok)
            depth += (tok.text == "{") - (tok.text == "}")
            if tok.kind == "ident":
                idents.add(tok.text)
        return _Function(name, attrs, params, idents, fn_tok.line, returns)

    def skip_statement(self) -> list[_Token]:
        """Consume tokens up to and including the next ``;`` outside brackets; return them."""
        start, depth = self.pos, 0
        while True:
            tok = self.next()
            if tok.kind == "eof":
                raise self.error("expected ';' before end of file", tok)
            if tok.text in "([{":
                depth += 1
            elif tok.text in ")]}":
                depth -= 1
            elif tok.text == ";" and depth <= 0:
                return self.tokens[start:self.pos]

    # -- types and (integer) expressions
    def type(self) -> _TypeRef:
        name = self.ident("a type")
        args: list[_Expr] = []
        if self.accept("<"):
            while not self.accept(">"):
                args.append(self.expr())
                if not self.accept(","):
                    self.expect(">")
                    break
        return _TypeRef(name.text, tuple(args), name.line)

    def expr(self) -> _Expr:
        lhs = self.term()
        while self.peek().text in ("+", "-"):
            op = self.next().text
            lhs = _BinOp(op, lhs, self.term())
        return lhs

    def term(self) -> _Expr:
        lhs = self.unary()
        while self.peek().text in ("*", "/", "%"):
            op = self.next().text
            lhs = _BinOp(op, lhs, self.unary())
        return lhs

    def unary(self) -> _Expr:
        if self.accept("-"):
            return _BinOp("-", 0, self.unary())
        tok = self.peek()
        if tok.kind == "number":
            self.next()
            return _number(tok.text)
        if self.accept("("):
            inner = self.expr()
            self.expect(")")
            return inner
        callee = self.type()
        if not self.accept("("):
            return callee
        args: list[_Expr] = []
        while not self.accept(")"):
            args.append(self.expr())
            if not self.accept(","):
                self.expect(")")
                break
        return _Call(callee, tuple(args))


def _describe(tok: _Token) -> str:
    return "end of file" if tok.kind == "eof" else f"'{tok.text}'"


def _number(text: str) -> int | float:
    """The value of a WGSL numeric literal (suffixes ``i u f h`` dropped)."""
    lower = text.lower()
    if lower.startswith("0x"):
        if "." in lower or "p" in lower:
            # 'f' is a hex digit: a hex float takes a suffix only after its exponent.
            return float.fromhex(lower.rstrip("fh") if "p" in lower else lower)
        return int(lower.rstrip("iu"), 16)
    if lower.endswith(("f", "h")) or "." in lower or "e" in lower:
        return float(lower.rstrip("fh"))
    return int(lower.rstrip("iu"))


# ----------------------------------------------------------------------------------------------
# Memory layout

_SCALARS = {"f32": np.dtype("<f4"), "i32": np.dtype("<i4"), "u32": np.dtype("<u4"), "f16": np.dtype("<f2")}
_VEC_RE = re.compile(r"vec([234])$")
_MAT_RE = re.compile(r"mat([234])x([234])$")


def _predeclared_aliases() -> dict[str, _TypeRef]:
    """``vec3f``, ``vec4i``, ``mat4x4f``, ... as their full template forms."""
    aliases: dict[str, _TypeRef] = {}
    suffixes = {"f": "f32", "i": "i32", "u": "u32", "h": "f16"}
    for n in "234":
        for suffix, scalar in suffixes.items():
            aliases[f"vec{n}{suffix}"] = _TypeRef(f"vec{n}", (_TypeRef(scalar, (), 0),), 0)
        for r in "234":
            for suffix in "fh":
                aliases[f"mat{n}x{r}{suffix}"] = _TypeRef(f"mat{n}x{r}", (_TypeRef(suffixes[suffix], (), 0),), 0)
    return aliases


_PREDECLARED = _predeclared_aliases()


def _round_up(align: int, n: int) -> int:
    return -(-n // align) * align


@dataclass(frozen=True)
class _Leaf:
    """A scalar, vector or matrix: written through one strided numpy view (matrices column-major)."""

    text: str
    size: int
    align: int
    dtype: np.dtype
    shape: tuple[int, ...]
    strides: tuple[int, ...]


@dataclass(frozen=True)
class _Array:
    text: str
    elem: _Layout
    count: int | None  # None: runtime-sized
    stride: int

    @property
    def align(self) -> int:
        return self.elem.align

    @property
    def size(self) -> int:
        return self.stride * (self.count or 0)

    def numeric(self) -> tuple[np.dtype, tuple[int, ...], tuple[int, ...]] | None:
        """dtype, per-element shape and strides when the elements are all numbers (no structs)."""
        if isinstance(self.elem, _Leaf):
            return self.elem.dtype, self.elem.shape, self.elem.strides
        if isinstance(self.elem, _Array) and (inner := self.elem.numeric()) is not None:
            return inner[0], (self.elem.count, *inner[1]), (self.elem.stride, *inner[2])
        return None


@dataclass(frozen=True)
class FieldLayout:
    """One struct member: byte ``offset``, ``size`` and ``align`` (after ``@align``/``@size``)."""

    name: str
    type: str
    offset: int
    size: int
    align: int
    line: int = field(default=0, compare=False)


@dataclass(frozen=True)
class StructLayout:
    """Host-shareable layout of a WGSL struct, with a packer for its bytes.

    For a struct ending in a runtime-sized array, ``size`` is the size with an empty array.
    """

    name: str
    size: int
    align: int
    fields: tuple[FieldLayout, ...]
    _members: tuple[_Layout, ...] = field(repr=False, compare=False)

    @property
    def text(self) -> str:
        return self.name

    @property
    def has_runtime_array(self) -> bool:
        """True when the last member is a runtime-sized array (storage buffers only)."""
        last = self._members[-1]
        return isinstance(last, _Array) and last.count is None

    def field(self, name: str) -> FieldLayout:
        """The layout of member ``name`` (KeyError naming the struct when absent)."""
        for f in self.fields:
            if f.name == name:
                return f
        raise KeyError(f"struct {self.name} has no field '{name}'")

    def offset_of(self, name: str) -> int:
        """Byte offset of member ``name``."""
        return self.field(name).offset

    def shape_of(self, name: str) -> tuple[int, ...] | None:
        """The numpy shape :meth:`pack` expects for a scalar, vector or matrix member (None for others)."""
        for f, layout in zip(self.fields, self._members):
            if f.name == name:
                return layout.shape if isinstance(layout, _Leaf) else None
        raise KeyError(f"struct {self.name} has no field '{name}'")

    def pack(self, values: Mapping[str, Any]) -> bytes:
        """The struct's bytes, every member taken from ``values`` (padding is zero).

        Floats are written as float32 (f16 as float16), integers as int32/uint32 (little-endian).
        Vectors take shape ``(N,)``; matrices take the math-convention ``(rows, cols)`` numpy array and
        are written column by column with the column stride; arrays take a leading element axis (or a
        sequence of dicts for arrays of structs; a runtime-sized last array may have any length);
        nested structs take a dict. Missing or unknown members raise KeyError, wrong shapes
        ValueError, both naming the struct and the member.
        """
        size = self.size
        if self.has_runtime_array:
            last, value = self._members[-1], values.get(self.fields[-1].name, ())
            size = _round_up(self.align, self.fields[-1].offset + last.stride * len(value))
        buf = bytearray(size)
        self._write(buf, 0, values, self.name)
        return bytes(buf)

    def _write(self, buf: bytearray, base: int, values: Any, path: str) -> None:
        if not isinstance(values, Mapping):
            raise TypeError(f"{path}: expected a dict of struct {self.name} members, got {type(values).__name__}")
        names = {f.name for f in self.fields}
        for key in values:
            if key not in names:
                raise KeyError(f"{path}: struct {self.name} has no field '{key}'")
        for f, layout in zip(self.fields, self._members):
            if f.name not in values:
                raise KeyError(f"{path}: missing value for field '{f.name}' of struct {self.name}")
            _write(buf, base + f.offset, layout, values[f.name], f"{path}.{f.name}")


_Layout = _Leaf | _Array | StructLayout


def _write(buf: bytearray, offset: int, layout: _Layout, value: Any, path: str) -> None:
    """Write ``value`` for a member of ``layout`` at ``offset``; ``path`` names it in errors."""
    if isinstance(layout, StructLayout):
        layout._write(buf, offset, value, path)
        return
    if isinstance(layout, _Leaf):
        dtype, shape, strides = layout.dtype, layout.shape, layout.strides
    else:
        numeric = layout.numeric()
        count = layout.count if layout.count is not None else len(value)
        if numeric is None:  # array of structs: one dict per element
            items = list(value)
            if len(items) != count:
                raise ValueError(f"{path}: expected {count} elements ({layout.text}), got {len(items)}")
            for i, item in enumerate(items):
                _write(buf, offset + i * layout.stride, layout.elem, item, f"{path}[{i}]")
            return
        dtype, shape, strides = numeric[0], (count, *numeric[1]), (layout.stride, *numeric[2])
    arr = _checked_numbers(value, dtype, shape, path, layout.text)
    np.ndarray(shape, dtype, buffer=buf, offset=offset, strides=strides)[...] = arr


def _checked_numbers(value: Any, dtype: np.dtype, shape: tuple[int, ...], path: str, text: str) -> np.ndarray:
    arr = np.asarray(value)
    if arr.dtype.kind not in "biuf":
        raise TypeError(f"{path}: expected numbers for {text}, got {arr.dtype}")
    if arr.shape != shape:
        raise ValueError(f"{path}: expected shape {shape} for {text}, got {arr.shape}")
    if dtype.kind in "iu":
        if arr.dtype.kind == "f" and not np.array_equal(arr, np.trunc(arr)):
            raise ValueError(f"{path}: {text} holds integers, got non-integral values")
        info = np.iinfo(dtype)
        if arr.size and (arr.min() < info.min or arr.max() > info.max):
            raise ValueError(f"{path}: values out of range for {text} [{info.min}, {info.max}]")
    else:
        # float64 -> float32 must not silently turn a finite value into inf.
        with np.errstate(over="ignore"):
            converted = arr.astype(dtype)
        if np.any(np.isfinite(arr) & ~np.isfinite(converted)):
            raise ValueError(f"{path}: values out of {dtype.name} range for {text}")
    return arr


# ----------------------------------------------------------------------------------------------
# Reflection results

@dataclass(frozen=True)
class Binding:
    """A module-scope resource ``@group(g) @binding(b) var ...``.

    ``kind`` is "uniform", "storage" (read_write), "read-only-storage", "texture", "storage-texture",
    "sampler" or "comparison-sampler". Enum-like strings use WebGPU's spelling. ``stages`` holds the
    stages ("vertex", "fragment", "compute") whose entry points name the variable (directly or through
    called functions; a local that shadows it counts too, which only widens visibility).
    """

    group: int
    binding: int
    name: str
    kind: str
    type: str
    struct: str | None = None  # buffers: the struct type, or the element struct of an array
    min_binding_size: int = 0  # buffers: bytes (one element for a runtime-sized array)
    view_dimension: str | None = None  # textures: "1d", "2d", "2d-array", "cube", "cube-array", "3d"
    sample_type: str | None = None  # sampled textures: "float", "depth", "sint", "uint"
    multisampled: bool = False
    storage_format: str | None = None  # storage textures, e.g. "rgba8unorm"
    storage_access: str | None = None  # storage textures: "write-only", "read-only", "read-write"
    stages: frozenset[str] = frozenset()
    line: int = field(default=0, compare=False)


class VertexInput(NamedTuple):
    """One vertex attribute of a vertex entry point, its type in full form (``vec3<f32>``)."""

    location: int
    name: str
    type: str


@dataclass(frozen=True)
class EntryPoint:
    """A ``@vertex``, ``@fragment`` or ``@compute`` function and the resources it uses."""

    name: str
    stage: str
    vertex_inputs: tuple[VertexInput, ...] = ()
    bindings: tuple[tuple[int, int], ...] = ()  # (group, binding) pairs it uses, sorted
    line: int = field(default=0, compare=False)
    #: The user-defined (``@location``) values it takes in (fragment: the varyings it reads) and, for a vertex
    #: entry point, the ones it returns (the varyings it writes).
    location_inputs: tuple[VertexInput, ...] = ()
    location_outputs: tuple[VertexInput, ...] = ()


@dataclass(frozen=True)
class ShaderReflection:
    """What a WGSL module declares: host-shareable struct layouts, resources and entry points."""

    filename: str
    structs: dict[str, StructLayout]
    bindings: list[Binding]
    entry_points: dict[str, EntryPoint]

    def binding(self, name: str) -> Binding:
        """The resource variable called ``name``."""
        for b in self.bindings:
            if b.name == name:
                return b
        raise KeyError(f"{self.filename}: no resource variable '{name}'")

    def group(self, group: int) -> list[Binding]:
        """The bindings of bind group ``group``, sorted by binding number."""
        return [b for b in self.bindings if b.group == group]


_STAGES = ("vertex", "fragment", "compute")
_VIEW_DIMS = {"1d": "1d", "2d": "2d", "2d_array": "2d-array", "3d": "3d", "cube": "cube", "cube_array": "cube-array"}
_SAMPLE_TYPES = {"f32": "float", "i32": "sint", "u32": "uint"}
_TEXEL_ACCESS = {"write": "write-only", "read": "read-only", "read_write": "read-write"}
_TEXTURE_RE = re.compile(r"texture_(depth_)?(multisampled_)?(storage_)?(1d|2d|2d_array|3d|cube|cube_array)$")


class _Resolver:
    """Turns the parsed module into layouts and reflection records (names may be used before declared)."""

    def __init__(self, mod: _Module, filename: str) -> None:
        self.mod = mod
        self.filename = filename
        self.layouts: dict[str, StructLayout] = {}
        self.in_progress: set[str] = set()

    def error(self, line: int, what: str) -> WGSLReflectError:
        return WGSLReflectError(f"{self.filename}:{line}: {what}")

    def canonical(self, t: _TypeRef) -> _TypeRef:
        """Expand user and predeclared aliases (``vec3f`` -> ``vec3<f32>``)."""
        seen = set()
        while not t.args and (t.name in self.mod.aliases or t.name in _PREDECLARED):
            if t.name in seen:
                raise self.error(t.line, f"alias '{t.name}' refers to itself")
            seen.add(t.name)
            t = replace(self.mod.aliases.get(t.name) or _PREDECLARED[t.name], line=t.line)
        return t

    def integer(self, e: _Expr, line: int, what: str, seen: frozenset[str] = frozenset()) -> int:
        """Evaluate an integer constant expression (literals, ``const`` names, + - * / %)."""
        if isinstance(e, float):
            raise self.error(line, f"{what} must be an integer, got {e!r}")
        if isinstance(e, int):
            return e
        if isinstance(e, _BinOp):
            a = self.integer(e.lhs, line, what, seen)
            b = self.integer(e.rhs, line, what, seen)
            if e.op in "/%":
                if b == 0:
                    raise self.error(line, f"{what}: division by zero")
                # WGSL integer division truncates toward zero (Python's // floors).
                q = abs(a) // abs(b) * (1 if (a >= 0) == (b > 0) else -1)
                return q if e.op == "/" else a - b * q
            return {"+": a + b, "-": a - b, "*": a * b}[e.op]
        if isinstance(e, _Call) and e.callee.name in ("i32", "u32") and len(e.args) == 1:
            return self.integer(e.args[0], line, what, seen)
        if isinstance(e, _TypeRef) and not e.args and e.name in self.mod.consts and e.name not in seen:
            value = self.mod.consts[e.name]
            if value is None or isinstance(value, float):
                raise self.error(line, f"{what}: constant '{e.name}' is not an integer expression")
            return self.integer(value, line, what, seen | {e.name})
        name = e.name if isinstance(e, _TypeRef) else e.callee.name
        raise self.error(line, f"{what}: '{name}' is not a known integer constant")

    def text(self, e: _Expr) -> str:
        if isinstance(e, _TypeRef):
            t = self.canonical(e)
            if t.name == "array" and len(t.args) == 2:
                count = self.integer(t.args[1], t.line, "array element count")
                return f"array<{self.text(t.args[0])}, {count}>"
            return t.name + (f"<{', '.join(self.text(a) for a in t.args)}>" if t.args else "")
        return str(e)

    def layout(self, t: _TypeRef) -> _Layout:
        """AlignOf/SizeOf of a host-shareable type (WGSL spec, 'Memory Layout')."""
        t = self.canonical(t)
        name, args = t.name, t.args
        if name in _SCALARS and not args:
            dtype = _SCALARS[name]
            return _Leaf(name, dtype.itemsize, dtype.itemsize, dtype, (), ())
        if name == "atomic" and len(args) == 1:
            inner = self.layout(self._type_arg(t, 0))
            return _Leaf(f"atomic<{inner.text}>", inner.size, inner.align, inner.dtype, (), ())
        if (m := _VEC_RE.match(name)) and len(args) == 1:
            scalar = self.layout(self._type_arg(t, 0))
            if not isinstance(scalar, _Leaf) or scalar.shape or scalar.text not in _SCALARS:
                raise self.error(t.line, f"'{self.text(t)}' needs a scalar component type")
            n, s = int(m.group(1)), scalar.size
            return _Leaf(f"{name}<{scalar.text}>", n * s, (4 if n == 3 else n) * s, scalar.dtype, (n,), (s,))
        if (m := _MAT_RE.match(name)) and len(args) == 1:
            cols, rows = int(m.group(1)), int(m.group(2))
            column = self.layout(_TypeRef(f"vec{rows}", args, t.line))
            stride = _round_up(column.align, column.size)
            s = column.dtype.itemsize
            return _Leaf(f"{name}<{self.text(args[0])}>", cols * stride, column.align, column.dtype,
                         (rows, cols), (s, stride))
        if name == "array" and len(args) in (1, 2):
            elem = self.layout(self._type_arg(t, 0))
            if isinstance(elem, _Array) and elem.count is None or (
                isinstance(elem, StructLayout) and elem.has_runtime_array
            ):
                raise self.error(t.line, f"array element type '{elem.text}' is runtime-sized")
            count = self.integer(args[1], t.line, "array element count") if len(args) == 2 else None
            if count is not None and count <= 0:
                raise self.error(t.line, f"array element count must be positive, got {count}")
            return _Array(self.text(t), elem, count, _round_up(elem.align, elem.size))
        if name in self.mod.structs and not args:
            return self.struct(name)
        if name == "bool":
            raise _NotHostShareable(f"{self.filename}:{t.line}: bool is not host-shareable (use u32)")
        raise self.error(t.line, f"unknown or non-host-shareable type '{self.text(t)}'")

    def _type_arg(self, t: _TypeRef, i: int) -> _TypeRef:
        arg = t.args[i]
        if not isinstance(arg, _TypeRef):
            raise self.error(t.line, f"'{t.name}' expects a type as template argument {i + 1}, got {arg!r}")
        return arg

    def struct(self, name: str) -> StructLayout:
        if name in self.layouts:
            return self.layouts[name]
        if name in self.in_progress:
            raise self.error(self.mod.struct_lines[name], f"struct '{name}' contains itself")
        self.in_progress.add(name)
        members = self.mod.structs[name]
        fields, layouts = [], []
        offset, struct_align = 0, 1
        for i, m in enumerate(members):
            lay = self.layout(m.type)
            runtime = isinstance(lay, _Array) and lay.count is None
            nested_runtime = isinstance(lay, StructLayout) and lay.has_runtime_array
            if (runtime and i != len(members) - 1) or nested_runtime:
                raise self.error(m.line, f"runtime-sized member '{name}.{m.name}' must be the last member "
                                         "of a top-level struct")
            align, size = lay.align, lay.size
            if "align" in m.attrs:
                align = self._attr_int(m, "align")
                if align <= 0 or align & (align - 1) or align % lay.align:
                    raise self.error(m.line, f"@align({align}) on '{name}.{m.name}' must be a power of two "
                                             f"and a multiple of {lay.text}'s alignment {lay.align}")
            if "size" in m.attrs:
                size = self._attr_int(m, "size")
                if runtime or size < lay.size:
                    raise self.error(m.line, f"@size({size}) on '{name}.{m.name}' must be at least "
                                             f"{lay.text}'s size {lay.size}")
            offset = _round_up(align, offset)
            fields.append(FieldLayout(m.name, lay.text, offset, size, align, m.line))
            layouts.append(lay)
            offset += size
            struct_align = max(struct_align, align)
        self.in_progress.discard(name)
        layout = StructLayout(name, _round_up(struct_align, offset), struct_align, tuple(fields), tuple(layouts))
        self.layouts[name] = layout
        return layout

    def _attr_int(self, d: _Decl | _Var, attr: str) -> int:
        args = d.attrs[attr]
        if len(args) != 1:
            raise self.error(d.line, f"@{attr} on '{d.name}' takes one argument")
        return self.integer(args[0], d.line, f"@{attr} on '{d.name}'")

    def check_uniform(self, lay: _Layout, var: _Var) -> None:
        """The uniform address space's extra layout constraints (WGSL 'Address Space Layout Constraints')."""
        where = f"uniform buffer '{var.name}'"
        if isinstance(lay, _Array):
            if lay.count is None:
                raise self.error(var.line, f"{where}: runtime-sized arrays are not allowed in uniform buffers")
            if lay.stride % 16:
                raise self.error(var.line, f"{where}: '{lay.text}' has an element stride of {lay.stride} bytes; "
                                           "uniform arrays need a multiple of 16 (use vec4 elements)")
            self.check_uniform(lay.elem, var)
        elif isinstance(lay, StructLayout):
            for i, (f, member) in enumerate(zip(lay.fields, lay._members)):
                if isinstance(member, (_Array, StructLayout)) and f.offset % 16:
                    raise self.error(f.line, f"{where}: member '{lay.name}.{f.name}' ({f.type}) is at offset "
                                             f"{f.offset}; uniform buffers need a multiple of 16 (add @align(16))")
                if isinstance(member, StructLayout) and i + 1 < len(lay.fields):
                    nxt = lay.fields[i + 1]
                    if nxt.offset - f.offset < _round_up(16, member.size):
                        raise self.error(nxt.line, f"{where}: member '{lay.name}.{nxt.name}' follows struct member "
                                                   f"'{f.name}' too closely; uniform buffers need it at offset "
                                                   f"{f.offset + _round_up(16, member.size)} (add @align(16))")
                self.check_uniform(member, var)

    def binding(self, var: _Var) -> Binding:
        group, number = self._attr_int(var, "group"), self._attr_int(var, "binding")
        t = self.canonical(var.type)
        text = self.text(t)
        common = {"group": group, "binding": number, "name": var.name, "type": text, "line": var.line}
        if var.space in ("uniform", "storage"):
            lay = self.layout(t)
            if var.space == "uniform":
                self.check_uniform(lay, var)
                kind = "uniform"
            elif var.access in (None, "read"):
                kind = "read-only-storage"
            elif var.access == "read_write":
                kind = "storage"
            else:
                raise self.error(var.line, f"storage buffer '{var.name}' has unknown access mode '{var.access}'")
            elem = lay.elem if isinstance(lay, _Array) else lay
            if isinstance(lay, StructLayout) and lay.has_runtime_array:
                last = lay._members[-1]
                min_size = _round_up(lay.align, lay.fields[-1].offset + last.stride)
            else:
                min_size = lay.stride if isinstance(lay, _Array) and lay.count is None else lay.size
            struct = elem.name if isinstance(elem, StructLayout) else None
            return Binding(kind=kind, struct=struct, min_binding_size=min_size, **common)
        if var.space is not None:
            raise self.error(var.line, f"'{var.name}': address space '{var.space}' cannot hold a resource binding")
        if t.name in ("sampler", "sampler_comparison"):
            return Binding(kind="sampler" if t.name == "sampler" else "comparison-sampler", **common)
        m = _TEXTURE_RE.match(t.name)
        if m is None:
            raise self.error(var.line, f"'{var.name}': unsupported resource type '{text}'")
        depth, multisampled, storage, dim = m.groups()
        view = _VIEW_DIMS[dim]
        if storage:
            if depth or multisampled or len(t.args) != 2:
                raise self.error(var.line, f"'{var.name}': malformed storage texture type '{text}'")
            fmt, access = self.text(t.args[0]), self.text(t.args[1])
            if access not in _TEXEL_ACCESS:
                raise self.error(var.line, f"'{var.name}': unknown storage texture access '{access}'")
            return Binding(kind="storage-texture", view_dimension=view, storage_format=fmt,
                           storage_access=_TEXEL_ACCESS[access], **common)
        if depth:
            sample = "depth"
        elif len(t.args) == 1 and self.text(t.args[0]) in _SAMPLE_TYPES:
            sample = _SAMPLE_TYPES[self.text(t.args[0])]
        else:
            raise self.error(var.line, f"'{var.name}': texture type '{text}' needs f32, i32 or u32 texels")
        return Binding(kind="texture", view_dimension=view, sample_type=sample, multisampled=bool(multisampled),
                       **common)

    def reachable(self, fn: _Function) -> set[str]:
        """Identifiers named by ``fn`` and every function it calls, transitively."""
        names: set[str] = set()
        todo = [fn]
        visited = {fn.name}
        while todo:
            f = todo.pop()
            names |= f.body_idents
            for ident in f.body_idents:
                if ident in self.mod.functions and ident not in visited:
                    visited.add(ident)
                    todo.append(self.mod.functions[ident])
        return names

    def vertex_inputs(self, fn: _Function) -> tuple[VertexInput, ...]:
        inputs = self.located(fn.params)
        locations = [i.location for i in inputs]
        if len(set(locations)) != len(locations):
            raise self.error(fn.line, f"vertex entry point '{fn.name}' uses a @location twice")
        return inputs

    def located(self, decls: list[_Decl]) -> tuple[VertexInput, ...]:
        """The ``@location`` values among ``decls`` (parameters), looking into struct-typed ones, by location."""
        found: list[VertexInput] = []
        for p in decls:
            t = self.canonical(p.type)
            if "location" in p.attrs:
                found.append(VertexInput(self._attr_int(p, "location"), p.name, self.text(t)))
            elif t.name in self.mod.structs and not t.args:
                for m in self.mod.structs[t.name]:
                    if "location" in m.attrs:
                        found.append(VertexInput(self._attr_int(m, "location"), m.name, self.text(m.type)))
        return tuple(sorted(found))

    def outputs(self, fn: _Function) -> tuple[VertexInput, ...]:
        """A vertex entry point's ``@location`` outputs (members of its returned struct)."""
        if fn.returns is None:
            return ()
        return self.located([_Decl("return", fn.returns, {}, fn.line)])


class _NotHostShareable(WGSLReflectError):
    """A struct that only lives inside shader code (e.g. has a bool member): no memory layout."""


def reflect(source: str, filename: str = "<wgsl>") -> ShaderReflection:
    """Reflect a WGSL module: struct layouts, ``@group/@binding`` resources and entry points.

    ``filename`` only names the source in errors, which are ``WGSLReflectError("<file>:<line>: ...")``.
    Structs that are not host-shareable (a bool member) are left out of ``structs``.
    """
    mod = _Parser(_tokenize(source, filename), filename).module()
    res = _Resolver(mod, filename)
    structs: dict[str, StructLayout] = {}
    for name in mod.structs:
        try:
            structs[name] = res.struct(name)
        except _NotHostShareable:
            res.in_progress.clear()
    resources = [v for v in mod.vars if "group" in v.attrs or "binding" in v.attrs]
    for v in resources:
        if "group" not in v.attrs or "binding" not in v.attrs:
            raise res.error(v.line, f"resource '{v.name}' needs both @group and @binding")
    bindings = sorted((res.binding(v) for v in resources), key=lambda b: (b.group, b.binding, b.name))
    entry_points: dict[str, EntryPoint] = {}
    stages_of: dict[str, set[str]] = {b.name: set() for b in bindings}
    for fn in mod.functions.values():
        stages = [s for s in _STAGES if s in fn.attrs]
        if not stages:
            continue
        if len(stages) > 1:
            raise res.error(fn.line, f"function '{fn.name}' has more than one stage attribute")
        names = res.reachable(fn)
        used = tuple(sorted((b.group, b.binding) for b in bindings if b.name in names))
        for b in bindings:
            if b.name in names:
                stages_of[b.name].add(stages[0])
        inputs = res.vertex_inputs(fn) if stages[0] == "vertex" else ()
        located = res.located(fn.params) if stages[0] == "fragment" else inputs
        outputs = res.outputs(fn) if stages[0] == "vertex" else ()
        entry_points[fn.name] = EntryPoint(fn.name, stages[0], inputs, used, fn.line, located, outputs)
    bindings = [replace(b, stages=frozenset(stages_of[b.name])) for b in bindings]
    return ShaderReflection(filename, structs, bindings, entry_points)

