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
    """Named meshes, textures (2D and cube) and materials.

    :attr:`version` counts changes (an asset added, replaced or removed), so a renderer can tell cheaply when to
    release the GPU objects of assets that no scene has any more.
    """

    def __init__(self) -> None:
        self.meshes: dict[str, MeshData] = {}
        self.textures: dict[str, TextureData | CubeTextureData] = {}
        self.materials: dict[str, MaterialData] = {}
        self.version = 0

    def remove_mesh(self, name: str) -> None:
        """Forget the mesh ``name`` (its GPU objects go when no scene of the app has it)."""
        self._remove(self.meshes, "mesh", name)

    def remove_texture(self, name: str) -> None:
        """Forget the texture ``name``."""
        self._remove(self.textures, "texture", name)

    def remove_material(self, name: str) -> None:
        """Forget the material ``name``."""
        self._remove(self.materials, "material", name)

    def _remove(self, table: dict[str, T], kind: str, name: str) -> None:
        if name not in table:
            raise ResourceError(f"{kind} '{name}'", "name", f"no such {kind} in the scene's assets "
                                f"(known: {', '.join(sorted(table)) or 'none'})")
        del table[name]
        self.version += 1

    def mesh(self, name: str, data: MeshData) -> str:
        from .mesh_data import MeshData

        return self._put(self.meshes, "mesh", name, data, MeshData)

    def texture(self, name: str, data: TextureData | CubeTextureData) -> str:
        from .texture_data import CubeTextureData, TextureData

        return self._put(self.textures, "texture", name, data, (TextureData, CubeTextureData))

    def material(self, name: str, data: MaterialData) -> str:
        from .material_data import MaterialData

        return self._put(self.materials, "material", name, data, MaterialData)

    def _put(self, table: dict[str, T], kind: str, name: str, data: T, types: type | tuple[type, ...]) -> str:
        if not isinstance(name, str) or not name:
            raise ResourceError(f"{kind} {name!r}", "name", "expected a non-empty string")
        if not isinstance(data, types):
            wanted = " or ".join(t.__name__ for t in (types if isinstance(types, tuple) else (types,)))
            raise ResourceError(f"{kind} '{name}'", "data", f"expected {wanted}, got {type(data).__name__}")
        table[name] = data
        self.version += 1
        return name
