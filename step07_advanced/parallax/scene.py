"""Normal mapping and the parallax family side by side, the same scene for OpenGL and WebGPU.

Four strips of the same brick wall (the showcase's procedural albedo, normal and height maps) lie flat under the
same light, stacked along the camera's up vector so that an orthographic camera sees every one of them at the same
grazing angle, 18° above the surface, where the methods differ most. From the top of the picture down:

0. **normal mapping**: the normal map bends the shading normal, the uv stays put: flat bricks that are lit as if
   they had relief;
1. **parallax offset**: one height sample moves the uv against the view, ``uv − v.xy / v.z · scale · (1 − h)``;
2. **steep parallax**: the view ray marches down through ``layers`` slabs and stops at the first one below the
   height field: real occlusion, in stair steps;
3. **parallax occlusion mapping**: the same march, then the linear interpolation between the last two layers.

Every strip uses one material of the one shader ``parallax_surface``; its ``method`` parameter picks the
function, its ``height_scale`` and ``layers`` the depth and the march (validated by :func:`parallax_material`).
The study (``study.py``) renders the same view with all four strips read by one method (:func:`study_scene`).
"""

from __future__ import annotations

import functools
import math
from types import ModuleType

import numpy as np

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import (
    CameraComponent,
    ClearColorComponent,
    InfoComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
)
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, MeshData, ResourceError, TextureData, plane

from ..checks import checked_number
from ..showcase.textures import brick_textures
from .reference import MAX_LAYERS
from .shaders import SHADER

#: Frames the course tour renders before it takes the picture (the scene stands still).
TOUR_FRAMES = 2
#: The methods, in the order of the strips (top to bottom) and of the shader's ``method`` parameter.
METHODS = ("normal", "offset", "steep", "occlusion")
LABELS = {"normal": "normal mapping", "offset": "parallax offset", "steep": "steep parallax",
          "occlusion": "parallax occlusion"}
#: The depth of height 0 in uv units of the repeated texture, and the march's layers in the tour.
HEIGHT_SCALE = 0.04
LAYERS = 16
TEXTURES = ("bricks_albedo", "bricks_normal", "bricks_height")
#: Each strip: width (x) and depth (z) in world units; the texture repeats once per 2 units.
STRIP = (4.4, 2.4)
UV_SCALE = (STRIP[0] / 2.0, STRIP[1] / 2.0)
COLOR = (1.0, 1.0, 1.0)
SPECULAR = 0.25
SHININESS = 24.0
BACKGROUND = (0.06, 0.07, 0.09)
#: An orthographic camera looks down at ELEVATION degrees from DISTANCE away and sees VIEW_HEIGHT world units
#: from the bottom of the picture to the top: every strip is seen at the same grazing angle (the view vectors the
#: shaders compute from the camera's position vary by at most 2.6° up and down and 3.4° across).
ELEVATION = 18.0
DISTANCE = 40.0
VIEW_HEIGHT = 3.6
TARGET = (0.0, 0.0, 0.0)
#: The camera's up vector and the unit vector from TARGET towards the camera (the strips, their labels and the
#: camera are all placed along these two).
VIEW_UP = (0.0, math.cos(math.radians(ELEVATION)), -math.sin(math.radians(ELEVATION)))
TOWARDS_CAMERA = (0.0, math.sin(math.radians(ELEVATION)), math.cos(math.radians(ELEVATION)))
#: The strips' spacing along the camera's up vector (world units): their projected depth plus a gap.
SPACING = STRIP[1] * TOWARDS_CAMERA[1] + 0.16
#: Where the light comes from (a unit vector is made of it): low, from the back left, so the bricks cast light
#: and shade on their sides.
SUN = (-0.55, 0.55, -0.35)


def validate_parallax(label: str, method: str, height_scale: float, layers: int) -> tuple[int, float, int]:
    """(method index, height_scale, layers) checked, or a ResourceError naming ``label`` and the parameter.

    ``method`` is one of :data:`METHODS`; ``height_scale`` a finite number ≥ 0; ``layers`` an int in
    [1, :data:`MAX_LAYERS`] (the shaders' PARALLAX_MAX_LAYERS: the march never runs longer).
    """
    if method not in METHODS:
        raise ResourceError(label, "method", f"{method!r} is not one of {', '.join(METHODS)}")
    scale = checked_number(label, "height_scale", height_scale, ">= 0 (a depth in uv units)", lambda v: v >= 0.0)
    if isinstance(layers, bool) or not isinstance(layers, int) or not 1 <= layers <= MAX_LAYERS:
        raise ResourceError(label, "layers", f"must be an int from 1 to {MAX_LAYERS} (the shader's "
                                             f"PARALLAX_MAX_LAYERS), got {layers!r}")
    return METHODS.index(method), scale, layers


# --8<-- [start:material]
def parallax_material(method: str, height_scale: float = HEIGHT_SCALE, layers: int = LAYERS, *,
                      uv_scale=UV_SCALE, name: str = "") -> MaterialData:
    """The brick material read by ``method``: the three brick maps and the shader's parameters."""
    name = name or f"bricks_{method}"
    index, scale, count = validate_parallax(f"material '{name}'", method, height_scale, layers)
    params = {"method": float(index), "height_scale": scale, "layers": float(count), "uv_scale": tuple(uv_scale),
              "specular": SPECULAR, "shininess": SHININESS}
    return MaterialData(SHADER, TEXTURES, color=COLOR, params=params, name=name)
# --8<-- [end:material]


@functools.cache
def _brick_maps(size: int) -> dict[str, TextureData]:
    return brick_textures(size)


@functools.cache
def _strip_mesh() -> MeshData:
    """The unit square every strip scales (one object, so one app can draw several of the scenes)."""
    return plane(1.0, 1)


def add_textures(scene: Scene, size: int = 256) -> None:
    """The showcase's procedural brick maps (albedo, normal, height), ``size``² texels (made once per size)."""
    for name, texture in _brick_maps(size).items():
        scene.assets.texture(name, texture)


def add_light(scene: Scene) -> None:
    """One directional light, low from the back left, and a little ambient light."""
    scene.create_entity(InfoComponent("background"), ClearColorComponent(BACKGROUND))
    length = math.sqrt(sum(c * c for c in SUN))
    sun = tuple(4.0 * c / length for c in SUN)
    scene.create_entity(InfoComponent("sun"), TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", (1.0, 0.95, 0.88), intensity=1.6))
    scene.create_entity(InfoComponent("ambient"), TransformComponent(), LightComponent("ambient", (0.16, 0.17, 0.2)))


#: Each strip's label: a quad facing the camera over the strip's top left corner, LABEL_SIZE world units wide and
#: high, its text drawn by Pillow into LABEL_TEXELS texels (white on the background colour).
LABEL_SIZE = (1.5, 0.2)
LABEL_TEXELS = (390, 52)


@functools.cache
def label_texture(text: str) -> TextureData:
    """``text`` in white on a dark box (Pillow's default font), an sRGB texture that the label quads show."""
    from PIL import Image, ImageDraw, ImageFont

    width, height = LABEL_TEXELS
    box = tuple(round(255 * c) for c in BACKGROUND)
    image = Image.new("RGBA", LABEL_TEXELS, (*box, 255))
    ImageDraw.Draw(image).text((12, height / 2), text, fill=(240, 240, 240, 255),
                               font=ImageFont.load_default(size=34), anchor="lm")
    return TextureData(np.asarray(image), wrap="clamp", name=f"label {text}")


def add_labels(scene: Scene, methods: tuple[str, ...]) -> None:
    """Name each strip's method on a label over its top left corner (an unlit quad facing the camera, a little
    in front of the strip so that it is never hidden)."""
    half_height = STRIP[1] / 2 * TOWARDS_CAMERA[1]  # the strip's half height in the picture
    x = -STRIP[0] / 2 + LABEL_SIZE[0] / 2 + 0.08
    lift = half_height - LABEL_SIZE[1] / 2 - 0.04
    scene.assets.mesh("label", _strip_mesh())
    for method, centre in zip(methods, strip_positions(), strict=True):
        name = f"label {method}"
        if name not in scene.assets.textures:
            scene.assets.texture(name, label_texture(LABELS[method]))
            scene.assets.material(name, MaterialData("gandalf.unlit", [name]))
        position = tuple(centre[j] + lift * VIEW_UP[j] + 1.0 * TOWARDS_CAMERA[j] + (x if j == 0 else 0.0)
                         for j in range(3))
        scene.create_entity(InfoComponent(f"{LABELS[method]} label"),
                            TransformComponent(position, rotation=(90.0 - ELEVATION, 0.0, 0.0),
                                               scale=(LABEL_SIZE[0], 1.0, LABEL_SIZE[1])),
                            MeshComponent("label"), MaterialComponent(name))


def camera_eye() -> tuple[float, float, float]:
    """Where the camera stands: DISTANCE from TARGET, ELEVATION degrees above the strips' planes."""
    return (TARGET[0], TARGET[1] + DISTANCE * TOWARDS_CAMERA[1], TARGET[2] + DISTANCE * TOWARDS_CAMERA[2])


def strip_positions() -> list[tuple[float, float, float]]:
    """The centres of the four strips, top of the picture to bottom: stacked along the camera's up vector, so
    none hides another and all are seen at the same angle."""
    return [tuple(TARGET[j] + (1.5 - k) * SPACING * VIEW_UP[j] for j in range(3)) for k in range(len(METHODS))]


def build_scene(impl: ModuleType | None = None, *, methods: tuple[str, ...] = METHODS,
                height_scale: float = HEIGHT_SCALE, layers: int = LAYERS, name: str = "step07_parallax",
                prefix: str = "bricks_", labels: bool = True) -> Scene:
    """The demo: four strips, top to bottom read by ``methods`` (normal, offset, steep, occlusion), each named on
    a label unless ``labels`` is False. ``impl`` (exercises or solutions) is the package the variant file built the
    shader with. The materials are called ``prefix + method`` (one app can hold several such scenes when their
    prefixes differ)."""
    del impl  # the shader was built with it; the scene itself is the same for both
    if len(methods) != len(METHODS):
        raise ValueError(f"methods: expected {len(METHODS)} method names (one per strip), got {methods!r}")
    scene = Scene(name)
    add_textures(scene)
    scene.assets.mesh("strip", _strip_mesh())
    for method, position in zip(methods, strip_positions(), strict=True):
        material = parallax_material(method, height_scale, layers, name=f"{prefix}{method}")
        scene.assets.material(material.name, material)
        scene.create_entity(InfoComponent(f"{LABELS[method]} strip"),
                            TransformComponent(position, scale=(STRIP[0], 1.0, STRIP[1])),
                            MeshComponent("strip"), MaterialComponent(material.name))
    if labels:
        add_labels(scene, methods)
    add_light(scene)
    eye = camera_eye()
    scene.create_entity(InfoComponent("camera"), TransformComponent(eye, quaternion=look_at_rotation(eye, TARGET)),
                        CameraComponent(near=DISTANCE - 10.0, far=DISTANCE + 10.0, projection="orthographic",
                                        height=VIEW_HEIGHT))
    return scene


def study_scene(method: str, layers: int = LAYERS, height_scale: float = HEIGHT_SCALE) -> Scene:
    """The demo's view with all four strips read by ``method`` (the study's scene: the same angles). Its scene
    and material names hold the method, layers and height_scale, so one app can switch between many of them."""
    label = f"{method}_l{layers}_s{height_scale:g}"
    return build_scene(methods=(method,) * len(METHODS), height_scale=height_scale, layers=layers,
                       name=f"parallax study {label}", prefix=f"study_{label}_", labels=False)


#: The technique the variants (``opengl.py``, ``webgpu.py``) hand the launcher with their programs.
PART = Part(__package__, build_scene)
