"""Plausible wrong answers to the BRDF exercises (``ggx_distribution``, ``smith_geometry``, ``fresnel``,
``metallic_roughness``, ``ggx_specular``), each of which must fail at least one graded check of
``test_pbr_model_brdf.py`` (the graded tests, which a student's release keeps). The tables are edits of the reference
solution's shader text, so a student's release leaves this module out; ``tests/mutants/step07_advanced.py`` reads
them from here for the mutation check (``python -m gandalf_tools.grading.mutants``).
"""

from __future__ import annotations

import pytest
from shader_checks import mutant_fails
from test_pbr_model_brdf import CHECKS

# --- mutants: plausible wrong answers, each must fail at least one graded check ---------------------------
# (name, description, edits): ``(file, old, new)`` replacements in a copy of solutions/brdf.*, the format of
# gandalf_tools.grading.mutants.shader_mutant (``old`` occurs exactly once).
G, W = "brdf.glsl", "brdf.wgsl"
SHADER_MUTANTS = [
    ("brdf-d-no-pi", "D without the 1/pi",
     [(G, "return a2 / (BRDF_PI * d * d);", "return a2 / (d * d);"), (W, "return a2 / (BRDF_PI * d * d);",
                                                                       "return a2 / (d * d);")]),
    ("brdf-d-alpha-is-roughness", "alpha = roughness instead of roughness²",
     [(G, "float a2 = r * r * r * r;", "float a2 = r * r;"), (W, "let a2 = r * r * r * r;", "let a2 = r * r;")]),
    ("brdf-d-no-clamp", "roughness 0 not clamped: 0/0 at n·h = 1",
     [(G, "float r = clamp(roughness, BRDF_MIN_ROUGHNESS, 1.0);\n    float a2", "float r = roughness;\n    float a2"),
      (W, "let r = clamp(roughness, BRDF_MIN_ROUGHNESS, 1.0);\n    let a2", "let r = roughness;\n    let a2")]),
    ("brdf-k-swapped", "k_direct uses the IBL remapping",
     [(G, "return (r + 1.0) * (r + 1.0) / 8.0;", "return r * r / 2.0;"),
      (W, "return (r + 1.0) * (r + 1.0) / 8.0;", "return r * r / 2.0;")]),
    ("brdf-k-ibl-perceptual", "k_ibl = roughness / 2 (alpha taken as roughness)",
     [(G, "return r * r / 2.0;", "return r / 2.0;"), (W, "return r * r / 2.0;", "return r / 2.0;")]),
    ("brdf-g-no-clamp", "cosines not clamped: 0/0 with k = 0",
     [(G, "float v = clamp(n_dot_v, BRDF_MIN_COSINE, 1.0);", "float v = n_dot_v;"),
      (W, "let v = clamp(n_dot_v, BRDF_MIN_COSINE, 1.0);", "let v = n_dot_v;")]),
    ("brdf-f-no-clamp", "cos_theta not clamped (negative base of the 5th power above 1)",
     [(G, "float m = 1.0 - clamp(cos_theta, 0.0, 1.0);\n    float m2 = m * m;\n    return f0 + (1.0 - f0)",
       "float m = 1.0 - cos_theta;\n    float m2 = m * m;\n    return f0 + (1.0 - f0)"),
      (W, "let m = 1.0 - clamp(cos_theta, 0.0, 1.0);\n    let m2 = m * m;\n    return f0 + (1.0 - f0)",
       "let m = 1.0 - cos_theta;\n    let m2 = m * m;\n    return f0 + (1.0 - f0)")]),
    ("brdf-f-roughness-ignored", "the IBL Fresnel ignores roughness",
     [(G, "max(vec3(1.0 - clamp(roughness, 0.0, 1.0)), f0)", "vec3(1.0)"),
      (W, "max(vec3<f32>(1.0 - clamp(roughness, 0.0, 1.0)), f0)", "vec3<f32>(1.0)")]),
    ("brdf-f0-base-for-dielectrics", "F0 = base for every material",
     [(G, "return mix(vec3(0.04), base, clamp(metallic, 0.0, 1.0));", "return base;"),
      (W, "return mix(vec3<f32>(0.04), base, clamp(metallic, 0.0, 1.0));", "return base;")]),
    ("brdf-diffuse-ignores-fresnel", "diffuse albedo without (1 - F)",
     [(G, "* (1.0 - fresnel);", ";"), (W, "* (1.0 - fresnel);", ";")]),
    ("brdf-diffuse-metals", "metals keep a diffuse albedo",
     [(G, "return base * (1.0 - clamp(metallic, 0.0, 1.0)) * (1.0 - fresnel);", "return base * (1.0 - fresnel);"),
      (W, "return base * (1.0 - clamp(metallic, 0.0, 1.0)) * (1.0 - fresnel);", "return base * (1.0 - fresnel);")]),
    ("brdf-specular-no-4", "no 4 in the denominator",
     [(G, "/ (4.0 * n_dot_v * n_dot_l);", "/ (n_dot_v * n_dot_l);"), (W, "/ (4.0 * n_dot_v * n_dot_l);",
                                                                   "/ (n_dot_v * n_dot_l);")]),
    ("brdf-specular-unclamped", "n·v not clamped: division by 0 at grazing angles",
     [(G, "float n_dot_v = clamp(dot(n, v), BRDF_MIN_COSINE, 1.0);", "float n_dot_v = dot(n, v);"),
      (W, "let n_dot_v = clamp(dot(n, v), BRDF_MIN_COSINE, 1.0);", "let n_dot_v = dot(n, v);")]),
    ("brdf-specular-no-half-guard", "normalize(l + v) when l = -v (NaN)",
     [(G, "vec3 h = len > 1e-6 ? sum / len : n;", "vec3 h = normalize(sum);"),
      (W, "let h = select(n, sum / max(len, 1e-6), len > 1e-6);", "let h = normalize(sum);")]),
    ("brdf-specular-f-of-n-dot-v", "Fresnel of n·v instead of v·h",
     [(G, "fresnel_schlick(dot(v, h), f0) / (4.0", "fresnel_schlick(n_dot_v, f0) / (4.0"),
      (W, "fresnel_schlick(dot(v, h), f0) / (4.0", "fresnel_schlick(n_dot_v, f0) / (4.0")]),
]


#: The exercise each mutant breaks, for registering them:
#:     for name, description, edits in SHADER_MUTANTS:
#:         shader_mutant(MUTANTS, "step07_advanced", MUTANT_EXERCISE[name], name, description, edits)
MUTANT_EXERCISE = {
    "brdf-d-no-pi": "ggx_distribution", "brdf-d-alpha-is-roughness": "ggx_distribution",
    "brdf-d-no-clamp": "ggx_distribution", "brdf-k-swapped": "smith_geometry",
    "brdf-k-ibl-perceptual": "smith_geometry", "brdf-g-no-clamp": "smith_geometry", "brdf-f-no-clamp": "fresnel",
    "brdf-f-roughness-ignored": "fresnel", "brdf-f0-base-for-dielectrics": "metallic_roughness",
    "brdf-diffuse-ignores-fresnel": "metallic_roughness", "brdf-diffuse-metals": "metallic_roughness",
    "brdf-specular-no-4": "ggx_specular", "brdf-specular-unclamped": "ggx_specular",
    "brdf-specular-no-half-guard": "ggx_specular", "brdf-specular-f-of-n-dot-v": "ggx_specular",
}


def test_every_mutant_names_its_exercise():
    assert set(MUTANT_EXERCISE) == {m[0] for m in SHADER_MUTANTS}


@pytest.mark.parametrize("language", ["glsl", "wgsl"])
@pytest.mark.parametrize("mutant", [m[0] for m in SHADER_MUTANTS])
def test_every_mutant_fails_a_graded_check(tmp_path, mutant, language):
    _name, description, edits = next(m for m in SHADER_MUTANTS if m[0] == mutant)
    assert mutant_fails(tmp_path, "brdf", language, edits, CHECKS.values()), \
        f"mutant '{mutant}' ({description}, {language}) passes every check: {list(CHECKS)}"
