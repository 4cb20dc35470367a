"""A small scene for the frame inspector's tests: a floor, three cubes of distinct colours, a blended pane, a sky and
a shadow-casting sun, seen from above at an angle; every object covers pixels of its own (``SPOTS``)."""

from __future__ import annotations

import numpy as np

from gandalf_core import Application, ClearColorComponent, Scene, TransformComponent
from gandalf_core.components import (
    CameraComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
    SkyboxComponent,
)
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import CubeTextureData, MaterialData, cube, plane

W, H = 160, 120
#: Each object's name -> (x, y, z) position and the material it uses.
OBJECTS = {
    "floor": ((0.0, 0.0, 0.0), "floor"),
    "red cube": ((-2.0, 0.5, 0.0), "red"),
    "green cube": ((0.0, 0.5, 0.0), "green"),
    "blue cube": ((2.0, 0.5, 0.0), "blue"),
    "pane": ((0.0, 1.0, 2.0), "glass"),
}
COLORS = {"red": (0.9, 0.1, 0.1), "green": (0.1, 0.8, 0.2), "blue": (0.15, 0.2, 0.9), "floor": (0.6, 0.6, 0.55)}
SHININESS = {"red": 8.0, "green": 16.0, "blue": 64.0, "floor": 4.0}


def inspector_scene(sky: bool = True, shadows: bool = True, pane: bool = True,
                    one_material: bool = False) -> tuple[Scene, dict[str, object]]:
    """The scene and its entities by name (``one_material``: the three cubes all green, one instanced draw)."""
    scene = Scene("inspector")
    scene.assets.mesh("floor", plane(10.0, 1))
    scene.assets.mesh("cube", cube(1.0))
    scene.assets.mesh("pane", plane(2.0, 1))
    for name, color in COLORS.items():
        scene.assets.material(name, MaterialData("gandalf.blinn_phong", color=color,
                                                 params={"shininess": SHININESS[name], "specular": 0.1}))
    scene.assets.material("glass", MaterialData("gandalf.unlit", color=(1.0, 1.0, 0.2, 0.5), blend="alpha",
                                                cull="none"))
    scene.create_entity(ClearColorComponent((0.05, 0.05, 0.1)))
    entities = {}
    for name, (position, material) in OBJECTS.items():
        if name == "pane" and not pane:
            continue
        mesh = "floor" if name == "floor" else "pane" if name == "pane" else "cube"
        rotation = (-60.0, 0.0, 0.0) if name == "pane" else (0.0, 0.0, 0.0)
        if one_material and mesh == "cube":
            material = "green"
        entities[name] = scene.create_entity(TransformComponent(position, rotation=rotation), MeshComponent(mesh),
                                             MaterialComponent(material))
    if sky:
        faces = [np.full((4, 4, 4), (40 * i, 90, 160, 255), dtype=np.uint8) for i in range(6)]
        scene.assets.texture("sky", CubeTextureData.from_arrays(faces))
        scene.create_entity(SkyboxComponent("sky"))
    sun = np.array([3.0, 8.0, 2.0])
    scene.create_entity(TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", (1, 1, 1), 1.0, cast_shadows=shadows, shadow_extent=8.0,
                                       shadow_depth=30.0))
    scene.create_entity(TransformComponent(), LightComponent("ambient", (0.2, 0.2, 0.2)))
    eye = np.array([0.0, 6.0, 7.0])
    scene.create_entity(TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0, 0.5))),
                        CameraComponent(near=0.5, far=60.0))
    return scene, entities


def inspector_app(backend: str, **kwargs: bool) -> tuple[Application, dict[str, object]]:
    app = Application(backend, W, H, headless=True, fixed_dt=1 / 60)
    scene, entities = inspector_scene(**kwargs)
    app.add_scene(scene)
    return app, entities


#: A world point of each object that the camera sees of it (nothing in front): a cube's top, the pane's middle,
#: the floor beside the cubes.
VISIBLE_POINT = {"floor": (3.0, 0.0, -2.5), "red cube": (-2.0, 1.0, 0.0), "green cube": (0.0, 1.0, 0.0),
                 "blue cube": (2.0, 1.0, 0.0), "pane": (0.0, 1.0, 2.0)}


def pixel_of(app: Application, point: tuple[float, float, float]) -> tuple[int, int]:
    """The pixel (column, row from the top) where ``app``'s primary camera sees world ``point``."""
    from gandalf_core.render import RenderSystem

    system = next(s for s in app.scene.systems if isinstance(s, RenderSystem))
    view, projection, _eye, _rz = system.camera()
    clip = projection @ view @ np.array([*point, 1.0])
    ndc = clip[:3] / clip[3]
    return int((ndc[0] + 1) / 2 * app.renderer.width), int((1 - ndc[1]) / 2 * app.renderer.height)
