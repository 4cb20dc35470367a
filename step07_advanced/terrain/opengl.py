"""Step 07 terrain, OpenGL variant: ``python -m step07_advanced.terrain.opengl [--student]``.

The patches are tessellated in hardware: a GLSL 4.10 program with a tessellation control stage (the levels, from
the exercise's ``tess_level``) and an evaluation stage (the vertices, lifted by ``terrain_height``). The mesh
is a patch mesh of four control points per patch.
"""

from __future__ import annotations

import os
from types import ModuleType
from typing import Any

import numpy as np

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, launcher
from gandalf_core.resources import MaterialData, MeshData

from .patches import GUARANTEED_MAX_LEVEL, TerrainParams, check_levels, patch_mesh
from .scene import PARAMS, PART, build_scene
from .shaders import GL_STAGES, MATERIAL, SHADER_DIR, SHADER_NAME, impl_shader_dir

GL_MAX_TESS_GEN_LEVEL = 0x8E7E


def max_tess_level() -> int:
    """The device's GL_MAX_TESS_GEN_LEVEL when PyOpenGL can ask it (``PYOPENGL_PLATFORM=egl``, as STACK.md says;
    moderngl does not expose it), else 64, the least the GL spec guarantees."""
    if os.environ.get("PYOPENGL_PLATFORM") != "egl":
        return GUARANTEED_MAX_LEVEL
    try:
        from OpenGL import GL

        value = int(GL.glGetIntegerv(GL_MAX_TESS_GEN_LEVEL))
    except Exception:  # no PyOpenGL, or no current context: the guaranteed minimum is always safe
        return GUARANTEED_MAX_LEVEL
    return value if value >= GUARANTEED_MAX_LEVEL else GUARANTEED_MAX_LEVEL


class GLTerrain:
    """The OpenGL backend of the terrain scene: the tessellation program and the patch mesh."""

    def __init__(self, app: Application, impl: ModuleType, params: TerrainParams = PARAMS) -> None:
        # --8<-- [start:build]
        check_levels(params.min_level, params.max_level, max_tess_level())
        stages = {stage: SHADER_DIR / file for stage, file in GL_STAGES.items()}
        app.renderer.shaders.build(SHADER_NAME, stages["vertex"], stages["fragment"],
                                   tess_control=stages["tess_control"], tess_evaluation=stages["tess_evaluation"],
                                   include_dirs=[impl_shader_dir(impl)], material=MATERIAL)
        # --8<-- [end:build]
        self.params = params

    def mesh(self) -> MeshData:
        return patch_mesh(self.params)

    def material(self, base: MaterialData) -> MaterialData:
        return base

    def update(self, eye: np.ndarray) -> None:
        """Nothing to do per frame: the tessellation control stage reads the camera from the frame block."""


class OpenGL(Backend):
    """The terrain on :class:`GLTerrain`; ``params`` changes its levels, ``scene`` goes to :func:`build_scene`
    (eye, target, heights)."""

    api = "opengl"

    def scene(self, app: Application, impl: ModuleType, params: TerrainParams = PARAMS, **scene: Any) -> Scene:
        return build_scene(impl, GLTerrain(app, impl, params), **scene)


create_app, main = launcher(PART, OpenGL(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
