"""Capabilities, stated and checked: what a part needs beyond OpenGL 3.3 / WebGPU's default limits, the check
against a real context or adapter, the launcher's one sentence, the skip and the grade's "not graded here"."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest
from capabilities_here import not_here

from gandalf_core import Application
from gandalf_core.app.cli import CAPABILITY_EXIT, Part, launcher
from gandalf_core.render.capabilities import WEBGPU_DEFAULT_LIMITS, CapabilityError, Needs, Offer
from gandalf_core.render.probe import offer_here
from gandalf_core.render.webgpu.device import ENGINE_FEATURES
from gandalf_tools.tour import REPO_ROOT
from step01_window.scene import build_scene

#: An OpenGL version no driver offers: the check must refuse it on every machine.
BEYOND_ANY_GL = 470


def test_a_webgpu_device_gets_the_default_limits_not_all_the_adapter_has():
    with Application("webgpu", 32, 24, headless=True) as app:
        device, adapter = app.renderer.device, app.renderer.adapter
        for name, default in WEBGPU_DEFAULT_LIMITS.items():
            have = adapter.limits.get(name)
            if not have:
                continue
            expected = max(default, have) if name.startswith("min-") else min(default, have)
            assert device.limits[name] == expected, (name, device.limits[name], expected, have)
        # The engine's own (ENGINE_FEATURES, where offered) and nothing else.
        unasked = set(device.features) - set(ENGINE_FEATURES)
        assert not unasked, f"a device with optional features nobody asked for: {unasked}"
        assert set(device.features) == set(ENGINE_FEATURES) & set(adapter.features)


def test_a_part_that_needs_a_higher_limit_gets_it():
    with Application("webgpu", 32, 24, headless=True, needs=Needs(limits={"max-bind-groups": 5})) as app:
        assert app.renderer.device.limits["max-bind-groups"] == 5


@pytest.mark.parametrize("api, needs, named", [
    ("opengl", Needs(opengl=BEYOND_ANY_GL, opengl_for="a test's shaders"), "OpenGL 4.7 a test's shaders"),
    ("webgpu", Needs(limits={"max-bind-groups": 10**6}), "WebGPU's max-bind-groups of 1000000"),
])
def test_an_app_refuses_a_need_the_machine_lacks_before_building_anything(api, needs, named):
    with pytest.raises(CapabilityError) as caught:
        Application(api, 32, 24, headless=True, needs=needs)
    assert named in str(caught.value) and str(offer_here(api)) in str(caught.value), str(caught.value)


def test_a_launcher_says_what_is_missing_and_what_to_run_instead(capsys):
    part = Part("step01_window", build_scene, needs=Needs(opengl=BEYOND_ANY_GL, opengl_for="for this test"))
    _create_app, main = launcher(part, "opengl")
    assert main(["--headless", "--frames", "1", "--size", "32x24"]) == CAPABILITY_EXIT
    said = capsys.readouterr().err.strip()
    assert said.splitlines() == [said] and "Traceback" not in said
    assert said.startswith("`python -m step01_window.opengl` needs OpenGL 4.7 for this test (this machine has OpenGL")
    assert said.endswith(": run `python -m step01_window.webgpu` instead"), said


def test_needs_in_words_and_what_an_offer_lacks():
    needs = Needs(opengl=430, opengl_for="compute shaders", features=("float32-filterable",),
                  limits={"max-storage-buffers-per-shader-stage": 10})
    assert needs.missing(Offer("opengl", version=410)) == "OpenGL 4.3 compute shaders"
    assert needs.missing(Offer("opengl", version=450)) == ""
    lacking = needs.missing(Offer("webgpu", limits={"max-storage-buffers-per-shader-stage": 8}))
    assert lacking == ("the WebGPU feature 'float32-filterable', WebGPU's max-storage-buffers-per-shader-stage of 10 "
                       "(this adapter: 8)")
    enough = Offer("webgpu", features=frozenset({"float32-filterable"}),
                   limits={"max-storage-buffers-per-shader-stage": 16})
    assert needs.missing(enough) == ""
    # Requested: the defaults, raised where needed, never beyond the adapter (a weaker one keeps its own value).
    limits = needs.device_limits({"max-storage-buffers-per-shader-stage": 16, "max-bind-groups": 3,
                                  "min-uniform-buffer-offset-alignment": 64})
    assert limits == {"max-storage-buffers-per-shader-stage": 10, "max-bind-groups": 3,
                      "min-uniform-buffer-offset-alignment": 256}
    with pytest.raises(ValueError, match="below the course's floor"):
        Needs(opengl=320)
    with pytest.raises(ValueError, match="unknown WebGPU limit"):
        Needs(limits={"max-bind-group": 5})


def _raise(exc: BaseException, module_name: str) -> pytest.ExceptionInfo[BaseException]:
    """``exc`` raised by code of a module named ``module_name``, caught as pytest catches it."""
    code = compile("def go(exc):\n    raise exc\n", f"<{module_name}>", "exec")
    scope = {"__name__": module_name}
    exec(code, scope)  # noqa: S102 - a function whose frame carries the module name, nothing else
    with pytest.raises(type(exc)) as caught:
        scope["go"](exc)
    return caught


def test_only_a_real_gap_raised_by_the_course_skips_a_test():
    real = CapabilityError("OpenGL 4.7", offer_here("opengl"), needs=Needs(opengl=BEYOND_ANY_GL))
    assert not_here(_raise(real, "step07_advanced.filter.compute_gl")).startswith("this program needs OpenGL 4.7")
    # Raised by an exercise: a failure, not a skip (an exercise cannot take its test out of the grade).
    assert not_here(_raise(real, "step07_advanced.exercises.blur")) == ""
    # A gap this machine does not have (it offers OpenGL 3.3): a failure.
    fake = CapabilityError("OpenGL 3.3", Offer("opengl", version=210), needs=Needs())
    assert not_here(_raise(fake, "step07_advanced.filter.compute_gl")) == ""
    assert not_here(_raise(RuntimeError("eglCreateContext failed"), "gandalf_core.render")) == ""


def test_the_grade_leaves_out_what_this_machine_cannot_run(tmp_path):
    env = {**os.environ, "MESA_GL_VERSION_OVERRIDE": "4.1", "MESA_GLSL_VERSION_OVERRIDE": "410"}
    env.pop("GANDALF_IMPL", None)
    grade = tmp_path / "grade.json"
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--student",
                          "--grade-json", str(grade), "tests/step07_advanced/test_filter.py", "-k", "test_blur_kernel"],
                         cwd=REPO_ROOT, env=env, capture_output=True, text=True, timeout=300)
    if "OpenGL 4.1" not in run.stdout:
        pytest.skip("this OpenGL driver ignores Mesa's version override")
    result = json.loads(grade.read_text())
    graded = {t["test"].split("[")[1].split("-")[0] for t in result["tests"]}
    assert graded == {"webgpu"}, result["tests"]  # the OpenGL cases are not graded here ...
    assert result["earned"] == 0 and result["possible"] > 0  # ... and the stubs still earn nothing on WebGPU
    assert "NOT GRADED HERE: tests/step07_advanced/test_filter.py::test_blur_kernel[opengl-" in run.stdout
    assert "needs OpenGL 4.3 compute shaders and image load/store" in run.stdout
