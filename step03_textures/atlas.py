"""The cross-shaped cube atlas of step 03: its layout, and a dice texture drawn in that layout.

A cube unfolds into a cross of six squares on a 4 x 3 grid (v = 0 is the top row of the image)::

            +Y
        -X  +Z  +X  -Z
            -Y

Each face is seen from outside with the same frame as :func:`gandalf_core.resources.primitives.cube`:
``FACE_FRAMES`` gives its outward normal, the direction of +u (image right) and of image up (-v). With these
frames the cross is a true net of the cube: edges that touch in the picture touch on the cube.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from gandalf_core.resources import TextureData

#: Grid size of the cross layout: 4 columns, 3 rows.
CROSS_GRID = (4, 3)

#: Face name -> (column, row) of its square in the cross (row 0 is the top of the image).
CROSS_CELLS: dict[str, tuple[int, int]] = {
    "+Y": (1, 0),
    "-X": (0, 1),
    "+Z": (1, 1),
    "+X": (2, 1),
    "-Z": (3, 1),
    "-Y": (1, 2),
}

#: Face name -> (outward normal, image right, image up), the frames of ``primitives.cube``.
FACE_FRAMES: dict[str, tuple[tuple[int, int, int], tuple[int, int, int], tuple[int, int, int]]] = {
    "+X": ((1, 0, 0), (0, 0, -1), (0, 1, 0)),
    "-X": ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    "+Y": ((0, 1, 0), (1, 0, 0), (0, 0, -1)),
    "-Y": ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    "+Z": ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
    "-Z": ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
}

# Opposite faces of a die add up to 7.
_PIPS = {"+Z": 1, "+X": 2, "+Y": 3, "-Y": 4, "-X": 5, "-Z": 6}
# Pip centres in a face's unit square (x right, y down); 2, 3 and 6 are not symmetric under a quarter
# turn, so a face mapped rotated or mirrored shows it.
_PIP_LAYOUT = {
    1: [(0.5, 0.5)],
    2: [(0.75, 0.25), (0.25, 0.75)],
    3: [(0.75, 0.25), (0.5, 0.5), (0.25, 0.75)],
    4: [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)],
    5: [(0.25, 0.25), (0.75, 0.25), (0.5, 0.5), (0.25, 0.75), (0.75, 0.75)],
    6: [(0.25, 0.25), (0.75, 0.25), (0.25, 0.5), (0.75, 0.5), (0.25, 0.75), (0.75, 0.75)],
}
_FACE_COLORS = {
    "+X": (0.93, 0.42, 0.36), "-X": (0.36, 0.70, 0.93), "+Y": (0.96, 0.84, 0.36),
    "-Y": (0.62, 0.50, 0.86), "+Z": (0.95, 0.95, 0.92), "-Z": (0.45, 0.82, 0.52),
}


def dice_atlas(cell: int = 64, **settings: Any) -> TextureData:
    """A die unfolded into the cross layout: ``4*cell`` x ``3*cell`` texels, one coloured square per face.

    Each face carries its pips (1 on +Z ... 6 on -Z), a dark frame, and a darker bar along its *top* edge
    so that a face mapped upside down or mirrored is easy to spot. Unused cells are mid grey.
    """
    if isinstance(cell, bool) or int(cell) != cell or cell < 8:
        raise ValueError(f"dice_atlas: cell must be an integer >= 8, got {cell!r}")
    cell = int(cell)
    settings.setdefault("name", "dice")
    cols, rows = CROSS_GRID
    img = np.full((rows * cell, cols * cell, 3), 0.5)
    centre = (np.arange(cell) + 0.5) / cell  # texel centres in the face's unit square
    y, x = np.meshgrid(centre, centre, indexing="ij")
    border = (np.minimum(np.minimum(x, 1 - x), np.minimum(y, 1 - y)) < 0.04)[..., None]
    top_bar = ((y > 0.04) & (y < 0.12) & (x > 0.04) & (x < 0.96))[..., None]
    for face, (col, row) in CROSS_CELLS.items():
        colour = np.array(_FACE_COLORS[face])
        square = np.broadcast_to(colour, (cell, cell, 3)).copy()
        square = np.where(top_bar, colour * 0.55, square)
        square = np.where(border, 0.15, square)
        pips = np.zeros((cell, cell), dtype=bool)
        for px, py in _PIP_LAYOUT[_PIPS[face]]:
            pips |= (x - px) ** 2 + (y - py) ** 2 < 0.085**2
        square = np.where(pips[..., None], 0.1, square)
        img[row * cell:(row + 1) * cell, col * cell:(col + 1) * cell] = square
    return TextureData.from_array(img, **settings)
