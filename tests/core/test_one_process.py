"""One process, the same pictures: the whole tour rendered in one process equals each part rendered alone.

Applications that follow one another in a process must not pass anything on (a cache keyed by an object's id, a
module-level GPU resource, a reused wgpu device or a GL context left current): the tour renders every part in both
APIs in one fresh process, then each part is rendered alone in a fresh process of its own, and the two pictures
must be the same bytes (the same implementation draws the same picture). Small pictures and few frames keep it
quick; both runs use the same size and frame count.
"""

from __future__ import annotations

import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
from PIL import Image

from gandalf_tools.testing import psnr
from gandalf_tools.tour import REPO_ROOT, find_steps, step_parts

PARTS = [p for step in find_steps() for p in step_parts(step)]
#: Both runs: pictures this small and this few frames (every part draws something by then).
OPTIONS = ["--headless", "--size", "64x48", "--frames", "3"]


def _tour(out: Path, *steps: str) -> str:
    """Run the headless tour (of ``steps``, default all) in a fresh process; "" or what went wrong."""
    command = [sys.executable, "-m", "gandalf_tools.tour", *OPTIONS, "--out", str(out)]
    if steps:
        command += ["--steps", *steps]
    run = subprocess.run(command, cwd=REPO_ROOT, capture_output=True, text=True, timeout=600)
    if run.returncode == 0:
        return ""
    return f"{' '.join(command[1:])} exited with {run.returncode}:\n{run.stdout[-2000:]}\n{run.stderr[-2000:]}"


def _difference(part: str, backend: str, alone: Path, in_tour: Path) -> str:
    """"" when the part's two pictures are the same bytes, else how they differ."""
    name = f"{part.replace('.', '-')}-{backend}.png"
    a, b = (np.asarray(Image.open(folder / name).convert("RGBA")) for folder in (alone, in_tour))
    differ = np.any(a != b, axis=-1)
    if not differ.any():
        return ""
    return (f"{part} in {backend}: {differ.mean():.2%} of pixels differ (PSNR {psnr(a, b):.1f} dB, largest channel "
            f"difference {int(np.abs(a.astype(int) - b.astype(int)).max())})")


def test_the_tour_in_one_process_draws_each_part_as_alone(tmp_path):
    """The one-process tour and every part alone run side by side (one process per core); the pictures must match."""
    with ThreadPoolExecutor(max_workers=max(2, os.cpu_count() or 2)) as pool:
        tour = pool.submit(_tour, tmp_path / "tour")
        alone = {part: pool.submit(_tour, tmp_path / part, part) for part in PARTS}
        errors = [e for e in [tour.result(), *(job.result() for job in alone.values())] if e]
    assert not errors, "\n".join(errors)
    differences = [d for part in PARTS for backend in ("opengl", "webgpu")
                   if (d := _difference(part, backend, tmp_path / part, tmp_path / "tour"))]
    assert not differences, (
        "drawn after the rest of the tour in one process, these pictures differ from the part drawn alone: an "
        "application passed state on to the next (a cache keyed by id, a module-level resource, a reused device "
        "or context):\n" + "\n".join(differences))
