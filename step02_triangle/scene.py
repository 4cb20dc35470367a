"""Step 02's scene, the same for OpenGL and WebGPU: a triangle, an indexed quad and an n-gon in clip space.

There is no camera, so view and projection are identity and model-space positions placed by each entity's
transform land directly in clip space (x and y in [-1, 1] across the window). Clip space knows nothing of
the window's shape: each transform squeezes x by :data:`ASPECT_CORRECTION` so that the shapes look right
in the course's 4:3 window (step 04's camera does this properly).
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

from gandalf_core import Application, ClearColorComponent, InfoComponent, Scene, TransformComponent
from gandalf_core.app.cli import Part, build_shaders
from gandalf_core.components import MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData

from .components import NGonComponent
from .meshes import quad_mesh, triangle_mesh

#: Frames the course tour renders before it takes the picture (the scene does not move).
TOUR_FRAMES = 2
#: The shader every shape uses (each variant file builds it from its own source).
SHADER = "vertex_color"
#: The shader table the variants build: GLSL ``shaders/<name>.vert/.frag`` or WGSL ``shaders/<name>.wgsl``.
SHADERS = (SHADER,)
#: Height over width of the course's 640x480 window: scales x so a square stays square.
ASPECT_CORRECTION = 3 / 4
#: Background (sRGB).
CLEAR_COLOR = (0.08, 0.09, 0.12)
#: The shapes' size in clip units, and their centres (left, middle, right).
SIZE = 0.6
CENTRES = {"triangle": (-0.62, 0.0, 0.0), "ngon": (0.0, 0.0, 0.0), "quad": (0.62, 0.0, 0.0)}
#: Corners of the n-gon in the middle.
NGON_SIDES = 6


def _place(name: str) -> TransformComponent:
    return TransformComponent(CENTRES[name], scale=(SIZE * ASPECT_CORRECTION, SIZE, 1.0))


def build_scene(impl: ModuleType) -> Scene:
    """``impl`` is the step's ``solutions`` or ``exercises`` package (it provides NGonSystem)."""
    scene = Scene("step02_triangle")
    scene.assets.mesh("triangle", triangle_mesh())
    scene.assets.mesh("quad", quad_mesh())
    # One material for all three: the shader reads its colours from the vertices.
    scene.assets.material("vertex_color", MaterialData(SHADER, name="vertex_color"))
    scene.create_entity(InfoComponent("background"), ClearColorComponent(CLEAR_COLOR))
    scene.create_entity(InfoComponent("triangle"), _place("triangle"), MeshComponent("triangle"),
                        MaterialComponent("vertex_color"))
    scene.create_entity(InfoComponent("quad"), _place("quad"), MeshComponent("quad"),
                        MaterialComponent("vertex_color"))
    # The n-gon's mesh does not exist yet: the NGonSystem builds it when the entity appears.
    scene.create_entity(InfoComponent("hexagon"), _place("ngon"), MeshComponent("hexagon"),
                        MaterialComponent("vertex_color"), NGonComponent(sides=NGON_SIDES, radius=0.5))
    scene.add_system(impl.NGonSystem())
    return scene


def register_shaders(app: Application) -> None:
    """Build the step's shader table in ``app``'s API (the variants, the preview and the tests use it)."""
    build_shaders(app, SHADERS, Path(__file__).resolve().parent / "shaders")


#: What the variants (``opengl.py``, ``webgpu.py``) hand the launcher: this step, its scene and its shaders.
PART = Part(__package__, build_scene, SHADERS)
