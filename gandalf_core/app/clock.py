"""The frame clock: real time in a window, a fixed step when asked (deterministic tests and captures).

The time-step policy, one for every system: each frame's step (measured, fixed, or given to ``app.step(dt)``) is
at most :attr:`Clock.max_dt` (0.25 s, or ``fixed_dt`` when that is larger), so a stall cannot hand a
physics system a step it explodes on. What a clamp cuts off is added to :attr:`Clock.dropped` and reported once
with a warning: simulated time is never lost silently.
"""

from __future__ import annotations

import math
import numbers
import time
import warnings


class Clock:
    """Measures frame times. ``fixed_dt`` makes every frame advance by exactly that many seconds."""

    #: Frame times are clamped to this, so a stall (a breakpoint, a dragged window) can't explode physics.
    MAX_DT = 0.25
    #: The first frame's step in real time: a nominal 60 Hz frame.
    FIRST_DT = 1 / 60

    def __init__(self, fixed_dt: float | None = None) -> None:
        if fixed_dt is not None and not (_is_number(fixed_dt) and math.isfinite(fixed_dt) and fixed_dt > 0):
            raise ValueError(f"fixed_dt must be positive seconds (and finite), got {fixed_dt!r}")
        self.fixed_dt = fixed_dt
        #: The largest step any system sees in one frame.
        self.max_dt = max(self.MAX_DT, fixed_dt or 0.0)
        #: Seconds of frame time the clamp has cut off so far.
        self.dropped = 0.0
        self.time = 0.0  # simulated seconds since start
        self.frame = 0
        self._last = time.perf_counter()

    def restart(self) -> None:
        """Start measuring the next frame from now (so time spent before a loop starts is not a frame)."""
        self._last = time.perf_counter()

    def tick(self, dt: float | None = None) -> float:
        """Advance one frame and return its time step in seconds."""
        now = time.perf_counter()
        if dt is None:
            if self.fixed_dt is not None:
                dt = self.fixed_dt
            elif self.frame == 0:
                dt = self.FIRST_DT  # the time since start-up (loading, compiling) is not a frame
            else:
                dt = now - self._last
        elif not _is_number(dt):
            raise TypeError(f"a frame's dt must be a number of seconds, got {dt!r}")
        elif not math.isfinite(dt):
            raise ValueError(f"a frame's dt must be finite, got {dt!r}")
        elif dt < 0:
            raise ValueError(f"a frame's dt cannot be negative, got {dt!r}")
        if dt > self.max_dt:
            if self.dropped == 0.0:
                warnings.warn(f"a frame of {dt:.3f} s is clamped to {self.max_dt:.3f} s, so no system gets a step "
                              "it cannot handle; Clock.dropped adds up the time cut off", stacklevel=3)
            self.dropped += dt - self.max_dt
            dt = self.max_dt
        self._last = now
        self.time += dt
        self.frame += 1
        return dt


def _is_number(value: object) -> bool:
    """A real number of seconds (a numpy scalar too), not a string or a boolean."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)
