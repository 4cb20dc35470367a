"""FixedStep: run a simulation at a fixed time step whatever the frame times are.

Frames arrive at irregular intervals (a window is dragged, the machine is busy); a physics integrator is
only stable and repeatable at a fixed ``dt``. The accumulator pattern turns each frame's time into a whole
number of fixed steps and keeps the remainder for the next frame:

* a frame time above ``max_frame_time`` is clamped (a two-second stall must not fire 240 steps at once);
* at most ``max_steps`` steps run per frame; time beyond that is dropped (counted in ``dropped`` and reported
  once with a warning, never silently) so a slow simulation cannot fall further and further behind (the
  "spiral of death");
* ``alpha`` (in [0, 1)) tells how far the frame lies between the last two simulated states, so a renderer
  can interpolate ``previous + alpha * (current - previous)`` and motion looks smooth at any frame rate.
"""

from __future__ import annotations

import math
import warnings

# Frame times are sums of floats: 1/60 seconds at dt = 1/120 must give 2 steps even when rounding makes the
# ratio 1.9999999999999998.
_EPSILON = 1e-9


class FixedStep:
    """Consumes frame times; ``advance(ts)`` returns how many fixed steps of ``dt`` to run now."""

    def __init__(self, dt: float = 1.0 / 120.0, max_frame_time: float = 0.25, max_steps: int = 8) -> None:
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"FixedStep.dt must be a positive number of seconds, got {dt!r}")
        if not (math.isfinite(max_frame_time) and max_frame_time >= dt):
            raise ValueError(f"FixedStep.max_frame_time must be at least dt ({dt}), got {max_frame_time!r}")
        if int(max_steps) != max_steps or max_steps < 1:
            raise ValueError(f"FixedStep.max_steps must be an integer >= 1, got {max_steps!r}")
        self.dt = float(dt)
        self.max_frame_time = float(max_frame_time)
        self.max_steps = int(max_steps)
        self.accumulator = 0.0
        self.steps = 0  # fixed steps run so far
        self.dropped = 0.0  # seconds of frame time thrown away by the clamps

    # --8<-- [start:advance]
    def advance(self, frame_ts: float) -> int:
        """Add one frame's time (seconds) and return the number of fixed steps to run for it."""
        if not (math.isfinite(frame_ts) and frame_ts >= 0.0):
            raise ValueError(f"FixedStep.advance: frame time must be a finite number >= 0, "
                             f"got {frame_ts!r}")
        dropped_before = self.dropped
        if frame_ts > self.max_frame_time:
            self.dropped += frame_ts - self.max_frame_time
            frame_ts = self.max_frame_time
        self.accumulator += frame_ts
        n = math.floor(self.accumulator / self.dt + _EPSILON)
        self.accumulator = max(self.accumulator - n * self.dt, 0.0)  # the remainder, below one step
        if n > self.max_steps:
            self.dropped += (n - self.max_steps) * self.dt
            n = self.max_steps
        if self.dropped > dropped_before and dropped_before == 0.0:
            warnings.warn(f"FixedStep: {self.dropped:.3f} s of simulated time dropped (frames "
                          f"longer than {self.max_frame_time} s or more than {self.max_steps} "
                          f"steps of {self.dt} s); FixedStep.dropped adds it up", stacklevel=2)
        self.steps += n
        return n
    # --8<-- [end:advance]

    @property
    def alpha(self) -> float:
        """How far (0..1) the present lies between the previous and the current simulated state."""
        return min(self.accumulator / self.dt, 1.0)
