"""A student's shaders are compiled and run in the grader's shader process (``gandalf_tools.grading.shader_box``), never
in the process that makes the grade.

Each hostile shader kept in ``tests/attacks/step07/`` replaces a submission's ``explode.glsl`` / ``explode.wgsl`` (the
rest of the submission is the reference), and the front end grades the explode tests (harness-evaluated functions
and the rendered bunny) and the parallax tests in one run, in one process (``--jobs 0``: no worker to fall back on):

* every attack costs the explode tests only: ``parallax`` keeps its point, and the run ends with a grade;
* ``huge_array`` (a 200,000-float local array) stalls both of Mesa's drivers: each distinct call (each API's harness
  expression and its bunny) waits out the shader budget once, 4 × 4 s here, and its later calls fail at once; the
  sentence says so. NVIDIA's refuses it at once (the GLSL linker fails, the WebGPU device is lost): each sentence then
  names the student's file;
* ``compiler_crash`` (brackets nested 100,000 deep) is a compile error in GLSL ("memory exhausted") and a segmentation
  fault of naga, the WGSL compiler, inside the process that compiles it: that process ends, the sentence says so;
* ``endless_loop`` and ``out_of_bounds`` end (Mesa's llvmpipe and lavapipe cap a loop's iterations; out-of-range
  reads are clamped or read as zero) with wrong values, which fail their tests;
* the reference's own files, graded the same way, earn every point.

No message names the shader process's private copy of the files, and a run takes well under ``LIMIT`` seconds
(measured on the 2-core machine: 21-64 s; the control 28 s).

Where Mesa's software drivers are not installed the students' shaders run on the machine's GPU, and these tests skip
with the grader's warning: on an NVIDIA H200 an endless-loop shader left the GPU stalling the reference's shaders in
every later process.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
ATTACKS = ROOT / "tests" / "attacks" / "step07"
TESTS = [f"tests/step07_advanced/{name}.py" for name in ("test_explode", "test_explode_render", "test_parallax_render")]
#: The shader budget of these runs: far above the slowest graded call (under 1 s; the first call of an API starts the
#: process and its device outside the budget), and each stalled call waits it out once.
BUDGET = 4.0
#: The whole run's bound: 4 stalled calls × (the budget + a fresh process's start), plus the tests themselves.
LIMIT = 240.0
NESTED = "(" * 100_000 + "t" + ")" * 100_000


def _submission(tmp_path: Path, attack: str | None) -> Path:
    folder = tmp_path / "submission" / "exercises"
    shutil.copytree(ROOT / "step07_advanced" / "solutions", folder, ignore=shutil.ignore_patterns("__pycache__"))
    # The shader process reads the shader files beside the package and never runs its Python: a package that would
    # end any process importing it costs nothing (the student's Python process never imports it either here).
    (folder / "__init__.py").write_text("import os\n\nos._exit(9)\n")
    for language in ("glsl", "wgsl") if attack else ():
        text = (ATTACKS / f"{attack}.{language}").read_text().replace("@@NESTED@@", NESTED)
        (folder / f"explode.{language}").write_text(text)
    return folder


def _grade(tmp_path: Path, folder: Path) -> tuple[float, dict, str]:
    out = tmp_path / "grade.json"
    env = {k: v for k, v in os.environ.items() if k != "GANDALF_IMPL"}
    start = time.perf_counter()
    proc = subprocess.run(
        [sys.executable, "-m", "gandalf_tools.grading", *TESTS, "--impl", f"step07_advanced={folder}",
         "--json", str(out), "--jobs", "0", "--grade-shader-budget", f"{BUDGET:g}"],
        cwd=ROOT, env=env, capture_output=True, text=True, timeout=2 * LIMIT)
    seconds = time.perf_counter() - start
    assert proc.returncode == 0 and out.exists(), f"{proc.returncode}:\n{proc.stdout[-3000:]}\n{proc.stderr[-2000:]}"
    return seconds, json.loads(out.read_text()), proc.stdout


def test_the_shader_process_draws_with_mesas_software_drivers(tmp_path):
    """Where Mesa's software drivers are installed the students' shaders run on them, whatever GPU the machine has;
    where they are not, the grader says so."""
    from gandalf_tools.grading import remote, sandbox, shader_box

    drivers = shader_box.software_drivers()
    if not drivers:
        pytest.skip(shader_box.NO_SOFTWARE_DRIVERS)
    shader_box.stop()  # the grader's own shader process, made as a grading run makes it
    try:
        box = shader_box._box({_submission(tmp_path, None): "step07_advanced"}, hide=())
        assert box.env == drivers  # on a machine whose only drivers are Mesa's, the renderers below cannot tell
        gl, webgpu = remote.Session(box, sandbox.STARTUP_BUDGET, None).call(  # type: ignore[arg-type]
            {"op": "helper", "file": str(ROOT / "tests" / "shader_harness.py"), "function": "renderers",
             "args": [], "kwargs": {}}, "renderers()", "renderers")
    finally:
        shader_box.stop()
    assert "llvmpipe" in gl, gl
    assert "llvmpipe" in webgpu and "Vulkan" in webgpu, webgpu  # lavapipe names its device after llvmpipe


@pytest.mark.parametrize("attack", [None, "endless_loop", "huge_array", "compiler_crash", "out_of_bounds"])
def test_a_hostile_shader_costs_its_own_tests_only_in_bounded_time(tmp_path, attack):
    from gandalf_tools.grading import shader_box

    if not shader_box.software_drivers():  # the GPU draws the shaders: nothing bounds a hostile one (see the message)
        pytest.skip(shader_box.NO_SOFTWARE_DRIVERS)
    seconds, result, stdout = _grade(tmp_path, _submission(tmp_path, attack))
    earned = {x["exercise"]: x["earned"] for x in result["exercises"]}
    assert earned["parallax"] == pytest.approx(1.0), stdout[-3000:]
    assert seconds < LIMIT, f"{attack}: {seconds:.0f} s"
    explode = [t for t in result["tests"] if t["exercise"] == "explode_offset"]
    if attack is None:  # the control: the reference's files, through the shader process, earn every point
        assert earned["explode_offset"] == pytest.approx(1.0), stdout[-3000:]
        return
    assert earned["explode_offset"] == 0.0 and all(t["message"] for t in explode)
    messages = " ".join(t["message"] for t in explode)
    assert "gandalf-sandbox-" not in messages  # the student's own file is named, not the shader process's copy
    assert "the test process crashed" not in messages
    if attack == "huge_array":
        # Mesa stalls on it (4 waits; each later call of a stalled kind fails at once); a driver that refuses it fails
        # each test at once with its own words (the H200's: "GLSL Linker failed", the WebGPU device lost). Either way
        # each sentence names the student's file or says that the call stalled.
        stalled = [t for t in explode if f"did not return within {BUDGET:g} s" in t["message"]]
        refused = [t for t in explode if t not in stalled and "exercises/explode." in t["message"]]
        assert len(stalled) + len(refused) == len(explode), messages
        if stalled:
            assert "a shader loop that never ends, or one too big to run?" in messages
    if attack == "compiler_crash":
        assert "explode.glsl" in messages and "memory exhausted" in messages, messages
        assert "with your shaders ended its process (exit status -11) (the shader compiler or the driver crashed" \
            in messages, messages
