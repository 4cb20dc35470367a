"""Input: key, mouse and resize events from a window, or fed synthetically in headless tests.

Systems read the current state (``input.is_down("W")``, ``input.mouse_position``) or this frame's
events (``input.events``). Keys are named by glfw's names without the prefix: "W", "SPACE", "ESCAPE".
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class KeyEvent:
    key: str
    action: str  # "press" | "release" | "repeat"


@dataclass(frozen=True)
class MouseMoveEvent:
    x: float
    y: float
    dx: float
    dy: float


@dataclass(frozen=True)
class MouseButtonEvent:
    button: int  # 0 left, 1 right, 2 middle
    action: str  # "press" | "release"


@dataclass(frozen=True)
class ScrollEvent:
    dx: float
    dy: float


@dataclass(frozen=True)
class ResizeEvent:
    width: int
    height: int


Event = KeyEvent | MouseMoveEvent | MouseButtonEvent | ScrollEvent | ResizeEvent


class Input:
    """Current input state plus the events of the current frame."""

    def __init__(self) -> None:
        self.keys_down: set[str] = set()
        self.buttons_down: set[int] = set()
        self.mouse_position = (0.0, 0.0)
        self.events: list[Event] = []
        self._queued: list[Event] = []

    # --- feeding (from a window, or from tests) -----------------------------------------------
    def key(self, key: str, action: str = "press") -> None:
        if action not in ("press", "release", "repeat"):
            raise ValueError(f"key action must be 'press', 'release' or 'repeat', got {action!r}")
        self._queued.append(KeyEvent(key.upper(), action))

    def move_mouse(self, x: float, y: float) -> None:
        last = self._queued_mouse()
        self._queued.append(MouseMoveEvent(float(x), float(y), float(x) - last[0], float(y) - last[1]))

    def button(self, button: int, action: str = "press") -> None:
        if action not in ("press", "release"):
            raise ValueError(f"mouse button action must be 'press' or 'release', got {action!r}")
        self._queued.append(MouseButtonEvent(int(button), action))

    def scroll(self, dx: float, dy: float) -> None:
        self._queued.append(ScrollEvent(float(dx), float(dy)))

    def resize(self, width: int, height: int) -> None:
        self._queued.append(ResizeEvent(int(width), int(height)))

    # --- frame boundary -------------------------------------------------------------------------
    def begin_frame(self) -> list[Event]:
        """Make the queued events this frame's events and update the state from them."""
        self.events, self._queued = self._queued, []
        for event in self.events:
            if isinstance(event, KeyEvent):
                if event.action == "release":
                    self.keys_down.discard(event.key)
                else:
                    self.keys_down.add(event.key)
            elif isinstance(event, MouseButtonEvent):
                (self.buttons_down.add if event.action == "press" else self.buttons_down.discard)(event.button)
            elif isinstance(event, MouseMoveEvent):
                self.mouse_position = (event.x, event.y)
        return self.events

    # --- queries --------------------------------------------------------------------------------
    def is_down(self, key: str) -> bool:
        return key.upper() in self.keys_down

    def pressed(self, key: str) -> bool:
        """True in the frame the key went down."""
        key = key.upper()
        return any(isinstance(e, KeyEvent) and e.key == key and e.action == "press" for e in self.events)

    def mouse_delta(self) -> tuple[float, float]:
        """Total mouse movement of this frame."""
        moves = [e for e in self.events if isinstance(e, MouseMoveEvent)]
        return (sum(e.dx for e in moves), sum(e.dy for e in moves))

    def scroll_delta(self) -> float:
        return sum(e.dy for e in self.events if isinstance(e, ScrollEvent))

    def _queued_mouse(self) -> tuple[float, float]:
        for event in reversed(self._queued):
            if isinstance(event, MouseMoveEvent):
                return (event.x, event.y)
        return self.mouse_position
