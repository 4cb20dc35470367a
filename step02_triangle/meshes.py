"""The step's hand-made meshes: a triangle (three vertices, no indices) and a quad (four vertices, six indices).

Vertex colours are **sRGB**, like every colour in gandalf (what a colour picker shows); the vertex shader
decodes them to linear light, and the sRGB framebuffer encodes the result again, so a flat colour ``c`` is
stored as ``round(255 * c)``.
"""

from __future__ import annotations

from gandalf_core.resources import MeshData


def triangle_mesh() -> MeshData:
    """A triangle in the z = 0 plane with red, green and blue corners, counter-clockwise seen from +Z."""
    return MeshData(
        positions=[(-0.5, -0.5, 0.0), (0.5, -0.5, 0.0), (0.0, 0.5, 0.0)],
        colors=[(1.0, 0.0, 0.0, 1.0), (0.0, 1.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0)],
        name="triangle",
    )


def quad_mesh() -> MeshData:
    """A unit square from two triangles that share the diagonal's two vertices through an index buffer."""
    return MeshData(
        positions=[(-0.5, -0.5, 0.0), (0.5, -0.5, 0.0), (0.5, 0.5, 0.0), (-0.5, 0.5, 0.0)],
        colors=[(1.0, 0.85, 0.1, 1.0), (1.0, 0.2, 0.6, 1.0), (0.2, 0.8, 1.0, 1.0), (0.6, 1.0, 0.4, 1.0)],
        # Both triangles counter-clockwise: 0-1-2 and 0-2-3. Four vertices instead of six.
        indices=[0, 1, 2, 0, 2, 3],
        name="quad",
    )
