"""Step 05's several scenes (not graded): keys switch scenes at the next frame, switching leaks no GPU object, and
the step's launcher picks a concept (``--concept``)."""

from __future__ import annotations

import pytest

import step05_scenegraph
from step05_scenegraph import opengl as step_opengl
from step05_scenegraph.several_scenes import opengl, webgpu
from step05_scenegraph.several_scenes.scene import SCENE_KEYS

VARIANTS = {"opengl": opengl, "webgpu": webgpu}


def test_keys_switch_scenes_at_the_next_frame(backend):
    with VARIANTS[backend].create_app(headless=True, width=32, height=24) as app:
        assert [s.name for s in app.scenes.scenes] == list(SCENE_KEYS.values())
        app.step()
        presses = [*SCENE_KEYS.items(), ("1", "solar"), *(("TAB", name) for name in [*SCENE_KEYS.values()][1:]),
                   ("TAB", "solar")]
        for key, name in presses:
            app.input.key(key)
            before = app.scene.name
            app.step()
            assert app.scene.name == before  # deferred: this frame still ran the old scene
            app.input.key(key, "release")
            app.step()
            assert app.scene.name == name, f"after {key}"
        app.switch_scene("house")
        app.step()
        assert app.scene.name == "house"


def test_a_thousand_switches_leak_nothing(backend):
    with VARIANTS[backend].create_app(headless=True, width=16, height=12) as app:
        names = list(SCENE_KEYS.values())
        for name in names:  # first round: every scene builds its GPU objects once
            app.switch_scene(name)
            app.step()
        live = app.renderer.live_objects()
        for i in range(1000):
            app.switch_scene(names[i % len(names)])
            app.step()
        assert app.renderer.live_objects() == live


def test_every_concept_is_a_sub_package_with_both_variants():
    assert step05_scenegraph.DEFAULT_CONCEPT in step05_scenegraph.CONCEPTS
    for concept in step05_scenegraph.CONCEPTS:
        package = __import__(f"step05_scenegraph.{concept}", fromlist=["opengl", "webgpu", "scene"])
        assert package.STEP == "step05_scenegraph" and package.__doc__


def test_the_launcher_runs_one_concept(tmp_path, capsys):
    out = tmp_path / "house.png"
    assert step_opengl.main(["--concept", "house", "--headless", "--frames", "2", "--size", "32x24",
                             "--out", str(out)]) == 0
    assert out.stat().st_size > 100


def test_the_launcher_help_lists_the_concepts(capsys):
    with pytest.raises(SystemExit) as stop:
        step_opengl.main(["--help"])
    text = capsys.readouterr().out
    assert stop.value.code == 0 and "--concept" in text
    assert all(concept in text for concept in step05_scenegraph.CONCEPTS)
    with pytest.raises(SystemExit):
        step_opengl.main(["--concept", "nope"])
