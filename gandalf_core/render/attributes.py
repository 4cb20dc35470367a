"""Which mesh attributes a shader reads, from its vertex input locations (the same for both backends)."""

from __future__ import annotations

from collections.abc import Iterable

from ..resources import ATTRIBUTE_LOCATIONS, INSTANCE_LOCATIONS
from .errors import ShaderCompileError

_BY_LOCATION = {loc: name for name, loc in ATTRIBUTE_LOCATIONS.items()}


def mesh_attributes(shader_name: str, locations: Iterable[int]) -> tuple[str, ...]:
    """Mesh attribute names for the shader's input ``locations`` (instance locations skipped), in location order."""
    locations = sorted(locations)
    unknown = [loc for loc in locations if loc not in _BY_LOCATION and loc not in INSTANCE_LOCATIONS]
    if unknown:
        raise ShaderCompileError(
            f"shader '{shader_name}': vertex input locations {unknown} are not engine attributes "
            f"(mesh: {ATTRIBUTE_LOCATIONS}; instance rows: 5, 6, 7)"
        )
    return tuple(_BY_LOCATION[loc] for loc in locations if loc in _BY_LOCATION)
