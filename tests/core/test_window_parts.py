"""Every step, concept and technique opens in a real window (run under Xvfb) in both APIs: its launcher's
``create_app(headless=False)`` at a small size, a few frames, a resize that the renderer follows, a few frames
more, close (``window_part.py``). One process per part runs both APIs (the imports are paid once, and a driver
abort cannot take pytest down); while one part runs, the next one starts, so the two cores both work.

Headless runs never open a window, so this is what catches a technique that only a window breaks (a GL function
loaded through the window context's loader, a surface format).
"""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from gandalf_core.app.window import display_available
from gandalf_tools.tour import find_steps, step_parts

# One window test at a time across xdist workers (the conftest's lock on the display).
pytestmark = [pytest.mark.skipif(not display_available(), reason="needs a display (run under xvfb-run)"),
              pytest.mark.usefixtures("one_window_at_a_time")]

SCRIPT = Path(__file__).with_name("window_part.py")
ROOT = Path(__file__).resolve().parents[2]
PARTS = [part for step in find_steps(ROOT) for part in step_parts(step)]
#: Seconds one part may take for both APIs (the slowest, pbr_model, takes ~10-25 s on two busy cores).
LIMIT = 240

_running: dict[str, subprocess.Popen] = {}


def _start(part: str) -> subprocess.Popen:
    if part not in _running:
        _running[part] = subprocess.Popen([sys.executable, str(SCRIPT), part], cwd=ROOT, stdout=subprocess.PIPE,
                                          stderr=subprocess.STDOUT, text=True)
    return _running[part]


@pytest.fixture(scope="module", autouse=True)
def _end_what_was_started() -> Iterator[None]:
    yield
    for proc in _running.values():
        if proc.poll() is None:
            proc.kill()
            proc.wait()


def test_every_part_is_listed():
    assert len(PARTS) >= 19 and "step07_advanced.pbr_model" in PARTS, PARTS


@pytest.mark.parametrize("part", PARTS)
def test_the_part_runs_in_a_window_in_both_apis(part):
    proc = _start(part)
    following = PARTS.index(part) + 1
    if following < len(PARTS):
        _start(PARTS[following])  # the next part starts on the other core
    try:
        output, _ = proc.communicate(timeout=LIMIT)
    except subprocess.TimeoutExpired:
        proc.kill()
        output, _ = proc.communicate()
        pytest.fail(f"{part}: still running after {LIMIT} s:\n{output[-3000:]}")
    for api in ("opengl", "webgpu"):
        assert f"{part} {api} ok 120x80" in output, f"{part} in a {api} window:\n{output[-6000:]}"
    assert proc.returncode == 0, output[-3000:]
