"""Step 02 reference solutions (same API as ``exercises``)."""

from gandalf_core.usd import register_system

from .ngon import NGonSystem, ngon_mesh
from .vertex_data import interleave

__all__ = ["NGonSystem", "interleave", "ngon_mesh"]

register_system(NGonSystem)  # allowed in saved scenes (gandalf_core.usd)
