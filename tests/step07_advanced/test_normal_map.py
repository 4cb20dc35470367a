"""Exercise 2: ``perturb_normal`` (TBN decoding of a tangent-space normal map) in GLSL and WGSL, graded by rendering
a normal-mapped quad with the ``normal_view`` shader (colour = shading normal · 0.5 + 0.5) through an orthographic
camera and comparing it with a numpy reference (bilinear lookup of the same map, the same TBN).

The quad is turned about the view axis (so T and B are not the screen axes), and also drawn with mirrored UVs
(tangent handedness w = -1). Tolerance (8-bit steps, pixels at least 2 pixels inside the quad): mean absolute
error <= 1.0 and 99th percentile <= 3; the reference solution measures at most 0.17 and 1 (largest error 1) in
both APIs.
"""

from __future__ import annotations

import numpy as np
import pytest
from light_reference import difference_sentence, pixel_errors
from step07_helpers import inner, render, sample_bilinear, to_srgb8

from gandalf_core import Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, MeshData, TextureData
from gandalf_tools.grading.shader_box import on_shader_box
from step07_advanced.showcase.textures import encode_normals, normal_map_from_height

SIZE = (96, 72)
VIEW_HEIGHT = 2.4


def bump_map() -> TextureData:
    """Smooth, tiling bumps in every direction (so a swapped or flipped axis shows)."""
    y, x = np.mgrid[0:64, 0:64] / 64.0
    height = 0.5 + 0.25 * np.sin(2 * np.pi * x) * np.cos(4 * np.pi * y) + 0.2 * np.sin(2 * np.pi * (x + 2 * y))
    normals = normal_map_from_height(height, strength=10.0)
    return TextureData.from_array(np.clip(normals * 0.5 + 0.5, 0, 1), srgb=False, mipmaps=False, name="bumps")


def quad(mirrored: bool) -> MeshData:
    """A 2×2 square facing +Z; mirrored UVs flip u, which makes the tangent handedness negative."""
    positions = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    u = [1.0, 0.0, 0.0, 1.0] if mirrored else [0.0, 1.0, 1.0, 0.0]
    uvs = np.stack([u, [1.0, 1.0, 0.0, 0.0]], axis=1)
    return MeshData(positions, normals=[[0, 0, 1]] * 4, uvs=uvs, indices=[0, 1, 2, 0, 2, 3],
                    name="quad").with_tangents()


def quad_scene(mesh: MeshData, texture: TextureData, angle: float) -> Scene:
    scene = Scene("normal map")
    scene.assets.mesh("quad", mesh)
    scene.assets.texture("bumps", texture)
    scene.assets.material("M", MaterialData("normal_view", ["bumps"], cull="none"))
    scene.create_entity(TransformComponent(rotation=(0.0, 0.0, angle)), MeshComponent("quad"), MaterialComponent("M"))
    scene.create_entity(TransformComponent((0.0, 0.0, 3.0)),
                        CameraComponent(projection="orthographic", height=VIEW_HEIGHT, near=0.1, far=10.0))
    return scene


def perturb_normal_np(n, tangent, rgb):
    """Numpy twin of the reference ``perturb_normal`` for one tangent frame and many texels."""
    m = rgb * 2.0 - 1.0
    t = tangent[:3] - n * np.dot(n, tangent[:3])
    t /= np.linalg.norm(t)
    b = np.cross(n, t) * (-1.0 if tangent[3] < 0 else 1.0)
    r = m[..., :1] * t + m[..., 1:2] * b + m[..., 2:3] * n
    return r / np.linalg.norm(r, axis=-1, keepdims=True)


def reference_quad(mesh: MeshData, texture: TextureData, angle: float) -> tuple[np.ndarray, np.ndarray]:
    """(expected 8-bit RGB, covered mask) of the quad turned by ``angle`` degrees about +Z."""
    w, h = SIZE
    x = ((np.arange(w) + 0.5) / w * 2.0 - 1.0) * VIEW_HEIGHT / 2 * w / h
    y = (1.0 - (np.arange(h) + 0.5) / h * 2.0) * VIEW_HEIGHT / 2
    px, py = np.meshgrid(x, y)
    c, s = np.cos(np.radians(angle)), np.sin(np.radians(angle))
    lx, ly = c * px + s * py, -s * px + c * py  # world -> the quad's own frame
    covered = (np.abs(lx) < 1.0) & (np.abs(ly) < 1.0)
    u = (lx + 1.0) / 2.0
    u = 1.0 - u if mesh.uvs[0, 0] > 0.5 else u
    uv = np.stack([u, (1.0 - ly) / 2.0], axis=-1)
    rotation = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    tangent = np.concatenate([rotation @ mesh.tangents[0, :3].astype(np.float64), mesh.tangents[0, 3:]])
    normal = perturb_normal_np(np.array([0.0, 0.0, 1.0]), tangent, sample_bilinear(texture, uv))
    return to_srgb8(normal * 0.5 + 0.5), covered


CASES = [(False, 0.0), (False, 25.0), (True, -35.0)]


@on_shader_box  # the student's shaders run in the grader's shader process; the picture comes back
def _quad_picture(backend: str, impl, mesh: MeshData, texture: TextureData, angle: float) -> np.ndarray:
    return render(backend, impl, quad_scene(mesh, texture, angle), size=SIZE)


@pytest.mark.exercise("normal_map")
@pytest.mark.parametrize(("mirrored", "angle"), CASES)
def test_normal_mapped_quad_matches_the_numpy_reference(impl, backend, mirrored, angle):
    mesh, texture = quad(mirrored), bump_map()
    assert (mesh.tangents[:, 3] < 0).all() == mirrored
    expected, covered = reference_quad(mesh, texture, angle)
    image = _quad_picture(backend, impl, mesh, texture, angle)
    mean, p99 = pixel_errors(image, expected, inner(covered))
    case = f"a bump-mapped quad in {backend} ({'mirrored' if mirrored else 'unmirrored'} UVs, turned {angle:g}°)"
    assert mean <= 1.0 and p99 <= 3.0, difference_sentence(image, expected, inner(covered), mean, p99, 1.0, 3.0, case)


@pytest.mark.exercise("normal_map")
def test_flat_normal_map_gives_the_surface_normal(impl, backend):
    flat = encode_normals(np.tile([0.0, 0.0, 1.0], (4, 4, 1)), "flat")
    image = _quad_picture(backend, impl, quad(False), flat, 30.0)
    _, covered = reference_quad(quad(False), flat, 30.0)
    # (128, 128, 255) decodes to (0.004, 0.004, 1): colour (0.5, 0.5, 1) -> sRGB (188, 188, 255) within 1 step.
    mask = inner(covered)
    error = np.abs(image[mask][:, :3].astype(int) - [188, 188, 255]).max()
    assert error <= 1, ("flat normal map (texels 128, 128, 255): "
                        + difference_sentence(image, [188.0, 188.0, 255.0], mask, float(error), float(error), 1, 1)
                        + ". Hint: decode 2 c - 1, then the TBN matrix")
