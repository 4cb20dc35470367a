"""What imports what: the engine's layers, its boundary, no import loops, and steps that stand on the engine alone.

Every import in every module is read from the source: at the top, inside a function (a late import is still a
dependency) and under ``if TYPE_CHECKING:`` (a type named is a module known).

* ``gandalf_core``'s layers import one way: ecs/math/resources -> components -> systems -> render -> app.
* The engine imports no course tool (``gandalf_tools``), no step, no ImGui and no USD: the editor and USD are the
  final step's, reached through the hooks of ``gandalf_core.app.extensions``.
* No package of the course has an import loop.
* A step imports the engine, the tools and itself; an earlier step only where :data:`CROSS_STEP` says so (and
  the step's page explains it).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
ROOT = REPO / "gandalf_core"
# --8<-- [start:rules]
#: Layer of each sub-package (and top-level module); higher numbers may import lower ones.
LAYERS = {
    "ecs": 0, "math": 0, "resources": 0, "lazy": 0,
    "components": 1,
    "systems": 2,
    "render": 3,
    "app": 4,
    "__init__": 5,
}
#: Top-level packages the engine never imports.
NOT_IN_THE_ENGINE = ("gandalf_tools", "imgui_bundle", "imgui", "pxr")
STEP = re.compile(r"step\d\d_[a-z0-9_]+")
STEPS = sorted(p.name for p in REPO.iterdir() if p.is_dir() and STEP.fullmatch(p.name))
#: step -> earlier steps it may import (none: shared parts live in the engine, e.g. the spin).
CROSS_STEP: dict[str, set[str]] = {}
# --8<-- [end:rules]


def _modules(root: Path) -> dict[str, Path]:
    """Dotted module name -> file, for every module below ``root`` (a package folder)."""
    found = {}
    for path in sorted(root.rglob("*.py")):
        if "__pycache__" in path.parts:
            continue
        parts = list(path.relative_to(root.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        found[".".join(parts)] = path
    return found


def _imported_names(path: Path, module: str) -> list[tuple[int, str]]:
    """(line, absolute dotted name) for every import in ``path`` (module ``module``): ``from a import b`` gives
    ``a.b`` (b may be a module or a name in a), relative imports resolved."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found += [(node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                base = parts[: len(parts) - node.level + 1]
                source = ".".join([*base, *([node.module] if node.module else [])])
            else:
                source = node.module or ""
            found += [(node.lineno, f"{source}.{a.name}") for a in node.names]
    return found


def _resolve(name: str, modules: dict[str, Path]) -> str | None:
    """The longest known module that ``name`` starts with (a.b.c -> a.b when c is a name in module a.b)."""
    parts = name.split(".")
    for k in range(len(parts), 0, -1):
        candidate = ".".join(parts[:k])
        if candidate in modules:
            return candidate
    return None


def import_graph(root: Path) -> dict[str, set[str]]:
    """module -> the modules of the same package tree it imports."""
    modules = _modules(root)
    return {m: {t for _, n in _imported_names(p, m) if (t := _resolve(n, modules)) not in (None, m)}
            for m, p in modules.items()}


def import_loops(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected groups of more than one module (Tarjan), each sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    loops: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                loops.append(sorted(group))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return loops


ENGINE = _modules(ROOT)


@pytest.mark.parametrize("module", sorted(ENGINE), ids=str)
def test_imports_go_down_the_layers(module):
    path = ENGINE[module]
    own = module.split(".")[1] if "." in module else "__init__"
    assert own in LAYERS, f"{path.relative_to(REPO)}: no layer for '{own}' (add it to LAYERS)"
    for line, name in _imported_names(path, module):
        parts = name.split(".")
        if parts[0] != "gandalf_core" or len(parts) < 2 or parts[1] not in LAYERS:
            continue
        imported = parts[1]
        assert imported == own or LAYERS[imported] <= LAYERS[own], (
            f"{path.relative_to(REPO)}:{line} ({own}, layer {LAYERS[own]}) imports {imported} "
            f"(layer {LAYERS[imported]}): imports must go down the layers")


def test_the_engine_imports_no_tool_step_gui_or_usd():
    offenders = [f"{path.relative_to(REPO)}:{line} imports {name}"
                 for module, path in ENGINE.items() for line, name in _imported_names(path, module)
                 if name.split(".")[0] in NOT_IN_THE_ENGINE or STEP.fullmatch(name.split(".")[0])]
    assert not offenders, offenders


def test_nothing_in_systems_imports_render():
    offenders = [f"{ENGINE[m].relative_to(REPO)}:{line}" for m in ENGINE if m.startswith("gandalf_core.systems")
                 for line, name in _imported_names(ENGINE[m], m) if name.startswith("gandalf_core.render")]
    assert not offenders, offenders


@pytest.mark.parametrize("package", ["gandalf_core", "gandalf_tools", *STEPS])
def test_no_import_loops(package):
    loops = import_loops(import_graph(REPO / package))
    assert not loops, f"{package}: modules that import each other (directly or round a circle): {loops}"


@pytest.mark.parametrize("step", STEPS)
def test_a_step_imports_only_the_engine_the_tools_and_itself(step):
    allowed = {step, *CROSS_STEP.get(step, ())}
    offenders = [f"{path.relative_to(REPO)}:{line} imports {name}"
                 for module, path in _modules(REPO / step).items() for line, name in _imported_names(path, module)
                 if STEP.fullmatch(name.split(".")[0]) and name.split(".")[0] not in allowed]
    assert not offenders, offenders


def test_the_checks_see_late_relative_and_type_only_imports(tmp_path):
    # Guards the checker: imports inside a function or under TYPE_CHECKING, written relatively, are found, and a
    # circle through them is a loop.
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "a.py").write_text("def f():\n    from .b import g\n")
    (package / "b.py").write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from . import a\n")
    (package / "c.py").write_text("from . import a\n")
    assert import_graph(package) == {"pkg": set(), "pkg.a": {"pkg.b"}, "pkg.b": {"pkg.a"}, "pkg.c": {"pkg.a"}}
    assert import_loops(import_graph(package)) == [["pkg.a", "pkg.b"]]
