"""Step 07 explode, WebGPU variant: ``python -m step07_advanced.explode.webgpu [--student]``.

WebGPU has no geometry stage: the bunny's corners, normals and indices go to storage buffers, the renderer
draws 3·F attribute-less vertices and the vertex shader pulls each triangle's corners from the buffers
(``shaders/explode_pulled.wgsl``), calling the student's ``explode_offset`` from ``exercises/explode.wgsl``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application, Scene
from gandalf_core.app.cli import Backend, launcher

from .scene import LIT_SHADER, PART, PullingRoute, build_scene
from .shaders import EXPLODE_MATERIAL, LIT_MATERIAL, WGSL_LIT, WGSL_PULLED, impl_shader_dir


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType, pulling: bool = True) -> None:
    """The vertex-pulling module with ``impl``'s ``explode.wgsl`` (and the unexploded reference ``explode_lit``)."""
    include = [impl_shader_dir(impl)]
    app.renderer.shaders.build("explode_pulled", WGSL_PULLED, include_dirs=include, material=EXPLODE_MATERIAL)
    app.renderer.shaders.build(LIT_SHADER, WGSL_LIT, include_dirs=include, material=LIT_MATERIAL)
# --8<-- [end:register]


class WebGPU(Backend):
    """The bunny's triangles pulled from storage buffers by the vertex shader."""

    api = "webgpu"

    def scene(self, app: Application, impl: ModuleType) -> Scene:
        register_shaders(app, impl)
        return build_scene(impl, PullingRoute(app.renderer))


create_app, main = launcher(PART, WebGPU(), __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
