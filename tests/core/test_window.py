"""Real glfw windows (run under Xvfb: ``./run.sh test`` does that when no display is set).

A window renders through the same offscreen target as headless runs, then presents it; these tests
check that path and that window events reach the input system.
"""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core import Application, ClearColorComponent, Scene
from gandalf_core.app.window import display_available

pytestmark = pytest.mark.skipif(not display_available(), reason="needs a display (run under xvfb-run)")


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
