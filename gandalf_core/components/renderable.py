"""Mesh and Material components: what an entity looks like, by the names of its resources.

The names refer to the scene's :class:`~gandalf_core.resources.assets.Assets` (backend-neutral data),
which each renderer turns into GPU objects on first use. Entities with the same mesh and material are
drawn together in one instanced draw call. To change an entity's mesh or material, add a new component
(that is how the render system learns of the change).
"""

from __future__ import annotations

from ..ecs import Component


class MeshComponent(Component):
    """The name of the mesh an entity draws."""

    __slots__ = ("_mesh",)
    immutable = True  # a name that never changes: Scene.create_entities may share one object

    def __init__(self, mesh: str) -> None:
        if not isinstance(mesh, str) or not mesh:
            raise TypeError(f"MeshComponent.mesh must be a mesh name (a non-empty string), got {mesh!r}")
        self._mesh = mesh

    @property
    def mesh(self) -> str:
        return self._mesh

    def __repr__(self) -> str:
        return f"MeshComponent({self._mesh!r})"


class MaterialComponent(Component):
    """The name of the material an entity is drawn with."""

    __slots__ = ("_material",)
    immutable = True  # a name that never changes: Scene.create_entities may share one object

    def __init__(self, material: str) -> None:
        if not isinstance(material, str) or not material:
            raise TypeError(f"MaterialComponent.material must be a material name, got {material!r}")
        self._material = material

    @property
    def material(self) -> str:
        return self._material

    def __repr__(self) -> str:
        return f"MaterialComponent({self._material!r})"
