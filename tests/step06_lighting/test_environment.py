"""Step 06's environment mapping (its exercise is graded in ``test_optics.py`` and ``test_shading_edges.py``): the
sky and the two environment-mapped bunnies, and the concept's picture in both APIs.

Pictures (160 × 120, 30 frames): the two APIs agree to PSNR ≥ 40 dB (measured on llvmpipe/lavapipe: 93.3 dB,
largest channel difference 1) and OpenGL matches ``references/step06_lighting-environment-opengl.png`` to ≥ 40 dB.
"""

from __future__ import annotations

import numpy as np
from step06_helpers import check_concept_apis_agree, check_concept_reference, concept_picture

from gandalf_core.components import LightComponent, MaterialComponent, SkyboxComponent
from step06_lighting import solutions
from step06_lighting.environment.scene import build_scene

PART = "step06_lighting.environment"


def test_the_sky_lights_the_bunnies_without_a_light():
    scene = build_scene(solutions)
    assert [sky.texture for (sky,) in scene.query(SkyboxComponent).components] == ["sky"]
    assert not scene.query(LightComponent).entities, "environment mapping needs no light"
    materials = {m.material for (m,) in scene.query(MaterialComponent).components}
    assert materials == {"silver", "ice"}
    for name in materials:
        assert tuple(scene.assets.materials[name].textures) == ("sky",), f"{name} samples the sky's cube map"


def test_the_bunnies_show_the_sky_not_a_flat_colour():
    picture = concept_picture(PART, "opengl")[..., :3].astype(int)
    middle = picture[40:110, 20:140].reshape(-1, 3)
    assert len(np.unique(middle, axis=0)) > 200, "a mirror and a glass show many colours of the sky"
    assert not np.any(np.all(middle == (255, 0, 255), axis=1)), "magenta: a stub's colour"


def test_both_apis_draw_the_same_environment():
    check_concept_apis_agree(PART, "environment")


def test_the_environment_matches_its_reference():
    check_concept_reference(PART, "environment")
