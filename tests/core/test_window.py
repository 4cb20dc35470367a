"""Real glfw windows (run under Xvfb: ``./run.sh test`` does that when no display is set).

A window renders through the same offscreen target as headless runs, then presents it; these tests
check that path and that window events reach the input system.
"""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core import Application, ClearColorComponent, Scene
from gandalf_core.app.window import display_available

# One window test at a time across xdist workers (the conftest's lock on the display).
pytestmark = [pytest.mark.skipif(not display_available(), reason="needs a display (run under xvfb-run)"),
              pytest.mark.usefixtures("one_window_at_a_time")]


def test_window_presents_the_frame(backend):
    scene = Scene("window")
    scene.create_entity(ClearColorComponent((0.2, 0.4, 0.8)))
    with Application(backend, 160, 120, headless=False, fixed_dt=1 / 60) as app:
        assert app.window is not None
        app.add_scene(scene)
        app.run(frames=3)
        expected = np.array([51, 102, 204, 255])
        assert np.array_equal(app.capture()[0, 0], expected)
        if backend == "opengl":
            # What reached the window is the offscreen frame, bytes unchanged (no second sRGB encode).
            shown = np.frombuffer(app.renderer.ctx.screen.read(components=4), np.uint8).reshape(-1, 4)
            assert np.array_equal(shown[0], expected)


def test_window_resize_event_resizes_the_target(backend):
    with Application(backend, 160, 120, headless=False) as app:
        app.add_scene(Scene("resize"))
        app.step()
        app.window._glfw.set_window_size(app.window.handle, 200, 100)
        for _ in range(20):  # the X server answers asynchronously
            app.step()
            if app.renderer.width == 200:
                break
        assert (app.renderer.width, app.renderer.height) == (200, 100)
        assert app.capture().shape == (100, 200, 4)


def test_escape_closes_the_window(backend):
    with Application(backend, 64, 48, headless=False) as app:
        app.add_scene(Scene("escape"))
        app.input.key("ESCAPE")
        app.run()  # returns because the window now wants to close
        assert app.window.should_close


def test_direct_present_gives_the_offscreen_picture(backend):
    """In a window, frames are drawn straight onto the window (no offscreen target and copy) when the window
    encodes sRGB; the picture read back is the same bytes as through the offscreen target and blit."""
    from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent, TransformComponent
    from gandalf_core.resources import MaterialData, primitives

    scene = Scene("direct")
    scene.assets.mesh("cube", primitives.cube())
    scene.assets.material("lit", MaterialData("gandalf.blinn_phong", color=(0.9, 0.5, 0.2)))
    scene.create_entity(ClearColorComponent((0.1, 0.2, 0.3)))
    scene.create_entity(TransformComponent((0.0, 0.0, 3.0)), CameraComponent(60.0, 0.1, 100.0))
    scene.create_entity(TransformComponent((0.0, 0.0, 0.0), quaternion=(0.9, 0.3, 0.3, 0.0)),
                        MeshComponent("cube"), MaterialComponent("lit"))
    with Application(backend, 160, 120, headless=False, fixed_dt=1 / 60) as app:
        app.add_scene(scene)
        renderer = app.renderer
        assert renderer.present_direct, "under Xvfb both APIs' windows encode sRGB, so frames go straight to them"
        app.run(frames=2)
        if backend == "webgpu":
            assert renderer._pending_surface is not None  # drawn onto the surface texture, not yet presented
        direct = app.capture()
        renderer.present_direct = False
        app.run(frames=2)
        blit = app.capture()
    assert not np.array_equal(direct[60, 80], direct[0, 0]), "the cube is drawn in the middle of the frame"
    assert np.array_equal(direct, blit), f"max difference {np.abs(direct.astype(int) - blit).max()}"
