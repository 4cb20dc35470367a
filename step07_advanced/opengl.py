"""Step 07, OpenGL: ``python -m step07_advanced.opengl --technique NAME [--student] [--headless] ...``.

Each technique also runs on its own: ``python -m step07_advanced.terrain.opengl``.
"""

from .techniques import launch

if __name__ == "__main__":
    raise SystemExit(launch("opengl"))
