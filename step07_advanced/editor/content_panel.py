"""The content browser: the scene's meshes, textures and materials, and the renderer's shaders.

Drag a mesh onto the viewport or the hierarchy to place it in the scene ("+" places it at the origin); drag a
texture onto a material (here, or on a texture slot in the inspector) to put it into the material's first slot.
Shaders show where they come from; "reload" (left of the name, so that a narrow panel never hides it) compiles
one again from its files, and a compile error goes to the console with its file:line.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from imgui_bundle import imgui

from .components import EditorPanelComponent
from .panel_base import TEXTURE_PAYLOAD, PanelSystem

MESH_PAYLOAD = "GANDALF_MESH"


class ContentPanelSystem(PanelSystem):
    """Lists the scene's assets; the drag sources for meshes and textures."""

    kind = "content"

    def draw(self, panel: EditorPanelComponent) -> None:
        editor = self.editor
        assets = self.scene.assets
        for name in self._section("Meshes", sorted(assets.meshes)):
            if imgui.small_button(f"+##{name}"):
                self.act(editor.spawn_mesh, name)
            self.remember(f"content/spawn/{name}")
            imgui.same_line()
            imgui.selectable(name, False)
            self.remember(f"content/mesh/{name}")
            self._source(MESH_PAYLOAD, "mesh", name)
        for name in self._section("Textures", sorted(assets.textures)):
            data = assets.textures[name]
            size = getattr(data, "width", None), getattr(data, "height", None)
            imgui.selectable(f"{name}  {size[0]}x{size[1]}" if size[0] else name, False)
            self.remember(f"content/texture/{name}")
            self._source(TEXTURE_PAYLOAD, "texture", name)
        for name in self._section("Materials", sorted(assets.materials)):
            data = assets.materials[name]
            imgui.selectable(f"{name}  ({data.shader})", False)
            self.remember(f"content/material/{name}")
            self.texture_drop_target(name, 0)
        shaders = editor.app.renderer.shaders
        for name in self._section("Shaders", shaders.names()):
            # The button before the name: a long name in a narrow panel (640x480) would push it out of sight.
            if editor.shader_files(name):
                if imgui.small_button(f"reload##{name}"):
                    self.act(editor.reload_shader, name)
                self.remember(f"content/reload/{name}")
                imgui.same_line()
            imgui.text(name)

    @staticmethod
    def _section(title: str, names: Iterable[str]) -> Iterator[str]:
        """The ``names`` to draw under a tree node ``title (count)``, open at first; none while it is closed."""
        names = list(names)
        if imgui.tree_node_ex(f"{title} ({len(names)})", imgui.TreeNodeFlags_.default_open):
            yield from names
            imgui.tree_pop()

    def _source(self, payload_type: str, kind: str, name: str) -> None:
        if imgui.begin_drag_drop_source():
            imgui.set_drag_drop_payload_py_id(payload_type, self.editor.payload_id(kind, name))
            imgui.text(f"{kind} {name}")
            imgui.end_drag_drop_source()
