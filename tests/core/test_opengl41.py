"""Under OpenGL 4.1 (macOS's ceiling, simulated with Mesa's version override) every OpenGL launcher either runs or
says in one sentence what it needs and what to run instead: no traceback, no driver error.

Each launcher runs headless in its own process with ``MESA_GL_VERSION_OVERRIDE=4.1`` (and GLSL 4.10): a part
whose declared needs (its ``PART.needs``) fit 4.1 must exit 0; one that needs more (compute shaders: 4.3) must exit
with the launchers' capability status, printing one line that names the missing version and the WebGPU variant.
"""

from __future__ import annotations

import importlib
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import pytest

from gandalf_core.app.cli import CAPABILITY_EXIT
from gandalf_tools.tour import REPO_ROOT, find_steps, step_parts

OVERRIDE = {"MESA_GL_VERSION_OVERRIDE": "4.1", "MESA_GLSL_VERSION_OVERRIDE": "410"}
PARTS = [p for step in find_steps() for p in step_parts(step)]
#: Launchers of a step of several parts (``python -m step07_advanced.opengl`` runs its default part).
STEP_LAUNCHERS = sorted({p.split(".")[0] for p in PARTS if "." in p})


def _run(module: str) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", module, "--headless", "--frames", "1", "--size", "32x24"]
    return subprocess.run(command, cwd=REPO_ROOT, env={**os.environ, **OVERRIDE}, capture_output=True, text=True,
                          timeout=300)


@pytest.fixture(scope="module")
def override_honoured() -> None:
    probe = subprocess.run([sys.executable, "-c", "import moderngl; print(moderngl.create_standalone_context("
                            "backend='egl', require=330).version_code)"], env={**os.environ, **OVERRIDE},
                           capture_output=True, text=True, timeout=60)
    if probe.stdout.strip() != "410":
        pytest.skip(f"this OpenGL driver ignores Mesa's version override (got {probe.stdout.strip() or probe.stderr})")


def _problem(module: str, run: subprocess.CompletedProcess[str], expect_need: bool | None) -> str:
    """"" when ``module`` behaved (ran, or said its need in one clean line), else what went wrong."""
    said = run.stderr.strip()
    if "Traceback" in run.stderr or run.returncode not in (0, CAPABILITY_EXIT):
        return f"{module}: exit {run.returncode}, a crash instead of a sentence:\n{said[-1500:]}"
    if run.returncode == CAPABILITY_EXIT:
        lines = said.splitlines()
        if len(lines) != 1 or "needs OpenGL 4." not in said or ".webgpu` instead" not in said:
            return f"{module}: its capability message is not one sentence naming the need and the WebGPU variant: " \
                   f"{said!r}"
    if expect_need is not None and expect_need != (run.returncode == CAPABILITY_EXIT):
        return (f"{module}: its part declares needs {'beyond' if expect_need else 'within'} OpenGL 4.1, yet it "
                f"{'ran' if run.returncode == 0 else 'refused'}: {said[-500:]!r}")
    return ""


def test_every_opengl_launcher_runs_or_names_its_need_under_opengl41(override_honoured):
    modules = {f"{part}.opengl": importlib.import_module(f"{part}.scene").PART.needs.opengl > 410 for part in PARTS}
    modules.update({f"{step}.opengl": None for step in STEP_LAUNCHERS})
    with ThreadPoolExecutor(max_workers=max(2, os.cpu_count() or 2)) as pool:
        runs = dict(zip(modules, pool.map(_run, modules)))
    problems = [p for module, run in runs.items() if (p := _problem(module, run, modules[module]))]
    assert not problems, "\n".join(problems)
    assert any(run.returncode == CAPABILITY_EXIT for run in runs.values()), "no part needs more than OpenGL 4.1?"


def test_the_tour_names_what_a_part_needs_and_goes_on(override_honoured, tmp_path):
    command = [sys.executable, "-m", "gandalf_tools.tour", "--headless", "--size", "32x24", "--frames", "1", "--out",
               str(tmp_path), "--steps", "step07_advanced.filter", "step01_window", "--backends", "opengl"]
    run = subprocess.run(command, cwd=REPO_ROOT, env={**os.environ, **OVERRIDE}, capture_output=True, text=True,
                         timeout=300)
    assert run.returncode == 0 and "Traceback" not in run.stderr, run.stdout + run.stderr
    said = "step07_advanced.filter     opengl  -> not here: `python -m step07_advanced.filter.opengl` needs OpenGL 4.3"
    assert said in run.stdout, run.stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == ["step01_window-opengl.png"]
