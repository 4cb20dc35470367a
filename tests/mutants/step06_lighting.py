"""Mutants of step 06: ``LightCollectionSystem``, ``reflect``/``refract`` (Python and shader) and ``blinn_phong``
(shader: the same slip made in ``shading.glsl`` and ``shading.wgsl``)."""

from __future__ import annotations

import warnings

import numpy as np

from gandalf_tools.grading.mutants import Mutant, mutant, patch, shader_mutant

STEP = "step06_lighting"
MUTANTS: list[Mutant] = []


# --- LightCollectionSystem -------------------------------------------------------------------------


def _lights(pkg, **slips):
    base = pkg.lights.LightCollectionSystem
    from gandalf_core.render.frame import LIGHTS_BYTES, MAX_LIGHTS
    from gandalf_core.resources import srgb_to_linear

    class LightCollectionSystem(base):
        def pack(self, components):
            block = np.zeros(LIGHTS_BYTES // 4, dtype=np.float32)
            ambient = np.zeros(3)
            positions = np.zeros((MAX_LIGHTS, 4))
            colors = np.zeros((MAX_LIGHTS, 4))
            count = 0
            for light, transform in components:
                colour = np.asarray(light.color, dtype=np.float64)
                radiance = (colour if slips.get("no_linear") else srgb_to_linear(colour)) * (
                    1.0 if slips.get("no_intensity") else light.intensity
                )
                if light.kind == "ambient" and not slips.get("ambient_as_light"):
                    ambient += radiance
                    continue
                if count == MAX_LIGHTS:
                    if not slips.get("silent_cap"):
                        warnings.warn(f"more than {MAX_LIGHTS} lights: the rest are ignored", stacklevel=2)
                    break
                world = transform.world
                if light.kind == "point" or (light.kind == "ambient" and slips.get("ambient_as_light")):
                    where = np.asarray(transform.translation, float) if slips.get("local") else world[:3, 3]
                    positions[count] = (*where, 1.0)
                else:
                    towards = world[:3, 2] * (-1.0 if slips.get("direction_sign") else 1.0)
                    length = np.linalg.norm(towards)
                    if slips.get("unnormalised"):
                        positions[count, :3] = towards
                    elif slips.get("unguarded"):
                        with np.errstate(all="ignore"):
                            positions[count, :3] = towards / length
                    else:
                        positions[count, :3] = towards / length if length > 0 else (0.0, 1.0, 0.0)
                colors[count] = (*radiance, 0.0 if slips.get("no_range") else light.range)
                count += 1
            block[0:4].view(np.int32)[0] = count
            block[4:7] = ambient
            block[8 : 8 + 4 * MAX_LIGHTS] = positions.ravel()
            block[8 + 4 * MAX_LIGHTS :] = colors.ravel()
            return block.tobytes()

    patch(pkg, "lights.LightCollectionSystem", LightCollectionSystem)


for _name, _slip, _text in [
    ("no-linear", "no_linear", "packs the sRGB colour without converting it to linear"),
    ("no-intensity", "no_intensity", "ignores the light's intensity"),
    ("ambient-as-light", "ambient_as_light", "packs ambient lights as point lights instead of summing them"),
    ("direction-sign", "direction_sign", "a directional light's direction along -Z (where it shines), not +Z"),
    ("local-position", "local", "the point light's local translation instead of its world position"),
    ("silent-cap", "silent_cap", "drops the lights past MAX_LIGHTS without a warning"),
    ("no-range", "no_range", "leaves the range (w of the colour) at 0"),
    ("unnormalised", "unnormalised", "a directional light's direction not normalised (scaled transforms)"),
    ("zero-axis-nan", "unguarded", "a zero Z axis divided by its zero length (NaN) instead of (0, 1, 0)"),
]:
    mutant(MUTANTS, STEP, "LightCollectionSystem", _name, _text)(lambda pkg, _s=_slip: _lights(pkg, **{_s: True}))


# --- reflect / refract: Python ---------------------------------------------------------------------


def _dot(a, b):
    return np.sum(a * b, axis=-1, keepdims=True)


# --8<-- [start:python-example]
@mutant(MUTANTS, STEP, "reflect_refract", "reflect-sign", "reflect: i + 2 (n.i) n (the sign of the correction)")
def _(pkg):
    def reflect(i, n):
        i, n = np.asarray(i, float), np.asarray(n, float)
        return i + 2.0 * _dot(n, i) * n

    patch(pkg, "optics.reflect", reflect)


# --8<-- [end:python-example]
@mutant(MUTANTS, STEP, "reflect_refract", "reflect-no-2", "reflect: i - (n.i) n (forgets the factor 2)")
def _(pkg):
    def reflect(i, n):
        i, n = np.asarray(i, float), np.asarray(n, float)
        return i - _dot(n, i) * n

    patch(pkg, "optics.reflect", reflect)


def _refract(pkg, *, tir_zero=True, invert_eta=False, cos_sign=1.0):
    def refract(i, n, eta):
        i, n = np.asarray(i, float), np.asarray(n, float)
        e = np.asarray(eta, float)[..., None] if np.ndim(eta) else float(eta)
        if invert_eta:
            e = 1.0 / e
        cos_i = _dot(n, i)
        k = 1.0 - e * e * (1.0 - cos_i * cos_i)
        t = e * i - (e * cos_i + cos_sign * np.sqrt(np.maximum(k, 0.0))) * n
        return np.where(k >= 0.0, t, 0.0) if tir_zero else t

    patch(pkg, "optics.refract", refract)


for _name, _text, _slips in [
    ("refract-no-tir", "refract: no zero vector on total internal reflection", {"tir_zero": False}),
    ("refract-inverted-eta", "refract: uses 1 / eta (n2 / n1 for n1 / n2)", {"invert_eta": True}),
    ("refract-cos-sign", "refract: eta cos_i - sqrt(k) (sign of the root)", {"cos_sign": -1.0}),
]:
    mutant(MUTANTS, STEP, "reflect_refract", _name, _text)(lambda pkg, _s=_slips: _refract(pkg, **_s))


# --- reflect / refract: shaders --------------------------------------------------------------------

for _name, _text, _edits in [
    ("shader-reflect-sign", "reflect_direction: i + 2 (n.i) n in both shaders", [
        ("shading.glsl", "return i - 2.0 * dot(n, i) * n;", "return i + 2.0 * dot(n, i) * n;"),
        ("shading.wgsl", "return i - 2.0 * dot(n, i) * n;", "return i + 2.0 * dot(n, i) * n;"),
    ]),
    ("shader-inverted-eta", "refract_direction: 1 / eta in both shaders", [
        ("shading.glsl", "float cos_i = dot(n, i);", "float cos_i = dot(n, i);\n    eta = 1.0 / eta;"),
        (
            "shading.wgsl",
            "fn refract_direction(i: vec3<f32>, n: vec3<f32>, eta: f32) -> vec3<f32> {\n",
            "fn refract_direction(i: vec3<f32>, n: vec3<f32>, eta_in: f32) -> vec3<f32> {\n"
            "    let eta = 1.0 / eta_in;\n",
        ),
    ]),
    ("shader-tir-reflects",
     "refract_direction returns the mirror direction on total internal reflection instead of zero", [
        ("shading.glsl", "return vec3(0.0);", "return reflect_direction(i, n);"),
        ("shading.wgsl", "return vec3<f32>(0.0);", "return reflect_direction(i, n);"),
    ]),
    ("glsl-only-root-sign", "refract_direction: - sqrt(k) only in the GLSL file (the WGSL one is right)", [
        (
            "shading.glsl",
            "return eta * i - (eta * cos_i + sqrt(k)) * n;",
            "return eta * i - (eta * cos_i - sqrt(k)) * n;",
        ),
    ]),
    ("wgsl-only-reflect-no-2", "reflect_direction without the 2, only in the WGSL file", [
        ("shading.wgsl", "return i - 2.0 * dot(n, i) * n;", "return i - dot(n, i) * n;"),
    ]),
]:
    shader_mutant(MUTANTS, STEP, "reflect_refract", _name, _text, _edits)


# --- blinn_phong: shaders --------------------------------------------------------------------------

# --8<-- [start:shader-example]
shader_mutant(
    MUTANTS,
    STEP,
    "blinn_phong",
    "no-clamp",
    "n.l not clamped at 0 (light from behind subtracts)",
    [
        ("shading.glsl", "float n_dot_l = max(dot(n, l), 0.0);", "float n_dot_l = dot(n, l);"),
        ("shading.wgsl", "let n_dot_l = max(dot(n, l), 0.0);", "let n_dot_l = dot(n, l);"),
    ],
)
# --8<-- [end:shader-example]
for _name, _text, _edits in [
    ("phong-lobe", "Phong's reflect(-l, n).v instead of the half vector", [
        ("shading.glsl", "pow(max(dot(n, h), 0.0), shininess)", "pow(max(dot(reflect(-l, n), v), 0.0), shininess)"),
        ("shading.wgsl", "pow(max(dot(n, h), 0.0), shininess)", "pow(max(dot(reflect(-l, n), v), 0.0), shininess)"),
    ]),
    ("h-not-normalised", "the half vector l + v used without normalising", [
        ("shading.glsl", "h = h_length > 1e-6 ? h / h_length : n;", "h = h_length > 1e-6 ? h : n;"),
        (
            "shading.wgsl",
            "select(n, h_sum / max(h_length, 1e-6), h_length > 1e-6)",
            "select(n, h_sum, h_length > 1e-6)",
        ),
    ]),
    ("pow-0-0", "shininess 0 not special-cased (pow(0, 0) is undefined)", [
        (
            "shading.glsl",
            "float lobe = shininess > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 1.0;",
            "float lobe = pow(max(dot(n, h), 0.0), shininess);",
        ),
        (
            "shading.wgsl",
            "let lobe = select(1.0, pow(max(dot(n, h), 0.0), shininess), shininess > 0.0);",
            "let lobe = pow(max(dot(n, h), 0.0), shininess);",
        ),
    ]),
    ("specular-without-nl", "the highlight not scaled by n.l", [
        (
            "shading.glsl",
            "return (albedo + specular * lobe) * radiance * n_dot_l;",
            "return (albedo * n_dot_l + specular * lobe) * radiance;",
        ),
        (
            "shading.wgsl",
            "return (albedo + specular * lobe) * radiance * n_dot_l;",
            "return (albedo * n_dot_l + specular * lobe) * radiance;",
        ),
    ]),
    ("tinted-highlight", "the highlight tinted by the albedo (not white)", [
        (
            "shading.glsl",
            "return (albedo + specular * lobe) * radiance * n_dot_l;",
            "return albedo * (1.0 + specular * lobe) * radiance * n_dot_l;",
        ),
        (
            "shading.wgsl",
            "return (albedo + specular * lobe) * radiance * n_dot_l;",
            "return albedo * (1.0 + specular * lobe) * radiance * n_dot_l;",
        ),
    ]),
    ("h-sign", "the half vector from l - v", [
        ("shading.glsl", "vec3 h = l + v;", "vec3 h = l - v;"),
        ("shading.wgsl", "let h_sum = l + v;", "let h_sum = l - v;"),
    ]),
]:
    shader_mutant(MUTANTS, STEP, "blinn_phong", _name, _text, _edits)
