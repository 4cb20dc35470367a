"""The one error type of the resource layer, and the warning of a mesh file the engine reads only in part.

Every resource problem (a bad file, a wrong array shape, an unknown setting) raises :class:`ResourceError`.
Its constructor takes the resource and the field separately, so a message always says *which* texture, mesh,
material or shader file is wrong and *which* part of it.
"""

from __future__ import annotations


class ResourceError(ValueError):
    """Invalid resource data or an unreadable resource file.

    The message reads ``"<resource>: <field>: <detail>"``, for example
    ``"texture 'bricks.png': wrap: 'tile' is not one of 'repeat', 'clamp'"``.
    The parts stay available as attributes for tools (the editor, the grader) that show them separately.
    """

    def __init__(self, resource: str, field: str, detail: str) -> None:
        self.resource = resource
        self.field = field
        self.detail = detail
        super().__init__(f"{resource}: {field}: {detail}")


class MeshFileWarning(UserWarning):
    """Something in a mesh file that the engine leaves out but can draw without (an OBJ's lines, a part that is a
    point cloud): named, never dropped silently."""
