"""Grades the exercise ``OrbitCameraSystem`` with synthetic mouse events, headless, in both APIs."""

from __future__ import annotations

import math

import numpy as np
import pytest
from step04_helpers import REFERENCES, make_app, only, rendered_camera

import gandalf_core.math as gm
from gandalf_core import Scene, TransformComponent
from gandalf_tools.testing import compare_to_reference
from step04_camera.components import OrbitCameraComponent

TARGET = np.array([0.0, 0.5, 0.0])  # the scene's orbit camera: distance 9, yaw 30, pitch 25, sensitivity 0.5


def expected_view(distance: float, yaw: float, pitch: float) -> np.ndarray:
    y, p = math.radians(yaw), math.radians(pitch)
    eye = TARGET + distance * np.array([math.cos(p) * math.sin(y), math.sin(p), math.cos(p) * math.cos(y)])
    return gm.look_at(eye, TARGET)


def assert_next_frame_view(app, distance: float, yaw: float, pitch: float) -> None:
    """Run one frame: the camera it renders from is the orbit (``distance``, ``yaw``, ``pitch``) around TARGET."""
    app.step()
    np.testing.assert_allclose(rendered_camera(app)[0], expected_view(distance, yaw, pitch), atol=1e-9)


def orbit_of(app) -> OrbitCameraComponent:
    return app.scene.get_component(app.scene.query(OrbitCameraComponent).entities[0], OrbitCameraComponent)


@pytest.fixture
def app(impl):
    with make_app("opengl", only(OrbitCameraSystem=impl.OrbitCameraSystem)) as app:
        yield app


@pytest.mark.exercise("OrbitCameraSystem")
def test_camera_starts_at_its_orbit(app):
    assert_next_frame_view(app, 9.0, 30.0, 25.0)


@pytest.mark.exercise("OrbitCameraSystem")
def test_left_drag_turns_the_orbit(app):
    app.input.move_mouse(100, 100)
    assert_next_frame_view(app, 9.0, 30.0, 25.0)  # moving without a button does nothing
    app.input.button(0, "press")
    app.input.move_mouse(140, 80)  # dx = 40, dy = -20 pixels at 0.5 degrees per pixel
    assert_next_frame_view(app, 9.0, 10.0, 15.0)
    app.input.button(0, "release")
    app.input.move_mouse(300, 300)
    assert_next_frame_view(app, 9.0, 10.0, 15.0)


@pytest.mark.exercise("OrbitCameraSystem")
def test_drag_and_scroll_update_the_orbit_values(app):
    """Graded on the component alone, so a mistake in placing the camera does not cost this part too."""
    app.input.button(0, "press")
    app.input.move_mouse(0, 0)
    app.step()
    app.input.move_mouse(40, -20)  # dx = 40, dy = -20 pixels at 0.5 degrees per pixel
    app.input.scroll(0, 1)
    app.step()
    orbit = orbit_of(app)
    assert (orbit.yaw, orbit.pitch) == (pytest.approx(10.0), pytest.approx(15.0)), "yaw -= dx·s, pitch += dy·s"
    assert orbit.distance == pytest.approx(9.0 * 0.9), "distance *= zoom_factor ** scroll"


@pytest.mark.exercise("OrbitCameraSystem")
def test_right_button_does_not_orbit(app):
    app.input.button(1, "press")
    app.input.move_mouse(50, 70)
    assert_next_frame_view(app, 9.0, 30.0, 25.0)


@pytest.mark.exercise("OrbitCameraSystem")
def test_scroll_zooms_and_clamps(app):
    app.input.scroll(0, 2)  # two steps in: 9 * 0.9^2
    assert_next_frame_view(app, 9.0 * 0.81, 30.0, 25.0)
    app.input.scroll(0, -100)
    app.step()
    assert orbit_of(app).distance == pytest.approx(50.0)
    np.testing.assert_allclose(rendered_camera(app)[0], expected_view(50.0, 30.0, 25.0), atol=1e-9)


@pytest.mark.exercise("OrbitCameraSystem")
@pytest.mark.parametrize("dy, pitch", [(10_000, 85.0), (-10_000, -85.0)])
def test_pitch_is_clamped_and_never_flips(app, dy, pitch):
    app.input.button(0, "press")
    app.input.move_mouse(0, dy)
    app.step()
    view = rendered_camera(app)[0]
    assert np.all(np.isfinite(view))
    assert orbit_of(app).pitch == pytest.approx(pitch)
    np.testing.assert_allclose(view, expected_view(9.0, 30.0, pitch), atol=1e-9)
    assert view[1, 1] > 0  # the camera's top still points up: no flip over the pole


@pytest.mark.exercise("OrbitCameraSystem")
def test_works_on_a_scene_without_an_application(impl):
    scene = Scene("no app")
    camera = scene.create_entity(TransformComponent(), OrbitCameraComponent(distance=4.0, yaw=90.0, pitch=0.0))
    scene.add_system(impl.OrbitCameraSystem())
    scene.update(1 / 60)
    np.testing.assert_allclose(scene.get_component(camera, TransformComponent).translation, [4.0, 0.0, 0.0],
                               atol=1e-12)


@pytest.mark.exercise("OrbitCameraSystem")
def test_dragged_and_zoomed_picture(impl, backend):
    with make_app(backend, only(OrbitCameraSystem=impl.OrbitCameraSystem)) as app:
        app.step()
        app.input.button(0, "press")
        app.input.move_mouse(-120, 30)  # yaw 30 + 60 = 90, pitch 25 + 15 = 40
        app.input.scroll(0, 3)
        app.step()
        image = app.capture()
    # One reference for both APIs: they agree to +-1 per channel (PSNR >= 40 dB).
    compare_to_reference(image, REFERENCES / "orbit_dragged.png", min_psnr=40.0)
