"""The editor's panel systems, one per panel kind; the stats and file panels live here, the others in their
own modules (hierarchy, inspector, viewport, systems, content browser, console, menu bar, shader).

Every system draws the visible :class:`EditorPanelComponent` entities of its kind (see
:class:`~step07_advanced.editor.panel_base.PanelSystem`).
"""

from __future__ import annotations

from imgui_bundle import imgui

from gandalf_core.render.gpu_memory import MIB

from .components import EditorPanelComponent, is_editor_entity
from .console_panel import ConsolePanelSystem
from .content_panel import ContentPanelSystem
from .frame_panel import FramePanelSystem
from .hierarchy_panel import HierarchyPanelSystem
from .inspector_panel import InspectorPanelSystem, _edited
from .menu_bar import MenuBarSystem
from .panel_base import ERROR_COLOR, PanelSystem, wrapped
from .shader_panel import ShaderPanelSystem
from .systems_panel import SystemsPanelSystem
from .viewport_panel import ViewportPanelSystem


class StatsPanelSystem(PanelSystem):
    """Frame rate, frame time, the editor's own share of it, draw calls, entity count, the GPU memory the renderer
    holds (by kind when hovered) and backend."""

    kind = "stats"
    #: The renderer's ``gpu_memory()`` report the panel last showed.
    gpu_memory: dict[str, int] | None = None

    def draw(self, panel: EditorPanelComponent) -> None:
        editor = self.editor
        app = editor.app
        renderer = app.renderer
        scene = self.scene
        if editor._entity_count_key != scene.membership_version:
            editor._entity_count = sum(1 for e in scene.entities if not is_editor_entity(scene, e))
            editor._entity_count_key = scene.membership_version
        # In a window: the wall clock, whatever the app's time step. Headless (captures, tests): the app's
        # own time step, so that a picture does not depend on how fast the machine was.
        seconds = editor.frame_seconds if app.window is not None else editor.frame_dt
        draws = renderer.stats["draw_calls"] + editor.viewport.draw_calls  # + the viewport's
        imgui.text(f"fps     {1.0 / seconds if seconds else 0.0:8.1f}   frame    {1000.0 * seconds:8.3f} ms")
        if app.window is not None:
            imgui.text(f"editor  {1000.0 * editor.gui_seconds:8.3f} ms")
        imgui.text(f"draws   {draws:8d}   entities {editor._entity_count:8d}")
        # The buffers and textures the renderer holds, as asked of the API; hovered: by kind.
        self.gpu_memory = held = renderer.gpu_memory()
        imgui.text(f"GPU mem {held['total'] / MIB:8.1f} MiB")
        if imgui.is_item_hovered():
            imgui.set_tooltip("\n".join(f"{kind:16s} {n / MIB:9.3f} MiB" for kind, n in held.items()
                                         if n and kind != "total"))
        self.remember("stats/gpu_memory")
        imgui.same_line()
        imgui.text(f"   backend {renderer.backend:>8}")


class FilePanelSystem(PanelSystem):
    """Save and Load of the scene as USD; the path is typed in, errors are shown whole in the panel."""

    kind = "file"

    def draw(self, panel: EditorPanelComponent) -> None:
        editor = self.editor
        changed, path = imgui.input_text("path", editor.path)
        if changed:
            editor.path = path
        if imgui.button("Save"):
            editor.save(editor.path)
        self.remember("file/save")
        imgui.same_line()
        if imgui.button("Load"):
            editor.load(editor.path)
        self.remember("file/load")
        if editor.status:
            wrapped(editor.status, ERROR_COLOR if editor.status_is_error else None)
            self.remember("file/status")


#: One system per panel kind, in drawing order (the menu bar first; the viewport's system also renders the scene
#: into its texture during the frame's update).
PANEL_SYSTEMS: tuple[type[PanelSystem], ...] = (
    MenuBarSystem, ViewportPanelSystem, HierarchyPanelSystem, InspectorPanelSystem, SystemsPanelSystem,
    ContentPanelSystem, ConsolePanelSystem, StatsPanelSystem, FilePanelSystem, FramePanelSystem, ShaderPanelSystem,
)

__all__ = ["PANEL_SYSTEMS", "PanelSystem", "_edited"]
