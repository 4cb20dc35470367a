"""The engine's hooks: every step opens the final step's editor and saves USD without importing either.

``gandalf_core.app.extensions`` finds the ``editor`` and ``save_scene`` hooks by name (entry points declared in
``pyproject.toml``); every launcher's ``--editor`` and ``--save FILE`` go through them. Here each step (each
concept and technique of steps 05-07) is run from its own launcher with both options, in one API per part
(alternating, so both APIs are covered), and the file is read back: the scene's entities without the editor's
panels (``Component.saved = False``) and its systems without the render system and the panels
(``System.saved = False``). A technique whose state no file can hold is refused by name, and writes nothing.
"""

from __future__ import annotations

import importlib
import importlib.metadata

import pytest

from gandalf_core import System
from gandalf_core.app import extensions
from gandalf_core.app.cli import run_variant
from gandalf_tools.tour import find_steps, step_parts

pytest.importorskip("pxr")
pytest.importorskip("imgui_bundle")

PARTS = [part for step in find_steps() for part in step_parts(step)]
#: Parts whose state lives on the GPU (step 07's saved.py says why): saving them is refused.
#: Parts whose scene holds a system a file leaves out, with a warning naming it: step 05's scene switcher (its
#: key table names the app's other scenes; a file holds one scene).
LEFT_OUT = {"step05_scenegraph.several_scenes": "SceneSwitchSystem"}
UNSAVEABLE = {"step07_advanced.showcase": "ParticleSystem", "step07_advanced.terrain": "TessellationSystem",
              "step07_advanced.explode": "ExplodeSystem", "step07_advanced.pathtracer": "PathTraceSystem"}


def test_the_hooks_are_found_by_name():
    editor, save = extensions.extension("editor"), extensions.extension("save_scene")
    assert (editor.__module__, editor.__name__) == ("step07_advanced.editor.enable", "enable_editor")
    assert (save.__module__, save.__name__) == ("step07_advanced.usd", "save_scene")


def test_an_unknown_hook_and_a_missing_extension_are_named(monkeypatch):
    with pytest.raises(ValueError, match="'gizmo' is not a hook the engine offers"):
        extensions.extension("gizmo")
    monkeypatch.setattr(extensions, "entry_points", lambda **_: importlib.metadata.EntryPoints(()))
    with pytest.raises(extensions.ExtensionMissingError, match=r"no 'editor' extension is installed.*pip install"):
        extensions.extension("editor")


@pytest.mark.parametrize("part", PARTS)
def test_every_step_opens_the_editor_and_saves_usd(part, tmp_path, capsys):
    from step07_advanced.editor import editor_of
    from step07_advanced.usd import USDSceneError, USDSceneWarning, load_scene

    backend = ("opengl", "webgpu")[PARTS.index(part) % 2]
    variant = importlib.import_module(f"{part}.{backend}")
    path = tmp_path / "scene.usda"
    apps, counts = [], []

    class Count(System):
        """Counts the scene's entities (the editor's panels among them) and names its saved systems, every frame
        (not saved itself: the test's own)."""

        saved = False

        def on_update_system(self, ts: float) -> None:
            entities = self.scene.entities
            counts.append((len(entities), sum(not all(type(c).saved for c in self.scene.components_of(e))
                                              for e in entities),
                           [type(s).__name__ for s in self.scene.systems if type(s).saved]))

    def create_app(**options):
        apps.append(variant.create_app(**options))
        apps[-1].scene.add_system(Count())
        return apps[-1]

    argv = ["--headless", "--frames", "2", "--size", "96x64", "--editor", "--save", str(path)]
    if part in UNSAVEABLE:
        with pytest.raises(USDSceneError, match=UNSAVEABLE[part]):
            run_variant(create_app, argv)
        assert not path.exists(), "a refused save wrote a file"
        return
    if part in LEFT_OUT:
        with pytest.warns(USDSceneWarning, match=f"not saved .*system {LEFT_OUT[part]} "):
            assert run_variant(create_app, argv) == 0
    else:
        assert run_variant(create_app, argv) == 0
    assert f"saved {path}" in capsys.readouterr().out
    (app,) = apps
    assert editor_of(app) is None, "closing the app turns its editor off"
    entities, panels, systems = counts[-1]
    assert panels >= 5, f"the editor's panels were not in the scene while it ran ({panels})"
    loaded = load_scene(path)
    assert len(loaded.entities) == entities - panels
    assert [type(s).__name__ for s in loaded.systems] == [s for s in systems if s != LEFT_OUT.get(part)]
