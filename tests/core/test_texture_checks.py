"""Textures are checked where they are built and bound, in both APIs, with errors that name them:
a texture beyond the device's size limit, and a cube map in a 2-D slot (or a 2-D texture in a cube slot)."""

from __future__ import annotations

import numpy as np
import pytest
from core_shaders import build_shaders

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent, SkyboxComponent
from gandalf_core.resources import MaterialData, ResourceError, TextureData, checkerboard, cube, sky_cube


def app_with_unlit(backend: str) -> Application:
    app = Application(backend, 16, 12, headless=True)
    build_shaders(app.renderer.shaders, backend, "unlit")
    return app


def test_a_cube_map_in_a_2d_slot_names_material_texture_and_slot(backend):
    scene = Scene("wrong kind")
    scene.assets.mesh("box", cube())
    scene.assets.texture("sky", sky_cube(8))
    scene.assets.material("M", MaterialData("unlit", ["sky"]))
    scene.create_entity(TransformComponent((0, 0, -3)), MeshComponent("box"), MaterialComponent("M"))
    scene.create_entity(TransformComponent(), CameraComponent())
    slot = "u_albedo" if backend == "opengl" else "albedo"
    with app_with_unlit(backend) as app, pytest.raises(
            ResourceError, match=rf"material 'M': textures: texture 'sky' is a cube map, but shader 'unlit' samples a "
                                 rf"2-D texture in slot '{slot}'"):
        app.add_scene(scene)
        app.run(frames=1)


def test_a_2d_texture_as_the_sky_names_the_texture(backend):
    scene = Scene("flat sky")
    scene.assets.texture("flat", checkerboard(8, 2))
    scene.create_entity(SkyboxComponent("flat"))
    scene.create_entity(TransformComponent(), CameraComponent())
    with Application(backend, 16, 12, headless=True) as app, pytest.raises(
            (ResourceError, TypeError, ValueError), match="flat"):
        app.add_scene(scene)
        app.run(frames=1)


def test_a_texture_beyond_the_device_limit_is_refused(backend):
    with Application(backend, 16, 12, headless=True) as app:
        renderer = app.renderer
        limit = (int(renderer.ctx.info["GL_MAX_TEXTURE_SIZE"]) if backend == "opengl"
                 else int(renderer.device.limits["max-texture-dimension-2d"]))
        # A 1-pixel-high strip one texel wider than the limit: cheap to make, still too large.
        strip = TextureData(np.zeros((1, limit + 1, 4), np.uint8), mipmaps=False, name="strip")
        with pytest.raises(ResourceError, match=rf"texture 'wide': size: {limit + 1}x1 is larger than this device's"):
            renderer.textures.build("wide", strip)
        assert "wide" not in renderer.textures
