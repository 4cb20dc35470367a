"""Cameras: degenerate projections (near = far, near <= 0, a field of view of 0 or 180 degrees, an aspect of 0,
values too extreme to represent) are errors naming ``CameraComponent.<field>``, at construction and, for a value
changed later, when the renderer builds the projection; huge but valid depth ranges (1e-6 to 1e9, an infinite far
plane, reverse-Z) give finite matrices that put near and far at the two ends of each API's depth range."""

from __future__ import annotations

import math

import numpy as np
import pytest

from gandalf_core import Scene
from gandalf_core.components import CameraComponent, TransformComponent
from gandalf_core.math import perspective

from .catalogue import error, params, result, run

nan, inf = math.nan, math.inf
_n = [0]


def _ndc_depth(m: np.ndarray, distance: float) -> float:
    clip = m @ np.array([0.0, 0.0, -distance, 1.0])
    return clip[2] / clip[3]


def _ends(depth_range: str, lo: float, hi: float, **camera):
    """The NDC depths of near and far (far = inf: a point very far away) must be lo and hi."""
    def action():
        cam = CameraComponent(**camera)
        m = cam.projection_matrix(depth_range, 1.5)
        far = cam.far if math.isfinite(cam.far) else 1e30
        return m, _ndc_depth(m, cam.near), _ndc_depth(m, far)

    def check(value):
        m, at_near, at_far = value
        assert np.isfinite(m).all(), f"projection not finite: {m}"
        assert math.isclose(at_near, lo, abs_tol=1e-6) and math.isclose(at_far, hi, abs_tol=1e-6), (
            f"{camera}: near -> {at_near}, far -> {at_far}; expected {lo}, {hi}")
    return action, check


def _changed_then_rendered(app, **change):
    """A camera valid when made, changed to a bad value afterwards: the frame that builds its projection fails."""
    _n[0] += 1
    scene = Scene(f"camera-change-{_n[0]}")
    camera = CameraComponent(60.0, 0.1, 100.0)
    scene.create_entity(TransformComponent((0, 0, 3)), camera)
    app.add_scene(scene)
    app.switch_scene(scene)
    for field, value in change.items():
        setattr(camera, field, value)
    app.step()


def _singular_camera(app):
    _n[0] += 1
    scene = Scene(f"camera-singular-{_n[0]}")
    from gandalf_core.components import InfoComponent

    scene.create_entity(InfoComponent("flat eye"), TransformComponent((0, 0, 3), scale=0.0), CameraComponent())
    app.add_scene(scene)
    app.switch_scene(scene)
    app.step()


def _traced_with_zero_scale():
    """The path tracer's view of a scene whose camera has scale 0 (its rays would have NaN directions)."""
    from gandalf_core.components import InfoComponent
    from gandalf_core.systems import TransformSystem
    from step07_advanced.pathtracer.scene import gather

    scene = Scene("tracer-flat-eye")
    scene.add_system(TransformSystem())
    scene.create_entity(InfoComponent("flat eye"), TransformComponent((0, 0, 3), scale=(1.0, 0.0, 1.0)),
                        CameraComponent())
    scene.update(0.0)  # world matrices (the scene's TransformSystem)
    return gather(scene)


CONSTRUCTION = [
    error("pathtracer-camera-with-zero-scale", _traced_with_zero_scale, ValueError, "entity 'flat eye'",
          "TransformComponent.scale", "non-zero world scale", "0.0"),
    error("near-equals-far", lambda: CameraComponent(near=1.0, far=1.0), ValueError, "CameraComponent.far",
          "greater than CameraComponent.near"),
    error("near-beyond-far", lambda: CameraComponent(near=10.0, far=1.0), ValueError, "CameraComponent.far"),
    error("near-zero", lambda: CameraComponent(near=0.0), ValueError, "CameraComponent.near", "> 0"),
    error("near-negative", lambda: CameraComponent(near=-1.0), ValueError, "CameraComponent.near"),
    error("near-nan", lambda: CameraComponent(near=nan), ValueError, "CameraComponent.near"),
    error("far-nan", lambda: CameraComponent(far=nan), ValueError, "CameraComponent.far"),
    error("far-minus-inf", lambda: CameraComponent(far=-inf), ValueError, "CameraComponent.far"),
    error("fov-zero", lambda: CameraComponent(0.0), ValueError, "CameraComponent.fov", "(0, 180)"),
    error("fov-180", lambda: CameraComponent(180.0), ValueError, "CameraComponent.fov", "(0, 180)"),
    error("fov-negative", lambda: CameraComponent(-30.0), ValueError, "CameraComponent.fov"),
    error("fov-360", lambda: CameraComponent(360.0), ValueError, "CameraComponent.fov"),
    error("fov-inf", lambda: CameraComponent(inf), ValueError, "CameraComponent.fov"),
    error("fov-radians-by-mistake-tiny", lambda: CameraComponent(1e-310), ValueError, "CameraComponent.fov",
          "not finite"),
    error("aspect-zero", lambda: CameraComponent(aspect=0.0), ValueError, "CameraComponent.aspect"),
    error("aspect-negative", lambda: CameraComponent(aspect=-1.0), ValueError, "CameraComponent.aspect"),
    error("aspect-inf", lambda: CameraComponent(aspect=inf), ValueError, "CameraComponent.aspect"),
    error("aspect-denormal", lambda: CameraComponent(aspect=1e-320), ValueError, "CameraComponent.aspect",
          "not finite"),
    error("ortho-height-zero", lambda: CameraComponent(projection="orthographic", height=0.0), ValueError,
          "CameraComponent.height"),
    error("ortho-height-overflow", lambda: CameraComponent(projection="orthographic", height=1e308, aspect=10.0),
          ValueError, "CameraComponent.height", "too large"),
    error("ortho-height-denormal", lambda: CameraComponent(projection="orthographic", height=1e-320), ValueError,
          "CameraComponent.height", "not finite"),
    error("ortho-near-equals-far", lambda: CameraComponent(projection="orthographic", near=2.0, far=2.0), ValueError,
          "CameraComponent.far"),
    error("ortho-near-beyond-far", lambda: CameraComponent(projection="orthographic", near=5.0, far=1.0), ValueError,
          "CameraComponent.far", "greater than CameraComponent.near"),
    error("near-far-overflow", lambda: CameraComponent(near=1e308, far=1.7e308), ValueError, "CameraComponent.near",
          "not finite"),
    error("target-aspect-zero", lambda: CameraComponent().projection_matrix("opengl", 0.0), ValueError,
          "CameraComponent.aspect"),
    error("target-aspect-nan", lambda: CameraComponent().projection_matrix("webgpu", nan), ValueError,
          "CameraComponent.aspect"),
    error("unknown-depth-range", lambda: CameraComponent().projection_matrix("vulkan", 1.0), ValueError,
          "depth_range", "'vulkan'"),
    error("math-perspective-names-parameter", lambda: perspective(60.0, 1.0, 0.0, 10.0), ValueError, "near", "> 0"),
    result("fov-just-under-180", lambda: CameraComponent(179.9).projection_matrix("webgpu", 1.0),
           lambda m: bool(np.isfinite(m).all())),
    result("aspect-none-follows-target", lambda: CameraComponent(aspect=None).projection_matrix("webgpu", 2.0),
           lambda m: math.isclose(m[0, 0] * 2.0, m[1, 1], rel_tol=1e-15)),
    result("fixed-aspect-ignores-target", lambda: CameraComponent(aspect=1.0).projection_matrix("webgpu", 2.0),
           lambda m: math.isclose(m[0, 0], m[1, 1], rel_tol=1e-15)),
]
for label, depth_range, lo, hi, camera in [
    ("huge-range-opengl", "opengl", -1.0, 1.0, {"near": 1e-6, "far": 1e9}),
    ("huge-range-webgpu", "webgpu", 0.0, 1.0, {"near": 1e-6, "far": 1e9}),
    ("huge-range-reverse-z", "webgpu", 1.0, 0.0, {"near": 1e-6, "far": 1e9, "reverse_z": True}),
    ("infinite-far-webgpu", "webgpu", 0.0, 1.0, {"near": 0.1, "far": inf}),
    ("infinite-far-reverse-z", "webgpu", 1.0, 0.0, {"near": 0.1, "far": inf, "reverse_z": True}),
    ("infinite-far-opengl", "opengl", -1.0, 1.0, {"near": 0.1, "far": inf}),
    ("near-far-one-ulp-apart", "webgpu", 0.0, 1.0, {"near": 1.0, "far": 1.0 + 2**-40}),
    ("ortho-huge-range", "opengl", -1.0, 1.0, {"projection": "orthographic", "near": 1e-6, "far": 1e9}),
]:
    action, check = _ends(depth_range, lo, hi, **camera)
    CONSTRUCTION.append(result(label, action, check))

IN_A_FRAME = [
    error("near-set-beyond-far", lambda app: _changed_then_rendered(app, near=500.0), ValueError,
          "CameraComponent.far", "greater than CameraComponent.near"),
    error("far-set-to-near", lambda app: _changed_then_rendered(app, far=0.1), ValueError, "CameraComponent.far"),
    error("ortho-set-with-far-below-near", lambda app: _changed_then_rendered(app, projection="orthographic",
                                                                                 near=50.0, far=10.0),
          ValueError, "CameraComponent.far"),
    error("camera-with-zero-scale", _singular_camera, ValueError, "camera entity 'flat eye'", "singular"),
]


@pytest.mark.parametrize("case", params(CONSTRUCTION))
def test_camera_values(case):
    run(case)


@pytest.mark.parametrize("case", params(IN_A_FRAME))
def test_camera_values_changed_after_construction(case, shared_app):
    run(case, shared_app)
