"""The image filter's checks that need the reference solution (``step07_advanced.filter``; the graded tests of
``blur_kernel`` and ``convolve`` are in ``test_filter.py``, which a student's release keeps): every blur method and
the Sobel filter of the engine against the numpy reference, its errors, and the mutants of both exercises, each of
which must fail one of ``test_filter.py``'s graded checks. ``tests/mutants/step07_advanced.py`` reads the mutant
tables from here. A student's release leaves this module out (it imports the solutions).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from shader_checks import LANGUAGE
from test_filter import CHECKS, _compare_image, _Filters, _impl_from, noise_image, scene_like

from step07_advanced import solutions
from step07_advanced.filter import kernels
from step07_advanced.filter.shaders import impl_shader_dir

SOLUTIONS_DIR = impl_shader_dir(solutions)


@pytest.fixture(scope="module")
def filters():
    cache = _Filters()
    yield cache
    cache.close()


# --- the engine side on the reference solution (not graded) -------------------------------------------------
@pytest.mark.parametrize("op", ["naive", "tiled", "separable"])
@pytest.mark.parametrize("size", [(37, 23), (1, 1), (130, 70)])
def test_every_blur_method_matches_the_reference(filters, backend, op, size):
    image = scene_like(*size)
    for r in (0, 7, kernels.MAX_RADIUS):
        msg = _compare_image(filters.get(backend, solutions), image, op, r, "blur", weights=False)
        assert msg is None, msg


def test_sobel_matches_the_reference(filters, backend):
    flt = filters.get(backend, solutions)
    for size in ((37, 23), (1, 1), (64, 48)):
        assert (msg := _compare_image(flt, scene_like(*size), "sobel", 0, "blur", weights=False)) is None, msg


def test_radius_beyond_the_limit_is_an_error(filters, backend):
    flt = filters.get(backend, solutions)
    image = scene_like(8, 8)
    with pytest.raises(ValueError, match=r"radius 33 is outside 0\.\.32.*MAX_RADIUS"):
        flt.run(image, "tiled", 33)
    with pytest.raises(ValueError, match="radius -1"):
        flt.run(image, "separable", -1)
    with pytest.raises(ValueError, match="must be an int"):
        flt.run(image, "separable", 2.5)
    with pytest.raises(ValueError, match="op 'median'"):
        flt.run(image, "median", 1)


def test_wrong_images_are_errors(filters, backend, monkeypatch):
    flt = filters.get(backend, solutions)
    with pytest.raises(ValueError, match=r"RGBA8.*float64 \(4, 4, 4\)"):
        flt.run(np.zeros((4, 4, 4)), "separable", 1)
    with pytest.raises(ValueError, match=r"RGBA8.*\(4, 4, 3\)"):
        flt.run(np.zeros((4, 4, 3), np.uint8), "separable", 1)
    with pytest.raises(TypeError, match="numpy array"):
        flt.run([[0, 0, 0, 255]], "separable", 1)
    limit = flt.max_size
    assert limit >= 2048 and flt.max_size_name in ("GL_MAX_TEXTURE_SIZE", "maxTextureDimension2D")
    monkeypatch.setattr(flt, "max_size", 32)  # a small limit stands in for a 16384+ image
    with pytest.raises(ValueError, match=rf"image 33x2 is larger than .*{flt.max_size_name} = 32"):
        flt.run(noise_image(33, 2), "separable", 1)



def test_shader_errors_name_the_file_and_line(filters, backend, tmp_path):
    language = LANGUAGE[backend]
    (tmp_path / f"blur_kernel.{language}").write_text((SOLUTIONS_DIR / f"blur_kernel.{language}").read_text())
    broken = (SOLUTIONS_DIR / f"convolve.{language}").read_text().replace("return sum;", "return sum + oops;")
    (tmp_path / f"convolve.{language}").write_text(broken)
    line = broken.splitlines().index(next(ln for ln in broken.splitlines() if "oops" in ln)) + 1
    flt = filters.get(backend, _impl_from(tmp_path), keep=False)
    try:
        assert flt.weight_table(2).shape == (5,)  # kernels that do not include convolve.* still build
        with pytest.raises(RuntimeError, match=rf"convolve\.{language}:{line}:"):
            flt.run(scene_like(4, 4), "separable", 1)
    finally:
        flt.release()


# --- mutants: plausible wrong answers, each must fail at least one graded check ----------------------------
_W_GLSL = "float gaussian_weight(int i, int radius) {{\n{body}\n}}\n"
_W_WGSL = "fn gaussian_weight(i: i32, radius: i32) -> f32 {{\n{body}\n}}\n"


def _weights_body(sigma: str, lo: str, hi: str, norm: str, zero_case: bool, language: str) -> str:
    if language == "glsl":
        head = "    if (radius == 0) { return i == 0 ? 1.0 : 0.0; }\n" if zero_case else ""
        return (f"{head}    float sigma = {sigma};\n    float sum = 0.0;\n"
                f"    for (int j = {lo}; j <= {hi}; ++j) {{ sum += exp(-float(j * j) / (2.0 * sigma * sigma)); }}\n"
                f"    return exp(-float(i * i) / (2.0 * sigma * sigma)) / {norm};")
    sigma = sigma.replace("float(", "f32(")
    head = "    if (radius == 0) { return select(0.0, 1.0, i == 0); }\n" if zero_case else ""
    norm = norm.replace("float(", "f32(")
    return (f"{head}    let sigma = {sigma};\n    var sum = 0.0;\n"
            f"    for (var j = {lo}; j <= {hi}; j++) {{ sum += exp(-f32(j * j) / (2.0 * sigma * sigma)); }}\n"
            f"    return exp(-f32(i * i) / (2.0 * sigma * sigma)) / {norm};")


WEIGHT_MUTANTS = {  # name -> (sigma, first tap, last tap, normaliser, radius-0 case)
    "not normalised": ("float(radius) / 2.0", "-radius", "radius", "1.0", True),
    "sigma = radius / 3": ("float(radius) / 3.0", "-radius", "radius", "sum", True),
    "sigma = radius": ("float(radius)", "-radius", "radius", "sum", True),
    "sum misses the last tap": ("float(radius) / 2.0", "-radius", "radius - 1", "sum", True),
    "sum over one tap too many": ("float(radius) / 2.0", "-radius - 1", "radius + 1", "sum", True),
    "continuous normalisation": ("float(radius) / 2.0", "-radius", "radius", "(2.5066283 * sigma)", True),
    "no radius-0 case (NaN)": ("float(radius) / 2.0", "-radius", "radius", "sum", False),
}

CONVOLVE_MUTANTS = {  # name -> (GLSL body, WGSL body) of blur_pass
    "alpha forced to 1": (
        "ivec2 last = image_size() - 1; vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i <= radius; ++i) {\n"
        "        sum += kernel_weight(i) * load_texel(clamp(p + i * dir, ivec2(0), last)); }\n"
        "    return vec4(sum.rgb, 1.0);",
        "let last = image_size() - 1; var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i <= radius; i++) {\n"
        "        sum += kernel_weight(i) * load_texel(clamp(p + i * dir, vec2<i32>(0), last)); }\n"
        "    return vec4<f32>(sum.rgb, 1.0);"),
    "alpha of the centre pixel, not blurred": (
        "ivec2 last = image_size() - 1; vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i <= radius; ++i) {\n"
        "        sum += kernel_weight(i) * load_texel(clamp(p + i * dir, ivec2(0), last)); }\n"
        "    return vec4(sum.rgb, load_texel(p).a);",
        "let last = image_size() - 1; var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i <= radius; i++) {\n"
        "        sum += kernel_weight(i) * load_texel(clamp(p + i * dir, vec2<i32>(0), last)); }\n"
        "    return vec4<f32>(sum.rgb, load_texel(p).a);"),
    "wrap instead of clamp": (
        "ivec2 s = image_size(); vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i <= radius; ++i) {\n"
        "        sum += kernel_weight(i) * load_texel(((p + i * dir) % s + s) % s); }\n"
        "    return sum;",
        "let s = image_size(); var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i <= radius; i++) {\n"
        "        sum += kernel_weight(i) * load_texel(((p + i * dir) % s + s) % s); }\n"
        "    return sum;"),
    "zero padding": (
        "ivec2 s = image_size(); vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i <= radius; ++i) { ivec2 q = p + i * dir;\n"
        "        if (all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, s))) {\n"
        "            sum += kernel_weight(i) * load_texel(q); } }\n"
        "    return sum;",
        "let s = image_size(); var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i <= radius; i++) { let q = p + i * dir;\n"
        "        if (all(q >= vec2<i32>(0)) && all(q < s)) { sum += kernel_weight(i) * load_texel(q); } }\n"
        "    return sum;"),
    "no clamp": (
        "vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i <= radius; ++i) { sum += kernel_weight(i) * load_texel(p + i * dir); }\n"
        "    return sum;",
        "var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i <= radius; i++) { sum += kernel_weight(i) * load_texel(p + i * dir); }\n"
        "    return sum;"),
    "x and y swapped": (
        "ivec2 last = image_size() - 1; vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i <= radius; ++i) {\n"
        "        sum += kernel_weight(i) * load_texel(clamp(p + i * dir.yx, ivec2(0), last)); }\n"
        "    return sum;",
        "let last = image_size() - 1; var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i <= radius; i++) {\n"
        "        sum += kernel_weight(i) * load_texel(clamp(p + i * dir.yx, vec2<i32>(0), last)); }\n"
        "    return sum;"),
    "off-by-one radius": (
        "ivec2 last = image_size() - 1; vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i < radius; ++i) {\n"
        "        sum += kernel_weight(i) * load_texel(clamp(p + i * dir, ivec2(0), last)); }\n"
        "    return sum;",
        "let last = image_size() - 1; var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i < radius; i++) {\n"
        "        sum += kernel_weight(i) * load_texel(clamp(p + i * dir, vec2<i32>(0), last)); }\n"
        "    return sum;"),
    "box blur (weights ignored)": (
        "ivec2 last = image_size() - 1; vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i <= radius; ++i) { sum += load_texel(clamp(p + i * dir, ivec2(0), last)); }\n"
        "    return sum / float(2 * radius + 1);",
        "let last = image_size() - 1; var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i <= radius; i++) { sum += load_texel(clamp(p + i * dir, vec2<i32>(0), last)); }\n"
        "    return sum / f32(2 * radius + 1);"),
    "clamps x only": (
        "ivec2 last = image_size() - 1; vec4 sum = vec4(0.0);\n"
        "    for (int i = -radius; i <= radius; ++i) { ivec2 q = p + i * dir;\n"
        "        sum += kernel_weight(i) * load_texel(ivec2(clamp(q.x, 0, last.x), q.y)); }\n"
        "    return sum;",
        "let last = image_size() - 1; var sum = vec4<f32>(0.0);\n"
        "    for (var i = -radius; i <= radius; i++) { let q = p + i * dir;\n"
        "        sum += kernel_weight(i) * load_texel(vec2<i32>(clamp(q.x, 0, last.x), q.y)); }\n"
        "    return sum;"),
}
_C_GLSL = "vec4 blur_pass(ivec2 p, ivec2 dir, int radius) {{\n    {body}\n}}\n"
_C_WGSL = "fn blur_pass(p: vec2<i32>, dir: vec2<i32>, radius: i32) -> vec4<f32> {{\n    {body}\n}}\n"


def _mutant_folder(tmp_path: Path, exercise: str, mutant: str, language: str) -> Path:
    other = "convolve" if exercise == "blur_kernel" else "blur_kernel"
    (tmp_path / f"{other}.{language}").write_text((SOLUTIONS_DIR / f"{other}.{language}").read_text())
    if exercise == "blur_kernel":
        template = _W_GLSL if language == "glsl" else _W_WGSL
        text = template.format(body=_weights_body(*WEIGHT_MUTANTS[mutant], language))
    else:
        template = _C_GLSL if language == "glsl" else _C_WGSL
        text = template.format(body=CONVOLVE_MUTANTS[mutant][0 if language == "glsl" else 1])
    (tmp_path / f"{exercise}.{language}").write_text(text)
    return tmp_path


@pytest.mark.parametrize("backend_name", ["opengl", "webgpu"])
@pytest.mark.parametrize(("exercise", "mutant"), [("blur_kernel", m) for m in WEIGHT_MUTANTS]
                         + [("convolve", m) for m in CONVOLVE_MUTANTS])
def test_every_mutant_fails_a_graded_check(filters, tmp_path, exercise, mutant, backend_name):
    folder = _mutant_folder(tmp_path, exercise, mutant, LANGUAGE[backend_name])
    flt = filters.get(backend_name, _impl_from(folder), keep=False)
    try:
        for check in CHECKS[exercise].values():
            if check(flt) is not None:
                return
    finally:
        flt.release()
    pytest.fail(f"mutant '{mutant}' of {exercise} ({LANGUAGE[backend_name]}) passes every check: "
                f"{list(CHECKS[exercise])}")


if __name__ == "__main__":  # pragma: no cover
    sys.exit(pytest.main([__file__, "-q"]))
