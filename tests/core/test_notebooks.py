"""The intro notebooks (``notebooks/*.ipynb``) run from top to bottom in both APIs, so they cannot rot.

Each notebook is executed by nbclient in a fresh ``python3`` kernel (ipykernel from this interpreter) once with
``GANDALF_BACKEND=opengl`` and once with ``GANDALF_BACKEND=webgpu`` (the two side by side), which the notebook's
first cell reads. A test fails on any cell error (the message names the notebook, the API and the cell), on a
notebook that shows no picture or a blank one, and when the two APIs' pictures differ: every picture a notebook
shows must agree between OpenGL and WebGPU with a PSNR of at least 35 dB (the same scene, the same picture;
anti-aliased edges may differ by a few levels).
"""

from __future__ import annotations

import asyncio
import base64
import io
import os
import re
from pathlib import Path

import numpy as np
import pytest

from gandalf_tools.testing import psnr

nbformat = pytest.importorskip("nbformat", reason="the notebook tests need the dev extra (nbformat)")
nbclient = pytest.importorskip("nbclient", reason="the notebook tests need the dev extra (nbclient)")
pytest.importorskip("ipykernel", reason="the notebook tests need the dev extra (ipykernel)")

NOTEBOOKS_DIR = Path(__file__).resolve().parents[2] / "notebooks"
NOTEBOOKS = sorted(NOTEBOOKS_DIR.glob("*.ipynb"))
#: Seconds one cell may take (the slowest, loading the bunny and rendering, takes about a second here).
CELL_TIMEOUT = 60
#: Every notebook runs once per API.
BACKENDS = ("opengl", "webgpu")
#: The two APIs' pictures must agree at least this well.
MIN_PSNR = 35.0


def test_there_are_six_notebooks_for_weeks_1_and_2() -> None:
    names = [p.stem for p in NOTEBOOKS]
    assert len(names) >= 6, f"expected at least 6 intro notebooks in {NOTEBOOKS_DIR}, found {names}"


def _plain(exc: Exception) -> str:
    """The kernel's traceback without its terminal colour codes."""
    return re.sub(r"\x1b\[[0-9;]*m", "", str(exc))


async def _execute(path: Path, backend: str) -> list[np.ndarray] | str:
    """Run the notebook with ``backend``; return the pictures it displayed (RGB arrays), or what went wrong."""
    from PIL import Image

    notebook = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(
        notebook, kernel_name="python3", timeout=CELL_TIMEOUT, resources={"metadata": {"path": str(path.parent)}}
    )
    try:
        # The kernel gets its own environment: the two APIs' runs go side by side, one kernel per core.
        await client.async_execute(env={**os.environ, "GANDALF_BACKEND": backend})
    except nbclient.exceptions.CellTimeoutError as exc:
        return f"{path.name} with GANDALF_BACKEND={backend}: a cell ran over {CELL_TIMEOUT} s:\n{_plain(exc)}"
    except nbclient.exceptions.CellExecutionError as exc:
        return f"{path.name} with GANDALF_BACKEND={backend}: a cell failed:\n{_plain(exc)}"
    pictures = []
    for cell in notebook.cells:
        for output in cell.get("outputs", []):
            png = output.get("data", {}).get("image/png")
            if png:
                pictures.append(np.asarray(Image.open(io.BytesIO(base64.b64decode(png))).convert("RGB")))
    return pictures


async def _execute_both(path: Path) -> dict[str, list[np.ndarray] | str]:
    runs = await asyncio.gather(*(_execute(path, backend) for backend in BACKENDS))
    return dict(zip(BACKENDS, runs))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs_in_both_apis_with_the_same_pictures(path: Path) -> None:
    shown = asyncio.run(_execute_both(path))
    failures = [run for run in shown.values() if isinstance(run, str)]
    if failures:
        pytest.fail("\n\n".join(failures))
    for backend, pictures in shown.items():
        assert pictures, f"{path.name} with {backend}: no picture was displayed (expected show(app.capture()))"
        for i, picture in enumerate(pictures):
            assert picture.reshape(-1, 3).std(axis=0).max() > 5.0, (
                f"{path.name} with {backend}: picture {i + 1} is one flat colour (nothing was drawn)"
            )
    gl, wgpu = shown["opengl"], shown["webgpu"]
    assert len(gl) == len(wgpu), f"{path.name}: OpenGL showed {len(gl)} pictures, WebGPU {len(wgpu)}"
    for i, (a, b) in enumerate(zip(gl, wgpu)):
        value = psnr(a, b)
        assert value >= MIN_PSNR, (
            f"{path.name}: picture {i + 1} differs between OpenGL and WebGPU: PSNR {value:.1f} dB < {MIN_PSNR} dB"
        )
