"""The parallax strips rendered in both APIs, and the technique's engine-side rules.

Graded per API (exercise ``parallax``), at 128×96, on the study's view (all four strips read by one method): each
of the student's three functions must move the picture away from plain normal mapping (RMSE ≥ 4 8-bit steps; the
solution measures about 11), and parallax occlusion mapping must converge faster with layers than steep parallax
(RMSE of 8 against 64 layers below half of steep's; the solution measures about 0.2 against 1.6).
Not graded: the two APIs agree on the tour picture at 640×480 (PSNR ≥ 35 dB; measured 74 dB: 0.6 % of the
pixels differ, by at most 4 8-bit steps), with height_scale 0 every method draws the normal-mapped picture
exactly, bad parameters get a ResourceError naming the material and the parameter, the study's numpy camera sees
exactly the pixels the strips are drawn on (≥ 99.5 %; measured 100 % in both APIs at 128×96), and the study runs
(``--quick`` at 64×48).
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest
from step07_helpers import check_tour_pictures_agree

from gandalf_core import Application
from gandalf_core.resources import ResourceError
from gandalf_tools.grading.shader_box import on_shader_box
from step07_advanced.parallax import scene as parallax
from step07_advanced.parallax.reference import MAX_LAYERS

SIZE = (128, 96)
MIN_MOVE = 4.0


@on_shader_box  # the student's shaders run in the grader's shader process
def render(backend: str, impl, configs: list[tuple], size=SIZE) -> list[np.ndarray]:
    """The study's view with every strip read by one method, per ``(method, layers, height_scale)`` config, as
    float64 RGB pictures (one app, one scene per config)."""
    pictures = []
    with Application(backend, *size, headless=True, fixed_dt=1 / 60) as app:
        importlib.import_module(f"step07_advanced.parallax.{backend}").register_shaders(app, impl)
        for method, *rest in configs:
            layers = rest[0] if rest else parallax.LAYERS
            height_scale = rest[1] if len(rest) > 1 else parallax.HEIGHT_SCALE
            scene = app.add_scene(parallax.study_scene(method, layers, height_scale))
            app.switch_scene(scene)
            app.run(frames=1)
            pictures.append(app.capture()[..., :3].astype(np.float64))
    return pictures


def rmse(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.sqrt(np.mean((a - b) ** 2)))


@pytest.mark.exercise("parallax")
def test_each_method_moves_the_picture(impl, backend):
    methods = {"offset": "parallax_offset", "steep": "parallax_steep", "occlusion": "parallax_occlusion"}
    flat, *pictures = render(backend, impl, [("normal",), *((m,) for m in methods)])
    for (method, function), picture in zip(methods.items(), pictures, strict=True):
        moved = rmse(picture, flat)
        assert moved >= MIN_MOVE, (
            f"{backend}: the {parallax.LABELS[method]} strips differ from plain normal mapping by RMSE {moved:.2f} "
            f"8-bit steps; expected ≥ {MIN_MOVE} (about 11). Hint: {function} must move uv against view_ts.xy")


@pytest.mark.exercise("parallax")
def test_occlusion_converges_faster_than_steep(impl, backend):
    s8, s64, o8, o64 = render(backend, impl, [("steep", 8), ("steep", 64), ("occlusion", 8), ("occlusion", 64)])
    errors = {"steep": rmse(s8, s64), "occlusion": rmse(o8, o64)}
    assert 0.0 < errors["occlusion"] < 0.5 * errors["steep"], (
        f"{backend}: RMSE of 8 against 64 layers: steep {errors['steep']:.3f}, occlusion {errors['occlusion']:.3f} "
        f"8-bit steps; expected occlusion > 0 and below half of steep's (about 0.2 against 1.6). Hint: interpolate "
        f"between the last layer above the surface and the first one below it")


def test_both_apis_agree_on_the_tour_picture(impl):
    """The tour's picture (TOUR_FRAMES, 640×480) from both variant files."""
    check_tour_pictures_agree("parallax", impl, parallax.TOUR_FRAMES)


@pytest.mark.parametrize("backend_name", ["opengl", "webgpu"])
def test_no_depth_draws_plain_normal_mapping(impl, backend_name):
    methods = ("offset", "steep", "occlusion")
    flat, *pictures = render(backend_name, impl, [(m, 16, 0.0) for m in ("normal", *methods)], size=(64, 48))
    for method, picture in zip(methods, pictures, strict=True):
        assert rmse(picture, flat) == 0.0, method


@pytest.mark.parametrize(("key", "kwargs"), [
    ("layers", {"layers": 0}), ("layers", {"layers": -3}), ("layers", {"layers": MAX_LAYERS + 1}),
    ("layers", {"layers": 2.5}), ("layers", {"layers": True}), ("height_scale", {"height_scale": -0.01}),
    ("height_scale", {"height_scale": float("nan")}), ("height_scale", {"height_scale": "deep"}),
])
def test_bad_parameters_are_refused_naming_material_and_parameter(key, kwargs):
    with pytest.raises(ResourceError, match=key) as info:
        parallax.parallax_material("occlusion", name="wall", **kwargs)
    assert "material 'wall'" in str(info.value)


def test_unknown_method_is_refused():
    with pytest.raises(ResourceError, match="method"):
        parallax.parallax_material("relief", name="wall")


def test_the_limits_are_accepted():
    for layers in (1, MAX_LAYERS):
        material = parallax.parallax_material("steep", 0.0, layers)
        assert material.params["layers"] == float(layers)
        assert material.params["height_scale"] == 0.0


def test_the_study_rays_see_the_rendered_strips(impl):
    """The study's numpy camera (for the uv error) covers the very pixels the engine draws the strips on."""
    from step07_advanced.parallax.study import pixel_rays

    picture = render("opengl", impl, [("normal",)], size=(128, 96))[0]
    background = np.array(picture[0, 0])
    drawn = np.abs(picture - background).max(axis=-1) > 0
    mask = pixel_rays(128, 96)["mask"]
    agree = float(np.mean(drawn == mask))
    assert agree >= 0.995, f"the study's rays and the rendered strips agree on {agree:.1%} of the pixels"


def test_the_study_runs_and_writes_its_files(tmp_path, capsys):
    from step07_advanced.parallax import study

    with pytest.raises(SystemExit) as info:
        study.main(["--help"])
    assert info.value.code == 0
    assert not list(tmp_path.iterdir())
    assert study.main(["--out", str(tmp_path), "--quick", "--size", "64x48", "--frames", "1", "--repeats", "1",
                       "--backends", "opengl"]) == 0
    for suffix in ("json", "md", "png"):
        assert (tmp_path / f"parallax_study.{suffix}").stat().st_size > 0
    assert "parallax occlusion" in capsys.readouterr().out
