"""Saving keeps behaviour: every step's scene comes back with its components and systems, and animates the same.

For every step's scene (steps 01-06 ``build_scene`` with the solutions, each concept of steps 05 and 06 but
step 05's several-scenes app, and step 07's techniques whose scenes a file can hold) the test saves, loads and
saves again, then checks:

* the first save warns about nothing left out (every component and system of the scene is registered);
* the second file is the first byte for byte apart from ONE stated field: the texture folder's name
  (``<stem>_usda_textures``), which follows the file name; the PNG files are byte-identical;
* the loaded scene has the same systems (class, order, enabled flag) and, after N = 30 fixed steps of 1/60 s
  with a TransformSystem at the end of both, the same local transforms, world matrices, clear colours and
  registered component fields as the original (max difference 0: the same float64 code runs on the same
  float64 values, which USD stores as doubles);
* opened with plain ``pxr``, the file passes usd-core's validators and has visible meshes with non-empty bounds
  and a UsdPreviewSurface per material (the checks of ``test_usd_interop``).

Step 07's showcase (compute-driven particles), explode (a per-API geometry route), terrain (a per-API
tessellation backend) and path tracer (a compute accumulation) cannot be saved: saving raises an error naming
the system and why, and writes nothing. A scene with a component or system class that is not registered for
saving fails, naming the classes.
"""

from __future__ import annotations

import importlib
import subprocess
import sys
import uuid
import warnings
from collections.abc import Callable
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest

from gandalf_core import Component, InfoComponent, Scene, System, TransformComponent
from gandalf_core.app.cli import load_impl
from gandalf_core.components import ClearColorComponent, LinkComponent
from gandalf_core.systems import FlyControllerComponent, TransformSystem
from step07_advanced.usd import (
    USDSceneError,
    USDSceneWarning,
    load_scene,
    register_component,
    register_system,
    save_scene,
    unregister_component,
    unregister_system,
)
from step07_advanced.usd.mapping import BUILTIN_TYPES
from step07_advanced.usd.registry import registration_for, system_registration_for

pytest.importorskip("pxr")

ROOT = Path(__file__).resolve().parents[2]
STEPS = ("step01_window", "step02_triangle", "step03_textures", "step04_camera", "step06_lighting")
FRAMES, DT = 30, 1.0 / 60.0


def _step(step: str) -> Callable[[], Scene]:
    return lambda: importlib.import_module(f"{step}.scene").build_scene(load_impl(step))


def _concept(step: str, concept: str) -> Callable[[], Scene]:
    def build() -> Scene:
        try:
            module = importlib.import_module(f"{step}.{concept}.scene")
        except ImportError as exc:
            pytest.skip(f"{step}.{concept} cannot be imported (is the step being split into concepts?): {exc}")
        return module.build_scene(load_impl(step))

    return build


def _concepts(step: str) -> tuple[str, ...]:
    """A step's concept sub-packages (steps 05 and 06 have them), except the one that holds several scenes."""
    return tuple(c for c in getattr(importlib.import_module(step), "CONCEPTS", ()) if c != "several_scenes")


def _step07(technique: str, build: Callable[[ModuleType], Scene]) -> Callable[[], Scene]:
    def make() -> Scene:
        module = importlib.import_module(f"step07_advanced.{technique}.scene")
        return build(module)

    return make


def _small_ibl():
    """Small IBL maps (2 s instead of the demo's ~8 s): what is saved is the same kind of data."""
    from step07_advanced.pbr_model.ibl import build_ibl

    return build_ibl(samples=16, size=16, levels=4)


def _filter_scene(module) -> Scene:
    return module.build_scene(module.panel_images(module.NumpyFilter()))


class _FakeTerrain:
    """Just enough of a terrain backend to build the scene (the system is what matters here)."""

    def __init__(self) -> None:
        from step07_advanced.terrain.scene import PARAMS

        self.params = PARAMS

    def mesh(self):
        from step07_advanced.terrain.patches import patch_mesh

        return patch_mesh(self.params)

    def material(self, base):
        return base

    def update(self, eye) -> None:
        pass


class _FakeKernel:
    width, height = 8, 6

    def release(self) -> None:
        pass


def _explode_scene(module) -> Scene:
    return module.build_scene(load_impl("step07_advanced"), module.GeometryShaderRoute())


SAVABLE: dict[str, Callable[[], Scene]] = {
    **{s: _step(s) for s in STEPS},
    **{f"step05_{c}": _concept("step05_scenegraph", c) for c in _concepts("step05_scenegraph")},
    **{f"step06_{c}": _concept("step06_lighting", c) for c in _concepts("step06_lighting")},
    "step07_pbr_model": _step07("pbr_model", lambda m: m.build_scene(ibl=_small_ibl())),
    "step07_parallax": _step07("parallax", lambda m: m.build_scene()),
    "step07_filter": _step07("filter", _filter_scene),
}

#: Techniques whose scene a file cannot hold: the system named in the error.
UNSAVEABLE: dict[str, tuple[Callable[[], Scene], str, str]] = {
    "step07_showcase": (_step07("showcase", lambda m: m.build_scene(load_impl("step07_advanced"))),
                        "ParticleSystem", "GPU buffer"),
    "step07_explode": (_step07("explode", _explode_scene), "ExplodeSystem", "explode route"),
    "step07_terrain": (_step07("terrain", lambda m: m.build_scene(load_impl("step07_advanced"), _FakeTerrain())),
                       "TessellationSystem", "tessellation backend"),
    "step07_pathtracer": (_step07("pathtracer", lambda m: m.build_scene(_FakeKernel(), samples=1, sky_size=4,
                                                                        bunny=False)),
                          "PathTraceSystem", "GPU buffers"),
}


def unregistered(scene: Scene) -> list[str]:
    """The scene's component and system classes that are not on the USD allow-list."""
    out = set()
    for entity in scene.entities:
        for c in scene.components_of(entity):
            if type(c) not in BUILTIN_TYPES and registration_for(type(c)) is None:
                out.add(f"{type(c).__module__}.{type(c).__qualname__}")
    out.update(f"{type(s).__module__}.{type(s).__qualname__}" for s in scene.systems
               if system_registration_for(type(s)) is None)
    return sorted(out)


def build(name: str) -> Scene:
    scene = SAVABLE[name]()
    missing = unregistered(scene)
    assert not missing, f"{name}: these classes are not registered for saving: {', '.join(missing)}"
    return scene


# --- matching entities across a save and load ------------------------------------------------------------
def entity_keys(scene: Scene) -> dict[tuple, uuid.UUID]:
    """Each entity by its path of names from the root (and its place among same-named siblings)."""
    keys: dict[tuple, uuid.UUID] = {}

    def path(e: uuid.UUID) -> tuple:
        chain = []
        while e is not None:
            info = scene.try_component(e, InfoComponent)
            chain.append(info.name if info else "")
            e = scene.parent_of(e)
        return tuple(reversed(chain))

    for e in scene.entities:
        base = path(e)
        n = 0
        while (base, n) in keys:
            n += 1
        keys[(base, n)] = e
    return keys


def state(scene: Scene) -> dict[tuple, dict[str, object]]:
    """What animates: local transforms, world matrices, clear colours and registered components' fields."""
    keys = entity_keys(scene)
    back = {e: k for k, e in keys.items()}
    out = {}
    for key, e in keys.items():
        row: dict[str, object] = {}
        t = scene.try_component(e, TransformComponent)
        if t is not None:
            for f in ("translation", "quaternion", "scale", "world"):
                row[f"Transform.{f}"] = np.array(getattr(t, f), dtype=np.float64)
        clear = scene.try_component(e, ClearColorComponent)
        if clear is not None:
            row["ClearColor.color"] = np.array(clear.color, dtype=np.float64)
        for c in scene.components_of(e):
            reg = registration_for(type(c))
            for f in reg.fields if reg else ():
                value = getattr(c, f)
                if isinstance(value, uuid.UUID):  # another entity: compared by its name path
                    value = "entity " + "/".join(back[value][0]) + f" #{back[value][1]}"
                row[f"{type(c).__name__}.{f}"] = value
        out[key] = row
    return out


def assert_same_state(name: str, a: Scene, b: Scene) -> None:
    sa, sb = state(a), state(b)
    assert sorted(sa) == sorted(sb), f"{name}: the loaded scene has other entities"
    for key, row in sa.items():
        assert sorted(row) == sorted(sb[key]), f"{name}: {key}: fields {sorted(row)} != {sorted(sb[key])}"
        for field, x in row.items():
            y = sb[key][field]
            if isinstance(x, np.ndarray) or isinstance(y, (np.ndarray, tuple, list)):
                x, y = np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)
                worst = float(np.max(np.abs(x - y))) if x.shape == y.shape else np.inf
                assert worst == 0.0, (f"{name}: entity {'/'.join(key[0])}: {field} after {FRAMES} steps: "
                                      f"original {x.tolist()}, loaded {y.tolist()} (max difference {worst:.3g}, "
                                      "expected 0: the same code on the same doubles)")
            else:
                assert x == y, f"{name}: entity {'/'.join(key[0])}: {field}: original {x!r}, loaded {y!r}"


def systems_of(scene: Scene) -> list[tuple[str, bool]]:
    return [(f"{type(s).__module__}.{type(s).__qualname__}", s.enabled) for s in scene.systems]


def animate(scene: Scene) -> None:
    if not any(isinstance(s, TransformSystem) for s in scene.systems):
        scene.add_system(TransformSystem())
    for _ in range(FRAMES):
        scene.update(DT)


def strict_save(scene: Scene, path: Path) -> Path:
    """Save; any USDSceneWarning (something left out) fails the test."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", USDSceneWarning)
        return save_scene(scene, path)


# --- save -> load -> save, and the animation ---------------------------------------------------------------
@pytest.mark.parametrize("name", list(SAVABLE))
def test_save_load_save_keeps_the_file_systems_and_animation(tmp_path, name):
    from test_usd_interop import assert_other_tools_see  # the same folder: pytest puts it on sys.path

    scene = build(name)
    first = strict_save(scene, tmp_path / f"{name}.usda")
    loaded = load_scene(first)
    assert systems_of(loaded) == systems_of(scene), f"{name}: systems {systems_of(loaded)} != {systems_of(scene)}"
    (tmp_path / "again").mkdir()
    second = strict_save(loaded, tmp_path / "again" / f"{name}.usda")
    a = first.read_text("utf-8").replace(f"{first.stem}_usda_textures", "TEXTURES")
    b = second.read_text("utf-8").replace(f"{second.stem}_usda_textures", "TEXTURES")
    if a != b:
        diff = [f"{x!r} != {y!r}" for x, y in zip(a.splitlines(), b.splitlines()) if x != y][:5]
        pytest.fail(f"{name}: the second save differs (only the texture folder's name may): {diff}")
    tex_a, tex_b = first.parent / f"{name}_usda_textures", second.parent / f"{name}_usda_textures"
    if tex_a.exists():
        files = sorted(p.name for p in tex_a.iterdir())
        assert files == sorted(p.name for p in tex_b.iterdir())
        for f in files:
            assert (tex_a / f).read_bytes() == (tex_b / f).read_bytes(), f"{name}: texture {f}"
    assert_other_tools_see(name, scene, first)
    assert_same_state(name, scene, loaded)  # before any step: what was saved came back
    animate(scene)
    animate(loaded)
    assert_same_state(name, scene, loaded)


@pytest.mark.parametrize("name", list(UNSAVEABLE))
def test_unsaveable_techniques_say_why_and_write_nothing(tmp_path, name):
    make, system, why = UNSAVEABLE[name]
    scene = make()
    with pytest.raises(USDSceneError, match=rf"system {system} \([\w.]+\) cannot be saved: .*{why}"):
        save_scene(scene, tmp_path / "t.usda")
    assert list(tmp_path.iterdir()) == [], "a refused save writes nothing"


# --- systems: settings, allow-list, errors -------------------------------------------------------------------
class Pulse(Component):
    def __init__(self) -> None:
        self.phase = 0.0
        self.partner: uuid.UUID | None = None


class PulseSystem(System):
    """A system with simple constructor settings."""

    def __init__(self, rate: float, label: str = "pulse", axis: tuple = (0.0, 1.0, 0.0), every: int = 1) -> None:
        super().__init__([Pulse, TransformComponent])
        self.rate, self.label, self.axis, self.every = rate, label, axis, every

    def on_update_entity(self, ts, entity, components) -> None:
        pulse, transform = components
        pulse.phase += self.rate * ts
        transform.translation = np.asarray(self.axis, dtype=np.float64) * np.sin(pulse.phase)


class Unlisted(System):
    pass


@pytest.fixture
def pulse_registered():
    register_component(Pulse, fields=["phase", "partner"])
    register_system(PulseSystem, settings=["rate", "label", "axis", "every"])
    yield
    unregister_component(Pulse)
    unregister_system(PulseSystem)


def pulse_scene() -> Scene:
    scene = Scene("pulse")
    a = scene.create_entity(InfoComponent("a"), TransformComponent(), Pulse())
    b = scene.create_entity(InfoComponent("b"), TransformComponent(), LinkComponent(a), Pulse())
    scene.get_component(b, Pulse).partner = a  # an entity field: saved as a relationship to a's prim
    scene.create_entity(InfoComponent("flyer"), TransformComponent(), FlyControllerComponent(yaw=None))
    scene.add_system(PulseSystem(2.5, "slow", (0.0, 0.5, 0.25), every=3))
    paused = scene.add_system(PulseSystem(-1.0))
    paused.enabled = False
    return scene


@pytest.mark.parametrize("suffix", [".usda", ".usdc"])
def test_system_settings_order_enabled_and_entity_fields_round_trip(tmp_path, pulse_registered, suffix):
    scene = pulse_scene()
    path = strict_save(scene, tmp_path / f"p{suffix}")
    if suffix == ".usda":
        text = path.read_text("utf-8")
        assert 'custom double gandalf:settings:rate = 2.5' in text and 'gandalf:settings:label = "slow"' in text
    loaded = load_scene(path)
    assert systems_of(loaded) == systems_of(scene)
    for s, t in zip(scene.systems, loaded.systems):
        assert (s.rate, s.label, tuple(s.axis), s.every) == (t.rate, t.label, tuple(t.axis), t.every)
        assert type(t.every) is int and type(t.label) is str
    keys = {k[0][-1]: e for k, e in entity_keys(loaded).items()}
    assert loaded.get_component(keys["b"], Pulse).partner == keys["a"]
    assert loaded.get_component(keys["a"], Pulse).partner is None
    assert loaded.get_component(keys["flyer"], FlyControllerComponent).yaw is None
    animate(scene)
    animate(loaded)
    assert_same_state("pulse", scene, loaded)


def test_unregistered_system_is_reported_on_save_and_left_out(tmp_path):
    scene = Scene("s")
    scene.add_system(Unlisted())
    with pytest.warns(USDSceneWarning, match=r"system Unlisted \([\w.]*Unlisted; register it with "
                                             r"step07_advanced.usd.register_system\)"):
        path = save_scene(scene, tmp_path / "s.usda")
    assert load_scene(path).systems == []


@pytest.mark.parametrize(("key", "why"), [
    ("os.system", r"its package 'os' is not on the allow-list"),
    ("builtins.eval", r"its package 'builtins' is not on the allow-list"),
    ("step01_window.no_such_module.Thing", r"there is no module step01_window.no_such_module"),
    ("step01_window.scene.build_scene", r"neither step01_window.saved declares it nor a program registered it"),
    ("gandalf_core.render.RenderSystem", r"neither gandalf_core.saved declares it nor a program registered it"),
    ("step01_window.__main__.main", r"the module step01_window.__main__ is private or a program"),
    ("step07_advanced.showcase.particles.ParticleSystem", r"it cannot be loaded: the particles live in a GPU buffer"),
    ("not a path; import os", r"it is not an import path"),
])
def test_a_disallowed_system_is_an_error_naming_prim_and_name(tmp_path, key, why):
    scene = importlib.import_module("step01_window.scene").build_scene(load_impl("step01_window"))
    path = strict_save(scene, tmp_path / "s.usda")
    good = 'gandalf:system = "step01_window.solutions.hue.HueCycleSystem"'
    text = path.read_text("utf-8")
    assert good in text
    path.write_text(text.replace(good, f'gandalf:system = "{key}"'), "utf-8")
    open_scene = importlib.import_module("step01_window.scene").build_scene(load_impl("step01_window"))
    before = [(e, [repr(c) for c in open_scene.components_of(e)]) for e in open_scene.entities]
    pattern = (r"s\.usda: prim </Systems/HueCycleSystem>: attribute 'gandalf:system': system "
               rf"'{key.replace('.', '[.]').replace('(', '[(]')}' is not allowed \(.*{why}")
    with pytest.raises(USDSceneError, match=pattern):
        load_scene(path)
    after = [(e, [repr(c) for c in open_scene.components_of(e)]) for e in open_scene.entities]
    assert after == before and len(open_scene.systems) == 1, "a failed load leaves the open scene as it was"
    with pytest.warns(USDSceneWarning, match="is not allowed"):
        assert load_scene(path, strict=False).systems == []


def test_a_bad_setting_is_an_error_naming_it(tmp_path, pulse_registered):
    path = strict_save(pulse_scene(), tmp_path / "p.usda")
    text = path.read_text("utf-8")
    path.write_text(text.replace("gandalf:settings:every", "gandalf:settings:evry", 1), "utf-8")
    with pytest.raises(USDSceneError, match=r"prim </Systems/PulseSystem>: attribute 'gandalf:settings:evry': "
                                            r"PulseSystem declares no setting 'evry'"):
        load_scene(path)
    path.write_text(text.replace("custom double gandalf:settings:rate = 2.5", 'custom string gandalf:settings:rate = '
                                 '"fast"', 1), "utf-8")
    loaded = load_scene(path)  # a string where a float was: the system gets what the file says
    assert loaded.systems[0].rate == "fast"


def test_a_fresh_program_imports_the_allowed_step_modules_it_needs(tmp_path):
    """A file names its classes by import path: a new process that never imported step 04 loads its scene."""
    scene = importlib.import_module("step04_camera.scene").build_scene(load_impl("step04_camera"))
    path = strict_save(scene, tmp_path / "s.usda")
    code = ("import sys\nfrom step07_advanced.usd import load_scene\n"
            "assert not any(m.startswith('step04') for m in sys.modules)\n"
            f"scene = load_scene({str(path)!r})\n"
            "print([type(s).__name__ for s in scene.systems], scene.systems[1].look_at.__module__)\n")
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120,
                            check=False)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == ("['OrbitCameraSystem', 'LookAtSystem', 'CameraSwitchSystem'] "
                                     "step04_camera.solutions.projection")
