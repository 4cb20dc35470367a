"""The several scenes' app, the same for OpenGL and WebGPU: every scene of the step in one app.

``build_scenes(impl)`` returns the four scenes of the other concepts (the house built from ``impl``), each with a
:class:`~.systems.SceneSwitchSystem` for the keys of :data:`SCENE_KEYS`; the variants add them all and the first
is shown. Resource names carry the scene's name as a prefix (``solar.sphere``, ``house.brick``) because the scenes
share one renderer, which caches GPU objects by name.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Scene
from gandalf_core.app.cli import Part

from .. import SHADERS
from ..custom_systems.scene import build_gravity_scene
from ..hierarchy.scene import build_solar_scene
from ..house.scene import build_house_scene
from ..integrators.scene import build_springs_scene
from .systems import SceneSwitchSystem

#: Frames the course tour renders before it takes the picture (of the first scene).
TOUR_FRAMES = 90

#: Which key shows which scene (TAB goes to the next, in this order).
SCENE_KEYS = {"1": "solar", "2": "gravity", "3": "springs", "4": "house"}


# --8<-- [start:scenes]
def build_scenes(impl: ModuleType) -> list[Scene]:
    """All four scenes, each with a system that switches on the keys of :data:`SCENE_KEYS`."""
    scenes = [build_solar_scene(), build_gravity_scene(), build_springs_scene(),
              build_house_scene(impl)]
    for scene in scenes:
        scene.add_system(SceneSwitchSystem(SCENE_KEYS), index=0)
    return scenes
# --8<-- [end:scenes]


def build_scene(impl: ModuleType) -> list[Scene]:
    """What the variants add: every scene (the app shows the first, the solar system)."""
    return build_scenes(impl)


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this concept, its scene and the step's shaders.
PART = Part(__package__, build_scene, SHADERS)
