"""The filter's scene, the same for OpenGL and WebGPU: four images on quads under an orthographic camera.

    original            | Gaussian blur (separable, radius BLUR_RADIUS)
    Sobel edges         | Sobel edges of the blur (less noise)

The GPU filters run once at start-up (``compute_gl.py`` / ``compute_wgpu.py``, in the variant files); their
results are read back and registered as ordinary ``TextureData`` assets, drawn by the core's ready unlit material
(``gandalf.unlit``).
That keeps the engine untouched: a texture asset is CPU data the renderer uploads. The round trip costs one
read-back per image at start-up, nothing per frame.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np

from gandalf_core import ClearColorComponent, InfoComponent, Scene, TransformComponent
from gandalf_core.app.cli import Needs, Part
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, TextureData, quad

from . import reference
from .shaders import DISPLAY_SHADER

#: Frames the course tour renders before it takes the picture (the picture does not change).
TOUR_FRAMES = 2
#: The source image's size (width, height) and the blur radius shown.
IMAGE_SIZE = (256, 192)
BLUR_RADIUS = 4
#: Panel name -> centre (x, y) in world units; the camera sees 2.1 units high.
PANELS = {
    "original": (-0.68, 0.51),
    "blur": (0.68, 0.51),
    "edges": (-0.68, -0.51),
    "edges_of_blur": (0.68, -0.51),
}
PANEL_HEIGHT = 0.98
VIEW_HEIGHT = 2.1


class ImageFilter(Protocol):
    """What the scene needs from a filter (GL, WebGPU or :class:`NumpyFilter`)."""

    def run(self, image: np.ndarray, op: str, radius: int = 0) -> np.ndarray: ...


class NumpyFilter:
    """The float64 reference as a filter: the backend-neutral fallback, and what the GPU results are checked by."""

    def run(self, image: np.ndarray, op: str, radius: int = 0) -> np.ndarray:
        return reference.to_unorm8(reference.apply(image, op, radius))


def panel_images(image_filter: ImageFilter, source: np.ndarray | None = None) -> dict[str, np.ndarray]:
    """The four panels' RGBA8 images, filtered by ``image_filter``."""
    src = reference.source_image(*IMAGE_SIZE) if source is None else source
    blurred = image_filter.run(src, "separable", BLUR_RADIUS)
    return {
        "original": src,
        "blur": blurred,
        "edges": image_filter.run(src, "sobel"),
        "edges_of_blur": image_filter.run(blurred, "sobel"),
    }


def build_scene(images: dict[str, np.ndarray]) -> Scene:
    """The four quads showing ``images`` (from :func:`panel_images`), as textures of an unlit material."""
    scene = Scene("step07_filter")
    h, w = images["original"].shape[:2]
    scene.assets.mesh("panel", quad(1.0))
    for name, pixels in images.items():
        # sRGB in, sRGB out: the sampler decodes, the framebuffer encodes, so the stored values show unchanged.
        scene.assets.texture(name, TextureData(pixels, wrap="clamp", filter="linear", mipmaps=False, name=name))
        scene.assets.material(f"panel_{name}", MaterialData(DISPLAY_SHADER, [name], color=(1.0, 1.0, 1.0)))
        x, y = PANELS[name]
        scene.create_entity(InfoComponent(name), TransformComponent((x, y, 0.0), scale=(PANEL_HEIGHT * w / h,
                                                                                         PANEL_HEIGHT, 1.0)),
                            MeshComponent("panel"), MaterialComponent(f"panel_{name}"))
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.08, 0.08, 0.09)))
    scene.create_entity(InfoComponent("camera"), TransformComponent((0.0, 0.0, 2.0)),
                        CameraComponent(projection="orthographic", height=VIEW_HEIGHT, near=0.1, far=10.0))
    return scene


#: The technique the variants (``opengl.py``, ``webgpu.py``) hand the launcher with their backends.
PART = Part(__package__, needs=Needs(opengl=430, opengl_for="compute shaders and image load/store"))
