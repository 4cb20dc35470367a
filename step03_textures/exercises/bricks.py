"""Exercise: a procedural brick texture (the house of the course's user study is built of these).

``brick_texture`` returns a ``width`` x ``height`` :class:`~gandalf_core.resources.TextureData`. Row 0 of the
image is its top. With ``bw, bh = brick_size``:

* texel row ``y`` belongs to course (row of bricks) ``r = y // bh``; even courses start at x = 0, odd courses
  are shifted right by ``bw // 2`` texels (running bond: every joint sits above the middle of a brick);
* a texel is **mortar** when ``y % bh < mortar`` (the bed joint along the top of each course) or when
  ``(x - shift) % bw < mortar`` (the head joint at the left of each brick); mortar texels are ``mortar_color``;
* every other texel belongs to one brick and is ``brick_color`` times a factor drawn once per brick,
  uniformly from ``[1 - variation, 1 + variation]`` with ``numpy.random.default_rng(seed)`` (clip to [0, 1]).
  All texels of a brick share its factor; the same arguments give the same texture;
* when ``width`` is a multiple of ``bw`` and ``height`` a multiple of ``2 * bh``, the texture tiles
  seamlessly: number the bricks of a course modulo ``ceil(width / bw)``, so the brick cut by the right edge
  is the one continuing at the left edge (same colour).

Colours are 3 floats in [0, 1] as a colour picker shows them (sRGB). Extra ``settings`` (wrap, filter,
mipmaps, name, ...) go to ``TextureData.from_array``; the name defaults to ``"bricks"``.
Raise ValueError naming the parameter for: sizes that are not integers >= 1, ``mortar`` < 0 or
``mortar >= min(bw, bh)``, ``variation`` outside [0, 1], colours that are not 3 floats in [0, 1].

Hint: build the texel coordinates with ``np.arange`` and broadcasting (``ys[:, None]``, ``xs[None, :]``), compute
masks, then pick colours with ``np.where``; no Python loop over texels is needed.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from gandalf_core.resources import TextureData


def brick_texture(
    width: int = 128,
    height: int = 128,
    brick_size: tuple[int, int] = (32, 16),
    mortar: int = 2,
    brick_color: Sequence[float] = (0.62, 0.27, 0.18),
    mortar_color: Sequence[float] = (0.80, 0.78, 0.72),
    variation: float = 0.1,
    seed: int = 0,
    **settings: Any,
) -> TextureData:
    """A running-bond brick wall, ``width`` x ``height`` texels (see the module docstring for the rules)."""
    raise NotImplementedError("exercise: brick_texture")
