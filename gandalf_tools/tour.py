"""The course tour: every available step, in both APIs.

``python -m gandalf_tools.tour`` opens each step in a window when a display exists; headless (or with
``--headless``) it renders every step offscreen and writes ``OUT/stepNN_<topic>-<backend>.png``; a step whose
package lists ``TECHNIQUES`` (step 07) or ``CONCEPTS`` (step 05) gets one picture pair per sub-package,
``OUT/stepNN_<topic>-<technique>-<backend>.png``.
Steps are found by folder name next to ``gandalf_core`` at run time (the framework never imports a
step statically).
"""

from __future__ import annotations

import argparse
import importlib
import re
import sys
import time
from pathlib import Path

from gandalf_core.render.base import BACKENDS

REPO_ROOT = Path(__file__).resolve().parent.parent
STEP_PATTERN = re.compile(r"^step\d\d_[a-z0-9_]+$")


def find_steps(root: Path = REPO_ROOT) -> list[str]:
    """Names of the step packages (folders ``stepNN_topic`` with an ``__init__.py``), in order."""
    return sorted(p.name for p in root.iterdir() if STEP_PATTERN.match(p.name) and (p / "__init__.py").exists())


#: The names a step package may list its runnable sub-packages under (step 07's techniques, step 05's concepts).
PART_LISTS = ("TECHNIQUES", "CONCEPTS")


def step_parts(step: str) -> list[str]:
    """The runnable packages of a step: the step itself, or ``step.part`` for each of its ``TECHNIQUES`` or
    ``CONCEPTS``."""
    package = importlib.import_module(step)
    parts = next((getattr(package, name) for name in PART_LISTS if getattr(package, name, None)), None)
    return [f"{step}.{name}" for name in parts] if parts else [step]


def render_step(part: str, backend: str, out_dir: Path, width: int = 640, height: int = 480) -> Path:
    """Render one step (or one technique, ``step.technique``) headless and save its picture; returns the PNG path."""
    variant = importlib.import_module(f"{part}.{backend}")
    frames = getattr(importlib.import_module(f"{part}.scene"), "TOUR_FRAMES", 30)
    with variant.create_app(headless=True, width=width, height=height) as app:
        app.run(frames=frames)
        return app.save_png(out_dir / f"{part.replace('.', '-')}-{backend}.png")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--headless", action="store_true", help="render offscreen even when a display exists")
    parser.add_argument("--out", default="out", help="folder for the headless pictures (default: out)")
    parser.add_argument("--steps", nargs="*", help="only these steps (default: all)")
    parser.add_argument("--backends", nargs="*", default=list(BACKENDS), choices=BACKENDS)
    args = parser.parse_args(argv)
    if str(REPO_ROOT) not in sys.path:
        sys.path.insert(0, str(REPO_ROOT))
    steps = args.steps or find_steps()
    from gandalf_core.app.window import display_available

    headless = args.headless or not display_available()
    out_dir = Path(args.out)
    for part in (p for step in steps for p in step_parts(step)):
        images = {}
        for backend in args.backends:
            if headless:
                start = time.perf_counter()
                path = render_step(part, backend, out_dir)
                images[backend] = path
                print(f"{part:<26} {backend:<7} -> {path}  ({time.perf_counter() - start:.2f} s)")
            else:
                print(f"{part} ({backend}): close the window to go on")
                with importlib.import_module(f"{part}.{backend}").create_app(headless=False) as app:
                    app.run()
        if len(images) == 2:
            print(f"{part:<26} OpenGL vs WebGPU: {_agreement(*images.values())}")
    return 0


def _agreement(a: Path, b: Path) -> str:
    """How closely the two backends' pictures agree (PSNR over RGB, largest channel difference)."""
    import numpy as np
    from PIL import Image

    from .testing import psnr

    x, y = (np.asarray(Image.open(p).convert("RGBA")) for p in (a, b))
    worst = int(np.abs(x[..., :3].astype(int) - y[..., :3].astype(int)).max())
    value = psnr(x, y)
    return "identical" if worst == 0 else f"PSNR {value:.1f} dB, largest channel difference {worst}/255"


if __name__ == "__main__":
    raise SystemExit(main())
