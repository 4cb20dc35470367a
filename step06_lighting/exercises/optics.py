"""Exercise: the reflection and refraction directions of environment mapping, in numpy.

Both take arrays of shape (..., 3) (a single vector or many at once) and follow the GLSL/WGSL
built-ins: ``i`` is the incident direction (from the eye towards the surface), ``n`` the unit
surface normal facing the eye, ``eta`` the ratio of refractive indices n1 / n2 (air to glass:
1 / 1.5).
"""

from __future__ import annotations

import numpy as np


def reflect(i: np.ndarray, n: np.ndarray) -> np.ndarray:
    """The mirror direction of ``i`` about ``n``: ``i - 2 (n·i) n``."""
    raise NotImplementedError("exercise: reflect")


# --8<-- [start:refract]
def refract(i: np.ndarray, n: np.ndarray, eta: float | np.ndarray) -> np.ndarray:
    """The refracted direction (Snell's law) for unit ``i`` and ``n``, or the zero vector on
    total internal reflection.

    Hint: with ``k = 1 - eta² (1 - (n·i)²)``, the result is ``eta i - (eta (n·i) + sqrt(k)) n``
    when k ≥ 0.
    """
    raise NotImplementedError("exercise: refract")
# --8<-- [end:refract]
