"""The repository's own conventions: every step has the same shape, and its two implementations the same API."""

from __future__ import annotations

import ast
import importlib
from collections import Counter
from pathlib import Path

import pytest

from gandalf_tools.tour import REPO_ROOT, find_steps, step_parts

STEPS = find_steps()
# Files that may talk to one API directly: the two variants, helpers named for their API, and the
# raw-API lesson and benchmark files.
BACKEND_FILES = ("opengl.py", "webgpu.py", "raw.py", "preview.py")


def _backend_specific(name: str) -> bool:
    return name in BACKEND_FILES or name.endswith(("_gl.py", "_wgpu.py")) or name.startswith("bench")


def test_steps_are_found_in_order():
    assert STEPS and STEPS == sorted(STEPS)
    assert STEPS[0] == "step01_window"


@pytest.mark.parametrize("step", STEPS)
def test_step_has_the_standard_files(step):
    folder = REPO_ROOT / step
    for name in ("__init__.py", "opengl.py", "webgpu.py", "exercises/__init__.py", "solutions/__init__.py"):
        assert (folder / name).is_file(), f"{step} lacks {name}"
    assert (REPO_ROOT / "tests" / step).is_dir(), f"{step} has no tests/{step} folder (its autograder)"
    # A step of several techniques (step 07) or concepts (step 05) has one sub-package per part, each in the step's
    # own shape, runnable on its own (``main``) and from the step's launcher.
    for part in step_parts(step):
        part_folder = REPO_ROOT / part.replace(".", "/")
        for name in ("__init__.py", "scene.py", "opengl.py", "webgpu.py"):
            assert (part_folder / name).is_file(), f"{part} lacks {name}"
        for variant in ("opengl", "webgpu"):
            module = importlib.import_module(f"{part}.{variant}")
            assert callable(getattr(module, "create_app", None)), f"{part}.{variant} has no create_app"
            if part != step:
                assert callable(getattr(module, "main", None)), f"{part}.{variant} has no main(argv)"
        if part != step:
            assert ast.get_docstring(ast.parse((part_folder / "__init__.py").read_text())), f"{part} has no docstring"
            assert importlib.import_module(part).STEP == step, f"{part}.STEP must name its step ({step})"



@pytest.mark.parametrize("step", STEPS)
def test_every_variant_is_handed_to_the_one_launcher(step):
    """One launcher shape: every ``opengl.py`` / ``webgpu.py`` (the step's and each part's) gets its ``create_app``
    and ``main`` from ``gandalf_core.app.cli.launcher`` (a part's description and the API's backend), in its API."""
    for part in dict.fromkeys([step, *step_parts(step)]):
        for variant in ("opengl", "webgpu"):
            module = importlib.import_module(f"{part}.{variant}")
            for name in ("create_app", "main"):
                function = getattr(module, name)
                assert function.__qualname__ == f"launcher.<locals>.{name}", (
                    f"{part}.{variant}.{name} is written by hand: hand the part and the backend to "
                    "gandalf_core.app.cli.launcher")
            assert f" in {'OpenGL' if variant == 'opengl' else 'WebGPU'} " in module.create_app.__doc__

@pytest.mark.parametrize("step", STEPS)
def test_exercises_and_solutions_export_the_same_names(step):
    """The same Python names and the same files (shader exercises are files the step's shaders include)."""
    exercises = importlib.import_module(f"{step}.exercises")
    solutions = importlib.import_module(f"{step}.solutions")
    assert sorted(getattr(exercises, "__all__", [])) == sorted(getattr(solutions, "__all__", []))

    def files(package: str) -> list[str]:
        return sorted(p.name for p in (REPO_ROOT / step / package).iterdir() if p.suffix != ".pyc" and p.is_file())

    assert files("exercises") == files("solutions")


@pytest.mark.parametrize("step", STEPS)
def test_backend_neutral_code_imports_no_gpu_library(step):
    """scene.py, components, exercises and solutions are the same for both APIs: no moderngl/wgpu in them."""
    folder = REPO_ROOT / step
    neutral = [p for p in folder.rglob("*.py") if not _backend_specific(p.name)]
    for path in neutral:
        for node in ast.walk(ast.parse(path.read_text())):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            for name in names:
                assert name.split(".")[0] not in ("moderngl", "wgpu"), f"{path.relative_to(REPO_ROOT)} imports {name}"


def test_test_file_names_are_unique():
    """Test folders are not packages, so pytest needs every test module name to be unique."""
    names = Counter(p.name for p in (REPO_ROOT / "tests").rglob("test_*.py"))
    assert not [n for n, c in names.items() if c > 1]


def test_every_module_has_a_docstring():
    missing = []
    for root in ["gandalf_core", *STEPS]:
        for path in Path(REPO_ROOT / root).rglob("*.py"):
            tree = ast.parse(path.read_text())
            if path.stat().st_size and ast.get_docstring(tree) is None:
                missing.append(str(path.relative_to(REPO_ROOT)))
    assert not missing, missing


def test_one_class_per_component_or_system_name():
    """One name per meaning: a component or system class is defined once in the course (a later step imports the
    earlier step's, as step 05 and step 07 import step 03's SpinComponent). Exercises and solutions are parallel
    implementations of the same names by design, so they are left out."""
    defined: dict[str, list[str]] = {}
    for root in ["gandalf_core", *STEPS]:
        for path in sorted(Path(REPO_ROOT / root).rglob("*.py")):
            if {"exercises", "solutions"} & set(path.relative_to(REPO_ROOT).parts):
                continue
            for node in ast.walk(ast.parse(path.read_text())):
                if isinstance(node, ast.ClassDef) and node.name.endswith(("Component", "System")):
                    defined.setdefault(node.name, []).append(str(path.relative_to(REPO_ROOT)))
    twice = {name: paths for name, paths in defined.items() if len(paths) > 1}
    assert not twice, f"defined more than once (keep one, import it elsewhere): {twice}"
