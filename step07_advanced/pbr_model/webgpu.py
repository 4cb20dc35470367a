"""Step 07 PBR model, WebGPU variant: ``python -m step07_advanced.pbr_model.webgpu [--student]``.

The same scene with one WGSL module (``shaders/pbr_model.wgsl``): the model's five glTF maps and the three
IBL textures are bindings 1-16 of the material's bind group, and the student's ``brdf.wgsl`` functions come
from ``exercises/`` (``--student``) or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import launcher

from .scene import PART
from .shaders import MATERIAL, SHADER_NAME, WGSL, include_dirs


# --8<-- [start:register]
def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the model's WGSL module with ``impl``'s ``brdf.wgsl`` and ``normal_map.wgsl``."""
    app.renderer.shaders.build(SHADER_NAME, WGSL, include_dirs=include_dirs(impl), material=MATERIAL)
# --8<-- [end:register]


create_app, main = launcher(PART, "webgpu", __doc__, shaders=register_shaders)


if __name__ == "__main__":
    raise SystemExit(main())
