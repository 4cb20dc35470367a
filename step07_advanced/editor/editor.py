"""The Editor: an ImGui layer over a running Application, built from ECS entities and systems.

``enable_editor(app)`` creates an ImGui context, registers a GUI overlay on ``app.renderer`` (drawn over
each finished frame on both backends) and adds the editor to the active scene and to every scene the app
switches to: one panel entity (:class:`EditorPanelComponent`) per panel kind and the systems that draw them
in ``on_gui_update``. Every edit goes through the undoable actions of
:class:`~step07_advanced.editor.actions.EditorActions`; the console shows the log
(:class:`~step07_advanced.editor.console_log.EditorLog`). Each frame the overlay feeds ImGui from ``app.input``,
runs ``scene.gui_update()`` (every system's GUI hook, the editor's and the scene's own) and draws the result.
``disable_editor(app)`` (or ``editor.disable()``) removes all of it again.
"""

from __future__ import annotations

import math
import time
import uuid
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from gandalf_core.ecs import Scene, System

from .actions import EditorActions
from .commands import Command, CommandStack
from .components import EditorPanelComponent
from .console_log import EditorLog

#: The editor of each application that has one enabled.


MENU_HEIGHT = 20.0


def _default_layout(width: int, height: int) -> list[tuple[str, str | None, tuple[float, float], tuple[float, float]]]:
    """(kind, title, position, size) of each panel: the menu bar on top, the viewport in the middle with the console
    under it, the hierarchy and content browser on the left, inspector, systems, stats and file on the right."""
    top = MENU_HEIGHT
    h = height - top
    left, mid = 0.22 * width, 0.50 * width
    right = width - left - mid
    return [
        ("menu", None, (0.0, 0.0), (float(width), top)),
        ("viewport", None, (left, top), (mid, 0.68 * h)),
        ("console", None, (left, top + 0.68 * h), (mid, 0.32 * h)),
        ("hierarchy", None, (0.0, top), (left, 0.5 * h)),
        ("content", None, (0.0, top + 0.5 * h), (left, 0.5 * h)),
        ("inspector", None, (left + mid, top), (right, 0.46 * h)),
        ("systems", None, (left + mid, top + 0.46 * h), (right, 0.24 * h)),
        ("stats", None, (left + mid, top + 0.70 * h), (right, 0.17 * h)),
        ("file", None, (left + mid, top + 0.87 * h), (right, 0.13 * h)),
    ]


def _closed_layout(width: int, height: int) -> list[tuple[str, str | None, tuple[float, float], tuple[float, float]]]:
    """The panels that start closed (View menu, or a button that opens them): the shader panel over the left column
    and the viewport's left third, so that most of the picture and the inspector stay in sight; the frame inspector
    over the right column."""
    top = MENU_HEIGHT
    left, mid = 0.22 * width, 0.50 * width
    return [("shader", None, (0.0, top), (left + 0.17 * width, height - top)),
            ("frame", None, (left + mid, top), (width - left - mid, height - top))]


class Editor(EditorActions):
    """The editor of one Application. Create it with :func:`enable_editor`."""

    def __init__(self, app: Any, panel_systems: Sequence[type[System]]) -> None:
        from imgui_bundle import imgui

        self.app = app
        #: The panel system classes added to each scene (:data:`.panels.PANEL_SYSTEMS`: the panels import the
        #: editor's type, the editor does not import the panels).
        self.panel_systems = tuple(panel_systems)
        #: The entity the hierarchy panel selected and the inspector edits (or None).
        self.selected: uuid.UUID | None = None
        #: The Save/Load path typed in the file panel, and the last action's message.
        self.path = "scene.usda"
        self.status = ""
        self.status_is_error = False
        #: Pixel rectangles (x0, y0, x1, y1) of this frame's named widgets, e.g. "hierarchy/<uuid>".
        self.item_rects: dict[str, tuple[float, float, float, float]] = {}
        self._material_colors: dict[str, tuple[float, ...]] = {}
        #: The undo/redo history of every edit.
        self.commands = CommandStack()
        #: The console's entries: log records, warnings and the editor's errors.
        self.log = EditorLog()
        self.log.install()
        #: Files saved or opened, newest first (File > Open Recent).
        self.recent: list[str] = []
        #: Whether the pointer is over the gizmo / the gizmo is being dragged (this frame).
        self.gizmo_over = self.gizmo_using = False
        #: The gizmo handle under the pointer ("move_x", "rotate_screen", ... or "none").
        self.gizmo_hovered = "none"
        #: Seconds the last GUI frame took (ImGui's frame, the panels, drawing it).
        self.gui_seconds = 0.0
        self._payloads: dict[int, tuple[str, Any]] = {}
        self._payload_ids: dict[tuple[str, Any], int] = {}
        self._entity_count, self._entity_count_key = 0, -1
        self._shader_sources: dict[str, tuple[Any, ...]] = {}
        self._shader_edits: Any = None
        #: Seconds (app clock) between the panels' runs while the GUI is idle; 0 runs them every frame.
        self.gui_interval = 1.0 / 20.0
        #: Frames that ran the panels, and frames that drew the last GUI frame again (see ``_gui_due``).
        self.gui_frames = self.skipped_gui_frames = 0
        self._busy_frames = 0
        #: The app clock's step between the last two frames (what the stats panel shows headless).
        self.frame_dt = 1.0 / 60.0
        self._prev_now: float | None = None
        self._state_key: Any = None
        self._gui_held = False
        self._panels_cache: tuple[Scene, int, list[EditorPanelComponent]] | None = None
        self._installed: dict[int, tuple[Scene, list[uuid.UUID], list[System]]] = {}
        self._imgui = imgui
        self._context = imgui.create_context()
        imgui.set_current_context(self._context)
        imgui.get_io().set_ini_filename("")  # no imgui.ini next to the student's files
        editor_style(imgui.get_style())
        renderer = app.renderer
        if renderer.backend == "opengl":
            from .backend_gl import GLGuiRenderer

            self._gui: Any = GLGuiRenderer(renderer.ctx)
        else:
            from .backend_wgpu import WGPUGuiRenderer

            self._gui = WGPUGuiRenderer(renderer.device, renderer.color_view.texture.format,
                                        renderer.depth_view.texture.format)
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
    # --8<-- [start:install]
    def install(self, scene: Scene) -> None:
        """Add the panel systems and panel entities to ``scene`` (once per scene)."""
        if id(scene) in self._installed:
            return
        from gandalf_core.render import RenderSystem

        systems = [scene.add_system(cls(self)) for cls in self.panel_systems]
        # A panel that acts in the frame's update (the viewport renders the scene into its texture) goes before the
        # frame's render system, whose overlay draws the GUI that shows the texture.
        render = [i for i, s in enumerate(scene.systems) if isinstance(s, RenderSystem)]
        if render:
            for system in systems:
                if system.updates_each_frame:
                    scene.move_system(system, render[0])
        renderer = self.app.renderer
        panels = [EditorPanelComponent(kind, title, position=pos, size=size)
                  for kind, title, pos, size in _default_layout(renderer.width, renderer.height)]
        panels += [EditorPanelComponent(kind, title, visible=False, position=pos, size=size)
                   for kind, title, pos, size in _closed_layout(renderer.width, renderer.height)]
        self._installed[id(scene)] = (scene, [scene.create_entity(p) for p in panels], systems)
    # --8<-- [end:install]

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
    def _overlay(self, renderer: Any, render_pass: Any = None) -> None:
        wall = time.perf_counter()
        if self._last_wall is not None:
            elapsed = wall - self._last_wall
            self.frame_seconds = elapsed if self.frame_seconds == 0.0 else 0.9 * self.frame_seconds + 0.1 * elapsed
        self._last_wall = wall
        now = self.app.clock.time
        if self._prev_now is not None and now > self._prev_now:
            self.frame_dt = now - self._prev_now
        self._prev_now = now
        if self._gui_due(now):
            imgui = self._imgui
            imgui.set_current_context(self._context)
            io = imgui.get_io()
            io.display_size = imgui.ImVec2(renderer.width, renderer.height)
            self._gui_frame(io, now)
            self._gui.draw_layer(imgui.get_draw_data(), renderer.width, renderer.height)
        else:
            self.skipped_gui_frames += 1
        # Every frame: the GUI layer (and the live images) over this frame, whose scene has moved.
        if render_pass is None:
            self._gui.composite(renderer.framebuffer)
        else:
            self._gui.composite(render_pass, renderer.width, renderer.height)
        self.gui_seconds = time.perf_counter() - wall

    def _gui_due(self, now: float) -> bool:
        """Whether this frame runs the panels (an ImGui frame) or only draws the last one's GUI layer again.

        The panels run on every frame with input (and the two after it), while a widget is held or the gizmo
        dragged, whenever the editor's state changed (an edit, the selection, entities, the log, a panel moved
        or hidden), and at least every :attr:`gui_interval` seconds of the app's clock; in between an idle GUI
        costs only its compositing. What ImGui knows (a held widget, text input) is read at the end of each GUI
        frame: it cannot change without one.
        """
        if self.gui_interval <= 0.0 or self.gui_frames == 0 or self._gui_held:
            return True
        if self.app.input.events:
            self._busy_frames = 3
        if self._busy_frames > 0:
            self._busy_frames -= 1
            return True
        scene = self.app.scene
        renderer = self.app.renderer
        key = (self.commands.version, self.selected, id(scene), scene.membership_version, scene.hierarchy_version,
               self.log.version, self.status, renderer.width, renderer.height,
               tuple([(p.visible, p.position, p.size) for p in self._panel_components(scene)]))
        if key != self._state_key:
            self._state_key = key
            return True
        return now - self._last_time >= self.gui_interval

    def invalidate_gui(self) -> None:
        """Run the panels on the next frame (the last GUI frame's draw lists are out of date)."""
        self._state_key = None

    def _panel_components(self, scene: Scene) -> list[EditorPanelComponent]:
        """The panel entities' components in ``scene``, looked up again only when its entities change."""
        cached = self._panels_cache
        if cached is None or cached[0] is not scene or cached[1] != scene.membership_version:
            panels = [scene.get_component(e, EditorPanelComponent) for e in self.panels(scene) if e in scene]
            cached = self._panels_cache = (scene, scene.membership_version, panels)
        return cached[2]

    def _gui_frame(self, io: Any, now: float) -> None:
        imgui = self._imgui
        dt, self._last_time = now - self._last_time, now
        io.delta_time = dt if dt > 0.0 else 1.0 / 60.0  # ImGui rejects a zero time step
        from imgui_bundle import imguizmo

        from .input_bridge import feed

        feed(io, self.app.input)
        self.item_rects = {}
        imgui.new_frame()
        imguizmo.im_guizmo.begin_frame()
        try:
            self.app.scene.gui_update()
            if not imgui.is_any_item_active() and not self.gizmo_using:
                self.commands.seal()  # the drag (if any) is over: the next edit is a new undo step
        finally:
            imgui.render()
        self.gui_frames += 1
        # A widget held or text being typed: the next frame runs the panels too (see _gui_due).
        self._gui_held = bool(imgui.is_any_item_active() or io.want_text_input or self.gizmo_using)

    @property
    def wants_mouse(self) -> bool:
        """True while the pointer is over a panel: camera controllers should leave the mouse alone."""
        return self._io_wants("want_capture_mouse")

    @property
    def wants_keyboard(self) -> bool:
        """True while a text field has the keyboard."""
        return self._io_wants("want_capture_keyboard")

    def _io_wants(self, flag: str) -> bool:
        """Dear ImGui's ``io.<flag>`` for this editor's context (False while the editor is off)."""
        if not self.enabled:
            return False
        self._imgui.set_current_context(self._context)
        return bool(getattr(self._imgui.get_io(), flag))

    # --- material colours (sRGB, as the colour picker shows them) ----------------------------------
    def material_color(self, name: str) -> tuple[float, ...] | None:
        """The sRGB colour of material ``name`` the inspector shows, or None before the renderer built it."""
        if name not in self.app.renderer.materials:
            return None
        if name not in self._material_colors:
            data = self.app.scene.assets.materials.get(name)
            self._material_colors[name] = tuple(data.color) if data is not None else (1.0, 1.0, 1.0, 1.0)
        return self._material_colors[name][:3]

    def set_material_color(self, name: str, rgb: Any, merge: bool = False) -> None:
        """Change material ``name``'s colour at run time (no pipeline is rebuilt); undoable."""
        current = self.material_color(name)
        if current is None:
            raise ValueError(f"material '{name}' has not been built by the renderer yet")
        before = self._material_colors[name]
        after = (*(float(c) for c in rgb), before[3])
        if len(after) != 4 or not all(math.isfinite(c) and c >= 0.0 for c in after):
            raise ValueError(f"material '{name}': a colour needs 3 finite values >= 0 (sRGB), got {rgb!r}")
        if after == before:
            return
        self.commands.push(Command(f"colour of {name}", lambda: self._put_material_color(name, after),
                                   lambda: self._put_material_color(name, before), merge_key=("color", name)),
                           merge=merge)

    def _put_material_color(self, name: str, color: tuple[float, ...]) -> None:
        if self.material_color(name) is None:  # rebuilt since (e.g. a texture changed): built again on next use
            data = self.app.scene.assets.materials.get(name)
            if data is not None:
                self.app.scene.assets.material(name, data.with_color(color))
            self._material_colors.pop(name, None)
            return
        materials = self.app.renderer.materials
        material = materials.get(name)
        if material.data is not self.app.scene.assets.materials.get(name, material.data):
            # The scene's data changed since the build (a texture swapped): the renderer builds it again anyway.
            self.app.scene.assets.material(name, self.app.scene.assets.materials[name].with_color(color))
            self._material_colors[name] = color
            return
        material.set_color(color)
        self._material_colors[name] = color
        # Write it back to the scene's assets too, so that Save keeps it.
        assets = self.app.scene.assets
        if name in assets.materials:
            data = assets.materials[name].with_color(color)
            assets.materials[name] = material.data = data
            materials.adopt(name, data)

    # --- errors, drag payloads, panels, systems ------------------------------------------------------
    def attempt(self, action: Any, *args: Any, **kwargs: Any) -> Any:
        """Run ``action``; an error is logged to the console whole and shown as the status, never raised."""
        try:
            return action(*args, **kwargs)
        except Exception as exc:  # noqa: BLE001 - the editor shows every failure and keeps running
            self._report(f"{type(exc).__name__}: {exc}", error=True)
            return None

    def payload_id(self, kind: str, value: Any) -> int:
        """A small integer standing for a dragged thing (ImGui payloads carry numbers)."""
        key = (kind, value)
        pid = self._payload_ids.get(key)
        if pid is None:
            pid = self._payload_ids[key] = len(self._payloads) + 1
            self._payloads[pid] = key
        return pid

    def payload(self, pid: int) -> tuple[str, Any]:
        return self._payloads.get(pid, ("", None))

    def panel(self, kind: str, scene: Scene | None = None) -> EditorPanelComponent | None:
        """The (first) panel component of ``kind`` in ``scene`` (the active one by default)."""
        scene = scene or self.app.scene
        for entity in self.panels(scene):
            component = scene.get_component(entity, EditorPanelComponent)
            if component.kind == kind:
                return component
        return None

    def panel_system(self, kind: str, scene: Scene | None = None) -> Any:
        """The editor's system drawing panels of ``kind`` in ``scene`` (the active one by default)."""
        scene = scene or self.app.scene
        entry = self._installed.get(id(scene))
        return next((s for s in entry[2] if s.kind == kind), None) if entry is not None else None

    @property
    def viewport(self) -> Any:
        """The viewport panel's system (its ``target`` holds the scene rendered at the panel's size)."""
        return self.panel_system("viewport")

    def panel_visible(self, kind: str) -> bool:
        panel = self.panel(kind)
        return panel is not None and panel.visible

    def show_panel(self, kind: str, visible: bool = True) -> None:
        """Show or hide the panel of ``kind`` (View menu)."""
        panel = self.panel(kind)
        if panel is None:
            raise ValueError(f"editor: no panel of kind {kind!r}")
        panel.visible = bool(visible)

    def set_system_enabled(self, system: System, enabled: bool) -> None:
        """Pause (False) or resume (True) ``system``, undoably; the render system cannot be paused (it draws the
        editor)."""
        from gandalf_core.render import RenderSystem

        if isinstance(system, RenderSystem) and not enabled:
            raise ValueError("editor: the RenderSystem cannot be paused (it draws the frame and the editor)")
        if system not in self.app.scene.systems:
            raise ValueError(f"editor: {system.name} is not a system of scene '{self.app.scene.name}'")
        before, after = system.enabled, bool(enabled)
        if before == after:
            return

        def put(value: bool) -> None:
            system.enabled = value

        self.commands.push(Command(f"{'resume' if after else 'pause'} {system.name}", lambda: put(after),
                                   lambda: put(before)))

    def step_system(self, system: System) -> None:
        """Run a (paused) system once with the app's time step."""
        clock = self.app.clock
        ts = clock.fixed_dt if getattr(clock, "fixed_dt", None) else (self.frame_seconds or 1.0 / 60.0)
        self.app.scene.run_system(system, ts)

    def move_system(self, system: System, delta: int) -> None:
        """Move ``system`` ``delta`` places in the update order (among all the scene's systems), undoably."""
        scene = self.app.scene
        if system not in scene.systems:
            raise ValueError(f"editor: {system.name} is not a system of scene '{scene.name}'")
        before = scene.systems.index(system)
        after = max(0, min(before + int(delta), len(scene.systems) - 1))
        if before == after:
            return
        self.commands.push(Command(f"move {system.name}", lambda: scene.move_system(system, after),
                                   lambda: scene.move_system(system, before)))

    # --- shaders ----------------------------------------------------------------------------------------
    @property
    def shader_edits(self) -> Any:
        """The shader panel's model (:class:`~step07_advanced.editor.shader_edits.ShaderEdits`), made on first use."""
        if self._shader_edits is None:
            from .shader_edits import ShaderEdits

            self._shader_edits = ShaderEdits(self)
        return self._shader_edits

    def shader_files(self, name: str) -> tuple[Any, ...]:
        """The files shader ``name`` was built from (empty when it was built from text)."""
        built = self._shader_sources.get(name)
        return built if built is not None else ()

    def build_shader(self, name: str, *files: str | Path) -> bool:
        """(Re)build shader ``name`` from ``files``; a compile error goes to the console with its file:line."""
        shaders = self.app.renderer.shaders
        try:
            material = None  # a rebuilt shader keeps its Material block
            if name in shaders:
                material = shaders.get(name).material_block
                shaders.forget(name)
            shaders.build(name, *files, material=material)
        except Exception as exc:  # noqa: BLE001 - shown in the console, whole
            return self._report(f"shader '{name}': {exc}", error=True)
        self._shader_sources[name] = tuple(files)
        return self._report(f"built shader '{name}'", error=False)

    def reload_shader(self, name: str) -> bool:
        """Compile shader ``name`` again from the files :meth:`build_shader` built it from; on an error the last
        good program keeps drawing (``renderer.shaders.rebuild``)."""
        files = self.shader_files(name)
        if not files:
            return self._report(f"shader '{name}': no files to reload it from", error=True)
        if name not in self.app.renderer.shaders:
            return self.build_shader(name, *files)
        error = self.app.renderer.shaders.rebuild(name)
        if error is not None:
            return self._report(f"shader '{name}': {error} (the last good program keeps drawing)", error=True)
        return self._report(f"built shader '{name}'", error=False)

    # --- New / Save / Load ------------------------------------------------------------------------------
    def _report(self, message: str, error: bool) -> bool:
        self.status, self.status_is_error = message, error
        if error:
            self.log.error(message)
        else:
            self.log.add("info", "editor", message)
        return not error

    def _remember_file(self, path: str | Path) -> None:
        text = str(path)
        self.recent = [text] + [p for p in self.recent if p != text][:7]
        self.path = text

    def new_scene(self) -> Scene:
        """Switch to a new, empty scene (named "untitled", numbered when taken) that shares the running assets."""
        names = {s.name for s in self.app.scenes.scenes}
        name, n = "untitled", 1
        while name in names:
            n += 1
            name = f"untitled ({n})"
        scene = Scene(name)
        scene.assets = self.app.scene.assets  # the renderer's named resources stay valid
        self.app.switch_scene(scene)
        self.selected = None
        self.commands.clear()
        self._report(f"new scene '{name}'", error=False)
        return scene

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
        self._remember_file(path)
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
            return self._report(f"load failed: {', '.join(clashes)} already built by the program's own code "
                                "with other data (rename them in the file)", error=True)
        names = {s.name for s in self.app.scenes.scenes}
        base, n = scene.name, 1
        while scene.name in names:  # a loaded copy must not clash with a registered scene
            n += 1
            scene.name = f"{base} ({n})"
        self.app.switch_scene(scene)
        self.selected = None
        self.commands.clear()
        self._material_colors.clear()
        self._remember_file(path)
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
        self.log.uninstall()
        self._imgui.set_current_context(self._context)
        self._gui.release()
        self._imgui.destroy_context(self._context)
        self._context = None


def editor_style(style: Any) -> None:
    """The editor's ImGui style: ImGui's own, with windows, menus and popups opaque. The GUI layer is blended over
    the scene in linear light (see :mod:`step07_advanced.editor.gui_layer`), which would let a translucent window
    show much more of a bright scene than ImGui's byte-space blending does; opaque, it shows ImGui's own bytes."""
    from imgui_bundle import imgui

    for colour in (imgui.Col_.window_bg, imgui.Col_.popup_bg, imgui.Col_.menu_bar_bg):
        value = style.color_(colour)
        style.set_color_(colour, imgui.ImVec4(value.x, value.y, value.z, 1.0))
