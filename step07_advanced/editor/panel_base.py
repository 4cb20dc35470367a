"""The base of every panel system: it draws the visible panel entities of its ``kind`` in ``on_gui_update``.

Each system matches the entities that have an :class:`EditorPanelComponent` and draws those of its kind that
are visible, each in its own ImGui window whose place and size are written back to the component. The editor
keeps shared state (the selection, the command stack, the log) on the :class:`~step07_advanced.editor.editor.Editor`,
which every panel system holds. An action a widget starts runs through :meth:`PanelSystem.act`: an error goes to
the console and the panel's status line, never up into the frame.
"""

from __future__ import annotations

import uuid
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from imgui_bundle import imgui

from gandalf_core.ecs import System

from .components import EditorPanelComponent

if TYPE_CHECKING:
    from .editor import Editor

ERROR_COLOR = imgui.ImVec4(1.0, 0.45, 0.4, 1.0)
WARNING_COLOR = imgui.ImVec4(1.0, 0.8, 0.35, 1.0)
#: The drag-and-drop payload type of a texture dragged from the content browser.
TEXTURE_PAYLOAD = "GANDALF_TEXTURE"


def wrapped(text: str, color: Any = None) -> None:
    """``text`` wrapped at the window's edge (never cut off), optionally coloured."""
    if color is not None:
        imgui.push_style_color(imgui.Col_.text, color)
    imgui.text_wrapped(text)
    if color is not None:
        imgui.pop_style_color()


def record_layout(panel: EditorPanelComponent) -> None:
    """Store the current ImGui window's position and size in ``panel`` (as shown: a program's change is new)."""
    pos, size = imgui.get_window_pos(), imgui.get_window_size()
    panel.position, panel.size = (pos.x, pos.y), (size.x, size.y)
    panel._shown = (panel.position, panel.size)


# --8<-- [start:panel_system]
class PanelSystem(System):
    """Draws every visible panel entity of ``kind``; subclasses fill the window in :meth:`draw`."""

    kind = ""
    window_flags = imgui.WindowFlags_.no_collapse
    updates_each_frame = False  # panels change nothing in the simulation step; they act in on_gui_update
    saved = False  # the editor's own: a saved scene does not hold its panels

    def __init__(self, editor: Editor) -> None:
        super().__init__([EditorPanelComponent], name=f"Editor{self.kind.capitalize()}System")
        self.editor = editor

    def on_gui_update(self) -> None:
        for entity, (panel,) in zip(self.entities, self.components):
            if panel.kind == self.kind and panel.visible:
                self._window(entity, panel)

    def _window(self, entity: uuid.UUID, panel: EditorPanelComponent) -> None:
        layout = (panel.position, panel.size)
        if panel._shown != layout:  # a program moved or resized the panel: apply it
            imgui.set_next_window_pos(imgui.ImVec2(*panel.position), imgui.Cond_.always)
            imgui.set_next_window_size(imgui.ImVec2(*panel.size), imgui.Cond_.always)
        imgui.begin(f"{panel.title}##{entity}", None, self.window_flags)
        try:
            self.draw(panel)
        finally:
            record_layout(panel)
            imgui.end()

    def draw(self, panel: EditorPanelComponent) -> None:
        raise NotImplementedError
# --8<-- [end:panel_system]

    def remember(self, key: str, width: float | None = None) -> None:
        """Record the last item's rectangle (pixels) under ``key``: tests and tools find widgets by it.

        ``width`` limits it to the widget's fields (without the label to their right).
        """
        lo, hi = imgui.get_item_rect_min(), imgui.get_item_rect_max()
        right = hi.x if width is None else lo.x + width
        self.editor.item_rects[key] = (lo.x, lo.y, right, hi.y)

    def texture_drop_target(self, material: str, slot: int) -> None:
        """A texture dragged from the content browser and dropped on the last item goes into ``material``'s
        texture ``slot`` (one undoable edit)."""
        if imgui.begin_drag_drop_target():
            payload = imgui.accept_drag_drop_payload_py_id(TEXTURE_PAYLOAD)
            if payload is not None:
                _kind, texture = self.editor.payload(payload.data_id)
                self.act(self.editor.set_material_texture, material, texture, slot)
            imgui.end_drag_drop_target()

    def act(self, action: Callable[..., Any], *args: Any, **kwargs: Any) -> Any:
        """Run an editor action; an error is logged to the console (whole) instead of raised."""
        return self.editor.attempt(action, *args, **kwargs)
