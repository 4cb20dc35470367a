"""Step 06, OpenGL variant: ``python -m step06_lighting.opengl [--student]``.

GLSL 330: the lights arrive in the ``Lights`` uniform block (``frame.glsl``), the cube map as a
``samplerCube``; the shading functions come from ``shading.glsl`` of ``exercises/`` or ``solutions/``.
"""

from __future__ import annotations

from types import ModuleType

from gandalf_core import Application
from gandalf_core.app.cli import load_impl, run_variant

from .scene import build_scene
from .shaders import SHADER_DIR, SHADERS, impl_shader_dir


def register_shaders(app: Application, impl: ModuleType) -> None:
    """Build the step's GLSL programs, including ``impl``'s ``shading.glsl``."""
    for name, (vert, frag) in SHADERS.items():
        app.renderer.shaders.build(name, SHADER_DIR / vert, SHADER_DIR / frag, include_dirs=[impl_shader_dir(impl)])


def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480) -> Application:
    impl = load_impl(__package__, student)
    app = Application("opengl", width, height, title="step06 · OpenGL", headless=headless, fixed_dt=1 / 60)
    register_shaders(app, impl)
    app.add_scene(build_scene(impl))
    return app


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
