"""Mirrored instances (a negative determinant: one or three negative scale factors) keep their outside out.

A sphere is symmetric under every mirror, so a lit sphere scaled by (-1, 1, 1), (1, -1, 1) or (-1, -1, -1) must
draw the same picture as the unmirrored one (no channel more than 2/255 apart; measured: identical), in both
backends, with back-face culling on, in a batch of its own or mixed with unmirrored instances of the same mesh and
material, and with a shadow-casting light.
"""

from __future__ import annotations

import numpy as np
import pytest
from core_shaders import build_shaders

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, plane, uv_sphere

W, H = 96, 72


def render(backend: str, scales: list[tuple[float, float, float]], shadows: bool = False) -> np.ndarray:
    scene = Scene("mirrors")
    scene.assets.mesh("sphere", uv_sphere(0.8, 32, 16))
    scene.assets.mesh("floor", plane(8.0, 1))
    scene.assets.material("M", MaterialData("lit", color=(0.9, 0.6, 0.3)))
    for i, scale in enumerate(scales):
        scene.create_entity(TransformComponent((2.0 * i - (len(scales) - 1), 0.0, 0.0), scale=scale),
                            MeshComponent("sphere"), MaterialComponent("M"))
    if shadows:
        scene.create_entity(TransformComponent((0, -0.8, 0)), MeshComponent("floor"), MaterialComponent("M"))
    sun = np.array([-2.0, 4.0, 3.0])
    scene.create_entity(TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", intensity=1.5, cast_shadows=shadows))
    scene.create_entity(TransformComponent(), LightComponent("ambient", (0.1, 0.1, 0.1)))
    eye = np.array([0.0, 1.0, 5.0])
    scene.create_entity(TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0, 0))),
                        CameraComponent(60.0, 0.1, 50.0))
    with Application(backend, W, H, headless=True) as app:
        build_shaders(app.renderer.shaders, backend, "lit")
        app.add_scene(scene)
        app.run(frames=1)
        return app.capture()


def assert_same(a: np.ndarray, b: np.ndarray, what: str) -> None:
    worst = int(np.abs(a.astype(int) - b.astype(int)).max())
    assert worst <= 2, f"{what}: largest channel difference {worst}/255 against the unmirrored picture (allowed 2)"


@pytest.mark.parametrize("scale", [(-1.0, 1.0, 1.0), (1.0, -1.0, 1.0), (-1.0, -1.0, -1.0)])
def test_a_mirrored_sphere_draws_like_the_unmirrored_one(backend, scale):
    assert_same(render(backend, [scale]), render(backend, [(1.0, 1.0, 1.0)]), f"scale {scale}")


def test_mirrored_and_plain_instances_in_one_batch(backend):
    mixed = render(backend, [(1.0, 1.0, 1.0), (-1.0, 1.0, 1.0), (1.0, 1.0, 1.0)])
    plain = render(backend, [(1.0, 1.0, 1.0)] * 3)
    assert_same(mixed, plain, "one mirrored instance among plain ones")


def test_mirrored_with_shadows(backend):
    assert_same(render(backend, [(1.0, 1.0, -1.0)], shadows=True), render(backend, [(1.0, 1.0, 1.0)], shadows=True),
                "mirrored, with a shadow-casting light")


@pytest.mark.parametrize("s", [1e-20, 1e20])
def test_mirroring_is_seen_at_extreme_scales(s):
    """The mirror test reads the packed float32 rows; where float32 cannot tell (1e-20 or 1e20 cubed) it decides in
    float64, so a mirrored tiny or huge instance still gets its own clockwise batch."""
    from gandalf_core.render.render_system import RenderSystem

    scene = Scene("extreme")
    scene.assets.mesh("sphere", uv_sphere(0.8, 8, 4))
    scene.assets.material("M", MaterialData("lit"))
    for scale in ((s, s, s), (-s, s, s)):
        scene.create_entity(TransformComponent(scale=scale), MeshComponent("sphere"), MaterialComponent("M"))
    with Application("opengl", 8, 8, headless=True) as app:
        build_shaders(app.renderer.shaders, "opengl", "lit")
        app.add_scene(scene)
        app.step()
        system = next(x for x in scene.systems if isinstance(x, RenderSystem))
        batches = system.frame_data(0.0).batches
    assert sorted((b.mirrored, b.count) for b in batches) == [(False, 1), (True, 1)]
