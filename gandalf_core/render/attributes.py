"""Which mesh attributes a draw binds: those a shader reads, from its vertex input locations (OpenGL, which lists
them), or all the mesh has (WebGPU: a pipeline may be given attributes its shader does not read)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from ..resources import ATTRIBUTE_LOCATIONS
from .errors import ShaderCompileError

_BY_LOCATION = {loc: name for name, loc in ATTRIBUTE_LOCATIONS.items()}
_FIELDS = {"position": "positions", "normal": "normals", "uv": "uvs", "tangent": "tangents", "color": "colors"}


def mesh_has(data: Any) -> tuple[str, ...]:
    """The attributes a MeshData holds, in location order; none for an indirectly drawn mesh (its vertices are
    placeholders: the GPU draws a count a compute pass wrote, and the shader pulls its vertices itself)."""
    if getattr(data, "indirect", None) is not None:
        return ()
    return tuple(name for name in ATTRIBUTE_LOCATIONS if getattr(data, _FIELDS[name]) is not None)


def mesh_attributes(shader_name: str, locations: Iterable[int]) -> tuple[str, ...]:
    """Mesh attribute names for the shader's input ``locations``, in location order."""
    locations = sorted(locations)
    unknown = [loc for loc in locations if loc not in _BY_LOCATION]
    if unknown:
        raise ShaderCompileError(
            f"shader '{shader_name}': vertex input locations {unknown} are not engine attributes "
            f"(mesh: {ATTRIBUTE_LOCATIONS}; the instance rows are no attributes: instance_model() reads them)"
        )
    return tuple(_BY_LOCATION[loc] for loc in locations)
