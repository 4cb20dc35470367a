"""The course tour: every available step, in both APIs.

``python -m gandalf_tools.tour`` opens each step in a window when a display exists; headless (or with
``--headless``) it renders every step offscreen and writes ``OUT/stepNN_<topic>-<backend>.png``; a step whose
package lists ``TECHNIQUES`` (step 07) or ``CONCEPTS`` (step 05) gets one picture pair per sub-package,
``OUT/stepNN_<topic>-<technique>-<backend>.png``. A part this machine cannot run in one API (see
``python -m gandalf_tools.doctor``) is named with what it needs, and the tour goes on.
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

from gandalf_core.app.cli import has_solutions, plain, unfinished_exercise
from gandalf_core.render.base import BACKENDS
from gandalf_core.render.capabilities import CapabilityError

from .testing import LocalDifferences, psnr

REPO_ROOT = Path(__file__).resolve().parent.parent
STEP_PATTERN = re.compile(r"^step\d\d_[a-z0-9_]+$")


def find_steps(root: Path = REPO_ROOT) -> list[str]:
    """Names of the step packages (folders ``stepNN_topic`` with an ``__init__.py``), in order."""
    return sorted(p.name for p in root.iterdir() if STEP_PATTERN.match(p.name) and (p / "__init__.py").exists())


#: The names a step package may list its runnable sub-packages under (step 07's techniques, step 05's concepts).
PART_LISTS = ("TECHNIQUES", "CONCEPTS")


def step_parts(step: str) -> list[str]:
    """The runnable packages of a step: the step itself, or ``step.part`` for each of its ``TECHNIQUES`` or
    ``CONCEPTS`` (a part named already, ``step06_lighting.environment``, is itself)."""
    if "." in step:
        return [step]
    package = importlib.import_module(step)
    parts = next((getattr(package, name) for name in PART_LISTS if getattr(package, name, None)), None)
    return [f"{step}.{name}" for name in parts] if parts else [step]


def render_step(part: str, backend: str, out_dir: Path, width: int = 640, height: int = 480,
                frames: int | None = None) -> Path:
    """Render one step (or one technique, ``step.technique``) headless and save its picture; returns the PNG path.
    ``frames``: how many frames before the picture (default: the part's ``TOUR_FRAMES``, else 30)."""
    variant = importlib.import_module(f"{part}.{backend}")
    if frames is None:
        frames = getattr(importlib.import_module(f"{part}.scene"), "TOUR_FRAMES", 30)
    with variant.create_app(headless=True, width=width, height=height) as app:
        app.run(frames=frames)
        return app.save_png(out_dir / f"{part.replace('.', '-')}-{backend}.png")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m gandalf_tools.tour", description=plain(__doc__),
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--headless", action="store_true", help="render offscreen even when a display exists")
    parser.add_argument("--out", default="out", help="folder for the headless pictures (default: out)")
    parser.add_argument("--steps", nargs="*",
                        help="only these steps or parts, e.g. step06_lighting.environment (default: all)")
    parser.add_argument("--backends", nargs="*", default=list(BACKENDS), choices=BACKENDS)
    parser.add_argument("--size", default=AGREEMENT_SIZE,
                        help=f"WIDTHxHEIGHT of the headless pictures (default {AGREEMENT_SIZE}; the two APIs' "
                             "pictures are judged against their bound at that size only)")
    parser.add_argument("--frames", type=int, default=None,
                        help="frames before each headless picture (default: each part's own count)")
    args = parser.parse_args(argv)
    width, height = (int(x) for x in args.size.lower().split("x"))
    judged = f"{width}x{height}" == AGREEMENT_SIZE
    if str(REPO_ROOT) not in sys.path:
        sys.path.insert(0, str(REPO_ROOT))
    steps = args.steps or find_steps()
    from gandalf_core.app.window import display_available

    headless = args.headless or not display_available()
    out_dir = Path(args.out)
    disagree = []
    waiting = []
    for part in (p for step in steps for p in step_parts(step)):
        images = {}
        for backend in args.backends:
            lead = f"{part:<26} {backend:<7} "
            try:
                if headless:
                    start = time.perf_counter()
                    print(lead, end="", flush=True)  # the part under way, while it renders
                    lead = ""
                    path = render_step(part, backend, out_dir, width, height, args.frames)
                    images[backend] = path
                    print(f"-> {path}  ({time.perf_counter() - start:.2f} s)")
                else:
                    print(f"{part} ({backend}): close the window to go on")
                    with importlib.import_module(f"{part}.{backend}").create_app(headless=False) as app:
                        app.run()
            except CapabilityError as exc:  # this machine lacks what the part needs: say so and go on
                print(f"{lead}-> not here: {exc}")
            except Exception as error:  # a student's release: this part runs the student's exercises
                sentence = unfinished_exercise(error)
                if sentence is None and has_solutions(part.split(".")[0]):
                    raise
                first = (str(error).strip().splitlines() or [type(error).__name__])[0]
                print(f"{lead}skipped: {sentence or f'your exercises failed: {first}'}")
                waiting.append(part)
                break
        if len(images) == 2:
            verdict, problems = _agreement(part, *images.values(), judged=judged)
            print(f"{part:<26} OpenGL vs WebGPU: {verdict}")
            if problems and judged:
                disagree.append(part)
    if waiting:
        print(f"{len(waiting)} parts wait for your exercises: {', '.join(waiting)}")
    if disagree:
        print(f"the two APIs' pictures differ beyond their stated bound for: {', '.join(disagree)}")
        return 1
    return 0


#: What the two APIs' pictures of a part may differ by (:class:`~gandalf_tools.testing.LocalDifferences`): by
#: default a level of 4 on 99.9 % of pixels (float32 arithmetic and texture filtering round differently; measured
#: on llvmpipe / lavapipe: at most 0.02 % of pixels beyond 2 levels, apart from the parts below), no 8 x 8 square
#: off by more than 12 on average.
AGREEMENT = LocalDifferences(level=4, share=0.999)
#: The picture size the bounds are stated for. At another size the agreement is reported, not judged: a smaller
#: picture samples its textures from coarser mip levels, where implementations legally pick and blend levels
#: differently (e.g. on an NVIDIA GPU the environment's 64 x 48 picture has 1.3 % of pixels beyond 4 levels).
AGREEMENT_SIZE = "640x480"
#: Parts whose two variants draw legitimately different geometry, and why.
AGREEMENT_BY_PART = {
    # OpenGL tessellates the patches in hardware, WebGPU in a compute kernel: the two cut a patch into other
    # triangles, so the silhouette and the shading between vertices differ a little (measured: 1.2 % of pixels
    # beyond 4 levels, worst 8 x 8 square 11.3).
    "step07_advanced.terrain": LocalDifferences(level=4, share=0.97, block_mean=24.0),
}


def _agreement(part: str, a: Path, b: Path, judged: bool = True) -> tuple[str, list[str]]:
    """How closely the two backends' pictures agree (PSNR, largest channel difference), the verdict against
    the part's bound (``judged``: the pictures are of :data:`AGREEMENT_SIZE`), and what breaks it (empty when
    within)."""
    import numpy as np
    from PIL import Image

    x, y = (np.asarray(Image.open(p).convert("RGBA")) for p in (a, b))
    worst = int(np.abs(x[..., :3].astype(int) - y[..., :3].astype(int)).max())
    bound = AGREEMENT_BY_PART.get(part, AGREEMENT)
    problems = bound.violations(x, y)
    if worst == 0:
        return "identical", []
    verdict = (f"within the bound ({bound.share:.1%} of pixels within {bound.level} levels)" if not problems
               else ("DIFFERENT: " if judged else f"beyond the {AGREEMENT_SIZE} bound, not judged at this size: ")
               + "; ".join(problems))
    return f"PSNR {psnr(x, y):.1f} dB, largest channel difference {worst}/255: {verdict}", problems


if __name__ == "__main__":
    raise SystemExit(main())
