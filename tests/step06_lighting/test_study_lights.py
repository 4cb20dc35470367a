"""The light-count study (``step06_lighting.lights.study_lights``) measures what it claims: not graded.

At 96×72, keeping more of the strongest lights must bring the picture closer to the one with all 64, in both APIs,
and keeping all of them must reproduce it exactly.
"""

from __future__ import annotations

import pytest
from cli_checks import check_help_only_prints_help, run_study

from step06_lighting.lights import study_lights as study

SIZE = (96, 72)


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_error_falls_as_more_lights_are_kept(backend):
    lights = study.light_set()
    reference, _ = study.measure(backend, study.TOTAL, lights, SIZE, 1, 1)
    errors = [study.picture_error(study.measure(backend, n, lights, SIZE, 1, 1)[0], reference)[0] for n in (2, 16, 64)]
    assert errors[0] > 2 * errors[1] > 0.0, f"mean 8-bit error keeping 2, 16, 64 lights: {errors}"
    assert errors[2] == 0.0, errors


def test_lights_are_sorted_strongest_first():
    intensities = [light["intensity"] for light in study.light_set()]
    assert len(intensities) == study.TOTAL and intensities == sorted(intensities, reverse=True)


def test_main_writes_json_table_and_plot(tmp_path):
    args = ["--out", str(tmp_path), "--quick", "--backends", "opengl", "--size", "64", "48", "--frames", "1",
            "--repeats", "1"]
    result, table = run_study(study.main, args, tmp_path, study.STEM)
    assert [r["lights"] for r in result["rows"]] == list(study.QUICK_COUNTS)
    assert "| API |" in table


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    check_help_only_prints_help(study.main, tmp_path, capsys, monkeypatch)
