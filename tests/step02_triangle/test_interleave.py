"""Grades exercise 1, ``interleave``: the student's vertex buffer and layout, drawn with the raw APIs.

The raw path (``step02_triangle/raw.py``) renders to a linear 8-bit target and passes colours through, so
a colour ``c`` reads back as ``round(255 * c)``. Tolerances: 1 step for a flat colour (rounding), 2 steps
where colours are interpolated (the rasteriser's float precision).
"""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core.resources import MeshData
from step02_triangle import raw

SIZE = 64
TRIANGLE = np.array([(-0.6, -0.5, 0.0), (0.6, -0.5, 0.0), (0.0, 0.7, 0.0)])
RGB = np.array([(1.0, 0.0, 0.0, 1.0), (0.0, 1.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0)])


def _pixel(x: float, y: float) -> tuple[int, int]:
    """(row, column) of the pixel containing clip-space point (x, y), top row first."""
    return int((1.0 - y) / 2.0 * SIZE), int((x + 1.0) / 2.0 * SIZE)


def _centre_of(row: int, col: int) -> np.ndarray:
    """Clip-space (x, y) of a pixel's centre."""
    return np.array([(col + 0.5) / SIZE * 2.0 - 1.0, 1.0 - (row + 0.5) / SIZE * 2.0])


def _barycentric(p: np.ndarray, tri: np.ndarray) -> np.ndarray:
    a, b, c = tri[:, :2]
    m = np.column_stack([b - a, c - a])
    u, v = np.linalg.solve(m, p - a)
    return np.array([1.0 - u - v, u, v])


@pytest.mark.exercise("interleave")
def test_layout_describes_the_interleaved_data(impl):
    data, layout = impl.interleave(TRIANGLE, RGB)
    assert isinstance(data, np.ndarray) and data.dtype == np.float32 and data.shape == (3, 7)
    assert np.allclose(data[:, :3], TRIANGLE) and np.allclose(data[:, 3:], RGB)
    by_name = {a.name: (a.location, a.components, a.offset_bytes) for a in layout.attributes}
    assert by_name == {"position": (0, 3, 0), "color": (4, 4, 12)}
    assert layout.stride == 28
    # The engine packs a mesh the same way.
    engine_data, engine_layout = MeshData(TRIANGLE, colors=RGB).interleaved(("position", "color"))
    assert np.array_equal(data, engine_data) and layout == engine_layout


@pytest.mark.exercise("interleave")
@pytest.mark.parametrize("positions, colors, field", [
    (TRIANGLE, RGB[:2], "colors"),
    (TRIANGLE[:, :2], RGB, "positions"),
    (TRIANGLE, RGB[:, :3], "colors"),
])
def test_wrong_shapes_are_named(impl, positions, colors, field):
    with pytest.raises(ValueError, match=field):
        impl.interleave(positions, colors)


@pytest.mark.exercise("interleave")
@pytest.mark.parametrize("color", [(0.2, 0.6, 0.9, 1.0), (1.0, 0.5, 0.0, 1.0)])
def test_flat_triangle_from_student_buffer(impl, backend, color):
    data, layout = impl.interleave(TRIANGLE, np.tile(color, (3, 1)))
    image = raw.draw(backend, data, layout, SIZE, SIZE).astype(int)
    expected = np.round(np.array(color) * 255).astype(int)
    inside = _pixel(0.0, -0.1)  # the triangle's centroid
    assert np.abs(image[inside] - expected).max() <= 1, f"centre pixel {image[inside]}, expected {expected}"
    # Outside: the corners, and points just beyond each edge, keep the black clear colour.
    for x, y in [(-0.95, 0.95), (0.95, 0.95), (-0.95, -0.95), (0.95, -0.95), (0.0, -0.6), (-0.45, 0.3), (0.45, 0.3)]:
        assert tuple(image[_pixel(x, y)][:3]) == (0, 0, 0), f"pixel at clip ({x}, {y}) is not background"


@pytest.mark.exercise("interleave")
def test_colours_interpolate_between_the_right_vertices(impl, backend):
    data, layout = impl.interleave(TRIANGLE, RGB)
    image = raw.draw(backend, data, layout, SIZE, SIZE).astype(int)
    for x, y in [(0.0, -0.1), (-0.3, -0.35), (0.3, -0.35), (0.0, 0.45)]:
        row, col = _pixel(x, y)
        weights = _barycentric(_centre_of(row, col), TRIANGLE)
        expected = np.round(255 * weights @ RGB).astype(int)
        assert np.abs(image[row, col] - expected).max() <= 2, f"pixel at clip ({x}, {y}): {image[row, col]}"
