"""The Editor: an ImGui layer over a running Application, built from ECS entities and systems.

``enable_editor(app)`` creates an ImGui context, registers a GUI overlay on ``app.renderer`` (drawn over
each finished frame on both backends) and adds the editor to the active scene and to every scene the app
switches to: four panel entities (:class:`EditorPanelComponent`) and the systems that draw them in
``on_gui_update``. Each frame the overlay feeds ImGui from ``app.input``, runs ``scene.gui_update()``
(every system's GUI hook, the editor's and the scene's own) and draws the result.
``disable_editor(app)`` (or ``editor.disable()``) removes all of it again.
"""

from __future__ import annotations

import time
import uuid
import warnings
import weakref
from pathlib import Path
from typing import Any

from ..ecs import Scene, System
from .components import EditorPanelComponent

#: The editor of each application that has one enabled.
_EDITORS: weakref.WeakKeyDictionary[Any, Editor] = weakref.WeakKeyDictionary()


def _default_layout(width: int, height: int) -> list[tuple[str, str, tuple[float, float], tuple[float, float]]]:
    """(kind, title, position, size) of each panel: two columns at the sides, the middle left free."""
    left, right = 0.28 * width, 0.36 * width
    return [
        ("hierarchy", "Hierarchy", (0.0, 0.0), (left, 0.55 * height)),
        ("file", "Scene file", (0.0, 0.55 * height), (left, 0.45 * height)),
        ("inspector", "Inspector", (width - right, 0.0), (right, 0.62 * height)),
        ("stats", "Stats", (width - right, 0.62 * height), (right, 0.38 * height)),
    ]


class Editor:
    """The editor of one Application. Create it with :func:`enable_editor`."""

    def __init__(self, app: Any) -> None:
        from imgui_bundle import imgui

        self.app = app
        #: The entity the hierarchy panel selected and the inspector edits (or None).
        self.selected: uuid.UUID | None = None
        #: The Save/Load path typed in the file panel, and the last action's message.
        self.path = "scene.usda"
        self.status = ""
        self.status_is_error = False
        #: Pixel rectangles (x0, y0, x1, y1) of this frame's named widgets, e.g. "hierarchy/<uuid>".
        self.item_rects: dict[str, tuple[float, float, float, float]] = {}
        self._material_colors: dict[str, tuple[float, ...]] = {}
        self._installed: dict[int, tuple[Scene, list[uuid.UUID], list[System]]] = {}
        self._imgui = imgui
        self._context = imgui.create_context()
        imgui.set_current_context(self._context)
        imgui.get_io().set_ini_filename("")  # no imgui.ini next to the student's files
        renderer = app.renderer
        if renderer.backend == "opengl":
            from .gl_backend import GLGuiRenderer

            self._gui: Any = GLGuiRenderer(renderer.ctx)
        else:
            from .wgpu_backend import WGPUGuiRenderer

            self._gui = WGPUGuiRenderer(renderer.device, renderer.color_view.texture.format)
        self._last_time = app.clock.time
        #: Wall-clock seconds per frame (smoothed), for the stats panel; the GUI's own time step follows
        #: the app's clock, which may be a fixed step.
        self.frame_seconds = 0.0
        self._last_wall: float | None = None
        self.enabled = True
        renderer.overlays.append(self._overlay)
        app.scenes.on_switch.append(self._on_switch)
        # The app owns these hooks: its camera controllers ask whether a panel has the pointer, and closing
        # the app takes the editor down first.
        app.gui_wants_mouse = lambda: self.wants_mouse
        app.on_close.append(self.disable)
        if app.scenes.active is not None:
            self.install(app.scenes.active)

    # --- scenes -------------------------------------------------------------------------------------
    def install(self, scene: Scene) -> None:
        """Add the panel systems and panel entities to ``scene`` (once per scene)."""
        if id(scene) in self._installed:
            return
        from .panels import PANEL_SYSTEMS

        systems = [scene.add_system(cls(self)) for cls in PANEL_SYSTEMS]
        renderer = self.app.renderer
        panels = [EditorPanelComponent(kind, title, position=pos, size=size)
                  for kind, title, pos, size in _default_layout(renderer.width, renderer.height)]
        self._installed[id(scene)] = (scene, [scene.create_entity(p) for p in panels], systems)

    def uninstall(self, scene: Scene) -> None:
        """Remove the editor's entities and systems from ``scene``."""
        entry = self._installed.pop(id(scene), None)
        if entry is None:
            return
        _scene, entities, systems = entry
        for entity in entities:
            if entity in scene:
                scene.destroy_entity(entity)
        for system in systems:
            if system.scene is scene:
                scene.remove_system(system)

    def panels(self, scene: Scene | None = None) -> list[uuid.UUID]:
        """The editor's panel entities in ``scene`` (the active scene by default)."""
        scene = scene or self.app.scene
        entry = self._installed.get(id(scene))
        return list(entry[1]) if entry is not None else []

    def _on_switch(self, _previous: Scene | None, scene: Scene) -> None:
        self.install(scene)

    # --- the GUI frame ------------------------------------------------------------------------------
    def _overlay(self, renderer: Any, encoder: Any = None) -> None:
        imgui = self._imgui
        imgui.set_current_context(self._context)
        io = imgui.get_io()
        io.display_size = imgui.ImVec2(renderer.width, renderer.height)
        wall = time.perf_counter()
        if self._last_wall is not None:
            elapsed = wall - self._last_wall
            self.frame_seconds = elapsed if self.frame_seconds == 0.0 else 0.9 * self.frame_seconds + 0.1 * elapsed
        self._last_wall = wall
        now = self.app.clock.time
        dt, self._last_time = now - self._last_time, now
        io.delta_time = dt if dt > 0.0 else 1.0 / 60.0  # ImGui rejects a zero time step
        from .input_bridge import feed

        feed(io, self.app.input)
        self.item_rects = {}
        imgui.new_frame()
        try:
            self.app.scene.gui_update()
        finally:
            imgui.render()
        if encoder is None:
            self._gui.render(imgui.get_draw_data(), renderer.framebuffer)
        else:
            self._gui.render(imgui.get_draw_data(), encoder, renderer.color_view)

    @property
    def wants_mouse(self) -> bool:
        """True while the pointer is over a panel: camera controllers should leave the mouse alone."""
        if not self.enabled:
            return False
        self._imgui.set_current_context(self._context)
        return bool(self._imgui.get_io().want_capture_mouse)

    @property
    def wants_keyboard(self) -> bool:
        """True while a text field has the keyboard."""
        if not self.enabled:
            return False
        self._imgui.set_current_context(self._context)
        return bool(self._imgui.get_io().want_capture_keyboard)

    # --- material colours (sRGB, as the colour picker shows them) ----------------------------------
    def material_color(self, name: str) -> tuple[float, ...] | None:
        """The sRGB colour of material ``name`` the inspector shows, or None before the renderer built it."""
        if name not in self.app.renderer.materials:
            return None
        if name not in self._material_colors:
            data = self.app.scene.assets.materials.get(name)
            self._material_colors[name] = tuple(data.color) if data is not None else (1.0, 1.0, 1.0, 1.0)
        return self._material_colors[name][:3]

    def set_material_color(self, name: str, rgb: Any) -> None:
        """Change material ``name``'s colour at run time (no pipeline is rebuilt)."""
        current = self.material_color(name)
        if current is None:
            raise ValueError(f"material '{name}' has not been built by the renderer yet")
        color = (*(float(c) for c in rgb), self._material_colors[name][3])
        materials = self.app.renderer.materials
        material = materials.get(name)
        material.set_color(color)
        self._material_colors[name] = color
        # Write it back to the scene's assets too, so that Save keeps it.
        assets = self.app.scene.assets
        if name in assets.materials:
            data = assets.materials[name].with_color(color)
            assets.materials[name] = material.data = data
            materials.adopt(name, data)

    # --- Save / Load ----------------------------------------------------------------------------------
    def _report(self, message: str, error: bool) -> bool:
        self.status, self.status_is_error = message, error
        return not error

    def save(self, path: str | Path) -> bool:
        """Save the active scene, without the editor's entities, as USD; the outcome goes to ``status``."""
        try:
            from ..usd import save_scene
        except ImportError as exc:
            return self._report(f"cannot save: USD support is unavailable ({exc})", error=True)
        scene = self.app.scene
        try:
            with warnings.catch_warnings(record=True) as caught:  # the writer leaves the editor's panels out
                warnings.simplefilter("always")
                save_scene(scene, path)
        except Exception as exc:  # noqa: BLE001 - any failure is shown in the panel; the editor never crashes
            return self._report(f"save failed: {type(exc).__name__}: {exc}", error=True)
        notes = "; ".join(str(w.message) for w in caught)
        return self._report(f"saved {path}" + (f" ({notes})" if notes else ""), error=False)

    def load(self, path: str | Path) -> bool:
        """Load a USD scene and switch to it (from the next frame); the outcome goes to ``status``."""
        try:
            from ..usd import load_scene
        except ImportError as exc:
            return self._report(f"cannot load: USD support is unavailable ({exc})", error=True)
        try:
            scene = load_scene(path)
        except Exception as exc:  # noqa: BLE001 - any failure is shown in the panel; the editor never crashes
            return self._report(f"load failed: {type(exc).__name__}: {exc}", error=True)
        from .reuse import adopt_built_assets

        clashes = adopt_built_assets(scene.assets, self.app.scene.assets, self.app.renderer)
        if clashes:
            return self._report(f"load failed: {', '.join(clashes)} already in use with other data "
                                "(rename them in the file)", error=True)
        names = {s.name for s in self.app.scenes.scenes}
        base, n = scene.name, 1
        while scene.name in names:  # a loaded copy must not clash with a registered scene
            n += 1
            scene.name = f"{base} ({n})"
        self.app.switch_scene(scene)
        self.selected = None
        return self._report(f"loaded {path} as scene '{scene.name}'", error=False)

    # --- teardown -------------------------------------------------------------------------------------
    def disable(self) -> None:
        """Remove the overlay, the editor's entities and systems, and free its GPU objects and ImGui context."""
        if not self.enabled:
            return
        self.enabled = False
        app = self.app
        if self._overlay in app.renderer.overlays:
            app.renderer.overlays.remove(self._overlay)
        if self._on_switch in app.scenes.on_switch:
            app.scenes.on_switch.remove(self._on_switch)
        if self.disable in app.on_close:
            app.on_close.remove(self.disable)
        app.gui_wants_mouse = lambda: False
        for scene, _entities, _systems in list(self._installed.values()):
            self.uninstall(scene)
        self._imgui.set_current_context(self._context)
        self._gui.release()
        self._imgui.destroy_context(self._context)
        self._context = None
        if _EDITORS.get(app) is self:
            del _EDITORS[app]


def enable_editor(app: Any) -> Editor:
    """Turn the editor on for ``app`` (either backend, window or headless); returns the (only) Editor."""
    editor = _EDITORS.get(app)
    if editor is None:
        editor = _EDITORS[app] = Editor(app)
    return editor


def disable_editor(app: Any) -> None:
    """Turn the editor off for ``app`` (nothing happens when it is off)."""
    editor = _EDITORS.get(app)
    if editor is not None:
        editor.disable()


def editor_of(app: Any) -> Editor | None:
    """The app's enabled editor, or None."""
    return _EDITORS.get(app)
