"""Tests for gandalf_core.render.wgsl_reflect: layouts with known answers, bindings, entry points, errors.

Layout answers come from the WGSL spec's 'Memory Layout' examples; the GPU tests check the packed bytes
and the uniform-buffer constraints against naga and the driver (skipped without a wgpu adapter).
"""

from __future__ import annotations

import random
import re
import time

import numpy as np
import pytest

from gandalf_core.render.wgsl_reflect import VertexInput, WGSLReflectError, reflect


def layout_of(struct_src: str, name: str):
    return reflect(struct_src).structs[name]


def fields(layout) -> list[tuple[str, int, int]]:
    return [(f.name, f.offset, f.size) for f in layout.fields]


# ---------------------------------------------------------------------------------------------
# Memory layout: answers from the WGSL spec

def test_vec3_then_f32_packs_into_16_bytes():
    a = layout_of("struct A { a: vec3<f32>, b: f32 }", "A")
    assert (a.size, a.align) == (16, 16)
    assert fields(a) == [("a", 0, 12), ("b", 12, 4)]


def test_f32_then_vec3_pads_to_the_vec3_alignment():
    b = layout_of("struct B { a: f32, b: vec3<f32> }", "B")
    assert b.offset_of("b") == 16
    assert (b.size, b.align) == (32, 16)


@pytest.mark.parametrize(
    ("wgsl_type", "size", "align"),
    [
        ("f32", 4, 4), ("i32", 4, 4), ("u32", 4, 4), ("f16", 2, 2), ("atomic<u32>", 4, 4),
        ("vec2<f32>", 8, 8), ("vec3<f32>", 12, 16), ("vec4<f32>", 16, 16), ("vec3<f16>", 6, 8),
        ("vec2i", 8, 8), ("vec3u", 12, 16), ("vec4f", 16, 16), ("vec4h", 8, 8),
        ("mat2x2<f32>", 16, 8), ("mat3x2<f32>", 24, 8), ("mat2x3<f32>", 32, 16),
        ("mat3x3<f32>", 48, 16), ("mat4x3f", 64, 16), ("mat4x4f", 64, 16), ("mat3x3h", 24, 8),
        ("array<f32, 4>", 16, 4), ("array<vec3<f32>, 2>", 32, 16), ("array<mat3x3f, 2>", 96, 16),
    ],
)
def test_scalar_vector_matrix_array_sizes(wgsl_type, size, align):
    f = layout_of(f"struct S {{ x: {wgsl_type} }}", "S").fields[0]
    assert (f.size, f.align) == (size, align)


def test_spec_example_without_attributes():
    src = """
    struct A { u: f32, v: f32, w: vec2<f32>, x: f32 }
    struct B { a: vec2<f32>, b: vec3<f32>, c: f32, d: f32, e: A, f: vec3<f32>, g: array<A, 3>, h: i32 }
    @group(0) @binding(0) var<storage, read_write> storage_buffer: B;
    """
    r = reflect(src)
    assert (r.structs["A"].size, r.structs["A"].align) == (24, 8)
    b = r.structs["B"]
    assert (b.size, b.align) == (160, 16)
    assert [f.offset for f in b.fields] == [0, 16, 28, 32, 40, 64, 80, 152]
    assert b.field("g").size == 72  # element stride 24
    assert r.binding("storage_buffer").min_binding_size == 160


def test_spec_example_with_align_and_size():
    src = """
    struct A { u: f32, v: f32, w: vec2<f32>, @size(16) x: f32 }
    struct B { a: vec2<f32>, b: vec3<f32>, c: f32, d: f32, @align(16) e: A, f: vec3<f32>,
               g: array<A, 3>, h: i32 }
    @group(0) @binding(0) var<uniform> uniform_buffer: B;
    """
    r = reflect(src)
    assert (r.structs["A"].size, r.structs["A"].align) == (32, 8)
    b = r.structs["B"]
    assert (b.size, b.align) == (208, 16)
    assert [f.offset for f in b.fields] == [0, 16, 28, 32, 48, 80, 96, 192]
    assert (b.field("e").align, b.field("g").size) == (16, 96)


def test_nested_struct_alignment_and_size_rounding():
    src = """
    struct Inner { v: vec2<f32>, s: f32 }              // align 8, size 16 (12 rounded to 8)
    struct Outer { a: f32, inner: Inner, b: f32, c: array<Inner, 2> }
    """
    r = reflect(src)
    assert (r.structs["Inner"].size, r.structs["Inner"].align) == (16, 8)
    assert fields(r.structs["Outer"]) == [("a", 0, 4), ("inner", 8, 16), ("b", 24, 4), ("c", 32, 32)]
    assert r.structs["Outer"].size == 64


def test_uniform_array_of_f32_is_rejected_with_a_clear_error():
    # WGSL does not pad uniform arrays: a 4-byte stride is invalid there (naga rejects it too).
    src = "struct U { a: array<f32, 4> }\n@group(0) @binding(0) var<uniform> u: U;"
    with pytest.raises(WGSLReflectError, match=r"^<wgsl>:2: .*stride of 4 bytes.*multiple of 16"):
        reflect(src)


def test_storage_array_of_f32_has_stride_4():
    r = reflect("struct S { a: array<f32, 4> }\n@group(0) @binding(0) var<storage> s: S;")
    assert r.structs["S"].field("a").size == 16
    assert r.binding("s").min_binding_size == 16


def test_uniform_nested_struct_needs_16_byte_alignment():
    bad = "struct I { x: f32 }\nstruct U { a: f32,\n b: I }\n@group(0) @binding(0) var<uniform> u: U;"
    with pytest.raises(WGSLReflectError, match=r"^<wgsl>:3: .*'U\.b'.*offset 4.*@align\(16\)"):
        reflect(bad)
    too_close = "struct I { x: f32 }\nstruct U { @align(16) b: I,\n c: f32 }\n@group(0) @binding(0) var<uniform> u: U;"
    with pytest.raises(WGSLReflectError, match=r"^<wgsl>:3: .*'U\.c'.*offset 16"):
        reflect(too_close)
    good = "struct I { x: f32 }\nstruct U { a: f32, @align(16) b: I, @align(16) c: f32 }\n" \
           "@group(0) @binding(0) var<uniform> u: U;"
    assert fields(reflect(good).structs["U"]) == [("a", 0, 4), ("b", 16, 4), ("c", 32, 4)]


def test_runtime_sized_array_struct():
    src = """
    struct P { pos: vec3<f32>, mass: f32 }
    struct Particles { count: u32, items: array<P> }
    @group(0) @binding(0) var<storage, read_write> particles: Particles;
    @group(0) @binding(1) var<storage, read> weights: array<f32>;
    """
    r = reflect(src)
    layout = r.structs["Particles"]
    assert layout.has_runtime_array
    assert (layout.offset_of("items"), layout.size) == (16, 16)
    assert r.binding("particles").min_binding_size == 32  # fixed part + one element
    assert r.binding("particles").struct == "Particles"
    assert r.binding("weights").min_binding_size == 4
    data = layout.pack({"count": 3, "items": [{"pos": (i, i, i), "mass": 10 + i} for i in range(3)]})
    assert len(data) == 16 + 3 * 16
    assert np.frombuffer(data, "<u4")[0] == 3
    assert np.frombuffer(data, "<f4")[4:].reshape(3, 4)[:, 3].tolist() == [10, 11, 12]


def test_const_sized_arrays_and_aliases():
    src = """
    struct U { a: array<vec4<f32>, N>, b: array<vec4f, M>, c: array<Color, K>, d: array<vec4f, 0x3u> }
    const N: u32 = 16u;
    const M = 4;
    const K = N / 2 - M * (1 + 0) ;
    const NOT_INT = vec3<f32>(1.0, 2.0, 3.0);
    alias Color = vec4<f32>;
    """
    u = reflect(src).structs["U"]
    assert [(f.type, f.size) for f in u.fields] == [
        ("array<vec4<f32>, 16>", 256), ("array<vec4<f32>, 4>", 64), ("array<vec4<f32>, 4>", 64),
        ("array<vec4<f32>, 3>", 48),
    ]


def test_non_host_shareable_structs_are_left_out_unless_bound():
    src = "struct Hit { hit: bool, t: f32 }\nstruct U { t: f32 }"
    assert set(reflect(src).structs) == {"U"}
    with pytest.raises(WGSLReflectError, match=r"^<wgsl>:1: bool is not host-shareable"):
        reflect(src + "\n@group(0) @binding(0) var<uniform> u: Hit;")


# ---------------------------------------------------------------------------------------------
# pack()

PACK_SRC = """
struct Light { dir: vec3<f32>, power: f32 }
struct U {
    model: mat4x4<f32>,
    normal: mat3x3<f32>,
    color: vec3<f32>,
    time: f32,
    count: u32,
    offset: i32,
    lights: array<Light, 2>,
    weights: array<vec4<f32>, 2>,
}
"""


def pack_values(rng: np.random.Generator) -> dict:
    return {
        "model": rng.normal(size=(4, 4)),
        "normal": rng.normal(size=(3, 3)),
        "color": rng.normal(size=3),
        "time": 2.5,
        "count": 7,
        "offset": -3,
        "lights": [{"dir": rng.normal(size=3), "power": 1.5}, {"dir": rng.normal(size=3), "power": 3.0}],
        "weights": rng.normal(size=(2, 4)),
    }


def test_pack_writes_values_at_their_offsets():
    layout = reflect(PACK_SRC).structs["U"]
    v = pack_values(np.random.default_rng(1))
    data = layout.pack(v)
    assert len(data) == layout.size == 208
    f = np.frombuffer(data, "<f4")
    # Matrices column by column: column c starts at offset + c * column stride.
    np.testing.assert_array_equal(f[0:16].reshape(4, 4).T, v["model"].astype(np.float32))
    normal = f[16:28].reshape(3, 4)  # 3 columns of vec3 padded to 16 bytes
    np.testing.assert_array_equal(normal[:, :3].T, v["normal"].astype(np.float32))
    assert normal[:, 3].tolist() == [0, 0, 0]  # padding stays zero
    np.testing.assert_array_equal(f[28:31], v["color"].astype(np.float32))
    assert f[layout.offset_of("time") // 4] == 2.5
    assert np.frombuffer(data, "<u4")[layout.offset_of("count") // 4] == 7
    assert np.frombuffer(data, "<i4")[layout.offset_of("offset") // 4] == -3
    lights = layout.offset_of("lights") // 4
    np.testing.assert_array_equal(f[lights + 4:lights + 7], v["lights"][1]["dir"].astype(np.float32))
    assert f[lights + 7] == 3.0
    w = layout.offset_of("weights") // 4
    np.testing.assert_array_equal(f[w:w + 8], v["weights"].astype(np.float32).ravel())


def test_pack_errors_name_struct_field_and_shape():
    layout = reflect(PACK_SRC).structs["U"]
    v = pack_values(np.random.default_rng(2))
    with pytest.raises(KeyError, match=r"'time' of struct U"):
        layout.pack({k: x for k, x in v.items() if k != "time"})
    with pytest.raises(KeyError, match=r"struct U has no field 'tme'"):
        layout.pack({**v, "tme": 1.0})
    with pytest.raises(ValueError, match=r"U\.normal: expected shape \(3, 3\)"):
        layout.pack({**v, "normal": np.eye(4)})
    with pytest.raises(ValueError, match=r"U\.lights\[1\]\.dir: expected shape \(3,\)"):
        layout.pack({**v, "lights": [v["lights"][0], {"dir": (1.0, 2.0), "power": 1.0}]})
    with pytest.raises(ValueError, match=r"U\.lights: expected 2 elements"):
        layout.pack({**v, "lights": v["lights"][:1]})
    with pytest.raises(ValueError, match=r"U\.count: .*out of range"):
        layout.pack({**v, "count": -1})
    with pytest.raises(ValueError, match=r"U\.offset: .*non-integral"):
        layout.pack({**v, "offset": 1.5})
    with pytest.raises(ValueError, match=r"U\.time: .*float32 range"):
        layout.pack({**v, "time": 1e300})
    with pytest.raises(KeyError, match=r"struct U has no field 'nope'"):
        layout.offset_of("nope")


# ---------------------------------------------------------------------------------------------
# Bindings and entry points

BINDINGS_SRC = """
struct Camera { view_proj: mat4x4<f32> }
struct Item { color: vec4<f32> }
@group(0) @binding(0) var<uniform> camera: Camera;
@binding(1) @group(0) var<storage, read> items: array<Item>;
@ group ( 0 ) @ binding ( 2 ) var<storage, read_write> counters: array<atomic<u32>, 4>;
@group(1) @binding(0) var albedo: texture_2d<f32>;
@group(1) @binding(1) var albedo_sampler: sampler;
@group(1) @binding(2) var sky: texture_cube<f32>;
@group(1) @binding(3) var shadow: texture_depth_2d;
@group(1) @binding(4) var shadow_sampler: sampler_comparison;
@group(1) @binding(5) var layers: texture_2d_array<f32>;
@group(1) @binding(6) var ids: texture_2d<u32>;
@group(1) @binding(7) var volume: texture_3d<i32>;
@group(1) @binding(8) var msaa: texture_multisampled_2d<f32>;
@group(1) @binding(9) var shadows: texture_depth_2d_array;
@group(2) @binding(0) var out_image: texture_storage_2d<rgba8unorm, write>;
@group(2) @binding(1) var in_image: texture_storage_2d<r32float, read>;
var<private> scratch: vec4<f32>;
var<workgroup> tile: array<f32, 64>;
"""


def test_binding_extraction():
    r = reflect(BINDINGS_SRC)
    got = {(b.group, b.binding): b for b in r.bindings}
    assert [(b.group, b.binding) for b in r.bindings] == sorted(got)
    assert len(got) == 15  # private/workgroup variables are not resources
    camera = got[0, 0]
    assert (camera.name, camera.kind, camera.struct, camera.min_binding_size) == ("camera", "uniform", "Camera", 64)
    assert (got[0, 1].kind, got[0, 1].struct, got[0, 1].type) == ("read-only-storage", "Item", "array<Item>")
    assert (got[0, 2].kind, got[0, 2].min_binding_size) == ("storage", 16)
    expect = {
        (1, 0): ("texture", "2d", "float", False),
        (1, 2): ("texture", "cube", "float", False),
        (1, 3): ("texture", "2d", "depth", False),
        (1, 5): ("texture", "2d-array", "float", False),
        (1, 6): ("texture", "2d", "uint", False),
        (1, 7): ("texture", "3d", "sint", False),
        (1, 8): ("texture", "2d", "float", True),
        (1, 9): ("texture", "2d-array", "depth", False),
    }
    for key, (kind, dim, sample, ms) in expect.items():
        b = got[key]
        assert (b.kind, b.view_dimension, b.sample_type, b.multisampled) == (kind, dim, sample, ms), b
    assert got[1, 1].kind == "sampler"
    assert got[1, 4].kind == "comparison-sampler"
    out_image, in_image = got[2, 0], got[2, 1]
    assert (out_image.kind, out_image.view_dimension, out_image.storage_format, out_image.storage_access) == (
        "storage-texture", "2d", "rgba8unorm", "write-only")
    assert (in_image.storage_format, in_image.storage_access) == ("r32float", "read-only")
    assert [b.name for b in r.group(1)][:2] == ["albedo", "albedo_sampler"]


ENTRY_SRC = """
struct Globals { mvp: mat4x4<f32> }
@group(0) @binding(0) var<uniform> globals: Globals;
@group(0) @binding(1) var tex: texture_2d<f32>;
@group(0) @binding(2) var samp: sampler;
@group(0) @binding(3) var<storage, read_write> data: array<f32>;

struct VertexIn {
    @location(2) uv: vec2f,
    @builtin(instance_index) instance: u32,
    @location(0) position: vec3<f32>,
}
struct VertexOut { @builtin(position) clip: vec4f, @location(0) uv: vec2f }

fn transform(p: vec3f) -> vec4f { return globals.mvp * vec4f(p, 1.0); }
fn shade(uv: vec2f) -> vec4f { if (uv.x > 0.5) { return textureSample(tex, samp, uv); } return vec4f(1.0); }

@vertex
fn vs_main(v: VertexIn, @location(1) normal: vec3<f32>, @builtin(vertex_index) vi: u32) -> VertexOut {
    var out: VertexOut;
    out.clip = transform(v.position);
    out.uv = v.uv;
    return out;
}

@fragment fn fs_main(in: VertexOut) -> @location(0) vec4<f32> { return shade(in.uv); }

@compute @workgroup_size(64, 1, 1)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) { data[id.x] = data[id.x] * 2.0; }
"""


def test_entry_points_vertex_inputs_and_stages():
    r = reflect(ENTRY_SRC)
    assert {n: e.stage for n, e in r.entry_points.items()} == {
        "vs_main": "vertex", "fs_main": "fragment", "cs_main": "compute"}
    vs = r.entry_points["vs_main"]
    assert vs.vertex_inputs == (
        VertexInput(0, "position", "vec3<f32>"), VertexInput(1, "normal", "vec3<f32>"),
        VertexInput(2, "uv", "vec2<f32>"))
    assert [tuple(i) for i in vs.vertex_inputs][0] == (0, "position", "vec3<f32>")
    assert r.entry_points["fs_main"].vertex_inputs == ()
    # Resources are found through called helper functions.
    assert vs.bindings == ((0, 0),)
    assert r.entry_points["fs_main"].bindings == ((0, 1), (0, 2))
    assert r.entry_points["cs_main"].bindings == ((0, 3),)
    assert {b.name: b.stages for b in r.bindings} == {
        "globals": {"vertex"}, "tex": {"fragment"}, "samp": {"fragment"}, "data": {"compute"}}


def mangle(source: str, seed: int) -> str:
    """The same tokens with comments, newlines and odd spacing between every pair."""
    strip = re.sub(r"//[^\n]*", "", source)
    tokens = re.findall(r"\d+\.\d*(?:[eE][+-]?\d+)?[fh]?|\w+|->|\S", strip)
    seps = [" ", "\n", "\t \n\n  ", "/* a /* nested */ comment */", "// line comment\n", " /**/ ", "\r\n"]
    rng = random.Random(seed)
    return "/* header */\n" + "".join(t + rng.choice(seps) for t in tokens) + "// end"


@pytest.mark.parametrize("source", [PACK_SRC, BINDINGS_SRC, ENTRY_SRC])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_formatting_does_not_change_the_reflection(source, seed):
    mangled = mangle(source, seed)
    assert mangled.count("\n") > source.count("\n")
    assert reflect(mangled) == reflect(source)


def test_compact_source_equals_spaced_source():
    compact = "struct S{a:vec3f,@align(16)b:f32,}@group(0)@binding(0)var<uniform>s:S;" \
              "@vertex fn v(@location(0)p:vec4f)->@builtin(position)vec4f{return p;}"
    spaced = """
        struct S {
            a : vec3f ,
            @align( 16 )
            b : f32
        }
        @group( 0 )
        @binding( 0 )
        var < uniform > s : S ;
        @vertex
        fn v ( @location ( 0 ) p : vec4f ) -> @builtin ( position ) vec4f { return p ; }
    """
    assert reflect(compact) == reflect(spaced)
    assert reflect(compact).structs["S"].offset_of("b") == 16


# ---------------------------------------------------------------------------------------------
# Errors: file and line

@pytest.mark.parametrize(
    ("source", "line", "what"),
    [
        ("struct S {\n  a: f32,\n  b f32\n}", 3, "expected ':', found 'f32'"),
        ("struct S { a: f32 }\n/* never\n closed", 2, "unterminated block comment"),
        ("\n\nfn f() {\n  if (true) {\n}", 5, "unterminated body of function 'f'"),
        ("struct S { a: f32 }\n\nstruct S { b: f32 }", 3, "struct 'S' is declared twice"),
        ("struct S {\n a: vec3<f32>,\n b: flaot }", 3, "unknown or non-host-shareable type 'flaot'"),
        ("const N = 2.5;\nstruct S {\n a: array<f32, N> }", 3, "array element count: constant 'N'"),
        ("struct S { a: array<f32, M> }", 1, "'M' is not a known integer constant"),
        ("struct U { x: f32 }\n@group(0) var<uniform> u: U;", 2, "needs both @group and @binding"),
        ("let x = 1;", 1, "unexpected 'let' at module scope"),
        ("struct S { a: f32 }\n$", 2, "unexpected character '$'"),
        ("struct S {\n @align(3) a: f32 }", 2, "@align(3)"),
        ("struct S {\n @size(2) a: f32 }", 2, "@size(2)"),
        ("struct S {\n a: array<f32>,\n b: f32 }", 2, "runtime-sized member 'S.a'"),
        ("struct S {\n a: S }", 1, "struct 'S' contains itself"),
        ("@group(0) @binding(0)\nvar<uniform> t: texture_2d<f32>;", 2, "unknown or non-host-shareable type"),
    ],
)
def test_errors_name_file_and_line(source, line, what):
    with pytest.raises(WGSLReflectError) as info:
        reflect(source, "shaders/broken.wgsl")
    message = str(info.value)
    assert message.startswith(f"shaders/broken.wgsl:{line}: "), message
    assert what in message
    assert isinstance(info.value, ValueError)


# ---------------------------------------------------------------------------------------------
# Against the real GPU: naga's validator and the driver's view of the packed bytes

def gpu_device():
    wgpu = pytest.importorskip("wgpu")
    for attempt in range(3):  # the Vulkan ICD may still be being installed on a fresh machine
        adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
        if adapter is not None:
            return wgpu, adapter.request_device_sync()
        if attempt < 2:
            time.sleep(30)
    pytest.skip("no wgpu adapter")


GPU_STRUCTS = """
struct Inner { dir: vec3<f32>, id: u32 }
struct Params {
    color: vec3<f32>,
    alpha: f32,
    normal: mat3x3<f32>,
    rot: mat2x2<f32>,
    skew: mat3x2<f32>,
    level: i32,
    model: mat4x4<f32>,
    weights: array<vec4<f32>, 3>,
    inner: Inner,
    uv: vec2<f32>,
    @align(16) scale: f32,
    lights: array<Inner, 2>,
    @size(20) padded: f32,
    tail: vec3<f32>,
}
struct Particle { pos: vec3<f32>, mass: f32, tags: array<f32, 3> }
struct Particles { count: u32, items: array<Particle> }
"""


def gpu_reads(values: dict, particles: dict) -> list[tuple[str, float]]:
    """(WGSL expression, expected value) for every scalar the compute shader copies."""
    reads = [(f"u.color[{i}]", values["color"][i]) for i in range(3)]
    reads.append(("u.alpha", values["alpha"]))
    for name, (rows, cols) in (("normal", (3, 3)), ("rot", (2, 2)), ("skew", (2, 3)), ("model", (4, 4))):
        reads += [(f"u.{name}[{c}][{r}]", values[name][r, c]) for c in range(cols) for r in range(rows)]
    reads.append(("f32(u.level)", values["level"]))
    reads += [(f"u.weights[{i}][{j}]", values["weights"][i, j]) for i in range(3) for j in range(4)]
    reads += [(f"u.inner.dir[{i}]", values["inner"]["dir"][i]) for i in range(3)]
    reads.append(("f32(u.inner.id)", values["inner"]["id"]))
    reads += [(f"u.uv[{i}]", values["uv"][i]) for i in range(2)] + [("u.scale", values["scale"])]
    for k in range(2):
        reads += [(f"u.lights[{k}].dir[{i}]", values["lights"][k]["dir"][i]) for i in range(3)]
        reads.append((f"f32(u.lights[{k}].id)", values["lights"][k]["id"]))
    reads.append(("u.padded", values["padded"]))
    reads += [(f"u.tail[{i}]", values["tail"][i]) for i in range(3)]
    reads.append(("f32(p.count)", particles["count"]))
    for k, item in enumerate(particles["items"]):
        reads += [(f"p.items[{k}].pos[{i}]", item["pos"][i]) for i in range(3)]
        reads.append((f"p.items[{k}].mass", item["mass"]))
        reads += [(f"p.items[{k}].tags[{i}]", item["tags"][i]) for i in range(3)]
    return reads


def test_gpu_sees_exactly_the_packed_values():
    wgpu, device = gpu_device()
    rng = np.random.default_rng(7)
    values = {
        "color": rng.normal(size=3), "alpha": 0.25, "normal": rng.normal(size=(3, 3)),
        "rot": rng.normal(size=(2, 2)), "skew": rng.normal(size=(2, 3)), "level": -5,
        "model": rng.normal(size=(4, 4)), "weights": rng.normal(size=(3, 4)),
        "inner": {"dir": rng.normal(size=3), "id": 11}, "uv": rng.normal(size=2), "scale": 4.5,
        "lights": [{"dir": rng.normal(size=3), "id": 21}, {"dir": rng.normal(size=3), "id": 22}],
        "padded": -1.75, "tail": rng.normal(size=3),
    }
    particles = {"count": 3, "items": [
        {"pos": rng.normal(size=3), "mass": float(k + 1), "tags": rng.normal(size=3)} for k in range(3)]}
    reads = gpu_reads(values, particles)
    body = "\n".join(f"    out[{i}] = {expr};" for i, (expr, _) in enumerate(reads))
    source = GPU_STRUCTS + f"""
@group(0) @binding(0) var<uniform> u: Params;
@group(0) @binding(1) var<storage, read> p: Particles;
@group(0) @binding(2) var<storage, read_write> out: array<f32>;
@compute @workgroup_size(1)
fn main() {{
{body}
}}
"""
    refl = reflect(source, "gpu_test.wgsl")
    params, parts = refl.structs["Params"], refl.structs["Particles"]
    assert params.offset_of("tail") == 336  # after @size(20) padded at 304
    assert params.size == 352
    uniform = device.create_buffer_with_data(data=params.pack(values), usage=wgpu.BufferUsage.UNIFORM)
    storage = device.create_buffer_with_data(data=parts.pack(particles), usage=wgpu.BufferUsage.STORAGE)
    out = device.create_buffer(size=4 * len(reads), usage=wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.COPY_SRC)
    pipeline = device.create_compute_pipeline(
        layout="auto", compute={"module": device.create_shader_module(code=source), "entry_point": "main"})
    bind_group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=[
        {"binding": 0, "resource": {"buffer": uniform}},
        {"binding": 1, "resource": {"buffer": storage}},
        {"binding": 2, "resource": {"buffer": out}},
    ])
    encoder = device.create_command_encoder()
    compute = encoder.begin_compute_pass()
    compute.set_pipeline(pipeline)
    compute.set_bind_group(0, bind_group)
    compute.dispatch_workgroups(1)
    compute.end()
    device.queue.submit([encoder.finish()])
    seen = np.frombuffer(device.queue.read_buffer(out), "<f4")
    expected = np.array([v for _, v in reads], np.float32)
    # Exact: the GPU copies float32 bit patterns; small integers convert exactly.
    mismatched = [reads[i][0] for i in np.flatnonzero(seen != expected)]
    assert not mismatched, f"GPU read other values for {mismatched}"


@pytest.mark.parametrize(
    "struct_src",
    [
        "struct I { x: f32 } struct U { a: f32, b: I }",
        "struct I { x: f32 } struct U { @align(16) b: I, c: f32 }",
        "struct U { a: array<f32, 4> }",
        "struct U { a: f32, b: array<vec4<f32>, 2> }",
        "struct I { x: f32 } struct U { a: f32, @align(16) b: I, @align(16) c: f32 }",
        "struct U { a: vec3<f32>, b: f32, c: array<vec4<f32>, 2>, d: mat3x3<f32> }",
        "struct I { v: vec3<f32> } struct U { a: f32, b: I, c: f32 }",
    ],
)
def test_uniform_constraints_agree_with_naga(struct_src):
    wgpu, device = gpu_device()
    source = struct_src + "\n@group(0) @binding(0) var<uniform> u: U;\n" \
                          "@compute @workgroup_size(1) fn main() { _ = u; }"
    try:
        reflect(source)
        ours_ok = True
    except WGSLReflectError:
        ours_ok = False
    try:
        device.create_shader_module(code=source)
        naga_ok = True
    except Exception:  # noqa: BLE001 - wgpu reports shader validation errors with its own types
        naga_ok = False
    assert ours_ok == naga_ok
