"""Materials against their shaders, in both APIs: an unknown or misspelt parameter, a GLSL name given with its
``u_`` prefix, a shader value the material never sets, a value of the wrong size, a missing texture, a texture of
the wrong kind, a wrong number of textures, an unknown shader, a bad colour; and the names a frame resolves (mesh,
material, texture, sky). Each is an error naming the material (and the shader, field, texture or slot) when the
material is built, never a value dropped or read as 0. The data-level checks of MaterialData come first."""

from __future__ import annotations

import math

import numpy as np
import pytest
from core_shaders import FLAT_FRAG, FLAT_MATERIAL, FLAT_VERT, FLAT_WGSL, build_shaders

from gandalf_core import Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent, SkyboxComponent
from gandalf_core.render.errors import MissingResourceError
from gandalf_core.resources import MaterialData, ResourceError, checkerboard, cube, sky_cube
from gandalf_core.resources.assets import Assets

from .catalogue import error, params, params_per_backend, result, run

GOOD = {"tint": (1.0, 1.0, 1.0, 1.0), "m": np.eye(4).ravel()}


def ready(app):
    """The app with the catalogue's shaders built (cached by name: built once per app)."""
    shaders = app.renderer.shaders
    if app.backend == "opengl":
        shaders.build("flat", FLAT_VERT, FLAT_FRAG, material=FLAT_MATERIAL)
    else:
        shaders.build("flat", FLAT_WGSL, material=FLAT_MATERIAL)
    build_shaders(shaders, app.backend, "unlit")
    return app


def built(name: str, data: MaterialData, **textures):
    """Build material ``name`` from ``data`` (and ``textures``) the way a frame does, from a scene's assets."""
    def action(app):
        assets = Assets()
        for texture, texture_data in textures.items():
            assets.texture(texture, texture_data)
        assets.material(name, data)
        return ready(app).renderer.resolve_material(name, assets)
    return action


def recoloured(color):
    def action(app):
        material = built("recolour", MaterialData("flat", params=GOOD))(app)
        material.set_color(color)
    return action


_n = [0]


def frame(build):
    """A frame of a new scene (``build(scene)`` fills it) in the shared app."""
    def action(app):
        _n[0] += 1
        scene = Scene(f"materials-{_n[0]}")
        scene.create_entity(TransformComponent((0, 0, 3)), CameraComponent())
        build(scene)
        ready(app).add_scene(scene)
        app.switch_scene(scene)
        app.step()
        return app
    return action


def drawn(mesh: str = "cube", material: str = "M", **assets):
    def build(scene):
        for name, data in assets.items():
            kind = {MaterialData: "material"}.get(type(data), "mesh" if name.startswith("mesh") else "texture")
            getattr(scene.assets, kind)(name, data)
        scene.assets.mesh("cube", cube())
        scene.create_entity(TransformComponent(), MeshComponent(mesh), MaterialComponent(material))
    return build


def mesh_replaced_while_running(app):
    _n[0] += 1
    scene = Scene(f"replace-{_n[0]}")
    scene.create_entity(TransformComponent((0, 0, 3)), CameraComponent())
    scene.assets.mesh("box", cube(1.0))
    scene.assets.material("M", MaterialData("flat", params=GOOD))
    scene.create_entity(TransformComponent(), MeshComponent("box"), MaterialComponent("M"))
    ready(app).add_scene(scene)
    app.switch_scene(scene)
    app.step()
    scene.assets.mesh("box", cube(2.0))  # a new mesh under the same name while running
    app.step()
    return app.renderer.meshes.data_of("box") is scene.assets.meshes["box"]


def sky_of(texture):
    def build(scene):
        scene.assets.texture("flat-sky", texture)
        scene.create_entity(SkyboxComponent("flat-sky"))
    return build


IN_THE_RENDERER = [
    error("misspelt-parameter", built("misspelt", MaterialData("flat", params={**GOOD, "tnit": 1.0})), ResourceError,
          "material 'misspelt'", "params['tnit']", "shader 'flat'", "did you mean 'tint'"),
    error("unknown-parameter", built("unknown", MaterialData("flat", params={**GOOD, "glow": 1.0})), ResourceError,
          "material 'unknown'", "params['glow']", "has no value"),
    error("glsl-u-prefix", built("prefixed", MaterialData("flat", params={"u_tint": (1, 1, 1, 1), "m": GOOD["m"]})),
          ResourceError, "material 'prefixed'", "params['u_tint']"),
    error("value-never-set", built("unset", MaterialData("flat", params={"m": GOOD["m"]})), ResourceError,
          "material 'unset'", "shader 'flat'", "tint", "never sets"),
    error("vec4-given-three", built("tint3", MaterialData("flat", params={**GOOD, "tint": (1, 1, 1)})),
          ResourceError, "material 'tint3'", "tint", "4 value(s)", "got 3"),
    error("vec4-given-one", built("tint1", MaterialData("flat", params={**GOOD, "tint": 1.0})), ResourceError,
          "material 'tint1'", "tint", "4 value(s)", "got 1"),
    error("vec4-given-sixteen", built("tint16", MaterialData("flat", params={**GOOD, "tint": np.eye(4).ravel()})),
          ResourceError, "material 'tint16'", "tint", "4 value(s)", "got 16"),
    error("mat4-given-nine", built("m9", MaterialData("flat", params={**GOOD, "m": np.eye(3).ravel()})),
          ResourceError, "material 'm9'", "16 value(s)", "got 9"),
    result("mat4-given-as-4x4", built("m44", MaterialData("flat", params={**GOOD, "m": np.eye(4)})),
           lambda material: material is not None),
    error("missing-texture", built("lost", MaterialData("unlit", ["nowhere"])), MissingResourceError,
          "material 'lost'", "texture 'nowhere'"),
    error("cube-texture-in-2d-slot", built("cubed", MaterialData("unlit", ["sky"]), sky=sky_cube(8)), ResourceError,
          "material 'cubed'", "texture 'sky' is a cube map", "shader 'unlit'", "2-D texture in slot"),
    error("two-textures-for-one-slot", built("two", MaterialData("unlit", ["c", "c"]), c=checkerboard(8, 2)),
          ResourceError, "material 'two'", "2 texture(s) given", "shader 'unlit'"),
    error("no-texture-for-a-slot", built("none", MaterialData("unlit")), ResourceError, "material 'none'",
          "textures: 0 texture"),
    error("unknown-shader", built("orphan", MaterialData("no-such-shader")), MissingResourceError,
          "material 'orphan'", "shader 'no-such-shader'"),
    error("set-color-nan", recoloured((math.nan, 0, 0)), ResourceError, "material 'recolour'", "color", "finite"),
    error("set-color-name", recoloured("red"), ResourceError, "material 'recolour'", "color", "'red'"),
    error("frame-unknown-mesh", frame(drawn(mesh="no-such-mesh", M=MaterialData("flat", params=GOOD))),
          MissingResourceError, "mesh 'no-such-mesh'"),
    error("frame-unknown-material", frame(drawn(material="no-such-material")), MissingResourceError,
          "material 'no-such-material'"),
    error("frame-material-with-unknown-texture", frame(drawn(M=MaterialData("unlit", ["gone"]))),
          MissingResourceError, "material 'M'", "texture 'gone'"),
    error("frame-2d-texture-as-sky", frame(sky_of(checkerboard(8, 2))), ResourceError, "texture 'flat-sky'",
          "SkyboxComponent needs a cube texture"),
    error("frame-unknown-sky", frame(lambda s: s.create_entity(SkyboxComponent("no-sky"))), MissingResourceError,
          "texture 'no-sky'"),
    result("mesh-replaced-while-running-is-rebuilt", mesh_replaced_while_running, lambda same: same is True),
]

DATA = [
    error("data-shader-empty", lambda: MaterialData(""), ResourceError, "shader", "expected a shader name"),
    error("data-shader-number", lambda: MaterialData(3), ResourceError, "shader", "got 3"),
    error("data-color-name", lambda: MaterialData("flat", color="red", name="paint"), ResourceError,
          "material 'paint'", "color", "'red'"),
    error("data-color-nan", lambda: MaterialData("flat", color=(math.nan, 0, 0), name="paint"), ResourceError,
          "material 'paint'", "color", "finite"),
    error("data-color-five", lambda: MaterialData("flat", color=(1, 1, 1, 1, 1), name="paint"), ResourceError,
          "material 'paint'", "color", "3 or 4"),
    error("data-textures-string", lambda: MaterialData("unlit", "bricks", name="wall"), ResourceError,
          "material 'wall'", "textures", "'bricks'"),
    error("data-texture-name-number", lambda: MaterialData("unlit", [3], name="wall"), ResourceError,
          "material 'wall'", "textures[0]"),
    error("data-blend-unknown", lambda: MaterialData("flat", blend="multiply", name="glass"), ResourceError,
          "material 'glass'", "blend", "'multiply'", "'alpha'"),
    error("data-cull-unknown", lambda: MaterialData("flat", cull="sideways", name="glass"), ResourceError,
          "material 'glass'", "cull", "'sideways'"),
    error("data-depth-test-text", lambda: MaterialData("flat", depth_test="no", name="glass"), ResourceError,
          "material 'glass'", "depth_test", "True or False"),
    error("data-param-nan", lambda: MaterialData("flat", params={"tint": math.nan}, name="glass"), ResourceError,
          "material 'glass'", "params['tint']", "finite"),
    error("data-param-text", lambda: MaterialData("flat", params={"tint": "x"}, name="glass"), ResourceError,
          "material 'glass'", "params['tint']"),
    error("data-param-key-number", lambda: MaterialData("flat", params={3: 1.0}, name="glass"), ResourceError,
          "material 'glass'", "params", "key 3"),
    error("data-params-not-a-mapping", lambda: MaterialData("flat", params=[1.0], name="glass"), ResourceError,
          "material 'glass'", "params", "mapping"),
    error("assets-material-not-data", lambda: Assets().material("m", "flat"), ResourceError, "material 'm'",
          "expected MaterialData", "got str"),
]


@pytest.mark.parametrize(("case", "backend"), params_per_backend(IN_THE_RENDERER))
def test_materials_in_the_renderer(case, backend, apps):
    run(case, apps[backend])


@pytest.mark.parametrize("case", params(DATA))
def test_material_data(case):
    run(case)
