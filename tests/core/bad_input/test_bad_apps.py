"""Applications: bad constructor arguments, frames with bad time steps, use after ``close()``, a scene in two apps,
and two apps in one process. Errors name the argument or the method; two apps draw their own pictures,
interleaved, in either order of APIs; a scene whose app was closed runs in a new one."""

from __future__ import annotations

import math

import pytest

from gandalf_core import Application, Scene
from gandalf_core.components import ClearColorComponent
from gandalf_core.render.base import UnknownBackendError

from .catalogue import error, params, result, run

BLUE, ORANGE = (0.2, 0.4, 0.8), (0.8, 0.4, 0.2)
BLUE_BYTES, ORANGE_BYTES = [51, 102, 204, 255], [204, 102, 51, 255]


def app(backend: str = "opengl", **kwargs) -> Application:
    return Application(backend, **{"width": 8, "height": 6, "headless": True, **kwargs})


def coloured(color, name: str = "clear") -> Scene:
    scene = Scene(name)
    scene.create_entity(ClearColorComponent(color))
    return scene


def closed(method: str, *args):
    def action(backend: str):
        a = app(backend)
        a.add_scene(coloured(BLUE))
        a.step()
        a.close()
        getattr(a, method)(*args)
    return action


def with_scene(backend: str, call):
    with app(backend) as a:
        a.add_scene(coloured(BLUE))
        return call(a)


def scene_in_two_apps(backend: str):
    scene = coloured(BLUE)
    with app(backend) as a, app(backend) as b:
        a.add_scene(scene)
        b.add_scene(scene)


def two_apps(first: str, second: str):
    def action(_backend: str):
        a = app(first)
        a.add_scene(coloured(BLUE))
        a.run(frames=1)
        with app(second) as b:
            b.add_scene(coloured(ORANGE))
            b.run(frames=1)
            a.run(frames=1)  # interleaved
            pixels = [a.capture()[0, 0].tolist(), b.capture()[0, 0].tolist()]
        a.run(frames=1)  # after the other one closed
        pixels.append(a.capture()[0, 0].tolist())
        a.close()
        return pixels
    return action


def scene_moves_to_a_new_app(backend: str):
    scene = coloured(ORANGE)
    with app(backend) as a:
        a.add_scene(scene)
        a.step()
    with app("webgpu" if backend == "opengl" else "opengl") as b:
        b.add_scene(scene)
        b.step()
        return b.capture()[0, 0].tolist()


def closed_twice(backend: str):
    a = app(backend)
    a.close()
    a.close()
    return a.closed


CASES = [
    error("unknown-backend", lambda b: app("vulkan"), UnknownBackendError, "'vulkan'", "opengl, webgpu"),
    error("width-zero", lambda b: app(b, width=0), ValueError, "Application", "width", "got 0"),
    error("height-negative", lambda b: app(b, height=-5), ValueError, "height", "got -5"),
    error("width-fraction", lambda b: app(b, width=2.5), ValueError, "width", "whole number", "2.5"),
    error("width-text", lambda b: app(b, width="8"), ValueError, "width", "'8'"),
    error("width-bool", lambda b: app(b, width=True), ValueError, "width"),
    error("width-beyond-device-limit", lambda b: app(b, width=100_000), ValueError, "width", "100000",
          "largest render target"),
    error("fixed-dt-zero", lambda b: app(b, fixed_dt=0), ValueError, "fixed_dt", "got 0"),
    error("fixed-dt-text", lambda b: app(b, fixed_dt="fast"), ValueError, "fixed_dt", "'fast'"),
    error("fixed-dt-nan", lambda b: app(b, fixed_dt=math.nan), ValueError, "fixed_dt"),
    error("step-without-scene", lambda b: app(b).step(), RuntimeError, "no scene", "add_scene"),
    error("step-dt-nan", lambda b: with_scene(b, lambda a: a.step(math.nan)), ValueError, "dt", "finite"),
    error("step-dt-negative", lambda b: with_scene(b, lambda a: a.step(-0.5)), ValueError, "dt", "negative"),
    error("step-dt-text", lambda b: with_scene(b, lambda a: a.step("0.1")), TypeError, "dt", "'0.1'"),
    error("run-frames-negative", lambda b: with_scene(b, lambda a: a.run(frames=-1)), ValueError,
          "Application.run", "frames", "-1"),
    error("run-frames-text", lambda b: with_scene(b, lambda a: a.run(frames="10")), ValueError, "frames"),
    error("run-seconds-nan", lambda b: with_scene(b, lambda a: a.run(seconds=math.nan)), ValueError, "seconds"),
    error("run-headless-forever", lambda b: with_scene(b, lambda a: a.run()), RuntimeError, "headless run",
          "frames= or seconds="),
    error("add-scene-not-a-scene", lambda b: app(b).add_scene("level"), TypeError, "add_scene", "'level'",
          "not a Scene"),
    error("switch-to-unknown-scene", lambda b: with_scene(b, lambda a: a.switch_scene("lobby")), KeyError,
          "'lobby'"),
    error("second-scene-with-a-taken-name", lambda b: with_scene(b, lambda a: a.add_scene(coloured(ORANGE))),
          ValueError, "scene named 'clear'"),
    error("scene-in-two-apps", scene_in_two_apps, ValueError, "scene 'clear'", "another Application"),
    error("step-after-close", closed("step"), RuntimeError, "Application.step", "closed"),
    error("run-after-close", closed("run", 1), RuntimeError, "Application.run", "closed"),
    error("capture-after-close", closed("capture"), RuntimeError, "Application.capture", "closed"),
    error("save-png-after-close", closed("save_png", "x.png"), RuntimeError, "Application.save_png", "closed"),
    error("add-scene-after-close", closed("add_scene", Scene("late")), RuntimeError, "Application.add_scene"),
    error("save-png-unknown-extension", lambda b: with_scene(b, lambda a: (a.step(), a.save_png("frame.txt"))),
          ValueError, ".txt"),
    result("close-twice-does-nothing", closed_twice, lambda c: c is True),
    result("scene-moves-to-a-new-app-after-close", scene_moves_to_a_new_app, lambda px: px == ORANGE_BYTES),
]
TWO_APPS = [
    result(f"two-apps-{first}-then-{second}", two_apps(first, second),
           lambda px: px == [BLUE_BYTES, ORANGE_BYTES, BLUE_BYTES])
    for first, second in [("opengl", "opengl"), ("opengl", "webgpu"), ("webgpu", "opengl"), ("webgpu", "webgpu")]
]


@pytest.mark.parametrize("case", params(CASES))
def test_applications(case, backend):
    run(case, backend)


@pytest.mark.parametrize("case", params(TWO_APPS))
def test_two_applications_in_one_process(case):
    run(case, None)
