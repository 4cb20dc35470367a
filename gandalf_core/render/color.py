"""Colour handling shared by both backends: components hold sRGB colours, shaders get linear ones."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..resources.texture_data import srgb_to_linear


def srgb_rgba_to_linear(rgba: ArrayLike) -> np.ndarray:
    """An sRGB RGBA colour with its RGB decoded to linear light and alpha kept as it is."""
    rgba = np.asarray(rgba, dtype=np.float64)
    return np.concatenate([srgb_to_linear(rgba[:3]), rgba[3:4]])
