"""Step 07 terrain, WebGPU variant: ``python -m step07_advanced.terrain.webgpu [--student]``.

WebGPU has no tessellation stage. A compute pass (``tessellate.wgsl``) computes every patch's levels with the
same exercise function ``tess_level`` and writes the patches' triangles into a storage buffer, and their count
into an indirect draw's buffer; the render pipeline draws that many vertices (no more) with no vertex buffer, and
its vertex shader pulls each one by ``vertex_index`` (vertex pulling).
"""

from __future__ import annotations

from types import ModuleType
from typing import Any

import numpy as np

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, launcher
from gandalf_core.resources import MaterialData, MeshData

from .heightfield import encode_heights
from .patches import TerrainParams
from .scene import PARAMS, PART, build_scene, terrain_heights
from .shaders import MATERIAL, SHADER_NAME, WGSL_RENDER, impl_shader_dir
from .tessellate_wgpu import DRAW_BUFFER, VERTEX_BUFFER, WGPUTessellator


class WGPUTerrain:
    """The WebGPU backend of the terrain scene: the compute tessellator and a vertex-pulling material."""

    def __init__(self, app: Application, impl: ModuleType, params: TerrainParams = PARAMS,
                 heights: np.ndarray | None = None) -> None:
        app.renderer.shaders.build(SHADER_NAME, WGSL_RENDER, include_dirs=[impl_shader_dir(impl)],
                                   material=MATERIAL)
        heightmap = encode_heights(terrain_heights() if heights is None else heights)
        self.tessellator = WGPUTessellator(app.renderer, impl, params, heightmap)
        self.params = params

    def mesh(self) -> MeshData:
        # --8<-- [start:mesh]
        # Placeholder positions, never uploaded: the shader reads no attribute. The draw is indirect: the GPU
        # takes the vertex count the compute pass wrote, and the vertex shader fetches each vertex from its buffer.
        return MeshData(np.zeros((3, 3)), name="terrain (pulled)", indirect=DRAW_BUFFER)
        # --8<-- [end:mesh]

    def material(self, base: MaterialData) -> MaterialData:
        # The level of detail is the compute tessellator's (it gets its own copy each frame): the render shader's
        # "lod" field is declared for both APIs, and only OpenGL's tessellation stages read it.
        return MaterialData(base.shader, base.textures, color=base.color, params=base.params, cull=base.cull,
                            name=base.name, buffers=(VERTEX_BUFFER,))

    def update(self, eye: np.ndarray) -> None:
        self.tessellator.run(eye)


class WebGPU(Backend):
    """The terrain on :class:`WGPUTerrain`; ``params`` changes its levels, ``scene`` goes to :func:`build_scene`
    (eye, target, heights)."""

    api = "webgpu"

    def scene(self, app: Application, impl: ModuleType, params: TerrainParams = PARAMS, **scene: Any) -> Scene:
        return build_scene(impl, WGPUTerrain(app, impl, params, scene.get("heights")), **scene)


create_app, main = launcher(PART, WebGPU(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
