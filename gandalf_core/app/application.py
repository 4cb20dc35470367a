"""The Application: the frame loop over a scene manager, with an OpenGL or a WebGPU renderer.

With a display it opens a glfw window; without one (or with ``headless=True``) it renders offscreen.
Both take the same path: every frame is drawn offscreen and then, in a window, presented.

Frame order: apply a pending scene switch, poll input, handle resizes, then run the active scene's
systems in their order — the scene's own systems, then the core ones the app adds when missing
(TransformSystem, LightSystem), then the RenderSystem, last.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from ..ecs import Scene, SceneManager
from ..render.base import Renderer, check_backend
from ..render.capabilities import FLOOR, Needs
from .clock import Clock
from .input import Input, ResizeEvent
from .window import Window, display_available

#: Pressing this key closes the window (as closing it with the mouse does).
CLOSE_KEY = "ESCAPE"


def _never() -> bool:
    return False


class Application:
    """Runs scenes with one backend. ``backend`` is 'opengl' or 'webgpu'; ``editor=True`` turns on the
    editor (both backends), the course's ``editor`` extension (:mod:`gandalf_core.app.extensions`); ``needs``
    (:class:`~gandalf_core.render.capabilities.Needs`) is what the scenes need beyond OpenGL 3.3 / WebGPU's
    defaults, checked before anything is built (a :class:`~gandalf_core.render.capabilities.CapabilityError`)."""

    def __init__(
        self,
        backend: str = "opengl",
        width: int = 640,
        height: int = 480,
        *,
        title: str = "gandalf",
        headless: bool | None = None,
        fixed_dt: float | None = None,
        editor: bool = False,
        needs: Needs = FLOOR,
    ) -> None:
        self.backend = check_backend(backend)  # fails before any GPU library is imported
        for label, value in (("width", width), ("height", height)):
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value <= 0:
                raise ValueError(f"Application: {label} must be a positive whole number of pixels, got {value!r}")
        self.headless = (not display_available()) if headless is None else bool(headless)
        self.input = Input()
        self.clock = Clock(fixed_dt)
        self.scenes = SceneManager()
        self.scenes.on_switch.append(self._on_switch)
        self.window = None if self.headless else Window(width, height, title, self.backend, self.input)
        if self.window is not None:
            # On a high-DPI screen the framebuffer has more pixels than the window has points.
            width, height = self.window.framebuffer_size
        from ..render import create_renderer

        try:
            self.renderer: Renderer = create_renderer(self.backend, width, height, self.window, needs)
        except BaseException:  # a context that lacks what ``needs`` states, or no GPU: no window left behind
            if self.window is not None:
                self.window.close()
            raise
        self._prepared: set[int] = set()
        self.running = False
        self._closed = False
        self._assets_key: tuple[tuple[int, int], ...] | None = None
        #: Asked before a camera controller reads the mouse: a GUI layer (the editor) that has the pointer over
        #: one of its panels sets this to say so. The app owns the flag, so no system needs to know the GUI.
        self.gui_wants_mouse: Callable[[], bool] = _never
        #: Called (newest first) when the app closes, before the scenes and the renderer go: layers added
        #: on top of the app (the editor) tear themselves down here.
        self.on_close: list[Callable[[], None]] = []
        if editor:  # found by name only when asked for (an extension): the engine imports no editor
            from .extensions import extension

            extension("editor")(self)

    # --- scenes -------------------------------------------------------------------------------
    def add_scene(self, scene: Scene) -> Scene:
        """Register a scene; the first one becomes active. A scene belongs to one application at a time."""
        self._check_open("add_scene")
        if not isinstance(scene, Scene):
            raise TypeError(f"Application.add_scene: {scene!r} is not a Scene")
        if scene.app is not None and scene.app is not self and not scene.app.closed:
            raise ValueError(f"scene '{scene.name}' already runs in another Application; a scene's systems and "
                             "resources belong to one renderer: build a second scene for the second app")
        scene.app = self
        return self.scenes.add(scene)

    @property
    def closed(self) -> bool:
        """True after :meth:`close`: the renderer and the window are gone."""
        return self._closed

    def _check_open(self, what: str) -> None:
        if self._closed:
            raise RuntimeError(f"Application.{what}: the application was closed (its renderer and window are gone)")

    @property
    def scene(self) -> Scene:
        if self.scenes.active is None:
            raise RuntimeError("the application has no scene: call app.add_scene(scene) first")
        return self.scenes.active

    def switch_scene(self, scene: Scene | str) -> None:
        """Switch scenes at the start of the next frame."""
        self.scenes.request_switch(scene)

    def _on_switch(self, _previous: Scene | None, scene: Scene) -> None:
        scene.app = self
        self._prepare(scene)

    def _prepare(self, scene: Scene) -> None:
        # Core systems are added once per scene, after the scene's own systems.
        if id(scene) in self._prepared:
            return
        from ..render import RenderSystem
        from ..systems import LightSystem, TransformSystem

        systems = scene.systems
        if not any(isinstance(s, TransformSystem) for s in systems):
            # World matrices must be current before a scene's own light system reads them.
            lights = [i for i, s in enumerate(systems) if isinstance(s, LightSystem)]
            scene.add_system(TransformSystem(), index=lights[0] if lights else None)
        if not any(isinstance(s, LightSystem) for s in systems):
            scene.add_system(LightSystem())
        scene.add_system(RenderSystem(self.renderer))
        self._prepared.add(id(scene))

    # --- the loop -------------------------------------------------------------------------------
    # --8<-- [start:step]
    def step(self, dt: float | None = None) -> float:
        """Run exactly one frame and return its time step."""
        self._check_open("step")
        self.scenes.apply_pending()
        scene = self.scene
        self._prepare(scene)
        if self.window is not None:
            self.window.poll()
        for event in self.input.begin_frame():
            if isinstance(event, ResizeEvent):
                self.renderer.resize(event.width, event.height)
        if self.window is not None and self.input.pressed(CLOSE_KEY):
            self.window.request_close()
        ts = self.clock.tick(dt)
        scene.update(ts)
        self._collect_resources()
        return ts

    def _collect_resources(self) -> None:
        """When any scene's assets changed, release the GPU objects of assets no scene has any more."""
        key = tuple((id(s), s.assets.version) for s in self.scenes.scenes)
        if key != self._assets_key:
            if self._assets_key is not None:
                self.renderer.collect([s.assets for s in self.scenes.scenes])
            self._assets_key = key
    # --8<-- [end:step]

    def run(self, frames: int | None = None, seconds: float | None = None) -> None:
        """Run until the window closes, or for ``frames`` frames / ``seconds`` of clock time."""
        self._check_open("run")
        if frames is not None and (isinstance(frames, bool) or not isinstance(frames, (int, np.integer))
                                   or frames < 0):
            raise ValueError(f"Application.run: frames must be a whole number >= 0, got {frames!r}")
        if seconds is not None and (isinstance(seconds, bool) or not isinstance(seconds, (int, float, np.number))
                                    or not np.isfinite(seconds) or seconds < 0):
            raise ValueError(f"Application.run: seconds must be a finite number >= 0, got {seconds!r}")
        self.running = True
        self.clock.restart()
        start = self.clock.time
        count = 0
        while self.running:
            if self.window is not None and self.window.should_close:
                break
            if frames is not None and count >= frames:
                break
            if seconds is not None and self.clock.time - start >= seconds:
                break
            if frames is None and seconds is None and self.window is None:
                raise RuntimeError("a headless run needs frames= or seconds= (there is no window to close)")
            self.step()
            count += 1
        self.running = False

    def stop(self) -> None:
        self.running = False

    # --- capture --------------------------------------------------------------------------------
    def capture(self) -> np.ndarray:
        """The last frame as a ``(height, width, 4)`` uint8 RGBA array, top row first."""
        self._check_open("capture")
        return self.renderer.read_pixels()

    def save_png(self, path: str | Path) -> Path:
        self._check_open("save_png")
        return self.renderer.save_png(path)

    def close(self) -> None:
        """Tear down the layers on top (the editor, if on), every scene's systems, the renderer and the window.
        Closing twice does nothing; using the app afterwards is an error."""
        if self._closed:
            return
        self._closed = True
        for callback in reversed(list(self.on_close)):
            callback()
        self.on_close.clear()
        for scene in self.scenes.scenes:
            scene.teardown()
        self.renderer.release()
        if self.window is not None:
            self.window.close()

    def __enter__(self) -> Application:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()
