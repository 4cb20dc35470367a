"""The editor's shader panel, headless, in both APIs: edits through its code editor and Save button, errors at their
file and line (also inside an ``#include``d file), the last good program drawing on, undo, and a file changed on disk
by another editor. Pictures are read back from the viewport's texture: its middle pixel within 1 level of the
tint's sRGB bytes (rounding; see :mod:`shader_edit_scene`).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np
import pytest

from gandalf_core.components import MaterialComponent
from step07_advanced.editor import disable_editor, enable_editor

sys.path.insert(0, str(Path(__file__).parent))
from shader_edit_scene import (  # noqa: E402
    FIRST,
    FIXED,
    MATERIAL,
    SHADER,
    middle,
    shows,
    tint_text,
    tinted_app,
)
from test_editor import center, click  # noqa: E402


@pytest.fixture
def opened(backend: str, tmp_path: Path):
    """An editor over the tinted scene with the cube selected and the shader panel open (panels run every frame)."""
    app, files = tinted_app(backend, tmp_path, 800, 600)
    editor = enable_editor(app)
    editor.gui_interval = 0.0
    editor.selected = next(e for e, _ in app.scene.view(MaterialComponent))
    app.run(frames=2)
    click(app, *center(editor.item_rects["inspector/edit_shader"]))  # the inspector's button opens the panel
    app.run(frames=2)
    assert editor.panel_visible("shader")
    yield app, editor, editor.panel_system("shader"), files
    disable_editor(app)
    app.close()


def picture(editor) -> np.ndarray:
    return editor.viewport.target.read_pixels()


def save_in_panel(app, panel, tab: str, key, text: str) -> None:
    """Bring tab ``tab`` to the front, type ``text`` into its code editor and press Save."""
    click(app, *center(panel.editor.item_rects[f"shader/tab/{tab}"]))
    panel.text_editor(key).set_text(text)
    click(app, *center(panel.editor.item_rects["shader/save"]))
    app.run(frames=2)


def test_the_panel_opens_every_stage_and_include_of_the_selected_material(opened) -> None:
    app, editor, panel, files = opened
    lang = app.renderer.shading_language
    tabs = {key.removeprefix("shader/tab/") for key in editor.item_rects if key.startswith("shader/tab/")}
    assert {p.name for p in files.values()} | {f"material.{lang}", f"frame.{lang}", f"instance.{lang}"} <= tabs
    assert panel.text_editor(files["tint"]).get_text().rstrip("\n") == tint_text(app.renderer.backend,
                                                                                FIRST).rstrip("\n")
    assert "Material" in panel.text_editor(panel.material_key(SHADER)).get_text()
    assert panel.text_editor(files["tint"]).is_read_only_enabled() is False
    engine = next(path for path in app.renderer.shaders.files(SHADER) if path.name == f"frame.{lang}")
    assert panel.text_editor(engine).is_read_only_enabled(), "the engine's own snippets are read-only here"
    with pytest.raises(ValueError, match="engine's own"):
        editor.shader_edits.save(engine, "// nothing\n")


def test_a_broken_include_is_shown_at_its_line_while_the_last_good_program_draws(opened) -> None:
    app, editor, panel, files = opened
    assert shows(picture(editor), FIRST), middle(picture(editor))
    broken = tint_text(app.renderer.backend, FIXED, broken=True)
    save_in_panel(app, panel, files["tint"].name, files["tint"], broken)
    assert files["tint"].read_text() == broken
    error = editor.shader_edits.errors[SHADER]
    assert f"{files['tint']}:3:" in error, error  # the included file's own line
    assert panel.marked[files["tint"].resolve()] == [3], "the error is marked at its line in the include's tab"
    stage = files["frag"] if "frag" in files else files["wgsl"]
    assert panel.marked[stage.resolve()] == []
    assert panel.text_editor(files["tint"]).has_markers() and not panel.text_editor(stage).has_markers()
    assert any(e.level == "error" and "tint." in e.text for e in editor.log.entries)
    # Over the viewport: a note inside the picture's rectangle, drawn in the frame.
    x0, y0, x1, y1 = editor.item_rects["viewport/image"]
    nx0, ny0, nx1, ny1 = editor.item_rects["shader/viewport_error"]
    assert x0 <= nx0 < nx1 <= x1 and y0 <= ny0 < ny1 <= y1
    frame = app.capture()
    inside = frame[int(ny0) + 2:int(ny1) - 2, int(nx0) + 2:int(nx1) - 2, :3].astype(int)
    assert (inside[..., 0] > inside[..., 1] + 20).mean() > 0.5, "the note is drawn (dark red) over the picture"
    app.run(frames=3)
    assert shows(picture(editor), FIRST), f"the last good program keeps drawing: {middle(picture(editor))}"


def test_fixing_swaps_the_new_program_in_and_undo_restores_text_and_picture(opened) -> None:
    app, editor, panel, files = opened
    backend, tint = app.renderer.backend, files["tint"]
    first = tint.read_text()
    save_in_panel(app, panel, tint.name, tint, tint_text(backend, FIXED, broken=True))
    save_in_panel(app, panel, tint.name, tint, tint_text(backend, FIXED))
    assert SHADER not in editor.shader_edits.errors and panel.marked[tint.resolve()] == []
    assert not panel.text_editor(tint).has_markers()
    assert "shader/viewport_error" not in editor.item_rects
    assert shows(picture(editor), FIXED), middle(picture(editor))
    assert [c.label for c in editor.commands.done][-2:] == [f"edit {tint.name}"] * 2
    editor.undo()  # back to the broken text: it does not build, the fixed program draws on
    app.run(frames=2)
    assert "nope" in tint.read_text() and SHADER in editor.shader_edits.errors
    assert shows(picture(editor), FIXED)
    editor.undo()  # back to the first text and picture
    app.run(frames=2)
    assert tint.read_text() == first and SHADER not in editor.shader_edits.errors
    assert panel.text_editor(tint).get_text().rstrip("\n") == first.rstrip("\n"), "the panel shows the old text"
    assert shows(picture(editor), FIRST), middle(picture(editor))
    editor.redo()
    editor.redo()
    app.run(frames=2)
    assert shows(picture(editor), FIXED)


def test_a_file_written_by_another_editor_is_taken_in_like_a_save(opened) -> None:
    app, editor, panel, files = opened
    backend, tint = app.renderer.backend, files["tint"]

    def write(text: str) -> None:
        tint.write_text(text)
        stat = tint.stat()
        os.utime(tint, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000))  # a new time, whatever the clock
        app.run(frames=2)

    write(tint_text(backend, FIXED))
    assert shows(picture(editor), FIXED), middle(picture(editor))
    assert panel.text_editor(tint).get_text().rstrip("\n") == tint_text(backend, FIXED).rstrip("\n")
    write(tint_text(backend, FIRST, broken=True))
    assert f"{tint}:3:" in editor.shader_edits.errors[SHADER]
    assert panel.marked[tint.resolve()] == [3]
    assert shows(picture(editor), FIXED), "the last good program keeps drawing"
    assert editor.commands.done[-1].label == f"{tint.name} changed on disk"
    editor.undo()
    app.run(frames=2)
    assert tint.read_text() == tint_text(backend, FIXED) and SHADER not in editor.shader_edits.errors
    assert shows(picture(editor), FIXED)
    editor.undo()
    app.run(frames=2)
    assert shows(picture(editor), FIRST)


def test_a_new_material_field_shows_in_the_inspector_and_a_removed_one_is_reported(opened) -> None:
    app, editor, panel, _files = opened
    lang = app.renderer.shading_language
    key = panel.material_key(SHADER)
    text = panel.text_editor(key).get_text()
    member = "float glow;" if lang == "glsl" else "glow: f32,"
    anchor = "vec4 color;" if lang == "glsl" else "color: vec4<f32>,"
    save_in_panel(app, panel, f"material.{lang}", key, text.replace(anchor, f"{anchor}\n    {member}"))
    assert SHADER not in editor.shader_edits.errors, editor.shader_edits.errors
    assert [f.name for f in app.renderer.shaders.get(SHADER).material_block.fields] == ["color", "glow"]
    assert app.scene.assets.materials[MATERIAL].params == {"glow": 0.0}
    assert any("'glow'" in note and "set to 0" in note for note in editor.shader_edits.notes)
    app.run(frames=2)
    assert "inspector/param/glow" in editor.item_rects, "the new field shows in the inspector"
    assert shows(picture(editor), FIRST), "the material still draws (its new value is 0, which it does not use)"
    save_in_panel(app, panel, f"material.{lang}", key, text)
    assert app.scene.assets.materials[MATERIAL].params == {}
    assert any("'glow'" in note and "dropped" in note for note in editor.shader_edits.notes)
    app.run(frames=2)
    assert "inspector/param/glow" not in editor.item_rects
    editor.undo()
    app.run(frames=2)
    assert app.scene.assets.materials[MATERIAL].params == {"glow": 0.0}
    assert "inspector/param/glow" in editor.item_rects


def test_a_bad_material_member_is_marked_at_its_line_of_the_material_tab(opened) -> None:
    app, editor, panel, _files = opened
    lang = app.renderer.shading_language
    key = panel.material_key(SHADER)
    text = panel.text_editor(key).get_text()
    bad = text.replace("vec4 color;", "vec4 color;\n    flaot glow;") if lang == "glsl" else \
        text.replace("color: vec4<f32>,", "color: vec4<f32>,\n    glow: flaot,")
    save_in_panel(app, panel, f"material.{lang}", key, bad)
    assert f"material.{lang}:3:" in editor.shader_edits.errors[SHADER]
    assert panel.marked[key] == [3]
    assert shows(picture(editor), FIRST)


def test_ctrl_s_in_the_code_editor_saves_the_shader_not_the_scene(opened, tmp_path: Path, monkeypatch) -> None:
    from test_editor_panels import keys

    app, editor, panel, files = opened
    monkeypatch.chdir(tmp_path)
    tint = files["tint"]
    click(app, *center(editor.item_rects[f"shader/tab/{tint.name}"]))
    x0, y0, _x1, _y1 = editor.item_rects[f"shader/code/{tint.name}"]
    click(app, x0 + 60, y0 + 5)  # the code editor has the keyboard
    panel.text_editor(tint).set_text(tint_text(app.renderer.backend, FIXED))
    keys(app, "LEFT_CONTROL", "S")
    app.run(frames=2)
    assert tint.read_text() == tint_text(app.renderer.backend, FIXED)
    assert shows(picture(editor), FIXED), middle(picture(editor))
    assert not (tmp_path / editor.path).exists(), "the menu's Ctrl+S (save the scene) stays out of the code editor"


def test_a_program_its_material_cannot_use_is_refused_and_the_last_good_one_draws(opened) -> None:
    app, editor, _panel, files = opened
    if app.renderer.backend == "opengl":
        stage = files["frag"]
        text = stage.read_text().replace("out vec4 f_color;", "uniform sampler2D u_extra;\nout vec4 f_color;") \
            .replace("rgb), 1.0);", "rgb), 1.0) * texture(u_extra, vec2(0.5));")
    else:
        stage = files["wgsl"]
        text = stage.read_text().replace("@vertex", "@group(1) @binding(1) var extra: texture_2d<f32>;\n"
                                         "@group(1) @binding(2) var extra_sampler: sampler;\n@vertex", 1) \
            .replace("rgb), 1.0);", "rgb), 1.0) * textureSample(extra, extra_sampler, vec2<f32>(0.5));")
    assert not editor.shader_edits.save(stage, text)  # it compiles, but material M_tinted binds no texture
    assert f"material '{MATERIAL}'" in editor.shader_edits.errors[SHADER]
    app.run(frames=3)  # no error escapes into the frame
    assert shows(picture(editor), FIRST), middle(picture(editor))
    editor.undo()
    app.run(frames=2)
    assert SHADER not in editor.shader_edits.errors and shows(picture(editor), FIRST)
