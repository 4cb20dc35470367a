"""Grades step 01: HSV conversion and the hue-cycling clear colour, rendered headless in both APIs."""

from __future__ import annotations

import colorsys

import numpy as np
import pytest

from gandalf_core import Application, ClearColorComponent
from step01_window.components import HueCycleComponent
from step01_window.scene import build_scene

# An 8-bit sRGB target stores round(255 * c); both backends may round differently by one step.
PIXEL_TOLERANCE = 1


# --8<-- [start:graded-test]
@pytest.mark.exercise("hsv_to_rgb")
@pytest.mark.parametrize("hue", [0.0, 30.0, 59.9, 60.0, 123.4, 180.0, 250.0, 300.0, 359.9, 360.0, 725.0, -30.0,
                                 -1e-15])  # -1e-15 % 360 rounds to 360.0: it must still give the colour of hue 0
@pytest.mark.parametrize("sat_val", [(0.0, 0.5), (0.7, 0.9), (1.0, 1.0)], ids=["s0-v0.5", "s0.7-v0.9", "s1-v1"])
def test_hsv_to_rgb_matches_colorsys(impl, hue, sat_val):
    s, v = sat_val
    expected = colorsys.hsv_to_rgb((hue % 360.0) / 360.0, s, v)
    got = impl.hsv_to_rgb(hue, s, v)
    assert tuple(got) == pytest.approx(expected, abs=1e-9), f"hsv_to_rgb({hue}, {s}, {v})"
# --8<-- [end:graded-test]


def _expected_bytes(hue: float, s: float, v: float) -> np.ndarray:
    rgb = colorsys.hsv_to_rgb((hue % 360.0) / 360.0, s, v)
    return np.round(np.array([*rgb, 1.0]) * 255).astype(int)


@pytest.mark.exercise("HueCycleSystem")
@pytest.mark.parametrize("frames", [1, 30, 400])
def test_clear_colour_follows_the_hue_in_pixels(impl, backend, frames):
    with Application(backend, 32, 24, headless=True, fixed_dt=1 / 60) as app:
        scene = app.add_scene(build_scene(impl))
        app.run(frames=frames)
        image = app.capture()
    entity = scene.query(HueCycleComponent).entities[0]
    cycle = scene.get_component(entity, HueCycleComponent)
    expected_hue = (200.0 + 60.0 * frames / 60) % 360.0
    case = f"after {frames} frames of 1/60 s from hue 200 at 60°/s"
    assert cycle.hue == pytest.approx(expected_hue, abs=1e-6), (
        f"{case}: got the hue {cycle.hue:.6g}, expected {expected_hue:g}")
    assert 0.0 <= cycle.hue < 360.0, f"{case}: got the hue {cycle.hue:.6g}, expected it in [0, 360)"
    expected = _expected_bytes(expected_hue, 0.7, 0.9)
    assert image.shape == (24, 32, 4)
    # Every pixel is the clear colour.
    error = np.abs(image.reshape(-1, 4).astype(int) - expected)
    worst = int(error.max(axis=1).argmax())
    assert error.max() <= PIXEL_TOLERANCE, (
        f"{case}: got the pixel {image.reshape(-1, 4)[worst].tolist()} (x {worst % 32}, y {worst // 32}), expected "
        f"the clear colour {expected.tolist()} (hue {expected_hue:g}, saturation 0.7, value 0.9) "
        f"within {PIXEL_TOLERANCE}")


@pytest.mark.exercise("HueCycleSystem")
def test_each_entity_cycles_at_its_own_speed(impl):
    from gandalf_core import Scene

    scene = Scene("speeds")
    a = scene.create_entity(ClearColorComponent(), HueCycleComponent(hue=10, speed=90, saturation=1, value=1))
    b = scene.create_entity(ClearColorComponent(), HueCycleComponent(hue=350, speed=-20, saturation=0.5, value=0.5))
    scene.add_system(impl.HueCycleSystem())
    for _ in range(3):
        scene.update(0.5)
    assert scene.get_component(a, HueCycleComponent).hue == pytest.approx(145.0)
    assert scene.get_component(b, HueCycleComponent).hue == pytest.approx(320.0)
    assert np.allclose(scene.get_component(a, ClearColorComponent).color[:3], colorsys.hsv_to_rgb(145 / 360, 1, 1))


@pytest.mark.exercise("HueCycleSystem")
@pytest.mark.parametrize(("hue", "speed", "steps", "expected"), [
    (10.0, -20.0, 3, 310.0),    # turning backwards past 0 wraps to the top of the circle
    (5.0, -3690.0, 1, 275.0),   # ten and a quarter turns backwards in one step (a system that does nothing fails)
    (350.0, 45.0, 2, 80.0),     # forwards past 360
])
def test_the_hue_wraps_to_0_360_in_both_directions(impl, hue, speed, steps, expected):
    """The stub's rule: the hue advances by speed * dt, "wrapping to [0, 360)" — for negative speeds too."""
    from gandalf_core import Scene

    scene = Scene("wrap")
    e = scene.create_entity(ClearColorComponent(), HueCycleComponent(hue=hue, speed=speed, saturation=1, value=1))
    scene.add_system(impl.HueCycleSystem())
    for _ in range(steps):
        scene.update(1.0)
    got = scene.get_component(e, HueCycleComponent).hue
    assert 0.0 <= got < 360.0, f"hue {hue} at speed {speed} for {steps} s gave {got}: keep it in [0, 360)"
    assert got == pytest.approx(expected, abs=1e-9), (
        f"hue {hue} at speed {speed} for {steps} s: expected {expected}, got {got} (hint: Python's % wraps "
        "negative numbers into [0, 360), math.fmod does not)")
