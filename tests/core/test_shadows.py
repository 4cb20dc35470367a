"""Shadow mapping in both render systems, headless: a cube over a floor under a shadow-casting sun.

The shadow falls where the geometry says it must (pixels computed from the light's direction and a
top-down orthographic camera), and nowhere else; the passes exist only when a light casts shadows.
Tolerances: the two backends must agree with PSNR >= 40 dB and no channel more than 2/255 apart (measured:
identical bytes at 96x72; at 640x480 a few pixels 1/255 apart, PSNR 88 dB and more); pixels in shadow are at
least 40 levels darker than lit floor, and lit floor is within 1/255 of the same floor without a shadow map
(no shadow acne).
"""

from __future__ import annotations

import numpy as np
import pytest
from core_shaders import SHADERS

from gandalf_core import Application, ClearColorComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, cube, plane
from gandalf_tools.testing import compare_images

W, H = 96, 72
VIEW_HEIGHT = 8.0  # world units the top-down camera shows from the top of the picture to the bottom
CUBE_BOTTOM, CUBE_TOP = 1.0, 2.0  # the unit cube floats over the floor (y = 0) between these heights

SHADOWED_VERT = """#version 330 core
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_world;
out vec3 v_normal;
void main() {
    vec4 world = instance_model() * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = instance_normal(a_normal);
    gl_Position = u_projection * u_view * world;
}
"""
SHADOWED_FRAG = """#version 330 core
#include "shadow.glsl"
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"
out vec4 f_color;
void main() {
    vec3 n = normalize(v_normal);
    vec3 c = u_ambient.rgb * material.color.rgb;
    for (int i = 0; i < u_light_count.x; ++i) {
        float lit = i == int(u_shadow.w) ? shadow_factor(v_world, n) : 1.0;
        c += lit * material.color.rgb * u_light_color[i].rgb * max(dot(n, normalize(u_light_position[i].xyz)), 0.0);
    }
    f_color = vec4(c, 1.0);
}
"""
SHADOWED_WGSL = """
#include "lit_vertex.wgsl"
#include "shadow.wgsl"
#include "material.wgsl"
@fragment fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    var c = lights.ambient.rgb * material.color.rgb;
    for (var i = 0; i < lights.count.x; i++) {
        var lit = 1.0;
        if (i == i32(lights.shadow.w)) { lit = shadow_factor(in.world, n); }
        c += lit * material.color.rgb * lights.color[i].rgb * max(dot(n, normalize(lights.position[i].xyz)), 0.0);
    }
    return vec4<f32>(c, 1.0);
}
"""


def make_app(backend: str) -> Application:
    app = Application(backend, W, H, headless=True, fixed_dt=1 / 60)
    if backend == "opengl":
        app.renderer.shaders.build("shadowed", SHADOWED_VERT, SHADOWED_FRAG)
    else:
        app.renderer.shaders.build("shadowed", SHADOWED_WGSL, include_dirs=[SHADERS])
    return app


def sun_position(towards_light: tuple[float, float, float], distance: float = 8.0) -> np.ndarray:
    d = np.asarray(towards_light, dtype=float)
    return d / np.linalg.norm(d) * distance


def shadow_scene(towards_light=(1.0, 2.0, 0.0), cast_shadows: bool = True, reverse_z: bool = False,
                 extra_point_light: bool = False) -> Scene:
    """A floor, a cube floating over it, a sun shining towards -towards_light, a camera looking straight down."""
    scene = Scene("shadows")
    scene.assets.mesh("floor", plane(12.0, 1))
    scene.assets.mesh("cube", cube(1.0))
    scene.assets.material("grey", MaterialData("shadowed", color=(0.8, 0.8, 0.8)))
    scene.create_entity(ClearColorComponent((0.1, 0.1, 0.2)))
    scene.create_entity(TransformComponent(), MeshComponent("floor"), MaterialComponent("grey"))
    scene.create_entity(TransformComponent((0.0, (CUBE_BOTTOM + CUBE_TOP) / 2, 0.0)), MeshComponent("cube"),
                        MaterialComponent("grey"))
    if extra_point_light:  # a light before the sun: the sun's slot in the lights block is then 1
        scene.create_entity(TransformComponent((0, 5, 5)), LightComponent("point", (0.2, 0.2, 0.2)))
    sun = sun_position(towards_light)
    scene.create_entity(TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", (1, 1, 1), 1.0, cast_shadows=cast_shadows,
                                       shadow_extent=5.0, shadow_depth=30.0))
    scene.create_entity(TransformComponent(), LightComponent("ambient", (0.15, 0.15, 0.15)))
    eye = (0.0, 10.0, 0.0)
    scene.create_entity(TransformComponent(eye, rotation=(-90, 0, 0)),
                        CameraComponent(near=0.1, far=50.0, projection="orthographic", height=VIEW_HEIGHT,
                                        reverse_z=reverse_z))
    return scene


def pixel_of(x: float, z: float) -> tuple[int, int]:
    """(column, row) of the floor point (x, 0, z) in the top-down picture: +x right, +z down."""
    scale = H / VIEW_HEIGHT
    return int(W / 2 + x * scale), int(H / 2 + z * scale)


def shadow_points(towards_light) -> tuple[list[tuple[float, float]], list[tuple[float, float]]]:
    """Floor points (x, z) certainly in the cube's shadow and certainly lit, from the light's direction.

    A point of the cube at height y throws its shadow to (x, z) - y · (l.x, l.z) / l.y: the top face's
    shadow is a unit square around ``centre``, and its middle lies half a unit from the shadow's edges.
    """
    lx, ly, lz = np.asarray(towards_light, float) / np.linalg.norm(towards_light)
    centre = np.array([-CUBE_TOP * lx / ly, -CUBE_TOP * lz / ly])
    shadowed = [tuple(centre)]
    lit = [tuple(-centre), tuple(centre + (0.0, 2.0)), tuple(centre - (0.0, 2.0)), (3.0, 3.0)]
    for point in shadowed + lit:
        assert max(abs(point[0]), abs(point[1])) > 0.75, "a test point hides under the cube"
    return shadowed, lit


def render(backend: str, scene: Scene, frames: int = 2) -> tuple[np.ndarray, Application]:
    app = make_app(backend)
    app.add_scene(scene)
    app.run(frames=frames)
    return app.capture(), app


def brightness(image: np.ndarray, point: tuple[float, float]) -> int:
    col, row = pixel_of(*point)
    return int(image[row, col, :3].astype(int).mean())


@pytest.mark.parametrize("towards", [(1.0, 2.0, 0.0), (-0.5, 2.0, 1.0)], ids=["from-right", "from-back-left"])
def test_the_cube_shadows_the_floor_where_the_geometry_says(backend, towards):
    image, app = render(backend, shadow_scene(towards))
    assert app.renderer.stats["shadow_passes"] >= 1
    app.close()
    shadowed, lit = shadow_points(towards)
    lit_level = min(brightness(image, p) for p in lit)
    for point in shadowed:
        assert brightness(image, point) < lit_level - 40, f"no shadow at {point}"
    # Lit floor is as bright as floor without any shadow map at all.
    plain, app = render(backend, shadow_scene(towards, cast_shadows=False))
    app.close()
    for point in lit:
        assert abs(brightness(image, point) - brightness(plain, point)) <= 1, f"a shadow at {point}"
    # Everything differs only where the shadow falls: under a quarter of the picture.
    changed = np.abs(image[..., :3].astype(int) - plain[..., :3].astype(int)).max(axis=2) > 8
    assert 0.01 < changed.mean() < 0.25


def test_no_shadow_casting_light_builds_no_shadow_pass(backend):
    """The project's rule: no shadow pass, pipeline, shader or map unless a light casts shadows."""
    _image, app = render(backend, shadow_scene(cast_shadows=False))
    without = dict(app.renderer.stats)
    assert without.get("shadow_passes", 0) == 0 and without.get("shadow_maps_created", 0) == 0
    assert "gandalf.shadow_depth" not in app.renderer.shaders
    app.close()
    _image, app = render(backend, shadow_scene())
    with_shadows = app.renderer.stats
    assert with_shadows["shadow_passes"] == 2 and with_shadows["shadow_maps_created"] == 1  # one a frame, one map
    assert with_shadows["shaders_created"] == without["shaders_created"] + 1
    # One depth-only pipeline (WebGPU) or one vertex array per mesh (OpenGL) on top of the scene's own.
    key = "pipelines_created" if backend == "webgpu" else "vertex_arrays_created"
    extra = 1 if backend == "webgpu" else 2
    assert with_shadows[key] == without[key] + extra
    app.close()


@pytest.mark.parametrize("extra_point_light", [False, True], ids=["sun-only", "sun-second"])
def test_backends_draw_the_same_shadows(extra_point_light):
    """A perspective view from the side: shadow on the floor and the cube's own shading, in both APIs."""
    images = {}
    for backend in ("opengl", "webgpu"):
        scene = shadow_scene((-1.0, 1.5, 0.5), extra_point_light=extra_point_light)
        camera = next(e for e in scene.entities if scene.try_component(e, CameraComponent) is not None)
        eye = np.array([3.0, 4.0, 6.0])
        scene.add_component(camera, TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0.5, 0))))
        scene.add_component(camera, CameraComponent(50.0, 0.1, 50.0))
        images[backend], app = render(backend, scene)
        app.close()
    dark = images["opengl"][..., :3].astype(int).mean(axis=2) < 60
    assert dark.mean() > 0.01, "no shadow in the picture"
    compare_images(images["webgpu"], images["opengl"], "shadows-backends-agree", min_psnr=40.0, max_diff=2)


def test_moving_the_light_moves_the_shadow(backend):
    from_right, from_left = (1.0, 2.0, 0.0), (-1.0, 2.0, 0.0)
    scene = shadow_scene(from_right)
    sun = next(e for e in scene.entities
               if (light := scene.try_component(e, LightComponent)) is not None and light.cast_shadows)
    with make_app(backend) as app:
        app.add_scene(scene)
        app.run(frames=1)
        before = app.capture()
        position = sun_position(from_left)
        transform = scene.get_component(sun, TransformComponent)
        transform.translation = position
        transform.quaternion = look_at_rotation(position, (0, 0, 0))
        app.run(frames=1)
        after = app.capture()
        created = app.renderer.stats["shadow_maps_created"]
    (left_shadow,), _ = shadow_points(from_right)
    (right_shadow,), _ = shadow_points(from_left)
    assert brightness(before, left_shadow) < brightness(before, right_shadow) - 40
    assert brightness(after, right_shadow) < brightness(after, left_shadow) - 40
    assert created == 1  # the same map, redrawn


def test_switching_shadows_off_at_run_time_gives_the_unshadowed_picture(backend):
    scene = shadow_scene()
    sun = next(e for e in scene.entities
               if (light := scene.try_component(e, LightComponent)) is not None and light.cast_shadows)
    plain, app = render(backend, shadow_scene(cast_shadows=False))
    app.close()
    with make_app(backend) as app:
        app.add_scene(scene)
        app.run(frames=1)
        passes = app.renderer.stats["shadow_passes"]
        scene.get_component(sun, LightComponent).cast_shadows = False
        app.run(frames=2)
        assert app.renderer.stats["shadow_passes"] == passes
        assert np.array_equal(app.capture(), plain)


def test_reverse_z_camera_draws_the_same_shadows(backend):
    normal, app = render(backend, shadow_scene())
    app.close()
    reverse, app = render(backend, shadow_scene(reverse_z=True))
    app.close()
    compare_images(reverse, normal, f"shadows-reverse-z-{backend}", min_psnr=40.0, max_diff=2)


def test_many_frames_create_nothing_new(backend):
    with make_app(backend) as app:
        app.add_scene(shadow_scene())
        app.run(frames=3)
        live, created = app.renderer.live_objects(), dict(app.renderer.stats)
        app.run(frames=30)
        assert app.renderer.live_objects() == live
        ignore = {"draw_calls", "shadow_passes"}
        assert {k: v for k, v in app.renderer.stats.items() if k not in ignore} == {
            k: v for k, v in created.items() if k not in ignore
        }
        assert app.renderer.stats["shadow_passes"] == created["shadow_passes"] + 30


def test_transparent_surfaces_cast_no_shadow(backend):
    scene = shadow_scene()
    scene.assets.material("glass", MaterialData("shadowed", color=(0.8, 0.8, 0.8, 0.5), blend="alpha",
                                                depth_write=False))
    cube_entity = next(e for e in scene.entities if (m := scene.try_component(e, MeshComponent)) is not None
                       and m.mesh == "cube")
    scene.add_component(cube_entity, MaterialComponent("glass"))
    image, app = render(backend, scene)
    app.close()
    (shadowed,), _ = shadow_points((1.0, 2.0, 0.0))
    plain, app = render(backend, shadow_scene(cast_shadows=False))
    app.close()
    assert abs(brightness(image, shadowed) - brightness(plain, shadowed)) <= 1


@pytest.mark.parametrize("kind", ["point", "ambient"])
def test_only_directional_lights_cast_shadows(kind):
    with pytest.raises(ValueError, match="LightComponent.cast_shadows"):
        LightComponent(kind, cast_shadows=True)
    light = LightComponent(kind)
    with pytest.raises(ValueError, match="LightComponent.cast_shadows"):
        light.cast_shadows = True
    sun = LightComponent("directional", cast_shadows=True)
    with pytest.raises(ValueError, match="LightComponent.kind"):
        sun.kind = kind


@pytest.mark.parametrize("field,value", [("shadow_extent", 0.0), ("shadow_extent", float("nan")),
                                         ("shadow_depth", -1.0), ("shadow_depth", float("inf"))])
def test_shadow_box_fields_are_checked(field, value):
    with pytest.raises(ValueError, match=f"LightComponent.{field}"):
        LightComponent("directional", cast_shadows=True, **{field: value})
    light = LightComponent("directional")
    with pytest.raises(ValueError, match=f"LightComponent.{field}"):
        setattr(light, field, value)


@pytest.mark.parametrize("depth_range", ["opengl", "webgpu"])
def test_the_light_box_maps_onto_the_whole_clip_volume(depth_range):
    """Corners of the shadow box land on the NDC corners of the API's depth range; the light's slot counts
    point and directional lights only, as the lights part of the block does."""
    from gandalf_core.math import depth_range as ends
    from gandalf_core.math import trs
    from gandalf_core.render.frame import SHADOW_BYTES, SHADOW_MAP_SIZE
    from gandalf_core.systems.light_system import pack_shadow

    sun = np.array([2.0, 6.0, -1.0])
    transform = TransformComponent()
    transform.world = trs(sun, look_at_rotation(sun, (0, 0, 0)), (2.0, 0.5, 3.0))  # scale must not matter
    light = LightComponent("directional", cast_shadows=True, shadow_extent=3.0, shadow_depth=20.0)
    pairs = [(LightComponent("ambient"), TransformComponent()), (LightComponent("point"), TransformComponent()),
             (light, transform)]
    block = np.frombuffer(pack_shadow(pairs, depth_range), np.float32)
    assert block.nbytes == SHADOW_BYTES
    matrix = block[:16].reshape(4, 4).T.astype(np.float64)
    assert block[16] == 1.0 and block[19] == 1.0  # on; the sun is the second light slot (ambient takes none)
    assert block[18] == pytest.approx(1.0 / SHADOW_MAP_SIZE)
    forward = -transform.world[:3, 2] / np.linalg.norm(transform.world[:3, 2])
    lo, hi = ends(depth_range)
    for along, expected in [(-10.0, lo), (0.0, (lo + hi) / 2), (10.0, hi)]:
        clip = matrix @ np.append(sun + along * forward, 1.0)
        assert clip[2] / clip[3] == pytest.approx(expected, abs=1e-5)
    side = np.cross(forward, [0.0, 1.0, 0.0])
    side /= np.linalg.norm(side)
    clip = matrix @ np.append(sun + 3.0 * side, 1.0)
    assert max(abs(clip[0]), abs(clip[1])) == pytest.approx(1.0, abs=1e-5)
    assert not np.any(np.frombuffer(pack_shadow(pairs[:2], depth_range), np.float32))


def test_the_shadow_map_keeps_its_own_texture_unit_in_opengl():
    """u_shadow_map (declared first, through shadow.glsl) is no material texture: the material's start at 0."""
    frag = SHADOWED_FRAG.replace("out vec4 f_color;", "uniform sampler2D u_detail;\nout vec4 f_color;")
    with Application("opengl", 8, 8, headless=True) as app:
        shader = app.renderer.shaders.build("textured", SHADOWED_VERT, frag)
        assert shader.samplers == ["u_detail"]
        assert shader.program["u_shadow_map"].value == 15


def test_textures_built_during_a_frame_do_not_replace_the_shadow_map():
    """Some drivers (16 texture units) put moderngl's scratch unit on the shadow map's unit 15."""
    from gandalf_core.components import MaterialComponent, MeshComponent, TransformComponent
    from gandalf_core.resources import MaterialData, solid

    frag = SHADOWED_FRAG.replace("out vec4 f_color;", "uniform sampler2D u_tex;\nout vec4 f_color;").replace(
        "f_color = vec4(c, 1.0);", "f_color = vec4(c * texture(u_tex, vec2(0.5)).rgb, 1.0);")
    scene = shadow_scene()
    scene.assets.texture("white", solid((1.0, 1.0, 1.0), 4))
    scene.assets.material("tex", MaterialData("a_shadowed_tex", ["white"], color=(0.8, 0.8, 0.8)))
    scene.create_entity(TransformComponent((4.0, 0.5, 3.0)), MeshComponent("cube"), MaterialComponent("tex"))
    with make_app("opengl") as app:
        app.renderer.shaders.build("a_shadowed_tex", SHADOWED_VERT, frag)
        app.renderer.ctx.default_texture_unit = 15
        app.add_scene(scene)
        app.run(frames=1)  # the first frame builds the texture
        (shadowed,), _ = shadow_points((1.0, 2.0, 0.0))
        first = brightness(app.capture(), shadowed)
        app.run(frames=1)
        assert first == brightness(app.capture(), shadowed) < 60


# --- the shadow bias knob (LightComponent.shadow_bias; step 07's shadow study varies it) -------------------------
@pytest.mark.parametrize("value", [-0.1, float("nan"), float("inf"), True, "1"])
def test_shadow_bias_is_checked(value):
    with pytest.raises(ValueError, match="LightComponent.shadow_bias"):
        LightComponent("directional", cast_shadows=True, shadow_bias=value)


def test_shadow_bias_scales_the_packed_bias_and_defaults_to_the_old_bytes():
    from gandalf_core.math import trs
    from gandalf_core.systems.light_system import pack_shadow

    sun = sun_position((1.0, 2.0, 0.0))
    transform = TransformComponent()
    transform.world = trs(sun, look_at_rotation(sun, (0, 0, 0)), (1.0, 1.0, 1.0))

    def block(**bias) -> np.ndarray:
        light = LightComponent("directional", cast_shadows=True, shadow_extent=5.0, shadow_depth=30.0, **bias)
        return np.frombuffer(pack_shadow([(light, transform)]), np.float32)

    default, doubled, off = block(), block(shadow_bias=2.0), block(shadow_bias=0.0)
    assert LightComponent("directional").shadow_bias == 1.0
    assert np.array_equal(default, block(shadow_bias=1.0))
    assert doubled[17] == pytest.approx(2.0 * default[17]) and off[17] == 0.0
    assert np.array_equal(np.delete(doubled, 17), np.delete(default, 17))


def test_shadow_bias_survives_usd(tmp_path):
    from step07_advanced.usd import load_scene, save_scene

    scene = shadow_scene()
    for entity in scene.entities:
        for component in scene.components_of(entity):
            if isinstance(component, LightComponent) and component.cast_shadows:
                component.shadow_bias = 0.375
    loaded = load_scene(save_scene(scene, tmp_path / "bias.usda"))
    biases = [c.shadow_bias for e in loaded.entities for c in loaded.components_of(e)
              if isinstance(c, LightComponent) and c.cast_shadows]
    assert biases == [0.375]


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_no_bias_brings_shadow_acne_and_the_default_bias_removes_it(backend):
    """Bias 0: the lit floor shadows itself (acne, nearly every pixel darker than without shadows); the default
    bias leaves only the cube's real shadow (measured: 95 of 6912 pixels, both APIs)."""
    unshadowed, app = render(backend, shadow_scene(cast_shadows=False))
    app.close()
    darker = {}
    for bias in (0.0, 1.0):
        scene = shadow_scene()
        for entity in scene.entities:
            for component in scene.components_of(entity):
                if isinstance(component, LightComponent) and component.cast_shadows:
                    component.shadow_bias = bias
        image, app = render(backend, scene)
        app.close()
        diff = unshadowed[..., :3].astype(int) - image[..., :3].astype(int)
        darker[bias] = int((diff.max(axis=2) > 3).sum())
    assert darker[0.0] > 0.5 * W * H and darker[1.0] < 0.05 * W * H, darker
