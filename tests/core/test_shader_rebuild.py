"""Rebuilding a shader from new text (``renderer.shaders.rebuild``) in both APIs, headless, read back in pixels.

A broken edit (in an ``#include``d file) returns an error naming that file and line and leaves the last good program
drawing; a good one replaces it, and the materials, vertex arrays (OpenGL) and pipelines (WebGPU) made with the old
one are made again; a new Material declaration re-checks the material's values. Tolerance: the middle pixel within
1 level of the tint's sRGB bytes (rounding), see :mod:`shader_edit_scene`.
"""

from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

import pytest

from gandalf_core.render.errors import ShaderCompileError
from gandalf_core.resources import ResourceError

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


@pytest.fixture
def tinted(backend: str, tmp_path: Path):
    app, files = tinted_app(backend, tmp_path, 64, 48)
    app.run(frames=1)
    yield app, files
    app.close()


def test_a_broken_include_is_reported_at_its_line_and_the_last_good_program_keeps_drawing(tinted) -> None:
    app, files = tinted
    backend = app.renderer.backend
    assert shows(app.capture(), FIRST), middle(app.capture())
    old = app.renderer.shaders.get(SHADER)
    error = app.renderer.shaders.rebuild(SHADER, {files["tint"]: tint_text(backend, FIXED, broken=True)})
    assert isinstance(error, ShaderCompileError)
    assert f"{files['tint']}:3:" in str(error), str(error)  # the included file's own line, not the expanded one
    assert app.renderer.shaders.get(SHADER) is old
    app.run(frames=2)
    assert shows(app.capture(), FIRST), f"the last good program draws on: {middle(app.capture())}"


def test_a_good_edit_replaces_the_program_and_what_was_made_with_it(tinted) -> None:
    app, files = tinted
    renderer = app.renderer
    old_material = renderer.materials.get(MATERIAL)
    assert renderer.shaders.files(SHADER)[-1] == files["tint"].resolve()
    assert renderer.shaders.rebuild(SHADER, {files["tint"]: tint_text(renderer.backend, FIXED)}) is None
    assert renderer.stats["shaders_rebuilt"] == 1
    app.run(frames=1)
    assert shows(app.capture(), FIXED), middle(app.capture())
    assert renderer.materials.get(MATERIAL) is not old_material, "the material is built again with the new shader"
    # Without texts, the files on disk are read again: they still hold the first tint.
    assert renderer.shaders.rebuild(SHADER) is None
    app.run(frames=1)
    assert shows(app.capture(), FIRST), middle(app.capture())


def test_a_missing_include_is_an_error_that_changes_nothing(tinted) -> None:
    app, files = tinted
    broken = files["frag" if app.renderer.backend == "opengl" else "wgsl"]
    text = broken.read_text().replace('"tint.', '"tnit.')
    error = app.renderer.shaders.rebuild(SHADER, {broken: text})
    assert isinstance(error, ResourceError) and "tnit" in str(error) and str(broken) in str(error)
    app.run(frames=1)
    assert shows(app.capture(), FIRST)


def test_a_new_material_declaration_rechecks_the_material(tinted) -> None:
    app, _files = tinted
    shaders = app.renderer.shaders
    assert shaders.material_declaration(SHADER) is None
    assert shaders.rebuild(SHADER, material=[("color", "vec4"), ("glow", "float")]) is None
    assert [f.name for f in shaders.get(SHADER).material_block.fields] == ["color", "glow"]
    with pytest.raises(ResourceError, match="'glow'"):  # the material never sets it: named, not read as 0
        app.run(frames=1)
    assets = app.scene.assets
    assets.material(MATERIAL, dataclasses.replace(assets.materials[MATERIAL], params={"glow": 0.5}))
    app.run(frames=1)
    assert shows(app.capture(), FIRST)


def test_rebuilding_a_shader_built_from_nothing_names_it(tinted) -> None:
    app, _files = tinted
    with pytest.raises(KeyError, match="'nothing'"):
        app.renderer.shaders.rebuild("nothing")


def test_a_material_the_app_built_itself_is_built_again_with_the_new_shader(tinted) -> None:
    from gandalf_core.resources import MaterialData

    app, files = tinted
    renderer = app.renderer
    own = renderer.materials.build("own", MaterialData(SHADER, color=(0.5, 0.5, 0.5)))
    assert renderer.shaders.rebuild(SHADER, {files["tint"]: tint_text(renderer.backend, FIXED)}) is None
    again = renderer.materials.get("own")  # not from a scene's assets: nothing would build it on its next use
    assert again is not own and again.shader is renderer.shaders.get(SHADER)
    with pytest.warns(UserWarning, match="material 'own' could not be built again"):
        renderer.shaders.forget(SHADER)  # gone for good: so are the materials built with it
    assert "own" not in renderer.materials and MATERIAL not in renderer.materials
