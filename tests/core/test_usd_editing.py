"""Loading a USD scene into an app whose material colours were edited at run time, in both APIs.

It used to fail with "material 'M' already in use with other data": the renderer had built 'M' from the running
scene's data, and the file held other data under that name. The renderer now follows each scene's assets: a name
whose data differs is built again from the scene being drawn, and the editor's Load no longer refuses such a name
(only names the program built itself with other data). The picture checks use the centre pixel of a
96x72 frame filled by an unlit cube; each colour must come back within 2 levels of 255 (8-bit rounding on either
API), far from the other colours used (which differ by more than 150 levels in one channel).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest

from gandalf_core import Application, InfoComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, ClearColorComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, cube
from step07_advanced.usd import load_scene, save_scene

pytest.importorskip("pxr")

W, H = 96, 72
RED, GREEN, BLUE = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)


def cube_scene() -> Scene:
    scene = Scene("edited")
    scene.assets.mesh("cube", cube())
    scene.assets.material("M", MaterialData("gandalf.unlit", color=RED))
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.0, 0.0, 0.0)))
    scene.create_entity(InfoComponent("cube"), TransformComponent(scale=3.0), MeshComponent("cube"),
                        MaterialComponent("M"))
    scene.create_entity(InfoComponent("camera"), TransformComponent((0.0, 0.0, 3.0)), CameraComponent(60.0, 0.1, 10.0))
    return scene


def centre(app: Application) -> np.ndarray:
    return app.capture()[H // 2, W // 2, :3].astype(int)


def assert_colour(app: Application, rgb: tuple[float, ...], when: str) -> None:
    got = centre(app)
    expected = np.round(np.array(rgb) * 255).astype(int)
    assert np.abs(got - expected).max() <= 2, f"{when}: the cube shows {got.tolist()}, expected {expected.tolist()}"


def edit_colour(app: Application, name: str, rgb: tuple[float, ...]) -> None:
    """What an editor does: set the built material's colour (no rebuild) and write it back to the scene's assets."""
    library = app.renderer.materials
    material = library.get(name)
    color = (*rgb, 1.0)
    material.set_color(color)
    data = app.scene.assets.materials[name].with_color(color)
    app.scene.assets.materials[name] = material.data = data
    library.adopt(name, data)


def test_loading_after_a_material_colour_edit(backend, tmp_path: Path) -> None:
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        original = cube_scene()
        app.add_scene(original)
        app.run(frames=1)
        assert_colour(app, RED, "the scene as built")
        before = save_scene(original, tmp_path / "before.usda")
        edit_colour(app, "M", GREEN)
        app.run(frames=1)
        assert_colour(app, GREEN, "after the edit")
        after = save_scene(original, tmp_path / "after.usda")

        app.switch_scene(load_scene(before, name="before"))  # 'M' is red in the file, green in the running app
        app.run(frames=1)
        assert_colour(app, RED, "the file saved before the edit, loaded after it")
        edit_colour(app, "M", BLUE)  # editing the loaded scene leaves the first one alone
        app.run(frames=1)
        assert_colour(app, BLUE, "the loaded scene, edited")

        app.switch_scene(original)
        app.run(frames=1)
        assert_colour(app, GREEN, "back to the first scene")
        assert original.assets.materials["M"].color[:3] == pytest.approx(GREEN)

        app.switch_scene(load_scene(after, name="after"))
        app.run(frames=1)
        assert_colour(app, GREEN, "the file saved after the edit")


HAS_EDITOR = importlib.util.find_spec("imgui_bundle") is not None


@pytest.mark.skipif(not HAS_EDITOR, reason="imgui-bundle is not installed")
def test_editor_load_after_a_colour_edit(backend, tmp_path: Path) -> None:
    from step07_advanced.editor import disable_editor, enable_editor

    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        app.add_scene(cube_scene())
        editor = enable_editor(app)
        try:
            app.run(frames=1)
            path = tmp_path / "before.usda"
            assert editor.save(path), editor.status
            editor.set_material_color("M", GREEN)
            app.run(frames=1)
            assert editor.load(path), editor.status
            app.run(frames=1)
            assert app.scene.name == "edited (2)"
            assert app.scene.assets.materials["M"].color[:3] == pytest.approx(RED)  # (the panels cover the frame)
            # The scene's systems came back once each; the app's render system and the editor's panels were not
            # saved, so they are not doubled either.
            names = [type(s).__name__ for s in app.scene.systems]
            assert names.count("TransformSystem") == names.count("LightSystem") == names.count("RenderSystem") == 1
            editor_owned = [type(s).__module__.startswith("step07_advanced.editor") for s in app.scene.systems]
            panels = [n for n, owned in zip(names, editor_owned) if owned]
            assert len(panels) == len(set(panels)), names
        finally:
            disable_editor(app)
