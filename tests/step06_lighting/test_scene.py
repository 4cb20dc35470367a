"""The step's demo scene (solutions): the model file, both APIs agreeing, and committed reference pictures.

Tolerances: OpenGL vs WebGPU PSNR >= 40 dB (measured: 62.6 dB, largest channel difference 2); each API vs its reference
PNG PSNR >= 40 dB. Update the references with GANDALF_UPDATE_REFERENCES=1.
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest
from step06_helpers import REFERENCES

from gandalf_core.components import LightComponent, SkyboxComponent
from gandalf_core.resources.mesh_loader import load_meshes
from gandalf_core.testing import compare_images, compare_to_reference, render_frames
from step06_lighting import solutions
from step06_lighting.scene import BUNNY_PATH, TOUR_FRAMES, build_scene

SIZE = {"width": 160, "height": 120}


@pytest.fixture(scope="module")
def pictures() -> dict[str, np.ndarray]:
    return {
        backend: render_frames(importlib.import_module(f"step06_lighting.{backend}").create_app, TOUR_FRAMES, **SIZE)
        for backend in ("opengl", "webgpu")
    }


def test_bunny_model_is_small_and_has_five_parts():
    assert BUNNY_PATH.stat().st_size < 200_000
    parts = load_meshes(BUNNY_PATH)
    assert sorted(parts) == ["body", "ear_left", "ear_right", "head", "tail"]
    # The node transforms place the parts: the ears are the highest, the bunny stands on y = 0.
    tops = {name: mesh.bounds()[1][1] for name, mesh in parts.items()}
    assert max(tops, key=tops.get).startswith("ear")
    assert min(mesh.bounds()[0][1] for mesh in parts.values()) == pytest.approx(0.0, abs=0.02)


def test_scene_has_many_lights_and_a_skybox():
    scene = build_scene(solutions)
    kinds = [light.kind for (light,) in scene.query(LightComponent).components]
    assert kinds.count("point") >= 16 and "directional" in kinds and "ambient" in kinds
    assert len(scene.query(SkyboxComponent).entities) == 1


def test_opengl_and_webgpu_agree(pictures):
    compare_images(pictures["opengl"], pictures["webgpu"], "step06-backends", min_psnr=40.0)


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_matches_reference(pictures, backend):
    compare_to_reference(pictures[backend], REFERENCES / f"step06_lighting-{backend}.png", min_psnr=40.0)


def test_lights_move_between_frames():
    from step06_lighting.opengl import create_app

    early = render_frames(create_app, 1, **SIZE)
    late = render_frames(create_app, TOUR_FRAMES, **SIZE)
    assert not np.array_equal(early, late)
