"""The several scenes' system: read the keyboard and ask the app to show another scene."""

from __future__ import annotations

from gandalf_core import System


class SceneSwitchSystem(System):
    """Reads the keyboard and asks the app to switch scenes (taking effect at the next frame).

    ``keys`` maps key names to scene names; ``cycle_key`` goes to the next scene in the app's order.
    """

    def __init__(self, keys: dict[str, str], cycle_key: str = "TAB") -> None:
        super().__init__([])
        self.keys = {k.upper(): v for k, v in keys.items()}
        self.cycle_key = cycle_key.upper()

    # --8<-- [start:switch]
    def on_update_system(self, ts: float) -> None:
        app = self.scene.app
        if app is None:
            return
        for key, scene_name in self.keys.items():
            if app.input.pressed(key):
                app.switch_scene(scene_name)
        if app.input.pressed(self.cycle_key):
            names = [s.name for s in app.scenes.scenes]
            app.switch_scene(names[(names.index(self.scene.name) + 1) % len(names)])
    # --8<-- [end:switch]
