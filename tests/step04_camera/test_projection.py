"""Grades the exercise ``perspective`` and ``look_at``: numerically against gandalf_core.math, and by rendering."""

from __future__ import annotations

import math

import numpy as np
import pytest
from step04_helpers import REFERENCES, make_app, only

import gandalf_core.math as gm
from gandalf_tools.testing import compare_images, compare_to_reference

# Float64 maths on both sides: the matrices agree to rounding.
MATRIX_TOL = 1e-9
RANGES = ["opengl", "webgpu", (0.25, 0.75)]


@pytest.mark.exercise("perspective")
@pytest.mark.parametrize("depth_range", RANGES, ids=str)
@pytest.mark.parametrize("fov, aspect, near, far", [(60, 4 / 3, 0.1, 100), (90, 1, 1, 2), (10, 0.5, 0.01, 1e4),
                                                    (170, 2.5, 3, 7)])
def test_perspective_matches_the_engine(impl, depth_range, fov, aspect, near, far):
    expected = gm.perspective(fov, aspect, near, far, depth_range=depth_range)
    np.testing.assert_allclose(impl.perspective(fov, aspect, near, far, depth_range), expected, rtol=MATRIX_TOL,
                               atol=MATRIX_TOL)


@pytest.mark.exercise("perspective")
@pytest.mark.parametrize("depth_range", RANGES, ids=str)
def test_near_and_far_land_on_the_depth_range_ends(impl, depth_range):
    lo, hi = gm.depth_range(depth_range)
    fov, aspect, near, far = 50.0, 1.6, 0.5, 40.0
    p = impl.perspective(fov, aspect, near, far, depth_range)
    for distance, expected in ((near, lo), (far, hi)):
        # A point at the top-right corner of the view at this distance.
        half_h = distance * math.tan(math.radians(fov) / 2)
        clip = p @ np.array([half_h * aspect, half_h, -distance, 1.0])
        assert clip[3] == pytest.approx(distance)
        np.testing.assert_allclose(clip[:3] / clip[3], [1.0, 1.0, expected], atol=1e-9)


@pytest.mark.exercise("perspective")
@pytest.mark.parametrize("args, name", [
    ((0, 1, 0.1, 10), "fovy_deg"), ((180, 1, 0.1, 10), "fovy_deg"), ((-30, 1, 0.1, 10), "fovy_deg"),
    ((math.nan, 1, 0.1, 10), "fovy_deg"), ((60, 0, 0.1, 10), "aspect"), ((60, -1, 0.1, 10), "aspect"),
    ((60, 1, 0, 10), "near"), ((60, 1, -1, 10), "near"), ((60, 1, 5, 5), "far"), ((60, 1, 5, 1), "far"),
    # "or any value is not finite": infinities pass every range comparison, so they need their own check
    ((60, 1, 0.1, math.inf), "far"), ((60, math.inf, 0.1, 10), "aspect"), ((60, 1, math.nan, 10), "near"),
])
def test_degenerate_perspective_raises_naming_the_parameter(impl, args, name):
    with pytest.raises(ValueError, match=name):
        impl.perspective(*args, "opengl")


LOOKS = [((0, 0, 5), (0, 0, 0), (0, 1, 0)), ((8, 8, 8), (0, 0.5, 0), (0, 1, 0)), ((-3, 2, -7), (1, -1, 4), (0, 1, 0)),
         ((1, 2, 3), (4, 6, 3), (0, 0, 1)), ((1e4, -2e4, 3e3), (0, 0, 0), (0, 1, 0))]


@pytest.mark.exercise("look_at")
@pytest.mark.parametrize("eye, target, up", LOOKS)
def test_look_at_matches_the_engine(impl, eye, target, up):
    view = impl.look_at(eye, target, up)
    np.testing.assert_allclose(view, gm.look_at(eye, target, up), atol=1e-9)
    # The eye goes to the origin and the target onto the -Z axis in front of the camera.
    np.testing.assert_allclose((view @ [*eye, 1.0])[:3], 0.0, atol=1e-9 * max(1.0, np.abs(eye).max()))
    t = view @ [*target, 1.0]
    np.testing.assert_allclose(t[:2], 0.0, atol=1e-9 * max(1.0, np.abs(eye).max()))
    assert t[2] < 0


@pytest.mark.exercise("look_at")
@pytest.mark.parametrize("eye, target, up, name", [((1, 2, 3), (1, 2, 3), (0, 1, 0), "target"),
                                                   ((0, 0, 5), (0, 0, 0), (0, 0, 0), "up"),
                                                   ((0, 5, 0), (0, 0, 0), (0, 1, 0), "up")])
def test_degenerate_look_at_raises_naming_the_parameter(impl, eye, target, up, name):
    with pytest.raises(ValueError, match=name):
        impl.look_at(eye, target, up)


def _ortho_picture(backend: str, look_at) -> np.ndarray:
    with make_app(backend, only(look_at=look_at)) as app:
        app.step()
        app.input.key("C")  # switch to the orthographic camera that LookAtSystem places
        app.step()
        return app.capture()


@pytest.mark.exercise("look_at")
def test_ortho_camera_placed_by_look_at_renders_like_the_engine(impl, backend):
    actual = _ortho_picture(backend, impl.look_at)
    # Same pose -> same picture; PSNR >= 45 dB allows a few rounding-level pixel flips on edges.
    compare_images(actual, _ortho_picture(backend, gm.look_at), f"step04-ortho-{backend}", min_psnr=45.0)
    compare_to_reference(actual, REFERENCES / "ortho_view.png", min_psnr=40.0)
