"""Mesh and Material components: what an entity looks like, by the names of its resources.

The names refer to the scene's :class:`~gandalf_core.resources.assets.Assets` (backend-neutral data),
which each renderer turns into GPU objects on first use. Entities with the same mesh and material are
drawn together in one instanced draw call. To change an entity's mesh or material, add a new component
(that is how the render system learns of the change).
"""

from __future__ import annotations

from ..ecs import Component


class _AssetName(Component):
    """A component that is one asset's name, never changed (so Scene.create_entities may share one object)."""

    __slots__ = ("_name",)
    immutable = True

    def _set_name(self, what: str, name: str) -> None:
        if not isinstance(name, str) or not name:
            raise TypeError(f"{type(self).__name__}.{what} must be a {what} name (a non-empty string), got {name!r}")
        self._name = name

    def _get_name(self) -> str:
        return self._name

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self._name!r})"


class MeshComponent(_AssetName):
    """The name of the mesh an entity draws."""

    __slots__ = ()

    def __init__(self, mesh: str) -> None:
        self._set_name("mesh", mesh)

    mesh = property(_AssetName._get_name, doc="The mesh's name in the scene's assets.")


class MaterialComponent(_AssetName):
    """The name of the material an entity is drawn with."""

    __slots__ = ()

    def __init__(self, material: str) -> None:
        self._set_name("material", material)

    material = property(_AssetName._get_name, doc="The material's name in the scene's assets.")
