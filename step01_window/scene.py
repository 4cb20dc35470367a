"""Step 01's scene, the same for OpenGL and WebGPU: one entity holding the clear colour and its hue cycle."""

from __future__ import annotations

from types import ModuleType

from gandalf_core import ClearColorComponent, InfoComponent, Scene
from gandalf_core.app.cli import Part

from .components import HueCycleComponent

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 45


def build_scene(impl: ModuleType) -> Scene:
    """``impl`` is the step's ``solutions`` or ``exercises`` package (it provides HueCycleSystem)."""
    scene = Scene("step01_window")
    scene.create_entity(
        InfoComponent("background"),
        ClearColorComponent((0.0, 0.0, 0.0)),
        HueCycleComponent(hue=200.0, speed=60.0, saturation=0.7, value=0.9),
    )
    scene.add_system(impl.HueCycleSystem())
    return scene


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this step and its scene.
PART = Part(__package__, build_scene)
