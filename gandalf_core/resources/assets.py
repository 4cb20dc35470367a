"""Assets: a scene's backend-neutral resources by name (meshes, textures, materials).

Scene code registers data here; each renderer builds its GPU objects from it on first use and caches
them by name. Shaders are the one resource a scene does not register: their source differs per API
(GLSL or WGSL), so each step's variant file builds them in its renderer's shader library.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, TypeVar

from .errors import ResourceError

if TYPE_CHECKING:  # imported when first used: a Scene (which owns Assets) needs no dataclass module to exist
    from .material_data import MaterialData
    from .mesh_data import MeshData
    from .texture_data import CubeTextureData, TextureData

T = TypeVar("T")


class Assets:
    """Named meshes, textures (2D and cube) and materials."""

    def __init__(self) -> None:
        self.meshes: dict[str, MeshData] = {}
        self.textures: dict[str, TextureData | CubeTextureData] = {}
        self.materials: dict[str, MaterialData] = {}

    def mesh(self, name: str, data: MeshData) -> str:
        from .mesh_data import MeshData

        return self._put(self.meshes, "mesh", name, data, MeshData)

    def texture(self, name: str, data: TextureData | CubeTextureData) -> str:
        from .texture_data import CubeTextureData, TextureData

        return self._put(self.textures, "texture", name, data, (TextureData, CubeTextureData))

    def material(self, name: str, data: MaterialData) -> str:
        from .material_data import MaterialData

        return self._put(self.materials, "material", name, data, MaterialData)

    @staticmethod
    def _put(table: dict[str, T], kind: str, name: str, data: T, types: type | tuple[type, ...]) -> str:
        if not isinstance(name, str) or not name:
            raise ResourceError(f"{kind} {name!r}", "name", "expected a non-empty string")
        if not isinstance(data, types):
            raise ResourceError(f"{kind} '{name}'", "data", f"expected {types}, got {type(data).__name__}")
        table[name] = data
        return name
