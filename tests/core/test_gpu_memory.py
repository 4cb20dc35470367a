"""The GPU memory a renderer reports (``Renderer.gpu_memory()``): each kind is the bytes its buffers and textures were
made with, counted from the scene's own data here (a texture's levels, a mesh's vertices and indices, the target's
pixels), the same in both APIs where both hold the same objects, and given back when an object is released."""

from __future__ import annotations

import numpy as np

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import (
    CameraComponent,
    ClearColorComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
)
from gandalf_core.render.frame import INSTANCE_STRIDE, SHADOW_MAP_SIZE
from gandalf_core.render.gpu_memory import chain_bytes, in_mib
from gandalf_core.resources import MaterialData, TextureData, primitives

W, H = 40, 24
ENTITIES = 5


def test_a_chain_counts_every_level_and_layer():
    # 64x32: 64x32, 32x16, 16x8, 8x4, 4x2, 2x1, 1x1; 5x3: 5x3, 2x1, 1x1 (halved, rounded down, at least 1).
    assert chain_bytes(64, 32, 4, 7) == 4 * (2048 + 512 + 128 + 32 + 8 + 2 + 1)
    assert chain_bytes(5, 3, 4, 3, layers=6) == 6 * 4 * (15 + 2 + 1)
    assert chain_bytes(16, 16, 4) == 16 * 16 * 4


def _scene(shadows: bool) -> Scene:
    scene = Scene("held")
    scene.assets.mesh("box", primitives.cube())
    pixels = np.zeros((32, 64, 4), np.uint8)
    pixels[..., 0] = np.arange(64, dtype=np.uint8)[None, :] * 4
    pixels[..., 3] = 255
    scene.assets.texture("ramp", TextureData(pixels, mipmaps=True))
    scene.assets.material("lit", MaterialData("gandalf.blinn_phong", ["ramp"], color=(1, 1, 1)))
    scene.create_entity(ClearColorComponent((0.1, 0.1, 0.1)))
    scene.create_entity(TransformComponent((0.0, 0.0, 6.0)), CameraComponent(60.0, 0.1, 50.0))
    scene.create_entity(TransformComponent((0.0, 0.0, 0.0), quaternion=(0.92, -0.38, 0.0, 0.0)),
                        LightComponent("directional", cast_shadows=shadows))
    for i in range(ENTITIES):
        scene.create_entity(TransformComponent((1.2 * i - 2.4, 0.0, 0.0)), MeshComponent("box"),
                            MaterialComponent("lit"))
    return scene


def _held(backend: str, shadows: bool = False) -> tuple[dict[str, int], dict[str, int]]:
    """The report after one frame, and the bytes expected from the scene's data."""
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        scene = _scene(shadows)
        app.add_scene(scene)
        app.step()
        r = app.renderer
        held = r.gpu_memory()
        mesh = r.meshes.get("box")
        cube = scene.assets.meshes["box"]
        vertices = sum(cube.interleaved(attributes)[0].nbytes for attributes in mesh.vertex_buffers)
        expected = {
            "textures": chain_bytes(64, 32, 4, 7),
            "meshes": cube.indices.astype(np.uint32).nbytes + vertices,
            "frame targets": W * H * (4 + 4),  # sRGB RGBA8 colour and 32-bit depth
            "shadow map": SHADOW_MAP_SIZE * SHADOW_MAP_SIZE * 4 if shadows else 0,
            "instance rows": ENTITIES * INSTANCE_STRIDE,
            "attribute sets": len(mesh.vertex_buffers),
        }
        return held, expected


def test_the_report_counts_what_the_scene_holds(backend):
    held, expected = _held(backend)
    assert held["textures"] == expected["textures"]
    assert expected["attribute sets"] == 1  # one vertex buffer: the mesh's attributes the draws read
    assert held["meshes"] == expected["meshes"]
    assert held["frame targets"] == expected["frame targets"]
    assert held["shadow map"] == 0
    assert held["instances"] >= expected["instance rows"]
    assert held["material blocks"] > 0 and held["frame uniforms"] > 0
    assert held["total"] == sum(v for k, v in held.items() if k != "total")
    assert in_mib(held)["total"] == round(held["total"] / 2**20, 3)


def test_a_shadow_map_is_counted_once_made(backend):
    held, expected = _held(backend, shadows=True)
    assert held["shadow map"] == expected["shadow map"] > 0


def test_both_apis_report_the_same_textures_targets_and_shadow_map():
    gl, _ = _held("opengl", shadows=True)
    wg, _ = _held("webgpu", shadows=True)
    for kind in ("textures", "frame targets", "shadow map", "instances"):
        assert gl[kind] == wg[kind], kind


def test_a_forgotten_texture_gives_its_bytes_back(backend):
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        app.add_scene(_scene(False))
        app.step()
        r = app.renderer
        before = r.gpu_memory()
        r.materials.forget("lit")
        r.textures.forget("ramp")
        after = r.gpu_memory()
        assert before["textures"] == chain_bytes(64, 32, 4, 7) and after["textures"] == 0
        assert after["total"] == before["total"] - before["textures"] - before["material blocks"]
