"""Tests for the app's input state (fed with synthetic events, as a window would) and the frame clock."""

from __future__ import annotations

import types

import pytest

from gandalf_core.app import Clock, Input, KeyEvent, MouseButtonEvent, MouseMoveEvent, ResizeEvent, ScrollEvent
from gandalf_core.app import clock as clock_module

# ---------------------------------------------------------------------------------------------
# Input


def test_keys_are_down_until_released_and_pressed_only_in_their_frame() -> None:
    inp = Input()
    inp.key("w")
    assert not inp.is_down("W")  # queued events take effect at the next frame boundary
    inp.begin_frame()
    assert inp.is_down("W") and inp.is_down("w")
    assert inp.pressed("w")
    inp.begin_frame()
    assert inp.is_down("W") and not inp.pressed("W")
    inp.key("W", "repeat")
    inp.begin_frame()
    assert inp.is_down("W") and not inp.pressed("W")  # a repeat is not a new press
    inp.key("w", "release")
    inp.begin_frame()
    assert not inp.is_down("W") and not inp.pressed("W")


def test_press_and_release_in_one_frame_counts_as_pressed_but_not_down() -> None:
    inp = Input()
    inp.key("space")
    inp.key("space", "release")
    events = inp.begin_frame()
    assert events == [KeyEvent("SPACE", "press"), KeyEvent("SPACE", "release")]
    assert inp.pressed("SPACE") and not inp.is_down("SPACE")


def test_several_keys_are_tracked_independently() -> None:
    inp = Input()
    inp.key("A")
    inp.key("D")
    inp.begin_frame()
    inp.key("A", "release")
    inp.begin_frame()
    assert not inp.is_down("A") and inp.is_down("D")
    assert inp.keys_down == {"D"}


def test_mouse_delta_sums_the_moves_of_the_frame() -> None:
    inp = Input()
    inp.move_mouse(10, 20)
    inp.move_mouse(15, 18)
    inp.begin_frame()
    assert inp.mouse_position == (15.0, 18.0)
    assert inp.mouse_delta() == (15.0, 18.0)  # from the start position (0, 0)
    inp.move_mouse(5, 28)
    inp.begin_frame()
    assert inp.mouse_delta() == (-10.0, 10.0)
    inp.begin_frame()
    assert inp.mouse_delta() == (0.0, 0.0)
    assert inp.mouse_position == (5.0, 28.0)


def test_mouse_buttons_scroll_and_resize_events() -> None:
    inp = Input()
    inp.button(0)
    inp.button(1)
    inp.scroll(0, 1.5)
    inp.scroll(0.5, -0.5)
    inp.resize(800, 600)
    events = inp.begin_frame()
    assert inp.buttons_down == {0, 1}
    assert inp.scroll_delta() == 1.0
    assert ResizeEvent(800, 600) in events
    assert [type(e) for e in events] == [MouseButtonEvent, MouseButtonEvent, ScrollEvent, ScrollEvent, ResizeEvent]
    inp.button(0, "release")
    inp.begin_frame()
    assert inp.buttons_down == {1}
    assert inp.scroll_delta() == 0.0
    assert not any(isinstance(e, ResizeEvent) for e in inp.events)


def test_events_are_typed_values() -> None:
    inp = Input()
    inp.move_mouse(3, 4)
    (event,) = inp.begin_frame()
    assert event == MouseMoveEvent(3.0, 4.0, 3.0, 4.0)


def test_invalid_actions_are_rejected_with_the_action_named() -> None:
    inp = Input()
    with pytest.raises(ValueError, match=r"key action must be .* got 'hold'"):
        inp.key("W", "hold")
    with pytest.raises(ValueError, match=r"mouse button action must be .* got 'repeat'"):
        inp.button(0, "repeat")
    assert inp.begin_frame() == []


# ---------------------------------------------------------------------------------------------
# Clock


@pytest.fixture
def fake_time(monkeypatch: pytest.MonkeyPatch) -> list[float]:
    """Replace the clock's time source with a value the test sets (seconds)."""
    now = [1000.0]
    monkeypatch.setattr(clock_module, "time", types.SimpleNamespace(perf_counter=lambda: now[0]))
    return now


def test_fixed_dt_advances_exactly(fake_time: list[float]) -> None:
    clock = Clock(fixed_dt=1 / 60)
    for _ in range(60):
        fake_time[0] += 5.0  # real time is ignored with a fixed step
        assert clock.tick() == 1 / 60
    assert clock.frame == 60
    assert clock.time == pytest.approx(1.0, abs=1e-12)


def test_first_frame_does_not_count_start_up_time(fake_time: list[float]) -> None:
    clock = Clock()
    fake_time[0] += 3.0  # loading assets, compiling shaders
    assert clock.tick() == Clock.FIRST_DT


def test_real_frame_time_is_measured(fake_time: list[float]) -> None:
    clock = Clock()
    clock.tick()
    fake_time[0] += 0.016
    assert clock.tick() == pytest.approx(0.016, abs=1e-9)
    fake_time[0] += 0.040
    assert clock.tick() == pytest.approx(0.040, abs=1e-9)
    assert clock.time == pytest.approx(Clock.FIRST_DT + 0.056, abs=1e-9) and clock.frame == 3


def test_huge_real_frame_times_are_clamped(fake_time: list[float]) -> None:
    clock = Clock()
    clock.tick()
    fake_time[0] += 30.0  # a breakpoint or a dragged window
    with pytest.warns(UserWarning, match="clamped to 0.250 s"):
        assert clock.tick() == Clock.MAX_DT
    assert clock.dropped == pytest.approx(30.0 - Clock.MAX_DT)
    fake_time[0] += 0.01
    assert clock.tick() == pytest.approx(0.01, abs=1e-9)  # the next frame measures from the stall's end
    assert clock.time == pytest.approx(Clock.FIRST_DT + Clock.MAX_DT + 0.01, abs=1e-9)


def test_every_step_sees_the_same_clamp(fake_time: list[float]) -> None:
    """app.step(1.0) gets the same clamp as a measured stall; the cut-off time is counted, and reported once."""
    clock = Clock(fixed_dt=1 / 60)
    with pytest.warns(UserWarning, match="Clock.dropped"):
        assert clock.tick(1.0) == Clock.MAX_DT
    assert clock.tick(2.0) == Clock.MAX_DT  # reported once: no second warning
    assert clock.dropped == pytest.approx(0.75 + 1.75)
    assert clock.time == pytest.approx(2 * Clock.MAX_DT)
    assert Clock(fixed_dt=0.5).max_dt == 0.5  # a chosen large fixed step is the limit itself


def test_explicit_dt_and_negative_dt(fake_time: list[float]) -> None:
    clock = Clock(fixed_dt=0.5)
    assert clock.tick(0.1) == 0.1  # an explicit step wins over the fixed one
    assert clock.tick(0.0) == 0.0
    with pytest.raises(ValueError, match=r"dt cannot be negative, got -0.01"):
        clock.tick(-0.01)
    assert clock.frame == 2 and clock.time == pytest.approx(0.1)


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan")])
def test_fixed_dt_must_be_positive(bad: float) -> None:
    with pytest.raises(ValueError, match="fixed_dt must be positive seconds"):
        Clock(fixed_dt=bad)


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -1.0])
def test_clock_rejects_non_finite_or_negative_steps(bad):
    from gandalf_core.app.clock import Clock

    with pytest.raises(ValueError, match="dt"):
        Clock().tick(bad)
    if bad != -1.0:
        with pytest.raises(ValueError, match="fixed_dt"):
            Clock(fixed_dt=bad)
