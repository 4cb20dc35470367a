"""The uniform-block layout helper (``gandalf_core.resources.layout``): std140 and WGSL offsets against hand-computed
ones, packing by field name, and the errors that name the block and the field.

The engine's blocks (Frame, Lights, Material) are checked against both APIs' own view of them in
``test_material_blocks.py``.
"""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core.resources.layout import BlockLayout, LayoutError, Struct, parse_type

LIGHT = Struct("Light", [("position", "vec3"), ("range", "float"), ("color", "vec4")])


def offsets(layout: BlockLayout) -> dict[str, int]:
    return {f.name: f.offset for f in layout.fields}


@pytest.mark.parametrize("rules", ["std140", "wgsl", "both"])
def test_vec3_followed_by_a_float_shares_its_16_bytes(rules):
    layout = BlockLayout("B", [("a", "vec3"), ("b", "float"), ("c", "vec2"), ("d", "vec3")], rules=rules)
    assert offsets(layout) == {"a": 0, "b": 12, "c": 16, "d": 32}
    assert layout.size == 48


@pytest.mark.parametrize("rules", ["std140", "wgsl", "both"])
def test_array_of_vec3_has_a_16_byte_stride(rules):
    layout = BlockLayout("B", [("x", "f32"), ("arr", ("vec3<f32>", 3)), ("y", "f32")], rules=rules)
    assert offsets(layout) == {"x": 0, "arr": 16, "y": 64}
    assert layout.field("arr").stride == 16 and layout.field("arr").size == 48
    assert layout.offset("arr[2]") == 48
    assert layout.size == 80


@pytest.mark.parametrize("rules", ["std140", "wgsl", "both"])
def test_mat3_is_three_padded_columns(rules):
    layout = BlockLayout("B", [("f", "float"), ("m", "mat3"), ("v", "vec2")], rules=rules)
    assert offsets(layout) == {"f": 0, "m": 16, "v": 64}
    assert layout.field("m").size == 48 and layout.size == 80
    m = np.arange(9.0).reshape(3, 3)  # maths convention: m[row, column]
    data = np.frombuffer(layout.pack({"f": 1.0, "m": m, "v": (7, 8)}), dtype=np.float32)
    columns = data[4:16].reshape(3, 4)
    np.testing.assert_array_equal(columns[:, :3], m.T)  # column j holds m[:, j]
    np.testing.assert_array_equal(columns[:, 3], 0.0)  # the padding stays zero
    # 9 floats row-major, as materials give matrices, are the same matrix
    assert layout.pack({"f": 1.0, "m": m.ravel(), "v": (7, 8)}) == layout.pack({"f": 1.0, "m": m, "v": (7, 8)})


@pytest.mark.parametrize("rules", ["std140", "wgsl", "both"])
def test_nested_structs_and_arrays_of_structs(rules):
    layout = BlockLayout("Lights", [("count", "u32"), ("lights", ("Light", 8)), ("ambient", "vec3"), ("k", "i32")],
                         rules=rules, structs={"Light": LIGHT})
    assert offsets(layout) == {"count": 0, "lights": 16, "ambient": 272, "k": 284}
    assert layout.field("lights").stride == 32 and layout.size == 288
    assert layout.offset("lights[3].color") == 16 + 3 * 32 + 16
    assert layout.offset("lights[1].range") == 16 + 32 + 12
    lights = [{"position": (i, 0, 0), "range": 10 + i, "color": (1, 0.5, 0.25, 1)} for i in range(8)]
    data = layout.pack({"count": 3, "lights": lights, "ambient": (0.1, 0.2, 0.3), "k": -2})
    assert np.frombuffer(data, np.uint32, 1)[0] == 3
    assert np.frombuffer(data, np.float32, 1, layout.offset("lights[5].range"))[0] == 15
    assert np.frombuffer(data, np.int32, 1, 284)[0] == -2


def test_a_struct_member_is_padded_to_16_in_std140_and_rejected_unpadded_in_wgsl():
    small = Struct("S", [("a", "float")])
    fields = [("x", "float"), ("s", small), ("y", "float")]
    assert offsets(BlockLayout("B", fields, rules="std140")) == {"x": 0, "s": 16, "y": 32}
    with pytest.raises(LayoutError, match=r"block 'B' field 's'.*multiple of 16"):
        BlockLayout("B", fields, rules="wgsl")
    padded = [("x", "vec4"), ("s", small), ("y", "float")]
    with pytest.raises(LayoutError, match=r"block 'B' field 'y'.*after the struct"):
        BlockLayout("B", padded, rules="wgsl")


def test_rules_that_disagree_are_an_error_naming_the_field():
    fields = [("x", "float"), ("v", "vec2"), ("m", "mat2")]
    assert offsets(BlockLayout("B", fields, rules="wgsl")) == {"x": 0, "v": 8, "m": 16}
    assert BlockLayout("B", fields, rules="wgsl").size == 32
    assert BlockLayout("B", fields, rules="std140").size == 48
    with pytest.raises(LayoutError, match=r"block 'B' field 'm': std140 puts it at offset 16 \(size 32.*mat2"):
        BlockLayout("B", fields)
    with pytest.raises(LayoutError, match=r"block 'B' field 'f'.*stride.*multiple of 16"):
        BlockLayout("B", [("f", ("float", 4))])
    assert BlockLayout("B", [("f", ("float", 4))], rules="std140").field("f").stride == 16


def test_scalar_array_std140_packs_with_a_16_byte_stride():
    layout = BlockLayout("B", [("f", ("float", 3)), ("g", "int")], rules="std140")
    data = np.frombuffer(layout.pack({"f": (1, 2, 3), "g": 4}), np.float32)
    np.testing.assert_array_equal(data[[0, 4, 8]], (1, 2, 3))
    assert layout.offset("g") == 48


def test_pack_by_name_vec3_then_float():
    layout = BlockLayout("Material", [("color", "vec4"), ("tint", "vec3"), ("shininess", "float"),
                                      ("_pad", "vec4", 0.0), ("level", "u32", 1)])
    data = layout.pack({"color": (1, 0.5, 0.25, 1), "tint": (0.1, 0.2, 0.3), "shininess": 32})
    floats = np.frombuffer(data, np.float32)
    np.testing.assert_allclose(floats[:8], (1, 0.5, 0.25, 1, 0.1, 0.2, 0.3, 32))
    assert np.frombuffer(data, np.uint32)[12] == 1  # the default
    assert len(data) == layout.size == 64


@pytest.mark.parametrize(("values", "needle"), [
    ({"color": (1, 1, 1, 1), "shininess": 3, "tnit": 1}, r"block 'Material' has no field 'tnit'"),
    ({"color": (1, 1, 1, 1)}, r"block 'Material' field 'shininess': no value given and no default"),
    ({"color": (1, 1, 1), "shininess": 3}, r"block 'Material' field 'color': expected 4 value\(s\) \(vec4\), got 3"),
    ({"color": (1, 1, 1, 1), "shininess": (1, 2)}, r"field 'shininess': expected 1 value\(s\) \(float\), got 2"),
    ({"color": (1, 1, 1, np.nan), "shininess": 3}, r"field 'color': values must be finite"),
    ({"color": (1, 1, 1, 1), "shininess": 1e39}, r"field 'shininess': values beyond float32's range"),
    ({"color": (1, 1, 1, 1), "shininess": 3, "count": -1}, r"field 'count': out of u32's range"),
    ({"color": (1, 1, 1, 1), "shininess": 3, "count": 1.5}, r"field 'count': u32 holds integers"),
    ({"color": "red", "shininess": 3}, r"field 'color': expected numbers for vec4"),
])
def test_bad_values_name_the_block_and_the_field(values, needle):
    layout = BlockLayout("Material", [("color", "vec4"), ("shininess", "float"), ("count", "u32", 0)])
    with pytest.raises(LayoutError, match=needle):
        layout.pack(values)


def test_bad_declarations_name_the_block_and_the_field():
    with pytest.raises(LayoutError, match=r"block 'B' field 'x': unknown type 'vec5'"):
        BlockLayout("B", [("x", "vec5")])
    with pytest.raises(LayoutError, match=r"block 'B' field 'x.*declared twice"):
        BlockLayout("B", [("x", "float"), ("x", "float")])
    with pytest.raises(LayoutError, match=r"block 'B' field 'a': array count"):
        BlockLayout("B", [("a", ("vec4", 0))])
    with pytest.raises(LayoutError, match=r"block 'B' has no field 'nope'"):
        BlockLayout("B", [("a", "vec4")]).offset("nope")
    with pytest.raises(LayoutError, match=r"block 'B' field 'a\[4\]': index out of range"):
        BlockLayout("B", [("a", ("vec4", 4))]).offset("a[4]")
    with pytest.raises(LayoutError, match=r"block 'B' field 'l.position': no value"):
        BlockLayout("B", [("l", LIGHT)]).pack({"l": {"range": 1, "color": (0, 0, 0, 0)}})


def test_type_names_of_both_languages():
    for glsl, wgsl in [("float", "f32"), ("int", "i32"), ("uint", "u32"), ("vec2", "vec2<f32>"), ("ivec4", "vec4i"),
                       ("uvec3", "vec3<u32>"), ("mat3", "mat3x3<f32>"), ("mat4", "mat4x4f")]:
        a, b = parse_type(glsl), parse_type(wgsl)
        assert (a.kind, a.rows, a.columns) == (b.kind, b.rows, b.columns), (glsl, wgsl)


def test_leaves_name_members_as_gl_introspection_does():
    layout = BlockLayout("Lights", [("count", "u32"), ("lights", ("Light", 2)), ("pos", ("vec4", 4))],
                         structs={"Light": LIGHT})
    assert layout.leaves() == [("count", 0, "u32"), ("lights[0].position", 16, "vec3"),
                               ("lights[0].range", 28, "float"),
                               ("lights[0].color", 32, "vec4"), ("lights[1].position", 48, "vec3"),
                               ("lights[1].range", 60, "float"), ("lights[1].color", 64, "vec4"),
                               ("pos[0]", 80, "vec4")]


# --- the engine's Frame and Lights blocks: declared once, checked against both APIs' own view ----------------
def _engine_layouts():
    from gandalf_core.resources.blocks import FRAME_LAYOUT, LIGHTS_LAYOUT

    return {"Frame": FRAME_LAYOUT, "Lights": LIGHTS_LAYOUT}


def test_frame_and_lights_blocks_match_the_glsl_programs_offsets():
    """The driver's std140 offsets of every member of frame.glsl's blocks are the declared layout's."""
    moderngl = pytest.importorskip("moderngl")
    from gandalf_core.render.opengl.raw_gl import block_members
    from gandalf_core.render.shader_files import SNIPPETS_DIR
    from gandalf_core.resources import ShaderSource
    from gandalf_core.resources.blocks import GLSL_MEMBERS

    ctx = moderngl.create_standalone_context(backend="egl", require=330)
    try:
        src = ShaderSource.from_text((SNIPPETS_DIR / "frame.glsl").read_text(), "glsl", "vertex").text
        # std140 blocks keep every member active, read or not
        main = "void main() { gl_Position = u_view[0] + u_shadow; }"
        program = ctx.program(vertex_shader=f"#version 330\n{src}\n{main}",
                              fragment_shader="#version 330\nout vec4 f;\nvoid main() { f = vec4(1.0); }")
        members = block_members(program.glo)
        for block, layout in _engine_layouts().items():
            names = GLSL_MEMBERS[block]
            expected = {}
            for path, offset, _type in layout.leaves():
                field, _, rest = path.partition("[")
                expected[names[field] + ("[" + rest if rest else "")] = offset
            got = {name: offset for name, (offset, _stride) in members[block].items()}
            assert got == expected, f"block {block}: GL offsets {got} != declared {expected}"
            assert program[block].size == layout.size, block
    finally:
        ctx.release()


def test_frame_and_lights_blocks_match_the_wgsl_structs():
    """A compute shader reads the first number of every member of frame.wgsl's structs from blocks whose 32-bit
    words hold their own index: what it reads is each member's offset in WGSL, which must be the declared one."""
    wgpu = pytest.importorskip("wgpu")
    from gandalf_core.render.shader_files import SNIPPETS_DIR
    from gandalf_core.resources import ShaderSource

    device = wgpu.utils.get_default_device()
    leaves = [(block, path, offset, kind) for block, layout in _engine_layouts().items()
              for path, offset, kind in layout.leaves()]
    reads = []
    for i, (block, path, _offset, kind) in enumerate(leaves):
        first = "[0][0]" if kind.startswith("mat") else ".x" if "vec" in kind else ""
        value = f"{block.lower()}.{path}{first}"
        value = f"bitcast<f32>({value})" if kind.startswith("i") else value
        reads.append(f"    out[{i}] = f32({value});")
    text = ShaderSource.from_file(SNIPPETS_DIR / "frame.wgsl").text + (
        "@group(1) @binding(0) var<storage, read_write> out: array<f32>;\n"
        "@compute @workgroup_size(1) fn main() {\n" + "\n".join(reads) + "\n}\n")
    module = device.create_shader_module(code=text)
    pipeline = device.create_compute_pipeline(layout="auto", compute={"module": module, "entry_point": "main"})
    usage = wgpu.BufferUsage
    blocks = []
    for layout in _engine_layouts().values():
        words = np.arange(layout.size // 4, dtype=np.float32)
        blocks.append(device.create_buffer_with_data(data=words, usage=usage.UNIFORM))
    out = device.create_buffer(size=4 * len(leaves), usage=usage.STORAGE | usage.COPY_SRC)
    groups = [device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=[
        {"binding": 0, "resource": {"buffer": blocks[0]}}, {"binding": 1, "resource": {"buffer": blocks[1]}}]),
        device.create_bind_group(layout=pipeline.get_bind_group_layout(1),
                                 entries=[{"binding": 0, "resource": {"buffer": out}}])]
    encoder = device.create_command_encoder()
    cpass = encoder.begin_compute_pass()
    cpass.set_pipeline(pipeline)
    for index, group in enumerate(groups):
        cpass.set_bind_group(index, group)
    cpass.dispatch_workgroups(1)
    cpass.end()
    device.queue.submit([encoder.finish()])
    got = np.frombuffer(device.queue.read_buffer(out), np.float32)
    for (block, path, offset, _kind), value in zip(leaves, got):
        word = offset // 4  # an integer member's bits are the float's: bitcast back above
        assert value == word, f"{block}.{path}: WGSL reads word {value}, the declaration puts it at {word}"


def test_pack_frame_and_lights_put_values_at_the_declared_offsets():
    from gandalf_core.render.frame import pack_frame
    from gandalf_core.resources.blocks import FRAME_LAYOUT, LIGHTS_LAYOUT
    from gandalf_core.systems.light_system import pack_lights, pack_shadow

    view = np.arange(16.0).reshape(4, 4)
    data = pack_frame(view, np.eye(4), np.array([1.0, 2.0, 3.0]), 5.0, 0.25, (0.0, 1.0), origin=np.array([1e7 + 0.3,
                                                                                                         0.0, 0.0]))
    assert len(data) == FRAME_LAYOUT.size
    floats = np.frombuffer(data, np.float32)
    np.testing.assert_array_equal(floats[:16].reshape(4, 4).T, view)  # column-major
    at = {name: FRAME_LAYOUT.offset(name) // 4 for name in FRAME_LAYOUT.names()}
    np.testing.assert_array_equal(floats[at["camera_position"]:at["camera_position"] + 4], (1, 2, 3, 1))
    np.testing.assert_array_equal(floats[at["time"]:at["time"] + 3], (5, 0.25, 0))
    np.testing.assert_array_equal(floats[at["depth"]:at["depth"] + 2], (0, 1))
    high, low = floats[at["origin_high"]], floats[at["origin_low"]]
    assert float(high) + float(low) == pytest.approx(1e7 + 0.3, abs=1e-6)
    empty = pack_lights([]) + pack_shadow([])
    assert empty == bytes(LIGHTS_LAYOUT.size)


def test_views_fill_a_block_by_name_with_the_same_bytes_as_pack():
    layout = BlockLayout("B", [("n", "i32", 0), ("m", "mat4"), ("arr", ("vec3", 2)), ("f", "float", 2.5)])
    m = np.arange(16.0).reshape(4, 4)
    arr = np.array([[1.0, 2, 3], [4, 5, 6]])
    block = layout.new()
    layout.view(block, "m")[...] = m
    layout.view(block, "arr")[...] = arr
    layout.view(block, "n")[...] = 7
    assert block.tobytes() == layout.pack({"n": 7, "m": m, "arr": arr})
    assert np.frombuffer(block.tobytes(), np.float32)[layout.offset("f") // 4] == 2.5  # the default
    with pytest.raises(LayoutError, match=r"block 'B' has no field 'x'"):
        layout.view(block, "x")
