"""Colours: components hold sRGB colours (as a colour picker shows them); shaders get linear light."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .texture_data import srgb_to_linear


def srgb_rgba_to_linear(rgba: ArrayLike) -> np.ndarray:
    """An sRGB RGB(A) colour with its RGB decoded to linear light and alpha kept (1 when not given)."""
    rgba = np.asarray(rgba, dtype=np.float64).ravel()
    if rgba.shape == (3,):
        rgba = np.append(rgba, 1.0)
    if rgba.shape != (4,):
        raise ValueError(f"a colour needs 3 or 4 components, got {rgba.size}")
    return np.concatenate([srgb_to_linear(rgba[:3]), rgba[3:4]])
