"""The integrators' scene, the same for OpenGL and WebGPU: four damped springs, one per integrator.

``build_scene(impl)`` returns it (the springs use the reference integrators, or your own where there are no
``solutions/``; the exercise is graded numerically).
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import InfoComponent, Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, cube

from .. import SHADERS
from ..hierarchy.scene import add_camera, add_floor
from .components import SpringComponent
from .systems import SpringSystem

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second).
TOUR_FRAMES = 90

#: The four integrators side by side in the springs scene, each with its colour.
SPRING_COLUMNS = (
    ("explicit_euler", (0.9, 0.25, 0.2)),
    ("semi_implicit_euler", (0.3, 0.8, 0.3)),
    ("rk4", (0.25, 0.45, 0.95)),
    ("implicit_euler", (0.95, 0.8, 0.2)),
)


def build_springs_scene(impl: ModuleType | None = None) -> Scene:
    """Four damped springs with the same k, m, c and start, one per integrator.

    Explicit Euler gains energy every step until its mass runs away and is reset; implicit Euler loses
    energy too fast; semi-implicit Euler and RK4 follow the true motion.
    """
    scene = Scene("springs")
    assets = scene.assets
    assets.mesh("springs.cube", cube(1.0))
    assets.material("springs.anchor", MaterialData("shaded", color=(0.6, 0.6, 0.65), name="springs.anchor"))
    add_floor(scene, "springs")
    # --8<-- [start:springs]
    for i, (integrator, color) in enumerate(SPRING_COLUMNS):
        x = -2.4 + 1.6 * i
        material = f"springs.{integrator}"
        assets.material(material, MaterialData("shaded", color=color, name=material))
        scene.create_entity(
            InfoComponent(f"anchor {integrator}"),
            TransformComponent((x, 3.6, 0.0), scale=(0.6, 0.1, 0.6)),
            MeshComponent("springs.cube"), MaterialComponent("springs.anchor"),
        )
        scene.create_entity(
            InfoComponent(f"mass {integrator}"), TransformComponent((x, 3.0, 0.0), scale=0.5),
            MeshComponent("springs.cube"), MaterialComponent(material),
            SpringComponent(rest=(x, 2.0, 0.0), stiffness=40.0, mass=1.0, damping=0.2,
                            integrator=integrator),
        )
    scene.add_system(SpringSystem())
    # --8<-- [end:springs]
    add_camera(scene, (0.0, 2.6, 8.0), (0.0, 1.7, 0.0), 50.0)
    return scene


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this concept, its scene and the step's shaders.
PART = Part(__package__, build_springs_scene, SHADERS)
#: The concept's scene by its common name (``impl`` unused: the scene runs the reference integrators).
build_scene = build_springs_scene
