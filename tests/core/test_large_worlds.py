"""Large worlds and long runs: camera-relative positions and a wrapped time uniform, in both APIs.

* A scene moved 1e6 units from the origin (camera, objects, point lights, the shadow-casting sun) draws the same
  picture as at the origin: positions become camera-relative in float64 before they are float32. Measured:
  identical bytes, or a few pixels 1/255 apart; allowed: no channel more than 2/255 apart.
* A small cube moving past the camera at 1e6 units follows its path within 0.5 px (its drawn centre against the
  float64 projection of its centre).
* The time uniform keeps 1/60 s steps exact to 1% at t = 3e7 s (a year is 3.15e7 s).
* Objects, camera and lights scaled together from 1e-20 to 1e20 shade as at scale 1 (normals from the scaled
  cofactor matrix, every vector normalised after dividing by its largest component): no channel more than 2/255.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from core_shaders import build_shaders

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.render.frame import TIME_WRAP, pack_frame
from gandalf_core.resources import MaterialData, cube, plane, uv_sphere

W, H = 96, 72
FAR = np.array([1e6, -3e5, 2e6])


def lit_scene(offset: np.ndarray) -> Scene:
    scene = Scene("far away")
    scene.assets.mesh("sphere", uv_sphere(0.8, 32, 16))
    scene.assets.mesh("floor", plane(8.0, 1))
    scene.assets.material("M", MaterialData("lit", color=(0.9, 0.6, 0.3)))
    for x in (-1.2, 1.2):
        scene.create_entity(TransformComponent(offset + (x, 0.0, 0.0)), MeshComponent("sphere"), MaterialComponent("M"))
    scene.create_entity(TransformComponent(offset + (0.0, -0.8, 0.0)), MeshComponent("floor"), MaterialComponent("M"))
    sun = offset + (-2.0, 4.0, 3.0)
    scene.create_entity(TransformComponent(sun, quaternion=look_at_rotation(sun, offset)),
                        LightComponent("directional", intensity=1.2, cast_shadows=True))
    scene.create_entity(TransformComponent(offset + (1.0, 1.5, 1.5)), LightComponent("point", intensity=4.0, range=6.0))
    eye = offset + (0.0, 1.0, 5.0)
    scene.create_entity(TransformComponent(eye, quaternion=look_at_rotation(eye, offset)),
                        CameraComponent(60.0, 0.1, 50.0))
    return scene


def render(backend: str, scene: Scene, frames: int = 1) -> list[np.ndarray]:
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        build_shaders(app.renderer.shaders, backend, "lit", "flat")
        app.add_scene(scene)
        pictures = []
        for _ in range(frames):
            app.run(frames=1)
            pictures.append(app.capture())
        return pictures


def test_a_world_far_from_the_origin_draws_like_one_at_it(backend):
    near = render(backend, lit_scene(np.zeros(3)))[0]
    far = render(backend, lit_scene(FAR))[0]
    worst = int(np.abs(near.astype(int) - far.astype(int)).max())
    assert worst <= 2, f"{backend}: the scene at {FAR} differs from the one at the origin by up to {worst}/255"
    assert near[..., :3].max() > 60, "the test scene should be lit"


@pytest.mark.parametrize("offset", [np.zeros(3), FAR])
def test_a_small_moving_cube_far_away_follows_its_path(backend, offset):
    # A 0.2-unit cube passing 3 units in front of the camera at 1e6 units, 0.01 units a frame.
    scene = Scene("moving cube")
    scene.assets.mesh("cube", cube(0.2))
    scene.assets.material("white", MaterialData("flat"))
    eye = offset + (0.0, 0.0, 3.0)
    scene.create_entity(TransformComponent(eye), CameraComponent(60.0, 0.1, 100.0))
    mover = scene.create_entity(TransformComponent(offset.copy()), MeshComponent("cube"), MaterialComponent("white"))

    errors = []
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        build_shaders(app.renderer.shaders, backend, "flat")
        app.add_scene(scene)
        transform = scene.get_component(mover, TransformComponent)
        focal = (H / 2) / np.tan(np.radians(30.0))
        for k in range(12):
            position = offset + (-0.3 + 0.05 * k, 0.02 * k - 0.1, 0.0)
            transform.translation = position
            app.run(frames=1)
            mask = app.capture()[..., 0] > 128
            ys, xs = np.nonzero(mask)
            relative = position - eye
            expected = (W / 2 + focal * relative[0] / -relative[2], H / 2 - focal * relative[1] / -relative[2])
            errors.append(np.hypot(xs.mean() + 0.5 - expected[0], ys.mean() + 0.5 - expected[1]))
            width = xs.max() - xs.min() + 1
            assert abs(width - focal * 0.2 / 3.0) <= 2.0, f"frame {k}: drawn {width} px wide"
    assert max(errors) <= 0.5, f"{backend} at {offset}: off its path by up to {max(errors):.2f} px"


def test_time_steps_stay_exact_for_a_year():
    def packed_time(t: float) -> tuple[float, float]:
        frame = np.frombuffer(pack_frame(np.eye(4), np.eye(4), np.zeros(3), t, 1 / 60), np.float32)
        return float(frame[36]), float(frame[38])

    for start in (0.0, 1e5, 1e7, 3e7):
        times = [packed_time(start + k / 60.0) for k in range(120)]
        for (a, wraps_a), (b, wraps_b) in zip(times, times[1:]):
            assert 0.0 <= a < TIME_WRAP
            step = b - a + (wraps_b - wraps_a) * TIME_WRAP  # across a wrap, the wrap count makes up the jump
            assert abs(step - 1 / 60) <= 0.01 / 60, f"a step of {step} s near t = {start} s"


def scaled_scene(s: float) -> Scene:
    """A lit sphere of radius s, seen from 3 s away: the same picture at every scale."""
    scene = Scene("scaled")
    scene.assets.mesh("sphere", uv_sphere(1.0, 32, 16))
    scene.assets.material("M", MaterialData("lit", color=(0.9, 0.6, 0.3)))
    scene.create_entity(TransformComponent(scale=s), MeshComponent("sphere"), MaterialComponent("M"))
    sun = np.array([-2.0, 4.0, 3.0])
    scene.create_entity(TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", intensity=1.5))
    eye = np.array([0.0, 0.0, 3.0 * s])
    scene.create_entity(TransformComponent(eye), CameraComponent(50.0, 0.1 * s, 10.0 * s))
    return scene


@pytest.mark.parametrize("s", [1e-20, 1e-12, 1e15])
def test_tiny_and_huge_objects_keep_their_normals(backend, s):
    reference = render(backend, scaled_scene(1.0))[0]
    scaled = render(backend, scaled_scene(s))[0]
    worst = int(np.abs(reference.astype(int) - scaled.astype(int)).max())
    assert worst <= 2, f"{backend}: a sphere of radius {s} shades differently from one of radius 1 (up to {worst}/255)"


def specular_scene(s: float) -> Scene:
    """The built-in Blinn-Phong sphere of radius s with a highlight, lit by a sun and a point light (no range: no
    falloff), seen from 3 s away: every vector the shader normalises (normal, view, light, half) is of size s."""
    scene = Scene("scaled, specular")
    scene.assets.mesh("sphere", uv_sphere(1.0, 32, 16))
    scene.assets.material("M", MaterialData("gandalf.blinn_phong", color=(0.9, 0.6, 0.3),
                                            params={"shininess": 32.0, "specular": 0.5}))
    scene.create_entity(TransformComponent(scale=s), MeshComponent("sphere"), MaterialComponent("M"))
    sun = np.array([-2.0, 4.0, 3.0])
    scene.create_entity(TransformComponent(sun * s, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", intensity=1.0))
    scene.create_entity(TransformComponent(np.array([1.5, 1.0, 2.0]) * s), LightComponent("point", intensity=0.8))
    scene.create_entity(TransformComponent((0.0, 0.0, 3.0 * s)), CameraComponent(50.0, 0.1 * s, 10.0 * s))
    return scene


@pytest.mark.parametrize("s", [1e-20, 1e-12, 1e15, 1e20])
def test_the_same_specular_picture_at_every_scale(backend, s):
    """Measured before the scale-safe normalisation: 12.1 dB at 1e-20, 16.7 dB at 1e-12, 18.7 dB at 1e20."""
    reference = render(backend, specular_scene(1.0))[0]
    scaled = render(backend, specular_scene(s))[0]
    worst = int(np.abs(reference.astype(int) - scaled.astype(int)).max())
    assert worst <= 2, f"{backend}: the scene at scale {s} shades differently from scale 1 (up to {worst}/255)"
    assert reference[..., :3].max() > 200, "the test scene should have a highlight"


@pytest.mark.parametrize("near", [1e-21, 1e-3, 0.1, 7.0, 1e14])
@pytest.mark.parametrize("depth", [(-1.0, 1.0), (0.0, 1.0)])
def test_the_uploaded_projection_puts_clip_w_near_1_on_the_near_plane_exactly(near, depth):
    from gandalf_core.render.frame import clip_scale

    projection = CameraComponent(50.0, near, 100.0 * near).projection_matrix(depth, 1.5)
    k = clip_scale(projection, depth[0])
    assert math.frexp(k)[0] == 0.5, f"{k} is not a power of two (scaling would round)"
    assert 0.5 <= k * near < 1.0  # clip w is -z_eye: near on the near plane
    if depth == (0.0, 1.0):  # reverse-Z: the near plane at NDC depth 1
        reverse = CameraComponent(50.0, near, 100.0 * near, reverse_z=True).projection_matrix(depth, 1.5)
        assert 0.5 <= clip_scale(reverse, 1.0) * near < 1.0
    assert clip_scale(np.eye(4), -1.0) == 1.0  # orthographic (w = 1) and the identity stay as they are
