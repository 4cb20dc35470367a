"""The step's whole scene (solutions; ``step06_lighting.scene``: the three concepts together) and the step's
launcher: both APIs agreeing, committed reference pictures, and each concept run through ``--concept``.

Tolerances: OpenGL vs WebGPU PSNR >= 40 dB (measured: 94.0 dB, largest channel difference 1); each API vs its
reference PNG PSNR >= 40 dB (the whole scene is the one from before the step was split into concepts: measured
89.7 dB against the references made then). Update the references with GANDALF_UPDATE_REFERENCES=1.
"""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image
from step06_helpers import REFERENCES, concept_picture

from gandalf_core.components import LightComponent, SkyboxComponent
from gandalf_tools.testing import compare_images, compare_to_reference, render_frames
from step06_lighting import CONCEPTS, solutions
from step06_lighting.scene import TOUR_FRAMES, build_scene

SIZE = {"width": 160, "height": 120}
PART = "step06_lighting"


def test_scene_has_many_lights_and_a_skybox():
    scene = build_scene(solutions)
    kinds = [light.kind for (light,) in scene.query(LightComponent).components]
    assert kinds.count("point") >= 16 and "directional" in kinds and "ambient" in kinds
    assert len(scene.query(SkyboxComponent).entities) == 1


def test_opengl_and_webgpu_agree():
    compare_images(concept_picture(PART, "opengl"), concept_picture(PART, "webgpu"), "step06-backends",
                   min_psnr=40.0)


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_matches_reference(backend):
    compare_to_reference(concept_picture(PART, backend), REFERENCES / f"step06_lighting-{backend}.png",
                         min_psnr=40.0)


def test_lights_move_between_frames():
    from step06_lighting.opengl import create_app

    early = render_frames(create_app, 1, **SIZE)
    late = render_frames(create_app, TOUR_FRAMES, **SIZE)
    assert not np.array_equal(early, late)


@pytest.mark.parametrize("concept", CONCEPTS)
def test_the_launcher_runs_each_concept(concept, tmp_path, capsys):
    from step06_lighting import opengl

    out = tmp_path / f"{concept}.png"
    assert opengl.main(["--concept", concept, "--headless", "--frames", "2", "--size", "64x48", "--out", str(out)]) == 0
    assert Image.open(out).size == (64, 48)
    with pytest.raises(SystemExit) as stop:
        opengl.main(["--concept", concept, "--help"])
    assert stop.value.code == 0 and "--concept" in capsys.readouterr().out
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"{concept}.png"]
