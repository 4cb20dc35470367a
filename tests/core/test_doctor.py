"""``python -m gandalf_tools.doctor``: the machine's OpenGL context and WebGPU adapters, and where each part runs."""

from __future__ import annotations

import os
import subprocess
import sys

import moderngl
import pytest

from gandalf_tools import doctor
from gandalf_tools.tour import REPO_ROOT, find_steps, step_parts

PARTS = [p for step in find_steps() for p in step_parts(step)]


def _doctor(**env: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "gandalf_tools.doctor"], cwd=REPO_ROOT, env={**os.environ, **env},
                          capture_output=True, text=True, timeout=120)


def test_help_is_plain_text_naming_the_command(capsys):
    with pytest.raises(SystemExit) as stop:
        doctor.main(["--help"])
    out = capsys.readouterr().out
    assert stop.value.code == 0 and out.startswith("usage: python -m gandalf_tools.doctor")
    assert "``" not in out and ":func:" not in out


def test_it_names_this_machines_context_and_adapters_and_every_part():
    run = _doctor()
    assert run.returncode == 0, run.stderr[-2000:]
    ctx = moderngl.create_standalone_context(backend="egl")
    try:
        renderer = ctx.info["GL_RENDERER"]
    finally:
        ctx.release()
    out = run.stdout
    assert f"renderer    {renderer}" in out and "extensions  " in out
    assert "* " in out and "max-storage-buffers-per-shader-stage" in out  # the picked adapter and its limits
    table = out.split("What runs here", 1)[1].split("\n\n", 1)[0]  # up to the next section (grading isolation)
    rows = {line.split()[0]: line for line in table.splitlines()[2:]
            if line.startswith("  ") and not line.startswith("   ")}  # a part's row; its details are indented more
    assert sorted(rows) == sorted(PARTS)


def test_under_opengl41_it_sends_the_compute_parts_to_webgpu():
    run = _doctor(MESA_GL_VERSION_OVERRIDE="4.1", MESA_GLSL_VERSION_OVERRIDE="410")
    if "version     4.1" not in run.stdout:
        pytest.skip("this OpenGL driver ignores Mesa's version override")
    assert run.returncode == 0, run.stderr[-2000:]
    assert ("      OpenGL: needs OpenGL 4.3 compute shaders and image load/store\n"
            "              run python -m step07_advanced.filter.webgpu instead\n") in run.stdout
    assert any(line.split()[:3] == ["step07_advanced.terrain", "runs", "runs"] for line in run.stdout.splitlines())


def test_a_part_verdict_names_the_gap_and_the_other_api():
    from gandalf_core.render.capabilities import Needs, Offer

    needs = Needs(opengl=430, opengl_for="compute shaders")
    gl41, webgpu = Offer("opengl", version=410), Offer("webgpu")
    expected = "needs OpenGL 4.3 compute shaders -> run python -m p.webgpu"
    assert doctor.verdict("p", "opengl", needs, gl41, webgpu) == expected
    assert doctor.verdict("p", "opengl", needs, gl41, None) == "needs OpenGL 4.3 compute shaders"
    assert doctor.verdict("p", "webgpu", needs, webgpu, gl41) == "runs"
    assert doctor.verdict("p", "webgpu", needs, None, gl41) == "no WebGPU here"
