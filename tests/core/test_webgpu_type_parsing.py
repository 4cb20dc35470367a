"""cffi, told to declare only the typedefs a type string names (``gandalf_core.render.webgpu.type_parsing``), builds
the same C types as cffi declaring all of them, and builds them much faster."""

from __future__ import annotations

import time

import pytest

cffi = pytest.importorskip("cffi")
ffi_module = pytest.importorskip("wgpu.backends.wgpu_native._ffi")

from gandalf_core.render.webgpu.type_parsing import parse_only_mentioned_typedefs  # noqa: E402


@pytest.fixture(scope="module")
def two_parsers():
    """Two FFIs over wgpu-native's header: cffi's own parsing, and the engine's."""
    header = ffi_module.get_wgpu_header()
    plain, fast = cffi.FFI(), cffi.FFI()
    plain.cdef(header)
    fast.cdef(header)
    assert parse_only_mentioned_typedefs(fast)
    assert parse_only_mentioned_typedefs(fast)  # twice is once
    return plain, fast


def _type_strings(ffi) -> list[str]:
    """A spread of what wgpu-py asks for: every 10th typedef as a pointer, some as arrays, and harder shapes."""
    names = sorted(name[len("typedef "):] for name in ffi._parser._declarations if name.startswith("typedef "))
    sample = names[::10]
    return ([f"{name} *" for name in sample] + [f"{name}[]" for name in sample[::4]]
            + ["uint32_t *", "char[]", "const char *", "void *", "WGPUChainedStruct *", "WGPUFeatureName[4]",
               "WGPUBufferMapCallback", "WGPUStringView *", "int(*)(WGPUAdapter, void *)"])


def _described(ctype) -> tuple:
    """A type's C name and, where it points to or is a struct, its fields' names and C types (each FFI has its own
    struct objects, so they are compared by what they say)."""
    target = getattr(ctype, "totype", ctype)
    fields = tuple(zip(target.fldnames, (t.get_c_name() for t in target.fldtypes))) if getattr(
        target, "fldnames", None) else ()
    return ctype.get_c_name(), fields


def test_the_same_types_as_cffis_own_parsing(two_parsers):
    plain, fast = two_parsers
    strings = _type_strings(plain)
    assert len(strings) > 50
    described = [_described(fast._parser.parse_type(text)) for text in strings]
    assert described == [_described(plain._parser.parse_type(text)) for text in strings]
    assert sum(bool(fields) for _, fields in described) >= 10  # structs with fields were compared field by field
    # A name that is no type stays an error.
    with pytest.raises(cffi.CDefError):
        fast._parser.parse_type("WGPUNoSuchThing *")
    # The ctypes behave: a struct made through the fast parser has the fields wgpu-py fills.
    made = fast.new("WGPUTextureDescriptor *")
    made.mipLevelCount = 3
    assert made.mipLevelCount == 3 and fast.sizeof("WGPUTextureDescriptor") == plain.sizeof("WGPUTextureDescriptor")


def test_parsing_a_type_is_much_faster(two_parsers):
    plain, fast = two_parsers
    strings = [f"{name} *" for name in ("WGPUSamplerDescriptor", "WGPUBindGroupEntry", "WGPUColorTargetState")]

    def seconds(ffi) -> float:
        start = time.perf_counter()
        for text in strings:
            ffi._parser.parse_type(text)
        return time.perf_counter() - start

    # cffi parses ~440 typedef lines for each type; the fast parser one or two (measured: ~15 ms against ~2 ms).
    assert seconds(fast) < seconds(plain) / 2
