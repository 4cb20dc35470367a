"""The render systems of both backends, headless: instancing, caching, errors, lights, sky, reverse-Z.

Tolerances: the two backends rasterise the same triangles with the same (software) drivers' rules; we
require PSNR >= 40 dB between them and no channel more than 2/255 apart (measured: identical, or 1/255
on a few lit pixels).
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from core_shaders import FLAT_FRAG, FLAT_MATERIAL, FLAT_VERT, FLAT_WGSL, SHADERS, build_shaders

from gandalf_core import Application, ClearColorComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent, SkyboxComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.render.errors import MissingResourceError, ShaderCompileError
from gandalf_core.resources import MaterialData, checkerboard, cube, sky_cube, uv_sphere
from gandalf_tools.testing import LocalDifferences, compare_images

W, H = 96, 72


def make_app(backend: str, **kwargs) -> Application:
    app = Application(backend, W, H, headless=True, fixed_dt=1 / 60, **kwargs)
    build_shaders(app.renderer.shaders, backend, "unlit", "lit")
    return app


def add_camera(scene: Scene, eye=(0.0, 1.5, 6.0), **camera) -> None:
    eye = np.array(eye, dtype=float)
    scene.create_entity(
        TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0, 0))),
        CameraComponent(**{"fov": 50.0, "near": 0.1, "far": 100.0, **camera}),
    )


def cubes_scene(n: int = 5, **camera) -> Scene:
    scene = Scene("cubes")
    scene.assets.mesh("cube", cube())
    scene.assets.texture("checker", checkerboard(32, 4))
    scene.assets.material("M", MaterialData("unlit", ["checker"], color=(1.0, 0.6, 0.3)))
    scene.create_entity(ClearColorComponent((0.2, 0.3, 0.4)))
    for i in range(n):
        scene.create_entity(
            TransformComponent((i * 1.5 - 3.0, 0, 0), (30, 40 * i, 0)), MeshComponent("cube"), MaterialComponent("M")
        )
    add_camera(scene, **camera)
    return scene


def lit_scene(lights: int = 1, sky: bool = False, **camera) -> Scene:
    scene = Scene("lit")
    scene.assets.mesh("sphere", uv_sphere(segments=24, rings=12))
    scene.assets.material("M", MaterialData("lit", color=(0.9, 0.6, 0.3)))
    if sky:
        scene.assets.texture("sky", sky_cube(32))
        scene.create_entity(SkyboxComponent("sky"))
    for i in range(3):
        scene.create_entity(
            TransformComponent((i * 2.2 - 2.2, 0, 0), scale=(1, 1 + 0.5 * i, 1)),
            MeshComponent("sphere"),
            MaterialComponent("M"),
        )
    for i in range(lights):
        scene.create_entity(
            TransformComponent(rotation=(-45, 30 + 10 * i, 0)),
            LightComponent("directional", (1, 1, 1), 1.0 / max(lights, 1)),
        )
    scene.create_entity(TransformComponent(), LightComponent("ambient", (0.2, 0.2, 0.3)))
    add_camera(scene, **camera)
    return scene


def render(backend: str, scene: Scene, frames: int = 2) -> tuple[np.ndarray, Application]:
    app = make_app(backend)
    app.add_scene(scene)
    app.run(frames=frames)
    return app.capture(), app


@pytest.mark.parametrize("build", [cubes_scene, lambda: lit_scene(3, sky=True)], ids=["textured", "lit-sky"])
def test_backends_draw_the_same_picture(build):
    images = {}
    for backend in ("opengl", "webgpu"):
        images[backend], app = render(backend, build())
        app.close()
    assert (images["opengl"][..., :3] != images["opengl"][0, 0, :3]).any(), "nothing was drawn"
    # One implementation's two drivers: within 2 levels (Mesa: everywhere) on 99.9 % of pixels, the rest a legal
    # local difference (an NVIDIA H200's OpenGL and Vulkan drivers differ on one 2 x 2 spot of a textured edge).
    compare_images(images["webgpu"], images["opengl"], "backends-agree", local=LocalDifferences(level=2, share=0.999))


def test_ten_thousand_entities_share_one_draw_call(backend):
    scene = Scene("many")
    scene.assets.mesh("cube", cube(0.01))
    scene.assets.texture("checker", checkerboard(8, 2))
    scene.assets.material("M", MaterialData("unlit", ["checker"]))
    scene.assets.material("N", MaterialData("unlit", ["checker"], color=(0.2, 0.9, 0.2)))
    rng = np.random.default_rng(1)
    for p in rng.uniform(-2, 2, size=(10_000, 3)):
        scene.create_entity(TransformComponent(p), MeshComponent("cube"), MaterialComponent("M"))
    add_camera(scene)
    with make_app(backend) as app:
        app.add_scene(scene)
        app.run(frames=2)
        assert app.renderer.stats["draw_calls"] == 1
        # A second material is a second batch, whatever the counts.
        scene.create_entity(TransformComponent(), MeshComponent("cube"), MaterialComponent("N"))
        app.step()
        assert app.renderer.stats["draw_calls"] == 2


def test_colour_change_rebuilds_nothing(backend):
    with make_app(backend) as app:
        app.add_scene(cubes_scene(3))
        app.run(frames=2)
        before = app.capture()
        created = dict(app.renderer.stats)
        app.renderer.materials.get("M").set_color((0.1, 0.9, 0.2))
        app.run(frames=2)
        after = app.capture()
        for key in (
            "pipelines_created",
            "shaders_created",
            "vertex_arrays_created",
            "textures_created",
            "buffers_created",
        ):
            assert app.renderer.stats[key] == created.get(key, 0), key
    assert np.abs(after.astype(int) - before.astype(int)).max() > 50


def test_runtime_changes_show_up(backend):
    """Entities added and removed while running (instance buffer growth, batch re-planning)."""
    scene = cubes_scene(1)
    with make_app(backend) as app:
        app.add_scene(scene)
        app.step()
        one = app.capture()
        extra = [
            scene.create_entity(
                TransformComponent((x, -1.0, 0.0), scale=0.4), MeshComponent("cube"), MaterialComponent("M")
            )
            for x in np.linspace(-3, 3, 400)
        ]
        app.step()
        many = app.capture()
        for entity in extra:
            scene.remove_component(entity, MeshComponent)
        app.step()
        again = app.capture()
    background = np.round(np.array([0.2, 0.3, 0.4]) * 255)  # the clear colour reads back as its sRGB bytes

    def coverage(img: np.ndarray) -> float:
        return (np.abs(img[..., :3].astype(int) - background).max(axis=2) > 3).mean()

    assert coverage(many) > coverage(one) + 0.05
    assert np.array_equal(again, one)


@pytest.mark.parametrize("frag,line", [("broken.frag", 6)])
def test_glsl_error_names_file_and_line(frag, line):
    with Application("opengl", 8, 8, headless=True) as app:
        with pytest.raises(ShaderCompileError, match=rf"broken\.frag:{line}:"):
            app.renderer.shaders.build("broken", SHADERS / "unlit.vert", SHADERS / frag)


def test_wgsl_error_names_file_and_line():
    with Application("webgpu", 8, 8, headless=True) as app:
        with pytest.raises(ShaderCompileError, match=r"broken\.wgsl:7:"):
            app.renderer.shaders.build("broken", SHADERS / "broken.wgsl")


def test_missing_resources_are_named(backend):
    scene = Scene("bad")
    scene.assets.mesh("cube", cube())
    scene.assets.material("needs-shader", MaterialData("no-such-shader"))
    scene.assets.material("needs-texture", MaterialData("unlit", ["no-such-texture"]))
    scene.assets.material("ok", MaterialData("lit"))
    entity = scene.create_entity(TransformComponent(), MeshComponent("cube"), MaterialComponent("needs-shader"))
    with make_app(backend) as app:
        app.add_scene(scene)
        with pytest.raises(MissingResourceError, match="material 'needs-shader' names shader 'no-such-shader'"):
            app.step()
        scene.add_component(entity, MaterialComponent("needs-texture"))
        with pytest.raises(MissingResourceError, match="texture 'no-such-texture'"):
            app.step()
        scene.add_component(entity, MaterialComponent("no-such-material"))
        with pytest.raises(MissingResourceError, match="material 'no-such-material'"):
            app.step()
        scene.add_component(entity, MaterialComponent("ok"))
        scene.add_component(entity, MeshComponent("no-such-mesh"))
        with pytest.raises(MissingResourceError, match="mesh 'no-such-mesh'"):
            app.step()


def test_only_needed_passes_are_built(backend):
    """No sky pipeline/shader unless the scene has a SkyboxComponent."""
    without, app = render(backend, lit_scene(1, sky=False))
    shaders_without = app.renderer.stats["shaders_created"]
    app.close()
    with_sky, app = render(backend, lit_scene(1, sky=True))
    assert app.renderer.stats["shaders_created"] == shaders_without + 1
    app.close()
    top = slice(0, 8)  # the sky shows at the top of the picture
    assert np.abs(with_sky[top].astype(int) - without[top].astype(int)).max() > 20


def test_reverse_z_draws_the_same_picture(backend):
    normal, app = render(backend, lit_scene(2, sky=True, near=0.01, far=1e5))
    app.close()
    reverse, app = render(backend, lit_scene(2, sky=True, near=0.01, far=1e5, reverse_z=True))
    app.close()
    compare_images(reverse, normal, f"reverse-z-{backend}", min_psnr=40.0, max_diff=2)


def test_lights_count_and_no_lights(backend):
    dark, app = render(backend, lit_scene(0))
    app.close()
    lit, app = render(backend, lit_scene(1))
    app.close()
    assert lit[..., :3].astype(int).sum() > dark[..., :3].astype(int).sum()
    assert dark[..., :3].max() > 0  # ambient light still shows the spheres


def test_zero_scale_and_huge_scale_entities_render_without_errors(backend):
    scene = cubes_scene(0)
    scene.create_entity(TransformComponent(scale=0.0), MeshComponent("cube"), MaterialComponent("M"))
    scene.create_entity(TransformComponent((0, 0, -50), scale=1e-6), MeshComponent("cube"), MaterialComponent("M"))
    scene.create_entity(
        TransformComponent((0, 0, -90), scale=(1e3, 1e-3, 1)), MeshComponent("cube"), MaterialComponent("M")
    )
    image, app = render(backend, scene)
    app.close()
    assert image.shape == (H, W, 4)


def test_resize_follows_the_window_size(backend):
    with make_app(backend) as app:
        app.add_scene(cubes_scene(3))
        app.step()
        app.input.resize(64, 40)
        app.step()
        assert app.capture().shape == (40, 64, 4)


def test_many_frames_create_nothing_new(backend):
    with make_app(backend) as app:
        app.add_scene(lit_scene(2, sky=True))
        app.run(frames=3)
        live, created = app.renderer.live_objects(), dict(app.renderer.stats)
        app.run(frames=50)
        assert app.renderer.live_objects() == live
        assert {k: v for k, v in app.renderer.stats.items() if k != "draw_calls"} == {
            k: v for k, v in created.items() if k != "draw_calls"
        }


def test_one_name_for_different_data_in_two_scenes_draws_each_scenes_own(backend):
    """Libraries cache by name; a second scene that reuses a name for other data must not get the first's: the
    name is rebuilt from the active scene's data (and the first scene's again when it comes back)."""
    first, second = cubes_scene(1), cubes_scene(1)
    # The same material and texture objects may be shared by name; only the mesh differs.
    second.assets.material("M", first.assets.materials["M"])
    second.assets.texture("checker", first.assets.textures["checker"])
    second.assets.mesh("cube", cube(2.0))
    second.name = "cubes-2"
    alone, app_alone = render(backend, second_copy(second))
    app_alone.close()
    with make_app(backend) as app:
        app.add_scene(first)
        app.add_scene(second)
        app.step()
        picture_first = app.capture()
        app.switch_scene(second)
        app.step()
        picture_second = app.capture()
        app.switch_scene(first)
        app.step()
        assert np.array_equal(app.capture(), picture_first)
    assert not np.array_equal(picture_first, picture_second)
    assert np.array_equal(picture_second, alone)


def second_copy(scene: Scene) -> Scene:
    """A scene like ``scene`` (one cube of the given mesh, the same camera), built alone."""
    copy = cubes_scene(1)
    copy.assets.mesh("cube", scene.assets.meshes["cube"])
    return copy


def test_read_pixel_matches_the_full_read_back(backend):
    image, app = render(backend, cubes_scene(5))
    for x, y in [(0, 0), (W - 1, 0), (W // 2, H // 2), (10, H - 1)]:
        assert np.array_equal(app.renderer.read_pixel(x, y), image[y, x])
    app.close()


def test_instance_rows_read_as_a_slice_or_gathered_agree():
    from gandalf_core.render.frame import pack_instances

    world = np.random.default_rng(3).normal(size=(50, 4, 4))
    assert np.array_equal(pack_instances(world, slice(10, 40)), pack_instances(world, np.arange(10, 40)))
    assert pack_instances(world, slice(10, 40)).dtype == np.float32


RED_WGSL = """
@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let p = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4<f32>(p * 2.0 - 1.0, 0.0, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0, 0.0, 0.0, 1.0); }
"""


def test_overlays_draw_over_the_finished_frame(backend):
    """The hook a GUI layer uses: called once per frame after the scene (WebGPU: last in the scene's own pass, whose
    colour and depth formats its pipelines use), in both backends."""
    calls = []
    pipeline = []

    def overlay(renderer, *render_pass):
        calls.append(renderer.backend)
        if renderer.backend == "opengl":
            renderer.framebuffer.clear(1.0, 0.0, 0.0, 1.0, viewport=(0, 0, 4, 4))
            return
        (rpass,) = render_pass
        if not pipeline:
            module = renderer.device.create_shader_module(code=RED_WGSL)
            pipeline.append(renderer.device.create_render_pipeline(
                layout="auto", vertex={"module": module, "entry_point": "vs_main"},
                fragment={"module": module, "entry_point": "fs_main",
                          "targets": [{"format": renderer.color_view.texture.format}]},
                primitive={"topology": "triangle-list"},
                depth_stencil={"format": renderer.depth_view.texture.format, "depth_write_enabled": False,
                               "depth_compare": "always"}))
        rpass.set_pipeline(pipeline[0])
        rpass.set_scissor_rect(0, renderer.height - 4, 4, 4)  # the bottom-left corner, as OpenGL's
        rpass.draw(3)

    with make_app(backend) as app:
        app.add_scene(cubes_scene(3))
        app.renderer.overlays.append(overlay)
        app.run(frames=2)
        assert calls == [backend, backend]
        picture = app.capture()
        assert np.array_equal(picture[-1, 0], [255, 0, 0, 255])  # the corner the overlay drew
        assert not np.array_equal(picture[-5, 0], [255, 0, 0, 255])  # and only that corner


# --- blending, depth and material values: the same in both backends -------------------------------------
def flat_app(backend: str) -> Application:
    app = Application(backend, 32, 32, headless=True, fixed_dt=1 / 60)
    if backend == "opengl":
        app.renderer.shaders.build("flat", FLAT_VERT, FLAT_FRAG, material=FLAT_MATERIAL)
    else:
        app.renderer.shaders.build("flat", FLAT_WGSL, material=FLAT_MATERIAL)
    return app


def quads_scene(*quads: tuple[str, float, dict], sky: bool = False) -> Scene:
    """Full-screen quads at depth z (further is more negative), each with its own material."""
    from gandalf_core.resources import quad

    scene = Scene("quads")
    scene.assets.mesh("quad", quad(10.0))
    scene.create_entity(ClearColorComponent((0.0, 0.0, 1.0)))
    if sky:
        scene.assets.texture("sky", sky_cube(8))
        scene.create_entity(SkyboxComponent("sky"))
    for name, z, material in quads:
        params = {"tint": (1, 1, 1, 1), "m": np.zeros(16)}
        scene.assets.material(name, MaterialData("flat", **{"params": params, **material}))
        scene.create_entity(TransformComponent((0, 0, z)), MeshComponent("quad"), MaterialComponent(name))
    add_camera(scene, eye=(0, 0, 2), far=50.0)
    return scene


def centre(backend: str, scene: Scene) -> np.ndarray:
    with flat_app(backend) as app:
        app.add_scene(scene)
        app.run(frames=1)
        return app.capture()[16, 16].astype(int)


def test_transparent_surfaces_are_drawn_after_opaque_ones_and_the_sky(backend):
    glass = {"color": (1, 0, 0, 0.5), "blend": "alpha", "depth_write": False}
    # The glass's material sorts first by name, and it is nearer: it must still blend over the wall.
    pixel = centre(backend, quads_scene(("a_glass", -1.0, glass), ("b_wall", -5.0, {"color": (0, 1, 0)})))
    assert pixel[0] > 150 and pixel[1] > 150 and pixel[3] == 255  # red over green, and an opaque target
    with_sky = centre(backend, quads_scene(("a_glass", -1.0, glass), sky=True))
    assert with_sky[0] > 150 and with_sky[1] > 80  # red over the sky, not the sky drawn over the glass


def test_depth_test_off_still_writes_depth_in_both_backends(backend):
    near = {"color": (1, 0, 0), "depth_test": False, "depth_write": True}
    # Drawn first (name order), the red quad without a depth test still hides the green one behind it.
    pixel = centre(backend, quads_scene(("a_near", -1.0, near), ("b_far", -5.0, {"color": (0, 1, 0)})))
    assert pixel[:3].tolist() == [255, 0, 0]


def test_matrix_params_reach_the_shader_alike(backend):
    m = np.eye(4)
    m[0, 1] = 1.0  # row 0, column 1: material.m[1].x in both languages
    material = {"color": (1, 0, 0), "params": {"tint": (1, 1, 1, 1), "m": m.ravel()}}
    pixel = centre(backend, quads_scene(("a", -1.0, material)))
    assert pixel[:3].tolist() == [255, 0, 255]


@pytest.mark.parametrize(("params", "needle"), [
    ({"m": np.zeros(16)}, r"material 'a': params: shader 'flat' .* reads 'tint', which the material never "
                          r"sets \(it would read 0\)"),
    ({"tint": (1, 1, 1, 1), "m": np.zeros(16), "tnit": 1.0},
     r"material 'a': params\['tnit'\]: shader 'flat' .* has no value 'tnit'.*did you mean 'tint'"),
    ({"u_tint": (1, 1, 1, 1), "m": np.zeros(16)}, None),
])
def test_material_values_are_matched_to_the_shader_by_name_or_refused(backend, params, needle):
    """A value the shader reads but the material never sets, a misspelt parameter, or (OpenGL) a name given with
    GLSL's old u_ prefix: each an error naming the material, the shader and the field, never a silent 0 or a dropped
    value."""
    from gandalf_core.resources import ResourceError

    scene = Scene("values")
    scene.assets.mesh("quad", cube())
    scene.assets.material("a", MaterialData("flat", color=(1, 0, 0), params=params))
    scene.create_entity(TransformComponent((0, 0, -3)), MeshComponent("quad"), MaterialComponent("a"))
    add_camera(scene, eye=(0, 0, 2), far=50.0)
    if needle is None:  # the u_ prefix: both APIs say to leave it out
        needle = r"params\['u_tint'\]: give it without the 'u_' prefix: 'tint'"
    with flat_app(backend) as app, pytest.raises(ResourceError, match=needle):
        app.add_scene(scene)
        app.step()


def test_a_material_with_the_wrong_number_of_textures_is_named(backend):
    from gandalf_core.resources import ResourceError

    scene = cubes_scene(1)
    scene.assets.material("M", MaterialData("unlit"))  # unlit samples one texture
    with make_app(backend) as app:
        app.add_scene(scene)
        with pytest.raises(ResourceError, match="material 'M': textures: 0 texture"):
            app.step()


def test_material_values_must_be_finite(backend):
    from gandalf_core.resources import ResourceError

    with make_app(backend) as app:
        app.add_scene(cubes_scene(1))
        app.step()
        with pytest.raises(ResourceError, match="material 'M': color"):
            app.renderer.materials.get("M").set_color((float("nan"), 0, 0))


def test_ambient_lights_count_even_past_the_light_limit():
    from gandalf_core.render.frame import MAX_LIGHTS
    from gandalf_core.systems import pack_lights

    pairs = [(LightComponent("point"), TransformComponent()) for _ in range(MAX_LIGHTS + 1)]
    pairs.append((LightComponent("ambient", (1, 1, 1), 0.5), TransformComponent()))
    with pytest.warns(UserWarning, match=f"only the first {MAX_LIGHTS}"):
        block = np.frombuffer(pack_lights(pairs), np.float32)
    assert block[:4].view(np.int32)[0] == MAX_LIGHTS
    assert np.allclose(block[4:7], 0.5)


@pytest.mark.parametrize("aspect", [-1.0, 0.0, float("nan")])
def test_orthographic_camera_rejects_a_bad_aspect(aspect):
    with pytest.raises(ValueError, match="CameraComponent.aspect"):
        CameraComponent(projection="orthographic", aspect=aspect)


def test_light_fields_are_checked_when_set_later():
    light = LightComponent("point")
    for field, value in [("intensity", float("nan")), ("color", (1, float("inf"), 0)), ("kind", "spot"),
                         ("range", -1.0)]:
        with pytest.raises(ValueError, match=f"LightComponent.{field}"):
            setattr(light, field, value)


def test_the_sky_shows_a_view_with_an_orthographic_camera(backend):
    scene = lit_scene(0, sky=True, projection="orthographic", height=20.0)
    image, app = render(backend, scene)
    app.close()
    top_rows = image[:10, :, :3].astype(int)
    assert top_rows.std(axis=(0, 1)).max() > 1.0 or np.abs(top_rows[0] - top_rows[-1]).max() > 2


@pytest.mark.parametrize("projection", ["orthographic", "perspective"])
def test_transparent_instances_sort_by_view_depth_not_distance(backend, projection):
    """A nearer (in view depth) blended quad far off to the side is still drawn last, i.e. on top."""
    from gandalf_core.resources import plane

    scene = Scene("depth order")
    scene.assets.mesh("plane", plane(10.0, 1))
    for name, rgb in (("red", (1, 0, 0)), ("green", (0, 1, 0))):
        params = {"tint": (1, 1, 1, 1), "m": np.zeros(16)}
        scene.assets.material(name, MaterialData("flat", color=(*rgb, 0.5), params=params,
                                                 blend="alpha", depth_write=False, cull="none"))
    scene.create_entity(ClearColorComponent((0, 0, 0)))
    scene.create_entity(TransformComponent((0.0, 1.0, 0.0)), MeshComponent("plane"), MaterialComponent("red"))
    scene.create_entity(TransformComponent((6.0, 2.0, 0.0)), MeshComponent("plane"), MaterialComponent("green"))
    camera = (CameraComponent(near=0.1, far=50.0, projection="orthographic", height=16.0)
              if projection == "orthographic" else CameraComponent(90.0, 0.1, 50.0))
    scene.create_entity(TransformComponent((0.0, 10.0, 0.0), rotation=(-90, 0, 0)), camera)
    with flat_app(backend) as app:
        app.add_scene(scene)
        app.run(frames=1)
        image = app.capture()
    # Column 21 of the 32-pixel picture looks at world x of about 3, over both quads; green (nearer in
    # view depth) must be on top.
    r, g, _b = image[16, 21, :3].astype(int)
    assert g > r > 0


@pytest.mark.parametrize(("field", "value"), [("color", "red"), ("color", (1, 0)), ("intensity", "bright"),
                                              ("range", -1), ("shadow_extent", 0), ("shadow_depth", "far"),
                                              ("shadow_bias", float("inf"))])
def test_bad_light_values_name_the_field_and_change_nothing(field, value):
    light = LightComponent("directional", cast_shadows=True)
    before = repr(light)
    with pytest.raises(ValueError, match=rf"LightComponent\.{field} must be .*got {re.escape(repr(value))}"):
        setattr(light, field, value)
    assert repr(light) == before
