"""Step 02 reference solutions (same API as ``exercises``)."""


from .ngon import NGonSystem, ngon_mesh
from .vertex_data import interleave

__all__ = ["NGonSystem", "interleave", "ngon_mesh"]

