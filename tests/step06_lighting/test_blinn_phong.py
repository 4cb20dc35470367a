"""Exercise 1: ``blinn_phong`` in GLSL and WGSL, graded by rendering a lit sphere in both APIs and comparing
every pixel inside its silhouette with a per-pixel numpy reference (ray-sphere hit, same camera, same lights).

Tolerance (8-bit steps, all channels of the pixels at least 2 pixels inside the silhouette): mean absolute
error <= 1.0 and 99th percentile <= 3. The reference solution measures 0.10 and 1 in both APIs.
"""

from __future__ import annotations

import pytest
from light_reference import assert_near_reference
from step06_helpers import ambient, directional, inner, point, reference_sphere, render, sphere_scene

from gandalf_core.resources import MaterialData
from gandalf_tools.grading.shader_box import on_shader_box


def _lights():
    return [
        directional((-1.0, 1.5, 2.0), (1.0, 0.95, 0.9), 0.8),
        point((1.5, 1.2, 2.0), (0.6, 0.8, 1.0), 3.0, 6.0),
        ambient((0.1, 0.1, 0.12)),
    ]


@on_shader_box  # the student's shaders run in the grader's shader process; the picture comes back
def _sphere_picture(backend, impl, material, lights):
    return render(backend, impl, sphere_scene(material, lights))


def _check(backend, impl, material, lights):
    expected, hit = reference_sphere(material, lights)
    image = _sphere_picture(backend, impl, material, lights)
    params = ", ".join(f"{k} {v:g}" for k, v in material.params.items())
    assert_near_reference(image, expected, inner(hit),
                          f"a sphere in {backend} (colour {tuple(material.color)[:3]}, {params}, {len(lights)} lights)")


@pytest.mark.exercise("blinn_phong")
@pytest.mark.parametrize("shininess", [24.0, 0.0, 1.0, 1e4])
def test_lit_sphere_matches_the_numpy_reference(impl, backend, shininess):
    material = MaterialData("phong", color=(0.8, 0.5, 0.3), params={"specular": 0.5, "shininess": shininess})
    _check(backend, impl, material, _lights())


@pytest.mark.exercise("blinn_phong")
def test_point_light_only_with_a_white_highlight(impl, backend):
    material = MaterialData("phong", color=(0.3, 0.6, 0.35), params={"specular": 1.0, "shininess": 64.0})
    _check(backend, impl, material, [point((0.8, 0.6, 2.2), (1.0, 1.0, 1.0), 1.2)])
