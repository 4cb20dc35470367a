"""The house's component: how fast it turns and whether it is paused (the exercise's system turns it)."""

from __future__ import annotations

from gandalf_core import Component


class HouseRotationComponent(Component):
    """The house turns about its y-axis at ``speed`` degrees per second; ``pause_key`` toggles ``paused``."""

    def __init__(self, speed: float = 45.0, angle: float = 0.0, paused: bool = False, pause_key: str = "P") -> None:
        self.speed = float(speed)
        self.angle = float(angle)  # degrees turned so far
        self.paused = bool(paused)
        self.pause_key = pause_key.upper()

# Saved in USD scenes by name (the loader only builds classes registered like this).
