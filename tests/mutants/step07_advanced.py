"""Mutants of step 07's shader exercises, for the mutation check.

The lists live beside the checks that kill them, in the technique's test files (each of those files also runs
its mutants through the shader harness as ungraded tests); here they are read from the files' source (only the
literal tables, nothing is imported: the mutation runner forks with no GPU library loaded) and registered with
the exercise each one breaks. The terrain, filter and parallax mutants use other formats and are checked by
their own test files only.
"""

from __future__ import annotations

import ast
from pathlib import Path

from gandalf_core.grading.mutants import Mutant, shader_mutant

STEP = "step07_advanced"
MUTANTS: list[Mutant] = []
TESTS = Path(__file__).resolve().parent.parent / STEP


def _tables(test_file: str, names: set[str]) -> dict:
    """The module-level assignments of ``names`` in ``test_file``, evaluated in order in an empty namespace."""
    tree = ast.parse((TESTS / test_file).read_text())
    namespace: dict = {}
    for node in tree.body:
        if isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            flat = [t for target in targets for t in (target.elts if isinstance(target, ast.Tuple) else [target])]
            if any(isinstance(t, ast.Name) and t.id in names for t in flat):
                exec(compile(ast.Module([node], []), test_file, "exec"), {}, namespace)  # literal tables only
    return namespace


_explode = _tables("test_explode.py", {"G", "W", "SHADER_MUTANTS"})
for name, description, edits in _explode["SHADER_MUTANTS"]:
    shader_mutant(MUTANTS, STEP, "explode_offset", name, description, edits)

_tracer = _tables("test_pathtracer.py", {"HG", "HW", "SG", "SW", "HIT_MUTANTS", "SCATTER_MUTANTS"})
for exercise, table in (("hit_sphere", _tracer["HIT_MUTANTS"]), ("scatter_dielectric", _tracer["SCATTER_MUTANTS"])):
    for name, description, edits in table:
        shader_mutant(MUTANTS, STEP, exercise, name, description, edits)

_brdf = _tables("test_pbr_model_brdf.py", {"G", "W", "SHADER_MUTANTS", "MUTANT_EXERCISE"})
for name, description, edits in _brdf["SHADER_MUTANTS"]:
    shader_mutant(MUTANTS, STEP, _brdf["MUTANT_EXERCISE"][name], name, description, edits)
