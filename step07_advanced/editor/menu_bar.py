"""The menu bar: File (New, Open, Save, Save As, recent files), Edit (Undo, Redo) and View (each panel on or off).

Shortcuts: Ctrl+N, Ctrl+O, Ctrl+S, Ctrl+Z, Ctrl+Y (and Ctrl+Shift+Z). Open and Save As ask for a path in a small
dialog. Its panel entity (kind "menu") holds the bar's place and size like any other panel.
"""

from __future__ import annotations

import uuid

from imgui_bundle import imgui

from .components import PANEL_KINDS, EditorPanelComponent
from .panel_base import ERROR_COLOR, PanelSystem, record_layout, wrapped


class MenuBarSystem(PanelSystem):
    """Draws the main menu bar and its two path dialogs."""

    kind = "menu"

    def __init__(self, editor) -> None:  # noqa: ANN001 - the Editor
        super().__init__(editor)
        self._dialog: str | None = None  # "Open" or "Save As" while its popup should open
        self._path = ""

    def _window(self, entity: uuid.UUID, panel: EditorPanelComponent) -> None:
        if not imgui.begin_main_menu_bar():
            return
        try:
            self.draw(panel)
        finally:
            record_layout(panel)
            imgui.end_main_menu_bar()
        self._shortcuts()
        self._dialogs()

    def draw(self, panel: EditorPanelComponent) -> None:
        editor = self.editor
        if imgui.begin_menu("File"):
            if imgui.menu_item_simple("New", "Ctrl+N"):
                self.act(editor.new_scene)
            self.remember("menu/file/new")
            if imgui.menu_item_simple("Open...", "Ctrl+O"):
                self._open_dialog("Open")
            self.remember("menu/file/open")
            if imgui.menu_item_simple("Save", "Ctrl+S"):
                self.act(editor.save, editor.path)
            self.remember("menu/file/save")
            if imgui.menu_item_simple("Save As..."):
                self._open_dialog("Save As")
            self.remember("menu/file/save_as")
            recent = imgui.begin_menu("Open Recent", bool(editor.recent))
            self.remember("menu/file/recent")
            if recent:
                for i, path in enumerate(list(editor.recent)):
                    if imgui.menu_item_simple(path):
                        self.act(editor.load, path)
                    self.remember(f"menu/file/recent/{i}")
                imgui.end_menu()
            imgui.end_menu()
        self.remember("menu/file")
        if imgui.begin_menu("Edit"):
            commands = editor.commands
            undo = f"Undo {commands.done[-1].label}" if commands.can_undo else "Undo"
            redo = f"Redo {commands.undone[-1].label}" if commands.can_redo else "Redo"
            if imgui.menu_item_simple(undo, "Ctrl+Z", False, commands.can_undo):
                editor.undo()
            self.remember("menu/edit/undo")
            if imgui.menu_item_simple(redo, "Ctrl+Y", False, commands.can_redo):
                editor.redo()
            self.remember("menu/edit/redo")
            imgui.end_menu()
        self.remember("menu/edit")
        if imgui.begin_menu("View"):
            for kind in PANEL_KINDS:
                if kind == "menu":
                    continue
                shown = editor.panel_visible(kind)
                if imgui.menu_item_simple(kind.capitalize(), "", shown):
                    editor.show_panel(kind, not shown)
                self.remember(f"menu/view/{kind}")
            imgui.end_menu()
        self.remember("menu/view")
        if editor.status:
            imgui.text_disabled(editor.status[:80])

    def _open_dialog(self, which: str) -> None:
        self._dialog, self._path = which, self.editor.path

    def _shortcuts(self) -> None:
        io = imgui.get_io()
        if not io.key_ctrl or io.want_text_input:
            return
        editor = self.editor
        pressed = imgui.is_key_pressed
        if pressed(imgui.Key.z, False):
            editor.redo() if io.key_shift else editor.undo()
        elif pressed(imgui.Key.y, False):
            editor.redo()
        elif pressed(imgui.Key.s, False):
            self.act(editor.save, editor.path)
        elif pressed(imgui.Key.n, False):
            self.act(editor.new_scene)
        elif pressed(imgui.Key.o, False):
            self._open_dialog("Open")

    def _dialogs(self) -> None:
        if self._dialog is not None:
            imgui.open_popup(f"{self._dialog}##dialog")
            self._which, self._dialog = self._dialog, None
        which = getattr(self, "_which", None)
        if which is None:
            return
        imgui.set_next_window_size(imgui.ImVec2(420, 0))
        if imgui.begin_popup_modal(f"{which}##dialog", None, imgui.WindowFlags_.always_auto_resize)[0]:
            entered, self._path = imgui.input_text("path", self._path, imgui.InputTextFlags_.enter_returns_true)
            self.remember("menu/dialog/path")
            ok_clicked = imgui.button("OK")
            self.remember("menu/dialog/ok")
            if ok_clicked or entered:
                ok = self.editor.load(self._path) if which == "Open" else self.editor.save(self._path)
                if ok:
                    imgui.close_current_popup()
                    self._which = None
            imgui.same_line()
            if imgui.button("Cancel"):
                imgui.close_current_popup()
                self._which = None
            if self.editor.status_is_error:
                wrapped(self.editor.status, ERROR_COLOR)
            imgui.end_popup()
