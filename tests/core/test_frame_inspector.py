"""The frame inspector's engine part, headless in both APIs: a captured frame, its decoded blocks, GPU times, picking.

The scene (``inspector_scene.py``): a floor, three cubes, a blended pane, a sky and a shadow-casting sun.

* The capture lists the passes in the order the renderer draws them (shadow, opaque, sky, transparent) and exactly
  as many draws as the renderer's own counter (``stats["draw_calls"]``) and shadow-pass counter say.
* The Material, Frame and Lights blocks decoded by field name hold what the scene set: each material's colour (sRGB
  decoded to linear light, to float32's 1e-6), shininess and specular exactly; one light, its shadow on; the API's
  depth range.
* GPU times: present for every pass and draw where the device can time (llvmpipe: GL_TIMESTAMP; lavapipe: WebGPU
  timestamps once GANDALF_GPU_TIMING=1 asks for them), and the passes' sum within 20 % of the frame's GPU time
  (first timestamp to last, so the gaps between passes count against the sum). Without the request a WebGPU
  device has no timestamps and the capture says so.
* Picking returns the right entity, material and shader for a visible point of every object, and the background
  (the sky) where nothing else is; the picture is left as it was, byte for byte.
"""

from __future__ import annotations

import numpy as np
import pytest
from inspector_scene import COLORS, SHININESS, VISIBLE_POINT, inspector_app, pixel_of

from gandalf_core.render.color import srgb_rgba_to_linear
from gandalf_core.render.gpu_timing import TIMING_VARIABLE
from step07_advanced.editor.frame_inspector.capture import FrameRecorder, capture_frame
from step07_advanced.editor.frame_inspector.picking import pick


@pytest.fixture
def timed(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(TIMING_VARIABLE, "1")


def _captured(backend: str, **kwargs: bool):
    app, entities = inspector_app(backend, **kwargs)
    app.run(frames=2)
    shadow_passes = app.renderer.stats["shadow_passes"]
    capture = capture_frame(app)
    return app, entities, capture, app.renderer.stats["shadow_passes"] - shadow_passes


def test_capture_lists_the_passes_and_draws_the_renderer_counts(backend: str) -> None:
    app, entities, capture, shadow_passes = _captured(backend)
    try:
        assert capture.pass_names() == ["shadow", "opaque", "sky", "transparent"]
        assert len(capture.draws) == app.renderer.stats["draw_calls"] == 10
        assert capture.pass_names().count("shadow") == shadow_passes == 1
        # Every drawn object's entity is named by the draws that drew it: its shadow and its colour.
        for name, entity in entities.items():
            passes = [d.pass_name for d in capture.draws_of(entity)]
            assert passes == (["transparent"] if name == "pane" else ["shadow", "opaque"]), name
        sky = capture.passes[2].draws[0]
        assert sky.shader == "gandalf.skybox" and sky.textures[0]["name"] == "sky" and sky.textures[0]["kind"] == "cube"
        assert not sky.state["depth_write"]
        pane = capture.passes[3].draws[0]
        assert "alpha" in pane.state["blend"].lower() and pane.mesh == "pane" and pane.vertex_count > 0
        assert all(d.shader_files for d in capture.draws)
        # What the renderer held after the frame: its shadow map and sky among it.
        held = capture.gpu_memory
        assert held == app.renderer.gpu_memory() and held["shadow map"] > 0 and held["textures"] > 0
    finally:
        app.close()


def test_without_a_sky_shadows_or_blending_the_capture_has_only_the_opaque_pass(backend: str) -> None:
    app, _entities, capture, shadow_passes = _captured(backend, sky=False, shadows=False, pane=False)
    try:
        assert capture.pass_names() == ["opaque"] and shadow_passes == 0
        assert len(capture.draws) == app.renderer.stats["draw_calls"] == 4
    finally:
        app.close()


def test_blocks_are_decoded_by_field_name_with_the_values_the_scene_set(backend: str) -> None:
    app, _entities, capture, _ = _captured(backend)
    try:
        opaque = capture.passes[1].draws
        assert sorted(d.material for d in opaque) == sorted(COLORS)
        for draw in opaque:
            material = draw.blocks["Material"]["values"]
            expected = srgb_rgba_to_linear((*COLORS[draw.material], 1.0))
            np.testing.assert_allclose(material["color"], expected, atol=1e-6, err_msg=draw.material)
            assert material["shininess"] == SHININESS[draw.material]
            assert material["specular"] == pytest.approx(0.1, abs=1e-7)
            lights = draw.blocks["Lights"]["values"]
            assert lights["count"][0] == 1 and lights["shadow"][0] == 1.0
            depth = draw.blocks["Frame"]["values"]["depth"][:2]
            assert depth == ([-1.0, 1.0] if backend == "opengl" else [0.0, 1.0])
        glass = capture.passes[3].draws[0].blocks["Material"]["values"]
        np.testing.assert_allclose(glass["color"], srgb_rgba_to_linear((1.0, 1.0, 0.2, 0.5)), atol=1e-6)
    finally:
        app.close()


def test_gpu_times_are_present_and_add_up_to_the_frame(backend: str, timed: None) -> None:
    app, _entities, capture, _ = _captured(backend)
    try:
        assert "llvmpipe" in capture.timing or "GL_TIMESTAMP" in capture.timing or "WebGPU" in capture.timing
        assert len(capture.frame_gpu_ms) == 1 and capture.frame_gpu_ms[0] > 0.0
        assert all(p.gpu_ms is not None for p in capture.passes)
        assert all(d.gpu_ms is not None for d in capture.draws)
        total = sum(p.gpu_ms for p in capture.passes)
        frame = capture.frame_gpu_ms[0]
        assert abs(total - frame) <= 0.2 * frame, (total, frame, [(p.name, p.gpu_ms) for p in capture.passes])
    finally:
        app.close()


def test_webgpu_says_when_it_cannot_time(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(TIMING_VARIABLE, raising=False)
    app, _entities, capture, _ = _captured("webgpu")
    try:
        assert f"{TIMING_VARIABLE}=1" in capture.timing and capture.frame_gpu_ms == []
        assert all(d.gpu_ms is None for d in capture.draws)
    finally:
        app.close()


def test_picking_returns_every_objects_entity_and_leaves_the_picture(backend: str) -> None:
    app, entities, _capture, _ = _captured(backend)
    try:
        before = app.capture()
        materials = {"floor": "floor", "red cube": "red", "green cube": "green", "blue cube": "blue", "pane": "glass"}
        depths = {}
        for name, point in VISIBLE_POINT.items():
            x, y = pixel_of(app, point)
            picked = pick(app, x, y)
            assert picked.entity == entities[name], (name, (x, y), picked.describe())
            assert picked.material == materials[name]
            assert picked.shader == ("gandalf.unlit" if name == "pane" else "gandalf.blinn_phong")
            depths[name] = picked.depth
        assert 0.0 < depths["pane"] < depths["green cube"] < depths["floor"] < 1.0  # nearer is smaller
        corner = pick(app, 1, 1)
        assert corner.entity is None and corner.shader == "gandalf.skybox"
        assert np.array_equal(app.capture(), before)
    finally:
        app.close()


def test_frames_that_are_not_captured_never_call_a_recorder(backend: str, monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(*_args, **_kwargs):
        raise AssertionError("a frame that is not captured called the recorder")

    app, _entities, capture, _ = _captured(backend)
    try:
        for hook in ("draw", "begin_frame", "begin_target", "end_target", "overlay"):
            monkeypatch.setattr(FrameRecorder, hook, refuse)
        assert app.renderer.recorder is None
        app.run(frames=2)
    finally:
        app.close()


def test_unpack_is_the_inverse_of_pack() -> None:
    from gandalf_core.resources.layout import BlockLayout, LayoutError, Struct

    layout = BlockLayout("B", [("a", "float"), ("m", "mat3"), ("v", ("vec4", 2)),
                               ("s", Struct("S", [("x", "vec3"), ("y", "float")])), ("i", "ivec4")])
    values = {"a": 1.5, "m": np.arange(9.0).reshape(3, 3), "v": [[1, 2, 3, 4], [5, 6, 7, 8]],
              "s": {"x": (1, 2, 3), "y": 4}, "i": (1, -2, 3, 4)}
    unpacked = layout.unpack(layout.pack(values))
    assert unpacked["m"] == np.arange(9.0).reshape(3, 3).tolist()  # maths convention, as given
    assert unpacked["s"] == {"x": [1.0, 2.0, 3.0], "y": 4.0} and unpacked["i"] == [1, -2, 3, 4]
    assert layout.pack(unpacked) == layout.pack(values)
    with pytest.raises(LayoutError, match="block 'B'"):
        layout.unpack(b"\0" * 8)


def test_the_texture_viewer_reads_every_source_face_and_level(backend: str) -> None:
    """Frame colour equals the captured picture; each sky face at level 0 equals its pixels, a level's size halves;
    the frame depth at a picked pixel equals the pick's depth; the shadow map holds nearer depths than its clear."""
    from step07_advanced.editor.frame_inspector.texture_readback import display_rgba, read_source, texture_sources

    app, _entities, _capture, _ = _captured(backend)
    try:
        renderer = app.renderer
        sources = {s.name: s for s in texture_sources(renderer)}
        assert set(sources) == {"frame colour", "frame depth", "shadow map", "sky"}
        assert sources["sky"].faces == 6 and sources["sky"].levels == 3
        assert np.array_equal(read_source(renderer, "frame colour"), app.capture())
        faces = app.scene.assets.textures["sky"].faces
        for face in range(6):
            assert np.array_equal(read_source(renderer, "sky", face, 0), faces[face]), face
            assert read_source(renderer, "sky", face, 2).shape == (1, 1, 4)
        x, y = pixel_of(app, VISIBLE_POINT["green cube"])
        assert read_source(renderer, "frame depth")[y, x] == pytest.approx(pick(app, x, y).depth, abs=1e-7)
        shadow = read_source(renderer, "shadow map")
        assert shadow.shape == (2048, 2048) and shadow.min() < 0.9 and shadow.max() == 1.0
        assert display_rgba(shadow).dtype == np.uint8
        with pytest.raises(ValueError, match="'sky' has 6 face"):
            read_source(renderer, "sky", 6, 0)
    finally:
        app.close()


# --- the two debugging recipes of the editor page ------------------------------------------------------
GLOW_WGSL = """
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"
@vertex fn vs_main(@location(0) position: vec3<f32>, inst: Instance) -> @builtin(position) vec4<f32> {
    return frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(material.color.rgb * material.glow, 1.0); }
"""
GLOW_VERT = """#version 330 core
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
void main() { gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0); }
"""
GLOW_FRAG = """#version 330 core
#include "material.glsl"
out vec4 f_color;
void main() { f_color = vec4(material.color.rgb * material.glow, 1.0); }
"""
#: 'glow' has a default (0): a material that forgets it builds, and draws black.
GLOW_MATERIAL = [("color", "vec4"), ("glow", "float", 0.0), ("_pad", "vec3", 0.0)]


def test_recipe_a_missing_uniform_shows_as_its_decoded_default(backend: str) -> None:
    """The red cube draws black; a pick on it names its material, whose decoded block shows glow = 0 (the default
    it fell back to), where the green cube's shows the glow it was given."""
    from gandalf_core.resources import MaterialData

    app, entities = inspector_app(backend, sky=False, shadows=False, pane=False)
    try:
        if backend == "opengl":
            app.renderer.shaders.build("glow", GLOW_VERT, GLOW_FRAG, material=GLOW_MATERIAL)
        else:
            app.renderer.shaders.build("glow", GLOW_WGSL, material=GLOW_MATERIAL)
        assets = app.scene.assets
        assets.material("red", MaterialData("glow", color=(0.9, 0.1, 0.1)))  # glow forgotten
        assets.material("green", MaterialData("glow", color=(0.1, 0.8, 0.2), params={"glow": 1.5}))
        app.run(frames=2)
        x, y = pixel_of(app, VISIBLE_POINT["red cube"])
        assert app.capture()[y, x, :3].max() == 0, "the red cube should draw black"
        picked = pick(app, x, y)
        assert picked.entity == entities["red cube"] and picked.material == "red"
        capture = capture_frame(app)
        blocks = {d.material: d.blocks["Material"]["values"] for d in capture.draws}
        assert blocks["red"]["glow"] == 0.0 and blocks["green"]["glow"] == 1.5
    finally:
        app.close()


def test_recipe_a_wrong_depth_test_shows_in_the_pipeline_state(backend: str) -> None:
    """The floor's material turns its depth test off: drawn after the blue cube it covers it. A pick on the blue
    cube's top names the floor, and the floor's draw shows a compare that always passes."""
    from gandalf_core.resources import MaterialData

    app, entities = inspector_app(backend, sky=False, shadows=False, pane=False)
    try:
        assets = app.scene.assets
        floor = assets.materials["floor"]
        assets.material("floor", MaterialData(floor.shader, color=floor.color, params=floor.params, depth_test=False))
        app.run(frames=2)
        picked = pick(app, *pixel_of(app, VISIBLE_POINT["blue cube"]))
        assert picked.entity == entities["floor"], picked.describe()
        capture = capture_frame(app)
        state = {d.material: d.state for d in capture.draws}
        assert state["floor"]["depth_compare"] == ("GL_ALWAYS" if backend == "opengl" else "always")
        assert state["blue"]["depth_compare"] == ("GL_LEQUAL" if backend == "opengl" else "less-equal")
    finally:
        app.close()


def test_a_timing_only_capture_gives_the_same_passes_and_draws(backend: str, timed: None) -> None:
    """What a benchmark reads (``describe=False``): the same passes and draws, with GPU times, no details."""
    app, _entities, full, _ = _captured(backend)
    try:
        light = capture_frame(app, describe=False)
        assert light.pass_names() == full.pass_names()
        assert [(d.mesh, d.material, d.instances, d.rows) for d in light.draws] == \
            [(d.mesh, d.material, d.instances, d.rows) for d in full.draws]
        assert all(type(d.rows) is list for d in light.draws)  # made lists after the frame, as the full capture's
        assert all(p.gpu_ms is not None for p in light.passes) and light.frame_gpu_ms
        assert all(d.blocks == {} and d.state == {} for d in light.draws)
    finally:
        app.close()


def test_picking_tells_the_instances_of_one_instanced_draw_apart(backend: str) -> None:
    """The three cubes share one material: one draw of three instances; a pick names each cube's own entity."""
    app, entities = inspector_app(backend, sky=False, shadows=False, pane=False, one_material=True)
    try:
        app.run(frames=2)
        capture = capture_frame(app)
        (cubes,) = [d for d in capture.draws if d.mesh == "cube"]
        assert cubes.instances == 3
        for name in ("red cube", "green cube", "blue cube"):
            picked = pick(app, *pixel_of(app, VISIBLE_POINT[name]))
            assert picked.draw.index == cubes.index and picked.entity == entities[name], picked.describe()
    finally:
        app.close()
