"""Reverse-Z gives real precision in both APIs: the same camera draws the same picture in OpenGL and WebGPU.

The case: near 1e-4, far 1e7, a red plane 10,000 units away in front of a larger green plane 10 units behind it.
With reverse-Z (OpenGL: clip control to [0, 1] and a float depth buffer) no green pixel may show through the red
plane in either API; and the two APIs' pictures are identical. With the standard depth mapping the same planes
z-fight or vanish at the far end (the test shows that the case is hard enough to need reverse-Z).
"""

from __future__ import annotations

import numpy as np
from core_shaders import build_shaders

from gandalf_core import Application, Scene
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent, TransformComponent
from gandalf_core.resources import MaterialData, MeshData

W, H = 96, 72
DISTANCE = 10_000.0


def quad(half: float, z: float) -> MeshData:
    p = np.array([[-half, -half, z], [half, -half, z], [half, half, z], [-half, half, z]])
    return MeshData(p, uvs=np.zeros((4, 2)), indices=[0, 1, 2, 0, 2, 3])


def render(backend: str, reverse_z: bool) -> np.ndarray:
    scene = Scene("depth")
    scene.assets.mesh("front", quad(0.3 * DISTANCE, -DISTANCE))
    scene.assets.mesh("back", quad(0.6 * DISTANCE, -DISTANCE - 10.0))
    # Batches draw in material-name order: the near plane first, so only the depth test can keep it in front.
    scene.assets.material("a_red", MaterialData("flat", color=(1.0, 0.0, 0.0)))
    scene.assets.material("b_green", MaterialData("flat", color=(0.0, 1.0, 0.0)))
    scene.create_entity(TransformComponent(), MeshComponent("back"), MaterialComponent("b_green"))
    scene.create_entity(TransformComponent(), MeshComponent("front"), MaterialComponent("a_red"))
    scene.create_entity(TransformComponent(), CameraComponent(60.0, 1e-4, 1e7, reverse_z=reverse_z))
    with Application(backend, W, H, headless=True) as app:
        build_shaders(app.renderer.shaders, backend, "flat")
        app.add_scene(scene)
        app.run(frames=1)
        return app.capture()


def middle(image: np.ndarray) -> np.ndarray:
    h, w = image.shape[:2]
    return image[int(h * 0.4):int(h * 0.6), int(w * 0.45):int(w * 0.55)]


def green_through_red(image: np.ndarray) -> float:
    """Share of the red plane's pixels (the middle of the picture) that show the green plane instead."""
    return float((middle(image)[..., 1] > 128).mean())


def test_reverse_z_has_no_z_fighting_in_either_api(backend):
    image = render(backend, reverse_z=True)
    assert green_through_red(image) == 0.0, f"{backend}: the far plane shows through the near one"
    assert (image[..., 0] > 128).any() and (image[..., 1] > 128).any()


def test_both_apis_draw_the_same_reverse_z_picture():
    assert np.array_equal(render("opengl", True), render("webgpu", True))


def test_the_standard_mapping_fails_here(backend):
    # Standard depth cannot separate 10 units at 10,000 with near = 1e-4 (both planes round to the same depth):
    # the far plane, drawn second, shows through. The case really needs reverse-Z.
    assert green_through_red(render(backend, reverse_z=False)) > 0.5
