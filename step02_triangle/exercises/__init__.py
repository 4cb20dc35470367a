"""Step 02 exercises: fill in ``vertex_data.py`` and ``ngon.py``, then ``pytest --student tests/step02_triangle``."""


from .ngon import NGonSystem, ngon_mesh
from .vertex_data import interleave

__all__ = ["NGonSystem", "interleave", "ngon_mesh"]

