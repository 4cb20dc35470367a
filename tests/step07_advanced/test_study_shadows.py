"""The shadow-mapping study (``step07_advanced.showcase.study_shadows``) measures what it claims: not graded.

At 96×72, both APIs, against the ray-traced shadow: the default knobs (2048² map, 3×3 taps, bias 1) get the lit
state right to within 10 % of the shadow's area; a 256² map does worse; bias 0 covers the floor with acne (false
shadow larger than the shadow itself) and bias 32 detaches the shadows (missing shadow). The map-size override is
undone afterwards.
"""

from __future__ import annotations

import pytest
from cli_checks import check_help_only_prints_help, run_study

from step07_advanced.showcase import study_shadows as study

SIZE = (96, 72)


@pytest.fixture(scope="module")
def truth():
    return study.reference(SIZE)


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_each_knob_moves_the_error_the_way_it_should(backend, truth):
    def err(**knobs):
        picture, _ = study.measure(backend, {**study.DEFAULTS, **knobs}, SIZE, 1, 1)
        return study.errors(picture, *truth)

    default = err()
    assert default["wrong_share"] < 0.10, default
    assert err(map_size=256)["wrong_share"] > 1.5 * default["wrong_share"]
    assert err(bias=0.0)["false_shadow_share"] > 1.0
    assert err(bias=32.0)["missing_shadow_share"] > 2 * default["missing_shadow_share"] + 0.02


def test_the_map_size_override_is_undone():
    import gandalf_core.render.opengl.renderer as gl_renderer
    from gandalf_core.resources.blocks import SHADOW_MAP_SIZE

    with study.shadow_map_size(256):
        assert gl_renderer.SHADOW_MAP_SIZE == 256
    assert gl_renderer.SHADOW_MAP_SIZE == SHADOW_MAP_SIZE


def test_the_reference_shadow_lies_beside_the_casters(truth):
    shadowed, floor = truth
    assert 0.01 < shadowed[floor].mean() < 0.2 and floor.mean() > 0.8


def test_main_writes_json_table_and_plot(tmp_path):
    args = ["--out", str(tmp_path), "--quick", "--backends", "opengl", "--size", "64", "48", "--frames", "1",
            "--repeats", "1"]
    result, table = run_study(study.main, args, tmp_path, study.STEM)
    assert len(result["rows"]) == len(study.cases(study.QUICK_SWEEPS))
    assert "| API |" in table


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    check_help_only_prints_help(study.main, tmp_path, capsys, monkeypatch)
