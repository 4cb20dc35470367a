"""The PBR model scene, the same for OpenGL and WebGPU: a textured glTF power cell turning under a sun and
image-based light from a procedural sky.

The model (``models/power_cell.glb``, made by ``make_model.py``) is read by
:func:`gandalf_core.resources.load_gltf`; its material gets the three IBL textures computed by ``ibl.py`` in
numpy float64. The sky box shows the same sky the lighting comes from.
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType
from typing import Any

import numpy as np

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import (
    CameraComponent,
    InfoComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
    SkyboxComponent,
)
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import CubeTextureData, MaterialData, ResourceError, load_gltf
from gandalf_core.systems import SpinComponent, SpinSystem

from .ibl import SUN_DIRECTION, IBLMaps, default_ibl
from .shaders import SHADER_NAME

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 60
MODEL = Path(__file__).resolve().parent / "models" / "power_cell.glb"
IBL_TEXTURES = ("ibl_irradiance", "ibl_prefiltered", "ibl_brdf_lut")
#: Material params of the model's shader that must lie in [0, 1].
UNIT_PARAMS = ("metallic", "roughness", "occlusion_strength")
EYE = (0.0, 1.35, 3.6)
TARGET = (0.0, 0.92, 0.0)


def check_pbr_material(name: str, material: MaterialData, textures: dict[str, Any]) -> None:
    """Raise :class:`ResourceError` naming the material when a [0, 1] parameter is out of range, or naming the
    texture when an environment slot (the irradiance or prefiltered map) is not a cube map."""
    for key in UNIT_PARAMS:
        value = material.params.get(key)
        if value is not None and not 0.0 <= float(value) <= 1.0:
            raise ResourceError(f"material '{name}'", f"params['{key}']", f"{value} is outside [0, 1]")
    for slot, texture_name in zip(("irradiance", "prefiltered"), material.textures[5:7]):
        texture = textures.get(texture_name)
        if texture is not None and not isinstance(texture, CubeTextureData):
            raise ResourceError(f"texture '{texture_name}'", f"material '{name}' {slot}",
                                f"the environment must be a cube map (CubeTextureData), got {type(texture).__name__}")


def add_model(scene: Scene, ibl: IBLMaps, params: dict[str, float] | None = None,
              position: tuple[float, float, float] = (0.0, 0.0, 0.0), spin: float = 20.0) -> list:
    """Load the model into ``scene`` (its meshes, materials and textures plus the IBL textures) and create one
    spinning entity per part. ``params`` override material params (e.g. ``env_strength``)."""
    assets = scene.assets
    for name, texture in zip(IBL_TEXTURES, (ibl.irradiance, ibl.prefiltered, ibl.brdf_lut)):
        if name not in assets.textures:
            assets.texture(name, texture)
    values = {"env_strength": 1.0, "prefiltered_levels": float(ibl.levels), **(params or {})}
    model = load_gltf(MODEL, shader=SHADER_NAME, extra_textures=IBL_TEXTURES, params=values)
    for name, texture in model.textures.items():
        if name not in assets.textures:
            assets.texture(name, texture)
    for name, material in model.materials.items():
        check_pbr_material(name, material, assets.textures)
        assets.material(name, material)
    entities = []
    for mesh, material in model.parts:
        assets.mesh(mesh, model.meshes[mesh])
        entities.append(scene.create_entity(InfoComponent(mesh), TransformComponent(position),
                                            SpinComponent((0.0, 1.0, 0.0), spin), MeshComponent(mesh),
                                            MaterialComponent(material)))
    return entities


def build_scene(impl: ModuleType | None = None, ibl: IBLMaps | None = None, env_strength: float = 1.0,
                sun: float = 2.2) -> Scene:
    """The demo scene. ``impl`` is unused here (the variant files build the shaders with its includes);
    ``env_strength`` scales the image-based light, ``sun`` the directional light (0: none)."""
    ibl = ibl or default_ibl()
    scene = Scene("step07_pbr_model")
    scene.assets.texture("ibl_sky", ibl.sky)
    scene.create_entity(InfoComponent("sky"), SkyboxComponent("ibl_sky"))
    add_model(scene, ibl, {"env_strength": env_strength})
    if sun > 0.0:
        position = tuple(8.0 * np.asarray(SUN_DIRECTION))
        scene.create_entity(InfoComponent("sun"),
                            TransformComponent(position, quaternion=look_at_rotation(position, (0, 0, 0))),
                            LightComponent("directional", (1.0, 0.95, 0.85), intensity=sun))
    scene.create_entity(InfoComponent("camera"), TransformComponent(EYE, quaternion=look_at_rotation(EYE, TARGET)),
                        CameraComponent(40.0, 0.1, 50.0))
    scene.add_system(SpinSystem())
    return scene


#: The technique the variants (``opengl.py``, ``webgpu.py``) hand the launcher with their programs.
PART = Part(__package__, build_scene)
