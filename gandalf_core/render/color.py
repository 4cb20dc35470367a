"""Colour handling shared by both backends (defined in :mod:`gandalf_core.resources.color`, below the systems)."""

from __future__ import annotations

from ..resources.color import srgb_rgba_to_linear

__all__ = ["srgb_rgba_to_linear"]
