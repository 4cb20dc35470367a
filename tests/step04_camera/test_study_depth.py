"""The depth-precision study (``step04_camera.study_depth``) measures what it claims: not graded.

Both APIs, float32 depth: far from the camera (d = 1000, near 0.1, far 1e4) reverse-Z must separate planes at
least 100 times closer than the standard mapping, and each measured separation must lie within a factor 8 of the
float32 bound (one depth-buffer step, or one float32 step of d). At s = 0 the two planes must tie (green shows).
Where the depth passes through OpenGL's clip range on its way to the buffer (wgpu's OpenGL backend), the bound
says reverse-Z gains nothing (a factor 2 at d = 1000), and the measurement must show no real gain (less than 10).
"""

from __future__ import annotations

import numpy as np
import pytest
from cli_checks import check_help_only_prints_help, run_study

from step04_camera import study_depth as study


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_reverse_z_beats_standard_far_away_and_both_follow_the_bound(backend):
    d = 1000.0
    measured = {}
    for reverse_z in (False, True):
        rig = study.DepthRig(backend, 0.1, 1e4, reverse_z)
        try:
            assert rig.fights(d, 0.0), "identical planes must tie, and the later one show"
            measured[reverse_z] = study.smallest_separation(rig, d, 1e4, 1.0)
            through_gl_range = rig.through_gl_range
        finally:
            rig.close()
        b = study.bound(np.array([d]), 0.1, 1e4, reverse_z, through_gl_range)[0]
        assert measured[reverse_z] is not None and b / 8 < measured[reverse_z] < 8 * b, (reverse_z, measured, b)
    if through_gl_range:
        assert measured[False] < 10 * measured[True], measured
    else:
        assert measured[False] > 100 * measured[True], measured


def test_through_opengls_clip_range_reverse_z_keeps_only_the_precision_near_1():
    # z = 1e-4 (reverse-Z at d = 1000): its own float32 step is ~7e-12, but 2z - 1 = -0.9998 has steps of 6e-8.
    d = np.array([1000.0])
    native, through = (study.bound(d, 0.1, 1e4, True, gl)[0] for gl in (False, True))
    standard = study.bound(d, 0.1, 1e4, False, True)[0]
    assert through > 1000 * native and standard / 4 < through < standard, (native, through, standard)


def test_the_bound_grows_as_d_squared_for_standard_and_as_d_for_reverse_z():
    d = np.array([100.0, 1000.0])
    standard = study.bound(d, 0.1, 1e4, False)
    reverse = study.bound(d, 0.1, 1e4, True)
    assert 30 < standard[1] / standard[0] < 300 and 3 < reverse[1] / reverse[0] < 30, (standard, reverse)


def test_main_writes_json_table_and_plot(tmp_path):
    args = ["--out", str(tmp_path), "--quick", "--backends", "opengl", "--resolution", "4", "--frames", "1",
            "--repeats", "1"]
    result, table = run_study(study.main, args, tmp_path, study.STEM)
    assert {r["mapping"] for r in result["rows"]} == {m[0] for m in study.QUICK_MAPPINGS}
    assert "float32 bound" in table


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    check_help_only_prints_help(study.main, tmp_path, capsys, monkeypatch)
