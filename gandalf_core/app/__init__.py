"""The app layer: frame loop, clock, input, window."""

from .application import Application
from .clock import Clock
from .input import Input, KeyEvent, MouseButtonEvent, MouseMoveEvent, ResizeEvent, ScrollEvent

__all__ = [
    "Application",
    "Clock",
    "Input",
    "KeyEvent",
    "MouseButtonEvent",
    "MouseMoveEvent",
    "ResizeEvent",
    "ScrollEvent",
]
