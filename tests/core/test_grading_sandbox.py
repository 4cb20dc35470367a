"""The sandbox the student's package runs in, and the stand-in the grader gets (``gandalf_tools.grading.sandbox``,
``remote``, ``wire``).

A package written into ``tmp_path`` is graded as ``step01_window.exercises``: its functions run in another process
that cannot import or read the reference solutions (where this machine allows namespaces), whose results come back
as plain data only, whose hung function fails at once afterwards while the others go on in a fresh process, and
whose system changes only the component fields it may, with values of the right kind.
"""

from __future__ import annotations

import math
import os
import textwrap
from pathlib import Path

import numpy as np
import pytest

from gandalf_core import ClearColorComponent, Scene
from gandalf_tools.grading import remote, sandbox, wire
from gandalf_tools.grading.watchdog import ExerciseTimeout
from step01_window.components import HueCycleComponent

ROOT = Path(__file__).resolve().parents[2]

PACKAGE = '''
import os
import time

import numpy as np

from gandalf_core import ClearColorComponent, System

from ..components import HueCycleComponent


class Sneaky(float):
    def __eq__(self, other):
        return True

    __hash__ = float.__hash__


def values():
    return (Sneaky(0.25), np.float32(0.5), 3, [1, (2.0, "x")], {"k": np.arange(3.0)}, float("nan"), b"ab")


def sneaky_object():
    class Anything:
        def __eq__(self, other):
            return True
    return Anything()


def spin(n):
    while True:
        pass


def crash():
    os._exit(3)


def twice(x):
    return 2 * x


def apply(f, x):
    return f(x) + 1


def read(path):
    try:
        return open(path).read()[:40]
    except OSError as exc:
        return "unreadable: " + type(exc).__name__


def import_it(name):
    import importlib
    try:
        importlib.import_module(name)
        return "imported"
    except Exception as exc:
        return "not importable: " + type(exc).__name__


def whoami():
    return (os.getuid(), os.getcwd())


def top_folders():
    seen = {}
    for name in sorted(os.listdir("/")):
        try:
            seen[name] = sorted(os.listdir("/" + name))
        except OSError as exc:
            seen[name] = ["unreadable: " + type(exc).__name__]
    return seen


def warn():
    import warnings
    warnings.warn("watch out", UserWarning)
    return 1


def fail():
    raise ValueError("bad sides: 2")


class HueCycleSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        cycle, clear = components
        cycle.hue = (cycle.hue + cycle.speed * ts) % 360.0
        clear.color = (0.25, 0.5, 0.75, 1.0)


class BadSystem(System):
    def __init__(self):
        super().__init__([HueCycleComponent, ClearColorComponent])

    def on_update_entity(self, ts, entity, components):
        components[0].hue = "red"
'''


@pytest.fixture(scope="module")
def student(tmp_path_factory):
    folder = tmp_path_factory.mktemp("submission") / "exercises"
    folder.mkdir()
    (folder / "__init__.py").write_text(textwrap.dedent(PACKAGE))
    box = sandbox.Sandbox("step01_window", folder)
    package = remote.install("step01_window", folder, box, budget=2.0)
    yield package
    box.stop()
    import importlib
    import sys

    sys.modules.pop("step01_window.exercises", None)
    importlib.import_module("step01_window").exercises = importlib.import_module("step01_window.exercises")


def test_wire_round_trip_gives_plain_values_and_never_pickles():
    blobs: list[bytes] = []
    value = (1, 2.5, "s", [None, True], {"a": np.eye(2)}, {3}, b"x", float("inf"))
    data = wire.encode_value(value, blobs)
    back = wire.decode_value(data, blobs)
    assert back[:4] == value[:4] and np.array_equal(back[4]["a"], np.eye(2)) and back[5:] == value[5:]
    with pytest.raises(wire.WireError):
        wire.encode_value(np.array([object()]), [])
    with pytest.raises(wire.WireError):
        wire.encode_value(object(), [])
    assert all(b"pickle" not in b for b in blobs)


def test_arrays_travel_as_raw_numbers_of_a_plain_type_only():
    blobs: list[bytes] = []
    arrays = [np.arange(200.0).reshape(10, 20), np.array([np.nan, np.inf, -1.0]), np.arange(5, dtype=np.uint8),
              np.array([True, False]), np.float32(2.5) * np.ones((2, 3, 4), np.float32), np.array(3.0)]
    back = wire.decode_value(wire.encode_value(arrays, blobs), blobs)
    for a, b in zip(arrays, back):
        assert a.dtype == b.dtype and a.shape == b.shape and np.array_equal(a, b, equal_nan=True) and b.flags.writeable
    raw = blobs[0]
    for dtype, shape, blob in (("|O", [1], b"\0" * 8), ("[('a', '<f8')]", [1], b"\0" * 8), ("<f8", [3], raw[:16]),
                               ("<f8", [-1], b""), ("(2,)<f8", [1], b"\0" * 16)):
        with pytest.raises(wire.WireError):
            wire.decode_value({"$r": 0, "d": dtype, "s": shape}, [blob])


def test_results_come_back_as_plain_data(student):
    sneaky, f32, i, nested, mapping, nan, raw = student.values()
    assert type(sneaky) is float and sneaky == 0.25 and sneaky != 0.3  # the float subclass's __eq__ is gone
    assert type(f32) is float and type(i) is int and nested == [1, (2.0, "x")]
    assert np.array_equal(mapping["k"], [0.0, 1.0, 2.0]) and math.isnan(nan) and raw == b"ab"
    with pytest.raises(TypeError, match="cannot be graded|cannot use"):
        student.sneaky_object()


def test_errors_warnings_and_callbacks_cross(student):
    with pytest.raises(ValueError, match="bad sides: 2"):
        student.fail()
    with pytest.warns(UserWarning, match="watch out"):
        assert student.warn() == 1
    assert student.apply(lambda x: x * 10, 2) == 21  # the test's own function, called back from the sandbox


def test_the_student_process_cannot_reach_the_solutions(student):
    if sandbox.isolation() == "process":
        pytest.skip("no namespaces here: the student's process could read the checkout (the grade records it)")
    solution = ROOT / "step01_window" / "solutions" / "hue.py"
    assert student.import_it("step01_window.solutions.hue").startswith("not importable")
    assert student.import_it("gandalf_tools.grading.plugin").startswith("not importable")
    assert student.read(str(solution)).startswith("unreadable")
    assert student.read(str(ROOT / "tests" / "conftest.py")).startswith("unreadable")
    uid, cwd = student.whoami()
    assert uid != os.getuid() or sandbox.isolation() == "mount"
    assert not Path(cwd).resolve().is_relative_to(ROOT)


def test_every_top_folder_but_the_systems_shows_only_the_way_to_what_it_needs(student):
    """Another copy of the course may lie in any top folder (``/work``, ``/data``, ``/autograder``), not only beside
    this checkout: inside the sandbox each top folder but the system's holds nothing but the way to the engine, the
    step packages, Python and the sandbox's own folder."""
    if sandbox.isolation() in ("user", "process"):
        pytest.skip("no mount namespace here: the student's process sees the folders its user may list")
    import sys
    import tempfile

    needed = [ROOT, Path(sys.prefix), Path(sys.base_prefix), Path(sys.executable).parent, Path(tempfile.gettempdir()),
              *sandbox.site_folders()]
    ways: dict[str, set[str]] = {}
    for path in needed:
        parts = path.resolve().parts
        if len(parts) > 2:
            ways.setdefault(parts[1], set()).add(parts[2])
    for top, inside in student.top_folders().items():
        if top in sandbox.SYSTEM_FOLDERS or not Path("/", top).is_dir() or Path("/", top).is_symlink():
            continue
        extra = [name for name in inside
                 if name not in ways.get(top, set()) and not name.startswith("gandalf-sandbox-")]
        assert extra == [], f"/{top} shows {extra} to the student's process"


def test_an_installed_course_beside_the_packages_shows_no_solutions(tmp_path, monkeypatch):
    """A wheel of the course installed in a site folder (``pip install --target``) holds ``solutions/`` too: the
    site folder is put back for the student's process, and kept on its path (isolated Python, ``-I``, would drop a
    ``PYTHONPATH`` folder: a grader's packages installed so could not be imported), its solutions stay covered."""
    if sandbox.isolation() in ("user", "process"):
        pytest.skip("no mount namespace here: nothing is put back (a folder under pytest's private temp folder is "
                    "closed to every other user)")
    site = tmp_path / "site"
    (site / "gandalf_graphics_course-1.0.dist-info").mkdir(parents=True)
    (site / "step01_window" / "solutions").mkdir(parents=True)
    (site / "step01_window" / "solutions" / "hue.py").write_text("SECRET = 1\n")
    (site / "installed.py").write_text("VISIBLE = 1\n")
    monkeypatch.syspath_prepend(str(site))
    assert site.resolve() in sandbox.site_folders()
    folder = tmp_path / "submission" / "exercises"
    folder.mkdir(parents=True)
    (folder / "__init__.py").write_text(textwrap.dedent(PACKAGE))
    box = sandbox.Sandbox("step01_window", folder)
    try:
        package = remote.install("step01_window", folder, box, budget=5.0)
        assert package.read(str(site / "installed.py")) == "VISIBLE = 1\n"
        assert package.import_it("installed") == "imported"
        assert package.read(str(site / "step01_window" / "solutions" / "hue.py")).startswith("unreadable")
    finally:
        box.stop()
        import importlib
        import sys

        sys.modules.pop("step01_window.exercises", None)
        importlib.import_module("step01_window").exercises = importlib.import_module("step01_window.exercises")


def test_root_without_namespaces_still_runs_a_user_of_its_own_with_the_secrets_closed(tmp_path, monkeypatch):
    """As root in a container that may make no namespace (Docker's default, likely Gradescope's), the student's
    process is still a user of its own: the solutions, the mutants and the other submissions, open to every user as a
    checkout's folders are, are closed to other users before it starts."""
    import shutil
    import tempfile

    if os.geteuid() != 0 or not shutil.which("setpriv"):
        pytest.skip("needs root and setpriv (the grader as Gradescope runs it)")
    monkeypatch.setenv(sandbox.ISOLATION_ENV, "user")
    assert sandbox.isolation() == "user"
    klass = Path(tempfile.mkdtemp(prefix="gandalf-class-"))  # outside pytest's own folder, which is closed to all
    try:
        klass.chmod(0o755)
        (klass / "bob").mkdir(mode=0o755)
        (klass / "bob" / "hue.py").write_text("BOB = 1\n")
        (klass / "bob" / "hue.py").chmod(0o644)
        folder = tmp_path / "submission" / "exercises"
        folder.mkdir(parents=True)
        (folder / "__init__.py").write_text(textwrap.dedent(PACKAGE))
        box = sandbox.Sandbox("step01_window", folder, hide=(str(klass),))
        try:
            package = remote.install("step01_window", folder, box, budget=5.0)
            assert package.whoami()[0] not in (0, os.getuid())
            assert package.read(str(klass / "bob" / "hue.py")).startswith("unreadable"), "a classmate's file"
            assert package.read(str(ROOT / "step01_window" / "solutions" / "hue.py")).startswith("unreadable")
            assert package.read(str(ROOT / "tests" / "mutants" / "step01_window.py")).startswith("unreadable")
            assert not package.read(str(ROOT / "step01_window" / "__init__.py")).startswith("unreadable")  # the course
            # The tests' helpers stay open: the shader process, a user of its own under user+mount, reads them.
            assert not package.read(str(ROOT / "tests" / "shader_harness.py")).startswith("unreadable")
            assert klass.stat().st_mode & 0o007 == 0
        finally:
            box.stop()
            import importlib
            import sys

            sys.modules.pop("step01_window.exercises", None)
            importlib.import_module("step01_window").exercises = importlib.import_module("step01_window.exercises")
    finally:
        shutil.rmtree(klass, ignore_errors=True)


def _course_function(scale: float):
    """A function that :func:`sandbox.recipe` ships (as if of the engine's own code: plain captured values)."""
    def times(x):
        return scale * x + 1.0

    times.__module__ = "gandalf_core.fake"
    return times


def test_a_hung_function_fails_at_once_later_and_the_others_go_on(student):
    with pytest.raises(ExerciseTimeout, match=r"^spin\(1\) did not return within 2 s"):
        student.spin(1)
    with pytest.raises(ExerciseTimeout, match=r"^spin\(1\) did not return"):
        student.spin(2)  # remembered: no second wait
    assert student.twice(4) == 8  # a fresh process
    shipped = _course_function(3.0)  # the course's own function: sent whole once per process, then by its number
    assert student.apply(shipped, 1.0) == student.apply(shipped, 2.0) - 3.0 == 5.0
    with pytest.raises(ExerciseTimeout, match=r"crash\(\) ended its process \(exit status 3\)"):
        student.crash()
    assert student.twice(5) == 10
    assert student.apply(shipped, 1.0) == 5.0  # the fresh process is sent it whole again


def test_a_system_changes_only_fields_of_the_right_kind(student):
    scene = Scene("sandboxed")
    entity = scene.create_entity(ClearColorComponent(), HueCycleComponent(hue=350, speed=20))
    scene.add_system(student.HueCycleSystem())
    scene.update(1.0)
    assert scene.get_component(entity, HueCycleComponent).hue == pytest.approx(10.0)
    assert tuple(scene.get_component(entity, ClearColorComponent).color) == pytest.approx((0.25, 0.5, 0.75, 1.0))
    bad = Scene("bad")
    bad.create_entity(ClearColorComponent(), HueCycleComponent(hue=5))
    bad.add_system(student.BadSystem())
    with pytest.raises(remote.StudentError, match="HueCycleComponent.hue: expected int, got str"):
        bad.update(1.0)
