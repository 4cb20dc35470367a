"""Editor components: each editor panel is an entity with an :class:`EditorPanelComponent`.

Panels are ordinary ECS data. The editor's systems draw every visible panel of their kind in
``on_gui_update``; a scene can hide a panel (``visible = False``), move it or resize it by changing the
component, like any other component. Entities with this component belong to the editor: the hierarchy
panel does not list them and the editor's Save action does not write them.
"""

from __future__ import annotations

import math
import uuid
from collections.abc import Sequence
from typing import Any

from gandalf_core.ecs import Component

#: The panel kinds the editor's systems draw.
PANEL_KINDS = ("menu", "viewport", "hierarchy", "inspector", "systems", "content", "console", "stats", "file",
               "shader", "frame")


_TITLES = {"menu": "Menu bar", "content": "Content browser", "file": "Scene file", "frame": "Frame inspector"}


def _pair(name: str, value: Sequence[float]) -> tuple[float, float]:
    try:
        x, y = (float(v) for v in value)
    except (TypeError, ValueError):
        raise ValueError(f"EditorPanelComponent.{name} must be two numbers (pixels), got {value!r}") from None
    if not (math.isfinite(x) and math.isfinite(y)):
        raise ValueError(f"EditorPanelComponent.{name} must be finite, got {value!r}")
    return x, y


# --8<-- [start:panel_component]
class EditorPanelComponent(Component):
    """One editor panel: its ``kind`` (see :data:`PANEL_KINDS`), window ``title``, visibility and layout.

    ``position`` and ``size`` are in pixels from the top-left corner of the frame. The editor writes
    back where the user moved or resized the window, and applies any value a program assigns.
    """

    saved = False  # a panel entity is the editor's own: saving a scene leaves it out

    def __init__(
        self,
        kind: str,
        title: str | None = None,
        visible: bool = True,
        position: Sequence[float] = (0.0, 0.0),
        size: Sequence[float] = (200.0, 150.0),
    ) -> None:
        if kind not in PANEL_KINDS:
            raise ValueError(f"EditorPanelComponent.kind must be one of {PANEL_KINDS}, got {kind!r}")
        self.kind = kind
        self.title = title or _TITLES.get(kind, kind.capitalize())
        self.visible = bool(visible)
        self.position = _pair("position", position)
        self.size = _pair("size", size)
        self._shown: tuple[Any, ...] | None = None  # the layout last handed to ImGui


def is_editor_entity(scene: Any, entity: uuid.UUID) -> bool:
    """True for entities the editor owns (its panels): hidden from the hierarchy, never saved."""
    return scene.has_component(entity, EditorPanelComponent)
# --8<-- [end:panel_component]
