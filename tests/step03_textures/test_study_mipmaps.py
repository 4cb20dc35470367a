"""The mipmap study (``step03_textures.study_mipmaps``) measures what it claims: not graded.

At 96×72 against a 4×4-ray box-filtered reference, both APIs: trilinear filtering must beat plain nearest sampling
on the minified (far) half of the floor by a wide margin, and mipmaps must help nearest sampling there too.
"""

from __future__ import annotations

import pytest
from cli_checks import check_help_only_prints_help, run_study

from step03_textures import study_mipmaps as study

SIZE = (96, 72)


@pytest.fixture(scope="module")
def expected():
    return study.reference(SIZE, 4)


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_mipmaps_bring_the_far_floor_close_to_the_box_filtered_reference(backend, expected):
    far = {name: study.errors(study.measure(backend, name, SIZE, 1, 1)[0], expected)["far_error"]
           for name in ("nearest", "nearest + mipmaps", "trilinear (linear + mipmaps)", "anisotropic 16x")}
    assert far["nearest"] > 1.5 * far["nearest + mipmaps"] > 1.5 * far["trilinear (linear + mipmaps)"], far
    assert far["trilinear (linear + mipmaps)"] < 25.0, far
    # Anisotropic filtering is on in both APIs (not silently ignored): it changes the minified far floor.
    assert abs(far["anisotropic 16x"] - far["trilinear (linear + mipmaps)"]) > 0.1, far


def test_the_reference_is_the_texture_where_a_pixel_covers_few_texels():
    # Near the camera (bottom rows) a pixel covers about one check: the reference shows both check colours.
    near = study.reference((32, 24), 2)[-2:]
    assert near.min() < 100 and near.max() > 200, near


def test_main_writes_json_table_and_plot(tmp_path):
    args = ["--out", str(tmp_path), "--quick", "--backends", "opengl", "--size", "32", "24", "--ss", "2",
            "--frames", "1", "--repeats", "1"]
    result, table = run_study(study.main, args, tmp_path, study.STEM)
    assert [r["sampler"] for r in result["rows"]] == list(study.SAMPLERS)
    assert "| API |" in table


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    check_help_only_prints_help(study.main, tmp_path, capsys, monkeypatch)
