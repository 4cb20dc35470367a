"""The hierarchy panel: the scene's entities as a tree, with create, destroy, rename, duplicate and drag-to-reparent.

Rows are named by their InfoComponent, or (unnamed) by what they are and a short id. A click selects; dragging a
row onto another makes it that row's child, onto the space below the tree makes it a root (keeping its place in the
world). The buttons on top, Delete and Ctrl+D, and each row's context menu (right click) create, duplicate, rename
and destroy; a mesh dragged from the content browser onto the panel is placed in the scene. The root list is
cached and rebuilt only when entities, components or parents change.
"""

from __future__ import annotations

import uuid

from imgui_bundle import imgui

from gandalf_core.ecs import InfoComponent, LinkComponent

from .components import EditorPanelComponent, is_editor_entity
from .entities import display_name
from .panel_base import PanelSystem

ENTITY_PAYLOAD = "GANDALF_ENTITY"
# Tree-node flags, combined once (an enum "|" per row per frame adds up).
_ROW = int(imgui.TreeNodeFlags_.open_on_arrow | imgui.TreeNodeFlags_.default_open
           | imgui.TreeNodeFlags_.span_avail_width)
_LEAF = int(imgui.TreeNodeFlags_.leaf)
_SELECTED = int(imgui.TreeNodeFlags_.selected)


class HierarchyPanelSystem(PanelSystem):
    """The scene's entities as a tree (InfoComponent names, LinkComponent parents)."""

    kind = "hierarchy"

    def __init__(self, editor) -> None:  # noqa: ANN001 - the Editor
        super().__init__(editor)
        self._roots_key: tuple[int, int] | None = None
        self._roots: list[uuid.UUID] = []
        self._flat = True  # no root has children: the rows are one list, drawn with a clipper
        self._ids: dict[uuid.UUID, str] = {}  # "##<uuid>" per entity, made once
        self._labels: dict[uuid.UUID, str] = {}  # readable names of unnamed entities
        self._rename: tuple[uuid.UUID, str] | None = None
        self._open_rename = False

    def roots(self) -> list[uuid.UUID]:
        scene = self.scene
        key = (scene.membership_version, scene.hierarchy_version)
        if key != self._roots_key:
            self._roots = [e for e in scene.entities
                           if not is_editor_entity(scene, e) and scene.parent_of(e) is None]
            self._flat = not any(scene.try_component(e, LinkComponent) is not None
                                 and scene.get_component(e, LinkComponent).children for e in self._roots)
            self._roots_key = key
            self._labels.clear()
            if len(self._ids) > 4 * len(self._roots) + 1024:
                self._ids.clear()
        return self._roots

    def draw(self, panel: EditorPanelComponent) -> None:
        editor = self.editor
        if imgui.small_button("New"):
            self.act(editor.create_entity, "Entity", parent=editor.selected if imgui.get_io().key_shift else None)
        self.remember("hierarchy:create")
        selected = editor.selected if editor.selected in self.scene else None
        imgui.same_line()
        imgui.begin_disabled(selected is None)
        if imgui.small_button("Copy"):
            self.act(editor.duplicate_entity, selected)
        self.remember("hierarchy:duplicate")
        imgui.same_line()
        if imgui.small_button("Del"):
            self.act(editor.destroy_entity, selected)
        self.remember("hierarchy:delete")
        imgui.end_disabled()
        io = imgui.get_io()
        if selected is not None and imgui.is_window_focused() and not io.want_text_input:
            if imgui.is_key_pressed(imgui.Key.delete, False):  # Delete: destroy, Ctrl+D: duplicate
                self.act(editor.destroy_entity, selected)
            elif io.key_ctrl and imgui.is_key_pressed(imgui.Key.d, False):
                self.act(editor.duplicate_entity, selected)
        imgui.separator()
        roots = self.roots()
        if self._flat:  # every row is a leaf of the same height: draw only the visible ones
            clipper = imgui.ListClipper()
            clipper.begin(len(roots))
            while clipper.step():
                for i in range(clipper.display_start, clipper.display_end):
                    self._node(roots[i])
            clipper.end()
        else:
            for entity in list(roots):
                if entity in self.scene:
                    self._node(entity)
        # The free space below the tree: drop a row here to make it a root, a mesh to place it.
        avail = imgui.get_content_region_avail()
        imgui.invisible_button("##hierarchy_free", imgui.ImVec2(max(avail.x, 1.0), max(avail.y, 8.0)))
        self.remember("hierarchy:free")
        self._drop_target(None)
        self._rename_popup()

    def _node(self, entity: uuid.UUID) -> None:
        scene = self.scene
        link = scene.try_component(entity, LinkComponent)
        children = [c for c in link.children if c in scene] if link is not None else []
        info = scene.try_component(entity, InfoComponent)
        if info is not None and info.name:
            label = info.name
        else:
            label = self._labels.get(entity) or self._labels.setdefault(entity, display_name(scene, entity))
        flags = _ROW
        if not children:
            flags |= _LEAF
        if entity == self.editor.selected:
            flags |= _SELECTED
        ident = self._ids.get(entity) or self._ids.setdefault(entity, f"##{entity}")
        is_open = imgui.tree_node_ex(label + ident, flags)
        self.remember("hierarchy/" + ident[2:])
        if imgui.is_item_clicked() and not imgui.is_item_toggled_open():
            self.editor.selected = entity
        if imgui.begin_drag_drop_source():
            imgui.set_drag_drop_payload_py_id(ENTITY_PAYLOAD, self.editor.payload_id("entity", entity))
            imgui.text(label)
            imgui.end_drag_drop_source()
        self._drop_target(entity)
        if imgui.begin_popup_context_item(f"ctx##{entity}"):
            self._context_menu(entity, label)
            imgui.end_popup()
        if is_open:
            for child in children:
                self._node(child)
            imgui.tree_pop()

    def _context_menu(self, entity: uuid.UUID, label: str) -> None:
        editor = self.editor
        if imgui.menu_item_simple("Create child"):
            self.act(editor.create_entity, "Entity", parent=entity)
        if imgui.menu_item_simple("Duplicate"):
            self.act(editor.duplicate_entity, entity)
        if imgui.menu_item_simple("Rename"):
            self._rename, self._open_rename = (entity, label), True
        self.remember("hierarchy:menu/rename")
        if imgui.menu_item_simple("Make root", "", False, self.scene.parent_of(entity) is not None):
            self.act(editor.reparent, entity, None)
        if imgui.menu_item_simple("Destroy"):
            self.act(editor.destroy_entity, entity)

    def _rename_popup(self) -> None:
        if self._open_rename:
            imgui.open_popup("Rename entity")
            self._open_rename = False
        if self._rename is None or not imgui.begin_popup("Rename entity"):
            return
        entity, name = self._rename
        if imgui.is_window_appearing():
            imgui.set_keyboard_focus_here()
        entered, name = imgui.input_text("name", name, imgui.InputTextFlags_.enter_returns_true)
        self._rename = (entity, name)
        if imgui.button("OK") or entered:
            if entity in self.scene:
                self.act(self.editor.rename_entity, entity, name)
            self._rename = None
            imgui.close_current_popup()
        imgui.end_popup()

    def _drop_target(self, parent: uuid.UUID | None) -> None:
        if not imgui.begin_drag_drop_target():
            return
        editor = self.editor
        payload = imgui.accept_drag_drop_payload_py_id(ENTITY_PAYLOAD)
        if payload is not None:
            _kind, dragged = editor.payload(payload.data_id)
            if dragged in self.scene and dragged != parent:
                self.act(editor.reparent, dragged, parent)
        payload = imgui.accept_drag_drop_payload_py_id("GANDALF_MESH")
        if payload is not None:
            _kind, mesh = editor.payload(payload.data_id)
            self.act(editor.spawn_mesh, mesh, parent=parent)
        imgui.end_drag_drop_target()
