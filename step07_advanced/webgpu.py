"""Step 07, WebGPU: ``python -m step07_advanced.webgpu --technique NAME [--student] [--headless] ...``.

Each technique also runs on its own: ``python -m step07_advanced.terrain.webgpu``.
"""

from gandalf_core.app.cli import launcher

from .techniques import PART

create_app, main = launcher(PART, "webgpu", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
