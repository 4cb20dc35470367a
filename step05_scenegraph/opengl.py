"""Step 05, OpenGL variant: ``python -m step05_scenegraph.opengl`` (keys 1/2/3 or TAB switch scenes).

The scenes are the same for both APIs; only the shaders differ: GLSL 330 (``shaders/*.vert``/``*.frag``).
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core.app.cli import run_variant, variant

from .scene import SHADERS, build_scenes

#: The shader folder (``tests/step05_scenegraph/test_house.py`` reads it).
SHADER_DIR = Path(__file__).resolve().parent / "shaders"

create_app = variant("opengl", __package__, build_scenes, SHADERS)


if __name__ == "__main__":
    raise SystemExit(run_variant(create_app, description=__doc__))
