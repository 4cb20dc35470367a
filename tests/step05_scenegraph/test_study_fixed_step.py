"""The fixed-step study (``step05_scenegraph.integrators.study_fixed_step``) measures what it claims (not graded)."""

from __future__ import annotations

from cli_checks import check_help_only_prints_help, run_study

from step05_scenegraph.integrators import study_fixed_step as study


def test_error_falls_with_the_step_when_no_time_is_dropped():
    frames = study.frame_times(1.0)
    errors = [study.run_case(dt, 64, frames)[0] for dt in (1 / 30, 1 / 60, 1 / 120)]
    assert errors[0] > errors[1] > errors[2] > 0.0, f"errors for dt 1/30, 1/60, 1/120: {errors}"
    # Semi-implicit Euler plus one step of interpolation lag: about |v| dt + |g| dt t / 2, so halving dt halves it.
    assert 1.6 < errors[0] / errors[1] < 2.4 and 1.6 < errors[1] / errors[2] < 2.4, errors


def test_a_small_max_steps_drops_time_and_costs_accuracy():
    frames = study.frame_times(1.0)
    enough, dropped_none = study.run_case(1 / 120, 64, frames)
    starved, dropped = study.run_case(1 / 120, 2, frames)
    assert dropped_none == 0.0 and dropped > 0.05, (dropped_none, dropped)
    assert starved > 5 * enough, f"error with max_steps 2: {starved:.3f} m, with 64: {enough:.3f} m"


def test_main_writes_json_table_and_plot(tmp_path, capsys):
    result, table = run_study(study.main, ["--out", str(tmp_path), "--quick", "--repeats", "1"], tmp_path, study.STEM)
    assert len(result["rows"]) == len(study.QUICK_DTS) * len(study.QUICK_MAX_STEPS)
    assert table.startswith("| max_steps |")
    assert "fixed-step study" in capsys.readouterr().out


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    check_help_only_prints_help(study.main, tmp_path, capsys, monkeypatch)
