"""The time forms shaders get stay smooth on long runs, in both APIs (``gandalf_core/render/frame.py``).

A full-screen probe colours every pixel from the frame's time: red ``0.5 + 0.5 sin(time.w)``, green
``0.5 + 0.5 cos(3 time.w)`` (whole multiples of the 163-turn angle wrap), blue ``fract(time.x / 2)`` (a 2 s
period divides the 1024 s wrap). Started at 1e5 s, at 1e7 s and just before each wrap, four frames at 60 Hz
must each match the float64 values of the clock's time within 2/255 (sRGB-encoded, as the frame holds them):
a float32 time (steps of 1 s at 1e7 s) or a wrap that is not a whole number of periods (sin jumps by up to 2) cannot.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from core_shaders import FLAT_VERT

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.render.frame import ANGLE_WRAP, TIME_WRAP, phase
from gandalf_core.resources import MaterialData, plane
from gandalf_core.resources.texture_data import linear_to_srgb

PROBE_WGSL = """
#include "frame.wgsl"
#include "instance.wgsl"
@vertex fn vs_main(@location(0) position: vec3<f32>, inst: Instance) -> @builtin(position) vec4<f32> {
    return frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> {
    let t = frame.time;
    return vec4<f32>(0.5 + 0.5 * sin(t.w), 0.5 + 0.5 * cos(3.0 * t.w), fract(t.x * 0.5), 1.0);
}
"""
PROBE_FRAG = """#version 330 core
#include "frame.glsl"
out vec4 f_color;
void main() {
    f_color = vec4(0.5 + 0.5 * sin(u_time.w), 0.5 + 0.5 * cos(3.0 * u_time.w), fract(u_time.x * 0.5), 1.0);
}
"""
STARTS = {
    "1e5 s": 1e5,
    "1e7 s": 1e7 + 0.37,
    "time.x wraps": 977 * TIME_WRAP - 2 / 60,
    "time.w wraps": 9765 * ANGLE_WRAP - 2 / 60,
}


def expected(t: float) -> tuple[np.ndarray, np.ndarray]:
    """The probe's linear colour at time ``t`` from the float64 time itself, and the sRGB-encoded 0..255 the
    frame holds."""
    colour = np.array((0.5 + 0.5 * math.sin(t), 0.5 + 0.5 * math.cos(3.0 * t), (t / 2.0) % 1.0))
    return colour, linear_to_srgb(colour) * 255.0


def probe_scene() -> Scene:
    scene = Scene("time probe")
    scene.assets.mesh("quad", plane(4.0, 1))
    scene.assets.material("probe", MaterialData("probe", cull="none"))
    scene.create_entity(TransformComponent(rotation=(90.0, 0.0, 0.0)), MeshComponent("quad"),
                        MaterialComponent("probe"))
    scene.create_entity(TransformComponent((0.0, 0.0, 1.0)), CameraComponent(60.0, 0.1, 10.0))
    return scene


@pytest.mark.parametrize("start", list(STARTS.values()), ids=list(STARTS))
def test_the_time_forms_stay_smooth(backend, start):
    with Application(backend, 16, 12, headless=True, fixed_dt=1 / 60) as app:
        if backend == "opengl":
            app.renderer.shaders.build("probe", FLAT_VERT, PROBE_FRAG)  # the core tests' vertex stage
        else:
            app.renderer.shaders.build("probe", PROBE_WGSL)
        app.add_scene(probe_scene())
        app.run(frames=1)
        app.clock.time = start
        worst = 0.0
        for _ in range(4):
            app.run(frames=1)
            got = app.capture()[6, 8, :3].astype(np.float64)
            linear, want = expected(app.clock.time)
            if not 0.01 < linear[2] < 0.99:  # fract's own edge: the 2 s period's wrap, not the uniform's
                got, want = got[:2], want[:2]
            worst = max(worst, float(np.abs(got - want).max()))
    assert worst <= 2.0, f"{backend} from t = {start} s: the probe is up to {worst:.1f}/255 from the float64 time"


def test_the_wraps_are_whole_periods():
    assert TIME_WRAP % 2.0 == 0.0 and TIME_WRAP * 60.0 == round(TIME_WRAP * 60.0)
    assert ANGLE_WRAP / (2.0 * math.pi) == pytest.approx(163.0, abs=1e-12)
    assert phase(1e7 + 0.5, 4.0) == pytest.approx(0.5, abs=1e-9)
    with pytest.raises(ValueError, match="period must be a finite number of seconds > 0, got 0.0"):
        phase(1.0, 0.0)
