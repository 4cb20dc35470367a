"""Plausible wrong answers to ``explode_offset``, each of which must fail at least one graded check of
``test_explode.py`` (the graded tests, which a student's release keeps). The tables are edits of the reference
solution's shader text, so a student's release leaves this module out; ``tests/mutants/step07_advanced.py`` reads
them from here for the mutation check (``python -m gandalf_tools.grading.mutants``).
"""

from __future__ import annotations

import pytest
from shader_checks import mutant_fails
from test_explode import CHECKS

# --- mutants: plausible wrong answers, each must fail at least one graded check ---------------------------
# (name, description, edits): ``(file, old, new)`` replacements in a copy of solutions/explode.*, the format of
# gandalf_tools.grading.mutants.shader_mutant (``old`` occurs exactly once, so a changed solution breaks a stale
# mutant loudly). The step's mutation check can register them as they are:
#     for name, description, edits in SHADER_MUTANTS:
#         shader_mutant(MUTANTS, "step07_advanced", "explode_offset", name, description, edits)
G, W = "explode.glsl", "explode.wgsl"
SHADER_MUTANTS = [
    ("explode-not-normalised", "the cross product is not normalised",
     [(G, "return len > 1e-12 ? c / len : vec3(0.0);", "return c;"),
      (W, "    return c / len;\n}", "    return c;\n}")]),
    ("explode-clockwise", "the normal's sign is flipped (cross(e2, e1))",
     [(G, "vec3 c = cross(e1 / s, e2 / s);", "vec3 c = cross(e2 / s, e1 / s);"),
      (W, "let c = cross(e1 / s, e2 / s);", "let c = cross(e2 / s, e1 / s);")]),
    ("explode-degrees", "360 for 2 pi: degrees given to cos",
     [(G, "cos(6.283185307179586 * t / period)", "cos(360.0 * t / period)"),
      (W, "cos(6.283185307179586 * t / period)", "cos(360.0 * t / period)")]),
    ("explode-no-half", "(1 - cos) without the / 2: twice the amount at the peak",
     [(G, "0.5 - 0.5 * cos(", "1.0 - cos("), (W, "0.5 - 0.5 * cos(", "1.0 - cos(")]),
    ("explode-sine", "a sine pulse instead of (1 - cos) / 2",
     [(G, "0.5 - 0.5 * cos(6.283185307179586 * t / period)", "sin(3.141592653589793 * t / period)"),
      (W, "0.5 - 0.5 * cos(6.283185307179586 * t / period)", "sin(3.141592653589793 * t / period)")]),
    ("explode-no-degenerate-guard", "normalises a zero cross product (NaN)",
     [(G, "return len > 1e-12 ? c / len : vec3(0.0);", "return c / len;"), (W, "if (len <= 1e-12) {", "if (false) {")]),
    ("explode-no-edge-scaling", "cross product of the raw edges: overflows (1e30) and underflows (1e-30)",
     [(G, "vec3 c = cross(e1 / s, e2 / s);", "vec3 c = cross(e1, e2);"),
      (W, "let c = cross(e1 / s, e2 / s);", "let c = cross(e1, e2);")]),
    ("explode-vertex-direction", "a per-vertex direction (the first corner's) instead of the face normal",
     [(G, "return amount * w * face_normal(p0, p1, p2);", "return amount * w * normalize(p0);"),
      (W, "return amount * w * face_normal(p0, p1, p2);", "return amount * w * normalize(p0);")]),
]


@pytest.mark.parametrize("language", ["glsl", "wgsl"])
@pytest.mark.parametrize("mutant", [m[0] for m in SHADER_MUTANTS])
def test_every_mutant_fails_a_graded_check(tmp_path, mutant, language):
    _name, description, edits = next(m for m in SHADER_MUTANTS if m[0] == mutant)
    assert mutant_fails(tmp_path, "explode", language, edits, CHECKS.values()), \
        f"mutant '{mutant}' ({description}, {language}) passes every check: {list(CHECKS)}"
