"""Exercise 1: ``fresnel_schlick`` and ``ggx_specular`` in GLSL and WGSL, graded by rendering a PBR sphere in both
APIs and comparing every pixel inside its silhouette with a per-pixel numpy reference (ray-sphere hit, same
camera, same lights; environment light off).

Tolerance (8-bit steps, all channels of the pixels at least 2 pixels inside the silhouette): mean absolute
error <= 1.0 and 99th percentile <= 3. The reference solution measures at most 0.09 and 1 (largest error 2)
in both APIs.
The cases include the extremes roughness 0 (clamped to 0.045) and 1, metallic 0 and 1. The sphere's shader
(``pbr_lighting.*``) also calls ``base_reflectance`` and ``diffuse_albedo`` from the same file, so this render
passes once those are written too; ``test_pbr_model_brdf.py`` grades every function on its own.
"""

from __future__ import annotations

import pytest
from light_reference import assert_near_reference
from step07_helpers import ambient, directional, inner, pbr_material, point, reference_sphere, render, sphere_scene

from gandalf_tools.grading.shader_box import on_shader_box


def _lights():
    return [
        directional((-1.0, 1.5, 2.0), (1.0, 0.95, 0.9), 2.5),
        point((1.5, 1.2, 2.0), (0.6, 0.8, 1.0), 6.0, 6.0),
        ambient((0.04, 0.04, 0.05)),
    ]


@on_shader_box  # the student's shaders run in the grader's shader process; the picture comes back
def _sphere_picture(backend: str, impl, material):
    return render(backend, impl, sphere_scene(material, _lights()))


@pytest.mark.exercise("ggx_specular")
@pytest.mark.parametrize(("metallic", "roughness"), [(0.0, 0.5), (1.0, 0.3), (0.0, 0.0), (1.0, 1.0), (0.5, 0.15)])
def test_pbr_sphere_matches_the_numpy_reference(impl, backend, metallic, roughness):
    material = pbr_material((0.9, 0.6, 0.35), metallic, roughness)
    expected, hit = reference_sphere(material, _lights())
    image = _sphere_picture(backend, impl, material)
    assert_near_reference(image, expected, inner(hit),
                          f"a sphere in {backend} (metallic {metallic}, roughness {roughness}, 3 lights)")
