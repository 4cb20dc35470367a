"""Plausible wrong answers to ``hit_sphere`` and ``scatter_dielectric``, each of which must fail at least one graded
check of ``test_pathtracer.py`` (the graded tests, which a student's release keeps). The tables are edits of the
reference solution's shader text, so a student's release leaves this module out; ``tests/mutants/step07_advanced.py``
reads them from here for the mutation check (``python -m gandalf_tools.grading.mutants``).
"""

from __future__ import annotations

import pytest
from shader_checks import mutant_fails
from test_pathtracer import HIT_CHECKS, SCATTER_CHECKS

# --- mutants: plausible wrong answers, each must fail at least one graded check ---------------------------
# Edits are (file, old, new) in the solution files, as tests/mutants/ registers them with shader_mutant.
HG, HW = "ray_sphere.glsl", "ray_sphere.wgsl"
SG, SW = "dielectric.glsl", "dielectric.wgsl"
HIT_MUTANTS = [
    ("far-root-first", "returns the far root when both are in range",
     [(HG, "    if (t0 > t_min && t0 < t_max) {\n        return t0;\n    }\n    if (t1 > t_min && t1 < t_max) {\n"
          "        return t1;\n    }",
       "    if (t1 > t_min && t1 < t_max) {\n        return t1;\n    }\n    if (t0 > t_min && t0 < t_max) {\n"
       "        return t0;\n    }"),
      (HW, "    if (t0 > t_min && t0 < t_max) {\n        return t0;\n    }\n    if (t1 > t_min && t1 < t_max) {\n"
          "        return t1;\n    }",
       "    if (t1 > t_min && t1 < t_max) {\n        return t1;\n    }\n    if (t0 > t_min && t0 < t_max) {\n"
       "        return t0;\n    }")]),
    ("ignores-t-min", "takes the near root even behind t_min",
     [(HG, "if (t0 > t_min && t0 < t_max)", "if (t0 < t_max)"),
      (HW, "if (t0 > t_min && t0 < t_max)", "if (t0 < t_max)")]),
    ("ignores-t-max", "takes the near root even beyond t_max",
     [(HG, "if (t0 > t_min && t0 < t_max)", "if (t0 > t_min)"),
      (HW, "if (t0 > t_min && t0 < t_max)", "if (t0 > t_min)")]),
    ("naive-discriminant", "half_b^2 - a*c: catastrophic cancellation for a far sphere",
     [(HG, "a * (radius * radius - dot(to_line, to_line))", "half_b * half_b - a * (dot(oc, oc) - radius * radius)"),
      (HW, "a * (radius * radius - dot(to_line, to_line))", "half_b * half_b - a * (dot(oc, oc) - radius * radius)")]),
    ("unit-direction-assumed", "a = 1: wrong t for a direction that is not unit length",
     [(HG, "float a = dot(dir, dir);", "float a = 1.0;"), (HW, "let a = dot(dir, dir);", "let a = 1.0;")]),
    ("full-b-as-half-b", "b = 2 dot(oc, dir) used in the half-b formulas",
     [(HG, "float half_b = dot(oc, dir);", "float half_b = 2.0 * dot(oc, dir);"),
      (HW, "let half_b = dot(oc, dir);", "let half_b = 2.0 * dot(oc, dir);")]),
    ("tangent-misses", "a zero discriminant (a tangent ray) counted as a miss",
     [(HG, "if (discriminant < 0.0) {", "if (discriminant <= 0.0) {"),
      (HW, "if (discriminant < 0.0) {", "if (discriminant <= 0.0) {")]),
    ("inclusive-bounds", "t_min <= t <= t_max: a root exactly on a bound counts (the stub says strict)",
     [(HG, "if (t0 > t_min && t0 < t_max)", "if (t0 >= t_min && t0 <= t_max)"),
      (HG, "if (t1 > t_min && t1 < t_max)", "if (t1 >= t_min && t1 <= t_max)"),
      (HW, "if (t0 > t_min && t0 < t_max)", "if (t0 >= t_min && t0 <= t_max)"),
      (HW, "if (t1 > t_min && t1 < t_max)", "if (t1 >= t_min && t1 <= t_max)")]),
    ("inclusive-t-max", "t < t_max written t <= t_max",
     [(HG, "if (t1 > t_min && t1 < t_max)", "if (t1 > t_min && t1 <= t_max)"),
      (HW, "if (t1 > t_min && t1 < t_max)", "if (t1 > t_min && t1 <= t_max)")]),
    ("zero-on-miss", "returns 0 instead of -1 for a miss",
     [(HG, "    return -1.0;\n}", "    return 0.0;\n}"), (HW, "    return -1.0;\n}", "    return 0.0;\n}")]),
]
SCATTER_MUTANTS = [
    ("eta-inverted", "eta = ior when entering and 1/ior when leaving",
     [(SG, "float eta = entering ? 1.0 / ior : ior;", "float eta = entering ? ior : 1.0 / ior;"),
      (SW, "let eta = select(ior, 1.0 / ior, entering);", "let eta = select(1.0 / ior, ior, entering);")]),
    ("eta-always-entering", "eta = 1/ior on both sides",
     [(SG, "float eta = entering ? 1.0 / ior : ior;", "float eta = 1.0 / ior;"),
      (SW, "let eta = select(ior, 1.0 / ior, entering);", "let eta = 1.0 / ior;")]),
    ("normal-not-flipped", "uses the outward normal when leaving the glass",
     [(SG, "vec3 n = entering ? normal : -normal;", "vec3 n = normal;"),
      (SW, "let n = select(-normal, normal, entering);", "let n = normal;")]),
    ("no-total-internal-reflection", "refracts beyond the critical angle",
     [(SG, "if (sin2_t > 1.0 || u < reflectance)", "if (u < reflectance)"),
      (SW, "if (sin2_t > 1.0 || u < reflectance)", "if (u < reflectance)")]),
    ("no-schlick", "never reflects below the critical angle",
     [(SG, "if (sin2_t > 1.0 || u < reflectance)", "if (sin2_t > 1.0)"),
      (SW, "if (sin2_t > 1.0 || u < reflectance)", "if (sin2_t > 1.0)")]),
    ("schlick-inverted", "reflects when u > R",
     [(SG, "u < reflectance", "u > reflectance"), (SW, "u < reflectance", "u > reflectance")]),
    ("dir-not-normalised", "uses dir as given",
     [(SG, "vec3 d = normalize(dir);", "vec3 d = dir;"), (SW, "let d = normalize(dir);", "let d = dir;")]),
    ("result-not-normalised", "no sqrt clamp and no normalisation of the refracted ray",
     [(SG, "-sqrt(max(0.0, 1.0 - dot(t_perp, t_perp))) * n;\n    return normalize(t_perp + t_par);",
       "-sqrt(1.0 - dot(t_perp, t_perp)) * n;\n    return (t_perp + t_par) * length(dir);"),
      (SW, "-sqrt(max(0.0, 1.0 - dot(t_perp, t_perp))) * n;\n    return normalize(t_perp + t_par);",
       "-sqrt(1.0 - dot(t_perp, t_perp)) * n;\n    return (t_perp + t_par) * length(dir);")]),
    ("schlick-cubed", "(1 - cos)^3 in Schlick's formula",
     [(SG, "pow(1.0 - cos_i, 5.0)", "pow(1.0 - cos_i, 3.0)"), (SW, "pow(1.0 - cos_i, 5.0)", "pow(1.0 - cos_i, 3.0)")]),
]


@pytest.mark.parametrize("language", ["glsl", "wgsl"])
@pytest.mark.parametrize("mutant", [m[0] for m in HIT_MUTANTS])
def test_every_hit_sphere_mutant_fails_a_graded_check(tmp_path, mutant, language):
    _name, description, edits = next(m for m in HIT_MUTANTS if m[0] == mutant)
    assert mutant_fails(tmp_path, "ray_sphere", language, edits, HIT_CHECKS.values()), \
        f"mutant '{mutant}' ({description}, {language}) passes every check: {list(HIT_CHECKS)}"


@pytest.mark.parametrize("language", ["glsl", "wgsl"])
@pytest.mark.parametrize("mutant", [m[0] for m in SCATTER_MUTANTS])
def test_every_scatter_mutant_fails_a_graded_check(tmp_path, mutant, language):
    _name, description, edits = next(m for m in SCATTER_MUTANTS if m[0] == mutant)
    assert mutant_fails(tmp_path, "dielectric", language, edits, SCATTER_CHECKS.values()), \
        f"mutant '{mutant}' ({description}, {language}) passes every check: {list(SCATTER_CHECKS)}"
