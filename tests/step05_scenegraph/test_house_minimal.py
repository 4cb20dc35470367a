"""The house in under 40 lines (``step05_scenegraph/house/minimal.py``): core materials, no shader, both APIs.

Checked on 96 × 72 headless pictures with a fixed step of 1/4 s, in each API: the house is in view (it covers
8-60 % of the frame and touches no edge); orange roof pixels (red ≥ 220, green 0.35-0.7 · red, blue < 0.3 · red)
cover ≥ 2 % of the frame, darker brick pixels (red 60-210, green 0.25-0.55 · red, blue 0.1-0.45 · red) ≥ 2 %,
light grey mortar pixels ≥ 0.3 %; after 1 s (45°) the picture differs (mean ≥ 2 steps; measured 6.5) and after
8 s (360°) it is back to the first one (PSNR ≥ 40 dB; measured identical). The two APIs agree (PSNR ≥ 35 dB;
measured identical on llvmpipe/lavapipe). The file has at most 40 lines and builds no shader; its command line
runs either API and ``--help`` only prints help.
"""

from __future__ import annotations

import inspect
import re

import numpy as np
import pytest
from per_api import PerAPI

from gandalf_core import Application
from gandalf_core.app.cli import run_scene
from gandalf_tools.testing import psnr
from step05_scenegraph.house import minimal as house_minimal

W, H = 96, 72
STEP = 0.25


def frames(backend: str, counts: list[int]) -> list[np.ndarray]:
    """Pictures after each number of frames (cumulative), 1/4 s each (11.25° of turn)."""
    pictures = []
    with Application(backend, W, H, headless=True, fixed_dt=STEP) as app:
        app.add_scene(house_minimal.house_scene())
        done = 0
        for count in counts:
            app.run(frames=count - done)
            done = count
            pictures.append(app.capture()[..., :3].copy())
    return pictures


@pytest.fixture(scope="module")
def pictures() -> PerAPI:
    return PerAPI(lambda backend: frames(backend, [1, 5, 33]))  # 0, 1 and 8 s later


def test_the_file_is_short_and_has_no_shader():
    source = inspect.getsource(house_minimal)
    assert len(source.splitlines()) <= 40, f"{len(source.splitlines())} lines (at most 40)"
    for pattern in (r"shaders\.build", r"#version", r"@vertex", r"\.(wgsl|vert|frag)\b"):
        assert not re.search(pattern, source), f"the minimal house should need no shader, found {pattern!r}"


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_house_bricks_and_roof_are_in_view(pictures, backend):
    image = pictures[backend][0].astype(float)
    r, g, b = image[..., 0] + 1e-9, image[..., 1], image[..., 2]
    covered = image.max(axis=-1) > 12
    rows, cols = np.nonzero(covered)
    assert 0.08 <= covered.mean() <= 0.6, f"the house covers {100 * covered.mean():.1f} % of the frame (8-60 %)"
    assert rows.min() > 0 and cols.min() > 0 and rows.max() < H - 1 and cols.max() < W - 1, "the house is cut off"
    roof = (r >= 220) & (g > 0.35 * r) & (g < 0.7 * r) & (b < 0.3 * r)
    bricks = (r > 60) & (r < 210) & (g > 0.25 * r) & (g < 0.55 * r) & (b > 0.1 * r) & (b < 0.45 * r)
    mortar = (image.min(axis=-1) > 110) & (image.max(axis=-1) - image.min(axis=-1) < 40)
    for name, mask, need in (("orange roof", roof, 0.02), ("brick", bricks, 0.02), ("mortar", mortar, 0.003)):
        assert mask.mean() >= need, f"{backend}: {name} pixels cover {100 * mask.mean():.2f} % (need {100 * need} %)"


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_it_turns_about_y_at_45_degrees_a_second(pictures, backend):
    first, quarter, full = (p.astype(float) for p in pictures[backend])
    moved = np.abs(quarter - first).mean()
    assert moved >= 2, f"{backend}: after 1 s the picture changed by only {moved:.2f} steps on average"
    back = psnr(first.astype(np.uint8), full.astype(np.uint8))
    assert back >= 40, f"{backend}: after 8 s (360°) PSNR {back:.1f} dB against the first frame (need ≥ 40)"


def test_both_apis_agree(pictures):
    value = psnr(pictures["opengl"][0], pictures["webgpu"][0])
    assert value >= 35, f"PSNR {value:.1f} dB between OpenGL and WebGPU (need ≥ 35)"


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_command_line_runs_either_api_and_help_only_helps(backend, tmp_path, capsys):
    out = tmp_path / "house.png"
    argv = ["--backend", backend, "--headless", "--frames", "2", "--size", f"{W}x{H}", "--out", str(out)]
    assert run_scene(house_minimal.house_scene, argv) == 0
    from PIL import Image
    assert Image.open(out).size == (W, H)
    with pytest.raises(SystemExit) as exit_info:
        run_scene(house_minimal.house_scene, ["--help"], description=house_minimal.__doc__)
    assert exit_info.value.code == 0
    assert "--backend" in capsys.readouterr().out
    assert [p.name for p in tmp_path.iterdir()] == ["house.png"]
