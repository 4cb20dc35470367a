"""Cameras and camera controllers, headless in both APIs.

Tolerances: the same scene and camera give the same picture in OpenGL and WebGPU to PSNR >= 40 dB; two
cameras with the same world pose (reached differently) give PSNR >= 60 dB; matrices agree to 1e-9.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from core_shaders import build_shaders

from gandalf_core import Application, ClearColorComponent, LinkComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.math import invert_affine, look_at, look_at_rotation, quat_from_euler, trs
from gandalf_core.render import RenderSystem
from gandalf_core.resources import MaterialData, checkerboard, cube, plane
from gandalf_core.systems.camera_controllers import (
    FlyControllerComponent,
    FlyControllerSystem,
    OrbitControllerComponent,
    OrbitControllerSystem,
    heading_of,
)
from gandalf_tools.testing import compare_images, psnr

W, H = 96, 72


def make_app(backend: str, width: int = W, height: int = H) -> Application:
    app = Application(backend, width, height, headless=True, fixed_dt=1 / 60)
    build_shaders(app.renderer.shaders, backend, "unlit")
    return app


def world_scene() -> Scene:
    """A checkered ground with three cubes of different colours, no camera yet."""
    scene = Scene("camera test")
    scene.assets.mesh("cube", cube())
    scene.assets.mesh("ground", plane(8.0))
    scene.assets.texture("checker", checkerboard(32, 8, (0.9, 0.9, 0.9), (0.3, 0.3, 0.3)))
    scene.assets.material("ground", MaterialData("unlit", ["checker"]))
    for name, color in (("red", (1, 0.2, 0.1)), ("green", (0.2, 0.9, 0.2)), ("blue", (0.2, 0.3, 1.0))):
        scene.assets.material(name, MaterialData("unlit", ["checker"], color=color))
    scene.create_entity(ClearColorComponent((0.5, 0.6, 0.8)))
    scene.create_entity(TransformComponent(), MeshComponent("ground"), MaterialComponent("ground"))
    for x, name in ((-2.0, "red"), (0.0, "green"), (2.0, "blue")):
        scene.create_entity(TransformComponent((x, 0.5, -x)), MeshComponent("cube"), MaterialComponent(name))
    return scene


def add_camera(scene: Scene, eye=(3.0, 4.0, 7.0), target=(0.0, 0.5, 0.0), **camera):
    eye = np.asarray(eye, dtype=float)
    return scene.create_entity(TransformComponent(eye, quaternion=look_at_rotation(eye, target)),
                               CameraComponent(**{"fov": 50.0, "near": 0.1, "far": 100.0, **camera}))


def picture(backend: str, scene: Scene, frames: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """(image, view matrix) after ``frames`` frames."""
    with make_app(backend) as app:
        app.add_scene(scene)
        app.run(frames=frames)
        return app.capture(), app.scene.get_system(RenderSystem).camera()[0]


# --- the camera follows its entity ---------------------------------------------------------------------


def test_parented_camera_follows_its_moving_parent(backend):
    scene = world_scene()
    rig = scene.create_entity(TransformComponent((0.0, 0.0, 0.0)), LinkComponent())
    eye = np.array([0.0, 2.0, 6.0])
    camera = scene.create_entity(TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0.5, 0))),
                                 CameraComponent(50.0, 0.1, 100.0), LinkComponent(rig))
    with make_app(backend) as app:
        app.add_scene(scene)
        app.step()
        first = app.capture()
        rig_t = scene.get_component(rig, TransformComponent)
        rig_t.translation = (1.5, 0.5, 0.0)
        rig_t.quaternion = quat_from_euler((0.0, 40.0, 0.0))
        app.step()
        moved = app.capture()
        view = app.scene.get_system(RenderSystem).camera()[0]
    cam_t = scene.get_component(camera, TransformComponent)
    expected_world = trs((1.5, 0.5, 0.0), quat_from_euler((0.0, 40.0, 0.0)), 1.0) @ trs(eye, cam_t.quaternion, 1.0)
    np.testing.assert_allclose(view, invert_affine(expected_world), atol=1e-9)  # this frame's pose, not stale
    assert psnr(moved, first) < 25.0
    # The same world pose given directly to an unparented camera draws the same picture.
    direct = world_scene()
    t, q = expected_world[:3, 3], look_at_rotation(expected_world[:3, 3], expected_world[:3, 3] - expected_world[:3, 2])
    direct.create_entity(TransformComponent(t, quaternion=q), CameraComponent(50.0, 0.1, 100.0))
    compare_images(moved, picture(backend, direct)[0], f"parented-camera-{backend}", min_psnr=60.0)


# --- clear errors instead of NaN ----------------------------------------------------------------------


@pytest.mark.parametrize("kwargs, field", [
    ({"fov": 0.0}, "fov"), ({"fov": 180.0}, "fov"), ({"fov": math.nan}, "fov"), ({"fov": -10.0}, "fov"),
    ({"near": 0.0}, "near"), ({"near": -1.0}, "near"), ({"near": 5.0, "far": 5.0}, "far"),
    ({"near": 5.0, "far": 1.0}, "far"), ({"aspect": 0.0}, "aspect"), ({"aspect": -2.0}, "aspect"),
    ({"projection": "orthographic", "height": 0.0}, "height"), ({"projection": "fisheye"}, "projection"),
    ({"projection": "orthographic", "near": 1.0, "far": 1.0}, "far"),
])
def test_degenerate_camera_raises_a_clear_error(kwargs, field):
    with pytest.raises(ValueError, match=field):
        CameraComponent(**kwargs)


def test_camera_with_a_zero_scale_names_the_entity():
    scene = world_scene()
    camera = add_camera(scene)
    scene.get_component(camera, TransformComponent).scale = (1.0, 0.0, 1.0)
    with make_app("opengl") as app:
        app.add_scene(scene)
        with pytest.raises(ValueError, match="camera .*singular"):
            app.step()


def test_camera_made_degenerate_at_run_time_raises_not_nan():
    scene = world_scene()
    camera = add_camera(scene)
    with make_app("opengl") as app:
        app.add_scene(scene)
        app.step()
        component = scene.get_component(camera, CameraComponent)
        with pytest.raises(ValueError, match=r"CameraComponent\.fov must be a number in \(0, 180\).*got 0\.0"):
            component.fov = 0.0  # refused where it is set, naming the field
        assert component.fov == 50.0  # the camera keeps its good value
        component.near, component.far = 5.0, 1.0  # each fine alone: together checked when the frame is built
        with pytest.raises(ValueError, match=r"CameraComponent\.far must be greater than CameraComponent\.near"):
            app.step()


# --- aspect follows the target ------------------------------------------------------------------------


def test_aspect_follows_a_resize_event(backend):
    scene = world_scene()
    add_camera(scene)
    with make_app(backend) as app:
        app.add_scene(scene)
        app.step()
        projection = app.scene.get_system(RenderSystem).camera()[1]
        assert projection[1, 1] / projection[0, 0] == pytest.approx(W / H)
        app.input.resize(60, 90)
        app.step()
        projection = app.scene.get_system(RenderSystem).camera()[1]
        assert projection[1, 1] / projection[0, 0] == pytest.approx(60 / 90)
        assert app.capture().shape == (90, 60, 4)
        app.renderer.resize(100, 50)
        app.step()
        projection = app.scene.get_system(RenderSystem).camera()[1]
        assert projection[1, 1] / projection[0, 0] == pytest.approx(2.0)


def test_fixed_aspect_ignores_the_target():
    scene = world_scene()
    add_camera(scene, aspect=1.0)
    with make_app("opengl") as app:
        app.add_scene(scene)
        app.step()
        projection = app.scene.get_system(RenderSystem).camera()[1]
    assert projection[0, 0] == pytest.approx(projection[1, 1])


# --- both APIs, orthographic, reverse-Z ---------------------------------------------------------------


def test_opengl_and_webgpu_give_the_same_picture():
    scene_a, scene_b = world_scene(), world_scene()
    add_camera(scene_a)
    add_camera(scene_b)
    gl, wg = picture("opengl", scene_a)[0], picture("webgpu", scene_b)[0]
    compare_images(wg, gl, "camera-gl-vs-webgpu", min_psnr=40.0)


def test_orthographic_camera_keeps_sizes_at_any_distance(backend):
    """A unit cube seen face-on by an orthographic camera 4 units tall covers a quarter of the height."""
    images = []
    for distance in (3.0, 30.0):
        scene = Scene("ortho")
        scene.assets.mesh("cube", cube())
        scene.assets.texture("white", checkerboard(2, 1, (1, 1, 1), (1, 1, 1)))
        scene.assets.material("M", MaterialData("unlit", ["white"]))
        scene.create_entity(TransformComponent(), MeshComponent("cube"), MaterialComponent("M"))
        scene.create_entity(TransformComponent((0.0, 0.0, distance)),
                            CameraComponent(near=0.1, far=100.0, projection="orthographic", height=4.0))
        image, view = picture(backend, scene)
        images.append(image)
        rows = np.flatnonzero(image[..., 0].max(axis=1) > 128)
        cols = np.flatnonzero(image[..., 0].max(axis=0) > 128)
        # 1 world unit = H / 4 = 18 pixels tall and wide (the aspect keeps squares square); +-1 pixel for edges.
        assert abs(len(rows) - H / 4) <= 1 and abs(len(cols) - H / 4) <= 1
        assert abs(rows.mean() - (H - 1) / 2) <= 0.5 and abs(cols.mean() - (W - 1) / 2) <= 0.5
    compare_images(images[1], images[0], f"ortho-distance-{backend}", min_psnr=60.0)


def test_reverse_z_camera_draws_the_same_picture(backend):
    normal_scene, reverse_scene = world_scene(), world_scene()
    add_camera(normal_scene, near=0.05, far=1000.0)
    add_camera(reverse_scene, near=0.05, far=1000.0, reverse_z=True)
    normal = picture(backend, normal_scene)[0]
    reverse = picture(backend, reverse_scene)[0]
    compare_images(reverse, normal, f"camera-reverse-z-{backend}", min_psnr=40.0)


# --- controllers with synthetic input -----------------------------------------------------------------


def orbit_app(backend: str = "opengl", **orbit):
    scene = world_scene()
    camera = scene.create_entity(TransformComponent(), CameraComponent(50.0, 0.1, 100.0),
                                 OrbitControllerComponent(**{"target": (0.0, 0.5, 0.0), "distance": 6.0,
                                                             "yaw": 0.0, "pitch": 20.0, **orbit}))
    scene.add_system(OrbitControllerSystem())
    app = make_app(backend)
    app.add_scene(scene)
    return app, camera


def orbit_view(distance: float, yaw: float, pitch: float, target=(0.0, 0.5, 0.0)) -> np.ndarray:
    y, p = math.radians(yaw), math.radians(pitch)
    eye = np.asarray(target) + distance * np.array([math.cos(p) * math.sin(y), math.sin(p), math.cos(p) * math.cos(y)])
    return look_at(eye, target)


def current_view(app) -> np.ndarray:
    return app.scene.get_system(RenderSystem).camera()[0]


def test_orbit_drag_rotates_and_scroll_zooms():
    app, _ = orbit_app(sensitivity=0.5, zoom_speed=0.1)
    with app:
        app.step()
        np.testing.assert_allclose(current_view(app), orbit_view(6.0, 0.0, 20.0), atol=1e-9)
        app.input.move_mouse(10, 10)  # no button: nothing happens
        app.step()
        np.testing.assert_allclose(current_view(app), orbit_view(6.0, 0.0, 20.0), atol=1e-9)
        app.input.button(0)
        app.input.move_mouse(50, 30)  # dx 40 -> yaw -20, dy 20 -> pitch +10
        app.step()
        np.testing.assert_allclose(current_view(app), orbit_view(6.0, -20.0, 30.0), atol=1e-9)
        app.input.scroll(0, 2)
        app.step()
        np.testing.assert_allclose(current_view(app), orbit_view(6.0 * math.exp(-0.2), -20.0, 30.0), atol=1e-9)


def test_orbit_zoom_and_pitch_are_clamped():
    app, camera = orbit_app(min_distance=2.0, max_distance=10.0)
    with app:
        app.input.scroll(0, 1000)
        app.input.button(0)
        app.input.move_mouse(0, 1e6)
        app.step()
        orbit = app.scene.get_component(camera, OrbitControllerComponent)
        assert orbit.distance == pytest.approx(2.0) and orbit.pitch == pytest.approx(89.0)
        view = current_view(app)
        assert np.all(np.isfinite(view)) and view[1, 1] > 0  # still upright: no flip over the pole
        app.input.scroll(0, -1000)
        app.input.move_mouse(0, -1e6)
        app.step()
        assert orbit.distance == pytest.approx(10.0) and orbit.pitch == pytest.approx(-89.0)
        assert np.all(np.isfinite(current_view(app)))


@pytest.mark.parametrize("kwargs, field", [({"distance": 0.0}, "distance"), ({"min_distance": -1.0}, "min_distance"),
                                           ({"min_distance": 5.0, "max_distance": 1.0}, "min_distance"),
                                           ({"max_pitch": 90.0}, "max_pitch"), ({"yaw": math.inf}, "yaw"),
                                           ({"target": (0, 0)}, "target")])
def test_orbit_component_rejects_bad_values(kwargs, field):
    with pytest.raises(ValueError, match=field):
        OrbitControllerComponent(**kwargs)


def test_controllers_work_without_an_application():
    scene = Scene("no app")
    orbit = scene.create_entity(TransformComponent(), OrbitControllerComponent(distance=3.0, yaw=90.0, pitch=0.0))
    fly = scene.create_entity(TransformComponent((1.0, 2.0, 3.0)), FlyControllerComponent())
    scene.add_system(OrbitControllerSystem())
    scene.add_system(FlyControllerSystem())
    scene.update(1 / 60)
    np.testing.assert_allclose(scene.get_component(orbit, TransformComponent).translation, [3.0, 0.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(scene.get_component(fly, TransformComponent).translation, [1.0, 2.0, 3.0])


def fly_app(yaw: float = 0.0, pitch: float = 0.0):
    scene = world_scene()
    camera = scene.create_entity(TransformComponent((0.0, 1.0, 5.0), quaternion=quat_from_euler((pitch, yaw, 0.0))),
                                 CameraComponent(50.0, 0.1, 100.0), FlyControllerComponent(speed=2.0, sensitivity=0.5))
    scene.add_system(FlyControllerSystem())
    app = make_app("opengl")
    app.add_scene(scene)
    return app, camera


def test_fly_wasd_moves_in_the_camera_frame():
    app, camera = fly_app(yaw=90.0)  # looking down -X: forward is -X, right is -Z
    transform = app.scene.get_component(camera, TransformComponent)
    with app:
        app.step()
        np.testing.assert_allclose(transform.translation, [0.0, 1.0, 5.0], atol=1e-12)
        app.input.key("W")
        app.run(frames=30)  # half a second at 2 units per second
        np.testing.assert_allclose(transform.translation, [-1.0, 1.0, 5.0], atol=1e-9)
        app.input.key("W", "release")
        app.input.key("D")
        app.run(frames=30)
        np.testing.assert_allclose(transform.translation, [-1.0, 1.0, 4.0], atol=1e-9)
        app.input.key("D", "release")
        app.input.key("E")
        app.input.key("S")  # diagonal: normalised, still 2 units per second in total
        app.run(frames=30)
        step = 1.0 / math.sqrt(2.0)
        np.testing.assert_allclose(transform.translation, [-1.0 + step, 1.0 + step, 4.0], atol=1e-9)
        app.input.key("E", "release")
        app.input.key("S", "release")
        app.input.key("Q")
        app.run(frames=30)
        np.testing.assert_allclose(transform.translation, [-1.0 + step, step, 4.0], atol=1e-9)


def test_fly_right_drag_turns_and_keeps_the_initial_heading():
    app, camera = fly_app(yaw=30.0, pitch=-10.0)
    transform = app.scene.get_component(camera, TransformComponent)
    with app:
        app.step()
        assert heading_of(transform.quaternion) == pytest.approx((30.0, -10.0))
        app.input.move_mouse(20, 20)  # no button: no turn
        app.step()
        assert heading_of(transform.quaternion) == pytest.approx((30.0, -10.0))
        app.input.button(1)
        app.input.move_mouse(40, 30)  # right 20 px -> yaw -10, down 10 px -> pitch -5
        app.step()
        assert heading_of(transform.quaternion) == pytest.approx((20.0, -15.0))
        app.input.move_mouse(40, 1e6)
        app.step()
        assert heading_of(transform.quaternion)[1] == pytest.approx(-89.0)
        assert np.all(np.isfinite(current_view(app)))


@pytest.mark.parametrize(("make", "needle"), [
    (lambda: CameraComponent("wide"), r"CameraComponent\.fov must be a number in \(0, 180\).*got 'wide'"),
    (lambda: CameraComponent(near="close"), r"CameraComponent\.near must be a finite number > 0, got 'close'"),
    (lambda: CameraComponent(far=float("nan")), r"CameraComponent\.far must be"),
    (lambda: CameraComponent(projection="fisheye"), r"CameraComponent\.projection must be one of 'perspective'"),
    (lambda: CameraComponent(primary=1), r"CameraComponent\.primary must be True or False, got 1"),
    (lambda: CameraComponent(reverse_z="yes"), r"CameraComponent\.reverse_z must be True or False"),
    (lambda: CameraComponent(projection="orthographic", height=-2), r"CameraComponent\.height must be"),
])
def test_bad_camera_fields_name_the_field(make, needle):
    with pytest.raises(ValueError, match=needle):
        make()


@pytest.mark.parametrize("value", ["blue", (1, 0), (1, float("inf"), 0), (-0.1, 0, 0), None])
def test_bad_clear_colours_name_the_field(value):
    from gandalf_core.components import ClearColorComponent

    with pytest.raises(ValueError, match=r"ClearColorComponent\.color must be 3 or 4 finite floats"):
        ClearColorComponent(value)
