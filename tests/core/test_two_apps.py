"""Several Applications in one process work independently, and a closed one refuses to be used.

Each OpenGL renderer makes its own context current before it issues GL calls (drawing, reading back, building
resources), so an app made or closed in between does not redirect them; WebGPU devices are independent anyway.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from gandalf_core import Application, Scene
from gandalf_core.components import ClearColorComponent

SHADERS = Path(__file__).parent / "shaders"
BLUE, ORANGE = (0.2, 0.4, 0.8), (0.8, 0.4, 0.2)


def coloured(color) -> Scene:
    scene = Scene("clear")
    scene.create_entity(ClearColorComponent(color))
    return scene


@pytest.mark.parametrize(("first", "second"), [("opengl", "opengl"), ("opengl", "webgpu"), ("webgpu", "opengl")])
def test_two_applications_draw_their_own_pictures(first, second):
    a = Application(first, 16, 12, headless=True)
    a.add_scene(coloured(BLUE))
    a.run(frames=1)
    with Application(second, 16, 12, headless=True) as b:
        b.add_scene(coloured(ORANGE))
        b.run(frames=1)
        a.run(frames=1)  # interleaved frames
        assert a.capture()[0, 0].tolist() == [51, 102, 204, 255]
        assert b.capture()[0, 0].tolist() == [204, 102, 51, 255]
    a.run(frames=1)  # after the other app is closed
    assert a.capture()[0, 0].tolist() == [51, 102, 204, 255]
    a.close()


def test_a_shader_built_after_another_app_was_made_belongs_to_its_own_app():
    with Application("opengl", 16, 12, headless=True) as a, Application("opengl", 16, 12, headless=True) as b:
        shader = a.renderer.shaders.build("flat", SHADERS / "unlit.vert", SHADERS / "flat.frag")
        assert shader.program.ctx is a.renderer.ctx
        a.add_scene(coloured(BLUE))
        b.add_scene(coloured(ORANGE))
        a.run(frames=1)
        b.run(frames=1)
        assert np.array_equal(a.capture()[0, 0], [51, 102, 204, 255])


def test_a_scene_runs_in_one_application_at_a_time():
    scene = coloured(BLUE)
    with Application("opengl", 8, 8, headless=True) as a, Application("webgpu", 8, 8, headless=True) as b:
        a.add_scene(scene)
        with pytest.raises(ValueError, match="already runs in another Application"):
            b.add_scene(scene)
    with Application("webgpu", 8, 8, headless=True) as c:  # the first app is closed: the scene may move on
        c.add_scene(scene)
        c.run(frames=1)


@pytest.mark.parametrize("call", ["step", "run", "capture", "add_scene"])
def test_a_closed_application_says_so(call):
    app = Application("opengl", 8, 8, headless=True)
    app.add_scene(coloured(BLUE))
    app.close()
    app.close()  # closing twice is harmless
    args = {"step": (), "run": (), "capture": (), "add_scene": (coloured(BLUE),)}[call]
    with pytest.raises(RuntimeError, match=f"Application.{call}: the application was closed"):
        getattr(app, call)(*args)
