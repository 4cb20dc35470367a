"""Step 06's lights concept (its exercises are graded in ``test_blinn_phong.py`` and ``test_light_collection.py``):
the ring of lights that circle the clay bunny, the scene's light system, and the concept's picture in both APIs.

Pictures (160 × 120, 30 frames): the two APIs agree to PSNR ≥ 40 dB (measured on llvmpipe/lavapipe: 94.8 dB,
largest channel difference 1) and OpenGL matches ``references/step06_lighting-lights-opengl.png`` to ≥ 40 dB.
"""

from __future__ import annotations

import numpy as np
import pytest
from step06_helpers import check_concept_apis_agree, check_concept_reference

from gandalf_core import TransformComponent, TransformSystem
from gandalf_core.components import LightComponent
from step06_lighting import solutions
from step06_lighting.lights.components import OrbitComponent
from step06_lighting.lights.scene import RING_LIGHTS, TOUR_FRAMES, build_scene

PART = "step06_lighting.lights"


def test_the_ring_holds_sixteen_point_lights_a_key_and_an_ambient():
    scene = build_scene(solutions)
    kinds = [light.kind for (light,) in scene.query(LightComponent).components]
    assert kinds.count("point") == RING_LIGHTS == 16
    assert kinds.count("directional") == 1 and kinds.count("ambient") == 1
    assert any(isinstance(s, solutions.LightCollectionSystem) for s in scene.systems), \
        "the scene's lights go through the step's LightCollectionSystem (exercise 2)"


def test_the_lights_circle_the_bunny_at_their_speed():
    scene = build_scene(solutions)
    scene.add_system(TransformSystem())
    orbits = scene.query(OrbitComponent, TransformComponent).components
    start = [orbit.angle for orbit, _ in orbits]
    dt, frames = 1 / 60, 45
    for _ in range(frames):
        scene.update(dt)
    for (orbit, transform), angle in zip(orbits, start):
        assert orbit.angle == pytest.approx((angle + orbit.speed * dt * frames) % 360.0, abs=1e-9)
        offset = transform.translation - orbit.center
        assert offset[1] == pytest.approx(0.0, abs=1e-12)
        assert np.linalg.norm(offset) == pytest.approx(orbit.radius, abs=1e-12)
    assert TOUR_FRAMES > 1


def test_both_apis_draw_the_same_lights():
    check_concept_apis_agree(PART, "lights")


def test_the_lights_match_their_reference():
    check_concept_reference(PART, "lights")
