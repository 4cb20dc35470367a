"""The particle time-step study (``step07_advanced.showcase.study_particles``): not graded.

The error of the numpy twin and of the OpenGL and WebGPU kernels (reference solution) against the exact projectile
must follow semi-implicit Euler's ``|g| dt t / 2`` within 5 %, and fall as the step shrinks.
"""

from __future__ import annotations

import pytest
from cli_checks import check_help_only_prints_help, run_study

from step07_advanced.showcase import study_particles as study


@pytest.mark.parametrize("backend", study.BACKENDS)
def test_error_follows_the_euler_bound_and_falls_with_the_step(backend):
    state = study.launch_state(64)
    runner = study.open_runner(backend, state)
    try:
        rows = [study.measure(runner, state, dt, 1.0, repeats=1) for dt in (1 / 15, 1 / 60)]
    finally:
        runner.release()
    for row in rows:
        assert row["max_error_m"] == pytest.approx(row["predicted_error_m"], rel=0.05), row
    assert rows[0]["max_error_m"] > 3.5 * rows[1]["max_error_m"], rows


def test_main_writes_json_table_and_plot(tmp_path):
    args = ["--out", str(tmp_path), "--quick", "--backends", "numpy", "--particles", "16", "--repeats", "1"]
    result, table = run_study(study.main, args, tmp_path, study.STEM)
    assert [r["backend"] for r in result["rows"]] == ["numpy"] * len(study.QUICK_DTS)
    assert "| backend |" in table


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    check_help_only_prints_help(study.main, tmp_path, capsys, monkeypatch)
