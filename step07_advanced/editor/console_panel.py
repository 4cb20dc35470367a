"""The console: the engine's log, warnings and errors (newest last), each message wrapped and shown whole.

Filters for info, warnings and errors, and a Clear button. An error that names a ``file:line`` (a shader error)
shows that location first, highlighted. Only the last 200 entries are drawn.
"""

from __future__ import annotations

from imgui_bundle import imgui

from .components import EditorPanelComponent
from .console_log import file_line
from .panel_base import ERROR_COLOR, WARNING_COLOR, PanelSystem, wrapped

_COLORS = {"warning": WARNING_COLOR, "error": ERROR_COLOR}
_LOCATION_COLOR = imgui.ImVec4(0.55, 0.8, 1.0, 1.0)
SHOWN = 200


# --8<-- [start:console]
class ConsolePanelSystem(PanelSystem):
    """Shows :attr:`Editor.log`."""

    kind = "console"

    def __init__(self, editor) -> None:  # noqa: ANN001 - the Editor
        super().__init__(editor)
        self.show = {"info": True, "warning": True, "error": True}

    def draw(self, panel: EditorPanelComponent) -> None:
        log = self.editor.log
        for level in self.show:
            _changed, self.show[level] = imgui.checkbox(level, self.show[level])
            imgui.same_line()
        if imgui.small_button("Clear"):
            log.clear()
        imgui.separator()
        imgui.begin_child("console entries")
        entries = list(log.entries)[-SHOWN:]
        for entry in entries:
            if not self.show.get(entry.level, True):
                continue
            where = file_line(entry.text) if entry.level == "error" else None
            if where is not None:
                imgui.text_colored(_LOCATION_COLOR, f"{where[0]}:{where[1]}")
            wrapped(f"[{entry.source}] {entry.text}", _COLORS.get(entry.level))
        if entries and imgui.get_scroll_y() >= imgui.get_scroll_max_y() - 4:
            imgui.set_scroll_here_y(1.0)  # follow the newest entry unless the user scrolled up
        imgui.end_child()
# --8<-- [end:console]
