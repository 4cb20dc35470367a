"""Step 07, WebGPU: ``python -m step07_advanced.webgpu --technique NAME [--student] [--headless] ...``.

Each technique also runs on its own: ``python -m step07_advanced.terrain.webgpu``.
"""

from .techniques import launch

if __name__ == "__main__":
    raise SystemExit(launch("webgpu"))
