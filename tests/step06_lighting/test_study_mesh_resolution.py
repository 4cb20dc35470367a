"""The mesh-resolution study (``step06_lighting.meshes.study_mesh_resolution``) measures what it claims: not graded.

On a 96×72 picture, a finer ``uv_sphere`` must come closer to the ray-traced exact sphere in both APIs: the
silhouette error falls (and stays near the inscribed polygon's bound), and so does the shading error.
"""

from __future__ import annotations

import pytest
from cli_checks import check_help_only_prints_help, run_study

from gandalf_core.resources import uv_sphere
from step06_lighting.meshes import study_mesh_resolution as study

SIZE = (96, 72)


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_errors_fall_as_the_sphere_gets_finer(backend):
    expected, hit = study.reference(SIZE)
    coarse, fine = (study.errors(study.render(backend, uv_sphere(1.0, s, r), SIZE), expected, hit)
                    for s, r in ((8, 4), (64, 32)))
    assert coarse["silhouette_px"] > 4 * fine["silhouette_px"], (coarse, fine)
    assert fine["silhouette_px"] < 0.3, fine
    assert coarse["shading_8bit"] > 4 * fine["shading_8bit"], (coarse, fine)
    assert fine["shading_8bit"] < 1.0, f"a 64x32 sphere should shade within 1 8-bit step on average: {fine}"


def test_main_writes_json_table_and_plot(tmp_path):
    args = ["--out", str(tmp_path), "--quick", "--backends", "opengl", "--size", "64", "48", "--instances", "1",
            "--frames", "1", "--repeats", "1"]
    result, table = run_study(study.main, args, tmp_path, study.STEM)
    assert [r["triangles"] for r in result["rows"]] == [uv_sphere(1.0, s, r).triangle_count
                                                       for s, r in study.QUICK_SPHERES]
    assert "| API |" in table


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    check_help_only_prints_help(study.main, tmp_path, capsys, monkeypatch)
