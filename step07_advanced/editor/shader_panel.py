"""The shader panel: the selected entity's shader, every stage and ``#include``d file, in a code editor.

It shows the shader that draws the selected entity's material, one tab per file it reads (stages first, then the
includes; the engine's own snippets read-only) and one for its Material block as the shader sees it. Save (or
Ctrl+S) writes the tab's file and rebuilds the program or pipeline (:mod:`.shader_edits` does the work, undoably);
a file changed by any other editor is taken in the same way, polled once per GUI frame while the panel is open.
A compile or link error is listed at the top (click one to go to its line), marked at its line in the file where
it is, and written over the viewport; the last good program keeps drawing. Nothing here runs while the panel is
closed, except the error note over the viewport while a shader has an error.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from imgui_bundle import imgui
from imgui_bundle import imgui_color_text_edit as color_text_edit

from .components import EditorPanelComponent
from .panel_base import ERROR_COLOR, WARNING_COLOR, PanelSystem, wrapped
from .shader_edits import problems

TextEditor = color_text_edit.TextEditor
_LANGUAGE = {"glsl": TextEditor.Language.glsl, "wgsl": TextEditor.Language.cpp}  # no WGSL colours: C-like ones
_OVERLAY_BACKGROUND = imgui.ImVec4(0.25, 0.02, 0.02, 0.92)


def _u32(color: Any) -> int:
    return imgui.color_convert_float4_to_u32(color)


def _same(shown: str, text: str | None) -> bool:
    """Whether the code editor shows ``text`` (it ends every line with a newline and writes CRLF as LF)."""
    if text is None:
        return False
    text = text.replace("\r\n", "\n")
    return shown == (text if not text or text.endswith("\n") else text + "\n")


class ShaderPanelSystem(PanelSystem):
    """Edits the shader of the selected entity's material; shows its errors in the text and over the viewport."""

    kind = "shader"

    def __init__(self, editor) -> None:  # noqa: ANN001 - the Editor
        super().__init__(editor)
        self._editors: dict[Any, Any] = {}  # tab key (a file's Path, or "material:<shader>") -> TextEditor
        self._loaded: dict[Any, str] = {}  # the text last put into each editor (what is saved)
        self._marks_key: dict[Any, Any] = {}
        #: Tab key -> the lines (1-based) marked with an error in its editor.
        self.marked: dict[Any, list[int]] = {}
        #: The shader shown and the tab in front.
        self.shader: str | None = None
        self.active: Any = None
        self._jump: tuple[Any, int] | None = None

    # --- what tests and tools reach ------------------------------------------------------------------
    def text_editor(self, key: Any) -> Any:
        """The code editor of tab ``key`` (a file's path, or ``material_key(shader)``), made on first use."""
        editor = self._editors.get(key)  # the panel's own keys are resolved paths already: no file system call
        if editor is None and not (isinstance(key, str) and key.startswith("material:")):
            key = Path(key).resolve()
            editor = self._editors.get(key)
        if editor is None:
            editor = self._editors[key] = TextEditor()
            editor.set_language(_LANGUAGE[self.editor.app.renderer.shading_language]())
            editor.set_palette(TextEditor.get_dark_palette())
            editor.set_read_only_enabled(isinstance(key, Path) and not self.editor.shader_edits.editable(key))
        return editor

    @staticmethod
    def material_key(shader: str) -> str:
        return f"material:{shader}"

    # --- the panel -------------------------------------------------------------------------------------
    def on_gui_update(self) -> None:
        super().on_gui_update()
        edits = self.editor._shader_edits
        if edits is not None and edits.errors:
            self._viewport_note(edits.errors)

    def draw(self, panel: EditorPanelComponent) -> None:
        edits = self.editor.shader_edits
        edits.poll()
        shader = edits.shader_of(self.editor.selected)
        if shader is None:
            imgui.text_disabled("select an entity with a material (built) to edit its shader")
            return
        self.shader = shader
        files = edits.open(shader)
        material = edits.material_text(shader)
        # The shader's own files first (stages, then their includes), its Material block, then the engine's files.
        tabs: list[Any] = [path for path in files if edits.editable(path)]
        if material is not None:
            tabs.append(self.material_key(shader))
        tabs += [path for path in files if not edits.editable(path)]
        if self.active not in tabs:  # another shader was selected: its tab in front is found when drawn
            self.active = None
        for key in tabs:
            self._sync(key, edits.text(key) if isinstance(key, Path) else material, shader)
        imgui.text(f"shader '{shader}'")
        imgui.same_line()
        save = imgui.small_button("Save")
        self.remember("shader/save")
        imgui.same_line()
        if imgui.small_button("Revert"):
            self._revert(self.active)
        self.remember("shader/revert")
        io = imgui.get_io()
        focused = imgui.is_window_focused(imgui.FocusedFlags_.root_and_child_windows)
        if save or (focused and io.key_ctrl and imgui.is_key_pressed(imgui.Key.s, False)):
            self.act(self.save, self.active)
        self._problems(shader)
        if imgui.begin_tab_bar("shader files", imgui.TabBarFlags_.fitting_policy_shrink
                               | imgui.TabBarFlags_.tab_list_popup_button):
            for key in tabs:
                self._tab(key)
            imgui.end_tab_bar()

    def save(self, key: Any = None) -> bool:
        """Save tab ``key`` (the one in front by default): its file, or the Material block."""
        key = self.active if key is None else key
        if key is None or self.shader is None:
            return False
        edits = self.editor.shader_edits
        text = self.text_editor(key).get_text()
        if isinstance(key, str):
            return edits.save_material(self.shader, text)
        return edits.save(key, text)

    def _revert(self, key: Any) -> None:
        if key is not None and key in self._loaded:
            self.text_editor(key).set_text(self._loaded[key])

    def _sync(self, key: Any, text: str, shader: str) -> None:
        """Put ``text`` into tab ``key``'s editor when the file changed (a save, undo, another editor) and mark the
        lines of the shader's error in it."""
        editor = self.text_editor(key)
        loaded = self._loaded.get(key)
        if loaded != text:
            shown = editor.get_text()
            if loaded is not None and not _same(shown, loaded) and not _same(shown, text):  # unsaved typing: kept
                self.editor.log.add("warning", "shader panel", f"{getattr(key, 'name', key)} changed while it had "
                                    "unsaved edits here: they are kept (Revert shows the new text)")
            elif not _same(shown, text):
                editor.set_text(text)
            self._loaded[key] = text
        edits = self.editor.shader_edits
        marks_key = (edits.version, shader)
        if self._marks_key.get(key) == marks_key:
            return
        self._marks_key[key] = marks_key
        editor.clear_markers()
        where = key if isinstance(key, Path) else f"material.{edits.lang}"
        messages: dict[int, list[str]] = {}  # one marker per line, with every message about it
        for problem in problems(edits.errors.get(shader, "")):
            if problem.line is not None and problem.is_in(where):
                messages.setdefault(problem.line, []).append(problem.message)
        for line, texts in messages.items():
            tip = "\n".join(texts)
            editor.add_marker(line - 1, _u32(ERROR_COLOR), _u32(imgui.ImVec4(0.5, 0.1, 0.1, 0.6)), tip, tip)
        self.marked[key] = sorted(messages)

    def _problems(self, shader: str) -> None:
        """The shader's error, one line per problem (a click goes to its file and line), and the last notes."""
        edits = self.editor.shader_edits
        error = edits.errors.get(shader)
        if error is not None:
            imgui.push_style_color(imgui.Col_.text, ERROR_COLOR)
            for i, problem in enumerate(problems(error)):
                where = f"{Path(problem.file).name}:{problem.line}: " if problem.file else ""
                if imgui.selectable(f"{where}{problem.message}##problem{i}", False)[0] and problem.file:
                    self._go_to(problem)
                self.remember(f"shader/problem/{i}")
            imgui.pop_style_color()
            wrapped("the last good program keeps drawing", ERROR_COLOR)
        for note in edits.notes:
            wrapped(note, WARNING_COLOR)

    def _go_to(self, problem: Any) -> None:
        edits = self.editor.shader_edits
        name = f"material.{edits.lang}"
        key = self.material_key(self.shader) if problem.file == name else Path(problem.file).resolve()
        self._jump = (key, problem.line)

    def _tab(self, key: Any) -> None:
        editor = self.text_editor(key)
        label = f"material.{self.editor.shader_edits.lang}" if isinstance(key, str) else key.name
        # Typed into since its text was put in (set_text starts the editor's own undo history again at 0), and not
        # typed back: the text is read only then, not every frame.
        dirty = editor.get_undo_index() != 0 and not _same(editor.get_text(), self._loaded.get(key))
        flags = imgui.TabItemFlags_.unsaved_document if dirty else 0
        if self._jump is not None and self._jump[0] == key:
            flags |= imgui.TabItemFlags_.set_selected
        selected, _open = imgui.begin_tab_item(f"{label}##{key}", None, flags)
        self.remember(f"shader/tab/{label}")
        if not selected:
            return
        self.active = key
        if self._jump is not None and self._jump[0] == key:
            editor.set_cursor(TextEditor.DocPos(self._jump[1] - 1, 0))
            self._jump = None
        if isinstance(key, Path) and not self.editor.shader_edits.editable(key):
            imgui.text_disabled("the engine's own file: read-only here")
        elif isinstance(key, str):
            imgui.text_disabled("declared with the shader in Python (material=[...]); a change here lasts this run")
        editor.render(f"##code{key}", imgui.ImVec2(0, 0))
        self.remember(f"shader/code/{label}")
        imgui.end_tab_item()

    def _viewport_note(self, errors: dict[str, str]) -> None:
        """The errors written over the viewport's picture (top edge), so that a black or stale picture explains
        itself."""
        rect = self.editor.item_rects.get("viewport/image")
        if rect is None or not self.editor.panel_visible("viewport"):
            return
        x0, y0, x1, _y1 = rect
        lines = []
        for shader, error in errors.items():
            first = next(iter(problems(error)), None)
            where = f"{Path(first.file).name}:{first.line}: " if first is not None and first.file else ""
            lines.append(f"shader '{shader}' does not build ({where}{first.message if first else ''}); "
                         "the last good program is drawing")
        text = "\n".join(lines)
        panel = self.editor.panel("shader")
        if panel is not None and panel.visible and panel.position[0] <= x0 < panel.position[0] + panel.size[0]:
            x0 = panel.position[0] + panel.size[0]  # the part of the picture the open panel leaves in sight
        pad = 6.0
        wrap = max(x1 - x0 - 4.0 - 2.0 * pad, 40.0)
        size = imgui.calc_text_size(text, False, wrap)
        draw = imgui.get_foreground_draw_list()
        top = imgui.ImVec2(x0 + 2, y0 + 2)
        bottom = imgui.ImVec2(min(x0 + 2 + size.x + 2 * pad, x1 - 2), y0 + 2 + size.y + 2 * pad)
        draw.add_rect_filled(top, bottom, _u32(_OVERLAY_BACKGROUND), 3.0)
        draw.add_text(imgui.get_font(), imgui.get_font_size(), imgui.ImVec2(top.x + pad, top.y + pad),
                      _u32(ERROR_COLOR), text, wrap)
        self.editor.item_rects["shader/viewport_error"] = (top.x, top.y, bottom.x, bottom.y)
