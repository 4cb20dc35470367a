"""What keeps a grading process fast without changing what it checks, and the sample class's exercise table.

* Every grading process (the front end, the batch grader's, the mutation check's) leaves out hypothesis's pytest
  plugin, and a test module that fails to import does not stop the other steps from being graded: the grade
  names it (``collection_errors``, a NOT GRADED line), with and without a worker.
* Bytecode goes to a cache outside the checkout and the submissions (``PYTHONPYCACHEPREFIX``), never next to a
  source, and ``GANDALF_PYCACHE=off`` turns it off (then nothing is written at all).
* ``scripts/make_sample_submissions.py``'s table of the files each exercise's tests read names every graded
  exercise of every step (else its ``--check`` could not check that exercise), and only files that exist.
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import subprocess
import sys
from pathlib import Path

from gandalf_tools.grading import bytecode_cache_env
from gandalf_tools.grading.__main__ import pytest_options

ROOT = Path(__file__).resolve().parents[2]


def test_grading_processes_skip_hypothesis_and_survive_collection_errors():
    options = pytest_options(jobs=1)
    assert "no:hypothesispytest" in options and "--continue-on-collection-errors" in options


def test_bytecode_goes_to_a_cache_outside_the_checkout(monkeypatch, tmp_path):
    monkeypatch.setenv("GANDALF_PYCACHE", str(tmp_path / "cache"))
    env = bytecode_cache_env({"PYTHONDONTWRITEBYTECODE": "1", "KEEP": "x"})
    assert env == {"PYTHONPYCACHEPREFIX": str(tmp_path / "cache"), "KEEP": "x"}
    monkeypatch.setenv("GANDALF_PYCACHE", "off")
    assert bytecode_cache_env({"KEEP": "x"}) == {"PYTHONDONTWRITEBYTECODE": "1", "KEEP": "x"}


def test_a_grading_run_writes_no_bytecode_into_the_graded_folder(tmp_path):
    """A submission's folder gets no ``__pycache__`` (the cache is elsewhere), and the cache is used."""
    package = tmp_path / "submission" / "exercises"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("VALUE = 1\n")
    cache = tmp_path / "cache"
    env = {k: v for k, v in os.environ.items() if k != "GANDALF_IMPL"}
    env["GANDALF_PYCACHE"] = str(cache)
    code = (
        "import sys; from gandalf_tools.grading import use_bytecode_cache; use_bytecode_cache(); "
        f"sys.path.insert(0, {str(package.parent)!r}); import exercises; print(exercises.VALUE)"
    )
    proc = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0 and proc.stdout.strip() == "1", proc.stderr
    assert not list(package.parent.rglob("__pycache__"))
    assert list(cache.rglob("__init__*.pyc")), "the bytecode should be in the cache"


def _sample_script():
    path = ROOT / "scripts" / "make_sample_submissions.py"
    spec = importlib.util.spec_from_file_location("make_sample_submissions", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_sample_table_names_every_graded_exercise_and_existing_files():
    script = _sample_script()
    for step, table in script.EXERCISE_FILES.items():
        names = set()
        for path in (ROOT / "tests" / step).glob("*.py"):
            names |= set(re.findall(r'mark\.exercise\(\s*"([^"]+)"', path.read_text()))
        assert names == set(table), f"{step}: graded exercises {sorted(names)}, table {sorted(table)}"
        present = {p.name for p in (ROOT / step / "exercises").iterdir()}
        for exercise, files in table.items():
            for f in files:
                assert f in present or {f"{f}.glsl", f"{f}.wgsl"} <= present, f"{step}:{exercise}: no file {f}"
    steps = sorted(p.parent.parent.name for p in ROOT.glob("step*/exercises/__init__.py"))
    assert sorted(script.EXERCISE_FILES) == steps


def test_a_module_that_fails_to_import_is_named_and_the_rest_is_graded(tmp_path):
    """``--continue-on-collection-errors``: the other modules' graded tests count, and the grade names the one that
    could not be imported (with and without a worker)."""
    files = {
        "brokenstep/__init__.py": "",
        "brokenstep/solutions/__init__.py": "def one():\n    return 1\n",
        "brokenstep/exercises/__init__.py": "def one():\n    return 1\n",
        "grading_tests/brokenstep/conftest.py": "from gandalf_tools.grading.plugin import impl_fixture\n\n"
                                                "impl = impl_fixture('brokenstep')\n",
        "grading_tests/brokenstep/test_good.py": "import pytest\n\n\n@pytest.mark.exercise('one')\n"
                                                 "def test_one(impl):\n    assert impl.one() == 1\n",
        "grading_tests/brokenstep/test_bad.py": "import no_such_module_for_this_test\n",
    }
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    env = {k: v for k, v in os.environ.items() if k != "GANDALF_IMPL"}
    env["PYTHONPATH"] = os.pathsep.join([str(tmp_path), str(ROOT)])
    for jobs in ("0", "1"):
        out = tmp_path / f"grade{jobs}.json"
        proc = subprocess.run(
            [sys.executable, "-m", "gandalf_tools.grading", str(tmp_path / "grading_tests" / "brokenstep"), "--json",
             str(out), "--jobs", jobs], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
        assert out.exists(), proc.stdout[-2000:] + proc.stderr[-2000:]
        result = json.loads(out.read_text())
        assert result["earned"] == 1.0 and result["graded_tests_passed"] == 1, (jobs, result)
        bad = "grading_tests/brokenstep/test_bad.py"
        errors = result["collection_errors"]
        assert list(errors) == [bad] and "no_such_module_for_this_test" in errors[bad], errors
        assert f"NOT GRADED: {bad} failed to import" in proc.stdout
