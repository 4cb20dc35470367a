"""The step's demo scene (solutions): both APIs agree, committed reference pictures, and the fountain moves.

Tolerances: OpenGL vs WebGPU PSNR >= 40 dB (measured at 60 frames: 48.5 dB, 6 of 19200 pixels more than 2 steps
apart, at brick and particle edges; at 20 frames: 68.0 dB, 1 pixel); each API vs its reference PNG PSNR >= 40 dB. Update
the references with GANDALF_UPDATE_REFERENCES=1.

The pictures are of frame ``FRAMES``, not the tour's 60: the fountain has risen by then, and WebGPU on lavapipe
draws this scene at about 0.15 s a frame (each switch between materials that bind a cube texture costs ~6 ms there).
"""

from __future__ import annotations

import importlib
from pathlib import Path

import numpy as np
import pytest

from gandalf_core.components import SkyboxComponent
from gandalf_tools.testing import compare_images, compare_to_reference, render_frames
from step07_advanced import solutions
from step07_advanced.showcase.particles import ParticleComponent
from step07_advanced.showcase.scene import METALLIC, PARTICLE_COUNT, ROUGHNESS, build_scene

REFERENCES = Path(__file__).resolve().parent / "references"
SIZE = {"width": 160, "height": 120}
#: The frame the pictures are taken at (the references' too).
FRAMES = 20


@pytest.fixture(scope="module")
def pictures() -> dict[str, np.ndarray]:
    return {
        backend: render_frames(
            importlib.import_module(f"step07_advanced.showcase.{backend}").create_app, FRAMES, **SIZE
        )
        for backend in ("opengl", "webgpu")
    }


def test_scene_has_the_chart_the_fountain_and_a_sky():
    scene = build_scene(solutions)
    materials = {name for name in scene.assets.materials if name.startswith("chart_")}
    assert len(materials) == len(METALLIC) * len(ROUGHNESS)
    assert len(scene.query(ParticleComponent).entities) == PARTICLE_COUNT
    assert len(scene.query(SkyboxComponent).entities) == 1


def test_opengl_and_webgpu_agree(pictures):
    compare_images(pictures["opengl"], pictures["webgpu"], "step07-backends", min_psnr=40.0)


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_matches_reference(pictures, backend):
    compare_to_reference(pictures[backend], REFERENCES / f"step07_advanced-{backend}.png", min_psnr=40.0)


def test_particles_move_between_frames():
    from step07_advanced.showcase.opengl import create_app

    early = render_frames(create_app, 2, **SIZE)
    late = render_frames(create_app, 10, **SIZE)
    assert not np.array_equal(early, late)
