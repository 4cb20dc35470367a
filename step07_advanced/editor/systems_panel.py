"""The systems panel: the scene's systems in update order, each with pause/resume, a single step and its time.

The update order is the order of the list (the arrows move a system up or down). A paused system (its ``enabled``
flag off) is skipped by the frame; "step" runs it once with the app's time step. The time is the system's last
``on_update_system`` in milliseconds (smoothed), measured by the scene (``System.update_seconds``). The render
system cannot be paused (it draws the editor too), and the editor's own systems are not listed.
"""

from __future__ import annotations

from imgui_bundle import imgui

from gandalf_core.ecs import System

from .components import EditorPanelComponent
from .panel_base import PanelSystem


class SystemsPanelSystem(PanelSystem):
    """Order, pause/resume, single step and time per system."""

    kind = "systems"

    def __init__(self, editor) -> None:  # noqa: ANN001 - the Editor
        super().__init__(editor)
        self.smoothed: dict[int, float] = {}

    def listed(self) -> list[System]:
        """The scene's systems the panel shows, in update order (the editor's own left out)."""
        return [s for s in self.scene.systems if getattr(s, "editor", None) is not self.editor]

    def draw(self, panel: EditorPanelComponent) -> None:
        from gandalf_core.render import RenderSystem

        editor = self.editor
        systems = self.listed()
        flags = imgui.TableFlags_.row_bg | imgui.TableFlags_.borders_inner_v | imgui.TableFlags_.sizing_stretch_prop
        if not imgui.begin_table("systems", 4, flags):
            return
        imgui.table_setup_column("order", imgui.TableColumnFlags_.width_fixed)
        imgui.table_setup_column("run", imgui.TableColumnFlags_.width_fixed)
        imgui.table_setup_column("ms", imgui.TableColumnFlags_.width_fixed)
        imgui.table_setup_column("system", imgui.TableColumnFlags_.width_stretch)
        imgui.table_headers_row()
        for i, system in enumerate(systems):
            key = id(system)
            ms = 1000.0 * system.update_seconds
            ms = self.smoothed[key] = 0.9 * self.smoothed.get(key, ms) + 0.1 * ms
            imgui.push_id(i)
            imgui.table_next_row()
            imgui.table_next_column()
            if imgui.arrow_button("##up", imgui.Dir.up):
                editor.move_system(system, -1)
            self.remember(f"systems/up/{system.name}")
            imgui.same_line()
            if imgui.arrow_button("##down", imgui.Dir.down):
                editor.move_system(system, +1)
            self.remember(f"systems/down/{system.name}")
            imgui.table_next_column()
            imgui.begin_disabled(isinstance(system, RenderSystem))
            changed, on = imgui.checkbox("##run", system.enabled)
            self.remember(f"systems/run/{system.name}")
            if changed:
                editor.set_system_enabled(system, on)
            imgui.end_disabled()
            imgui.same_line()
            imgui.begin_disabled(system.enabled)
            if imgui.small_button("step"):
                self.act(editor.step_system, system)
            self.remember(f"systems/step/{system.name}")
            imgui.end_disabled()
            imgui.table_next_column()
            imgui.text(f"{ms:6.3f}")
            imgui.table_next_column()
            imgui.text(system.name if system.enabled else f"{system.name} (paused)")
            imgui.pop_id()
        imgui.end_table()
