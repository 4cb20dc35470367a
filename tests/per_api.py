"""Pictures of both APIs that a test module shares, each rendered when a test first asks for it.

A module-scoped fixture that rendered both APIs up front would make a test of one API open the other API too:
where only one API may run in a process (Mesa's softpipe breaks wgpu's Vulkan device; a machine without
WebGPU), the test of the API that works would then error. With :class:`PerAPI` a test renders only what it reads.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class PerAPI(dict):
    """``render(api)`` for each API on first use (``pictures["opengl"]``), then the same object again."""

    def __init__(self, render: Callable[[str], Any]) -> None:
        super().__init__()
        self._render = render

    def __missing__(self, api: str) -> Any:
        self[api] = value = self._render(api)
        return value
