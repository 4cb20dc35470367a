"""SceneManager: several scenes in one app, with deferred switching.

A switch requested during a frame (e.g. from a key handler inside a system) takes effect at the start
of the next frame, so no system ever sees the world change under it mid-frame.
"""

from __future__ import annotations

from collections.abc import Callable

from .scene import Scene


class SceneManager:
    """Holds scenes by name and which one is active."""

    def __init__(self) -> None:
        self._scenes: dict[str, Scene] = {}
        self._active: Scene | None = None
        self._pending: Scene | None = None
        self.on_switch: list[Callable[[Scene | None, Scene], None]] = []

    def add(self, scene: Scene) -> Scene:
        if scene.name in self._scenes and self._scenes[scene.name] is not scene:
            raise ValueError(f"a different scene named '{scene.name}' is already registered")
        self._scenes[scene.name] = scene
        if self._active is None:
            self._activate(scene)
        return scene

    @property
    def scenes(self) -> list[Scene]:
        return list(self._scenes.values())

    @property
    def active(self) -> Scene | None:
        return self._active

    def get(self, name: str) -> Scene:
        try:
            return self._scenes[name]
        except KeyError:
            raise KeyError(f"no scene named '{name}' (have: {', '.join(self._scenes) or 'none'})") from None

    def request_switch(self, scene: Scene | str) -> None:
        """Ask to make ``scene`` active from the next frame on."""
        target = self.get(scene) if isinstance(scene, str) else scene
        if self._scenes.get(target.name) is not target:
            self.add(target)  # registers it, or raises if a different scene already has that name
        self._pending = target

    def apply_pending(self) -> bool:
        """Perform a requested switch (called by the app at the start of a frame). Returns True if switched."""
        if self._pending is None or self._pending is self._active:
            self._pending = None
            return False
        target, self._pending = self._pending, None
        self._activate(target)
        return True

    def _activate(self, scene: Scene) -> None:
        previous, self._active = self._active, scene
        for callback in self.on_switch:
            callback(previous, scene)
