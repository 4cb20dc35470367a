"""Exercise: interleaved vertex data and its layout, by hand.

A GPU reads vertices from one buffer of bytes. *Interleaved* means each vertex's attributes sit next to
each other: ``x y z r g b a | x y z r g b a | ...``. The *layout* tells the GPU where each attribute is:
its name, its shader location, how many floats it has, and its byte offset inside one vertex; the *stride*
is the size of one whole vertex in bytes. (The engine does this for every mesh in
``MeshData.interleaved``; here you do it yourself.)
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from gandalf_core.resources import VertexAttribute, VertexLayout  # noqa: F401  (you build both)


def interleave(positions: ArrayLike, colors: ArrayLike) -> tuple[np.ndarray, VertexLayout]:
    """Interleave ``positions`` (N, 3) and ``colors`` (N, 4) into one float32 array of shape (N, 7).

    Return ``(data, layout)`` where ``layout`` is a ``VertexLayout`` whose ``attributes`` are two
    ``VertexAttribute(name, location, components, offset_bytes)``: ``"position"`` at shader location 0
    and ``"color"`` at location 4 (the engine's locations), and whose ``stride`` is the bytes per vertex.
    Raise ValueError naming ``positions`` or ``colors`` when a shape is wrong or the row counts differ.

    Hint: a float32 is 4 bytes; ``np.hstack`` or slicing into ``np.empty((n, 7), np.float32)`` both work.
    """
    raise NotImplementedError("exercise: interleave")
