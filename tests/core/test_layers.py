"""gandalf_core's layers import one way: ecs/math/resources -> components -> systems -> render -> app -> editor/usd.

Every import in every module (at the top or inside a function, since a late import is still a dependency) is read
from the source; a module may import its own layer and the layers below it, never one above. The only exception is
stated: ``Application(editor=True)`` imports the editor lazily, when asked for.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2] / "gandalf_core"
#: Layer of each sub-package (and top-level module); higher numbers may import lower ones.
LAYERS = {
    "ecs": 0, "math": 0, "resources": 0,
    "components": 1,
    "systems": 2,
    "render": 3,
    "app": 4,
    "editor": 5, "usd": 5,
    # tools on top of everything
    "grading": 6, "testing": 6, "tour": 6, "studies": 6, "__init__": 6,
}
#: (importing layer, imported layer): the lazy import behind ``Application(editor=True)``.
ALLOWED_UPWARD = {("app", "editor")}


def _layer_of_module(path: Path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return parts[0]


def _imports(path: Path, root: Path = ROOT) -> list[tuple[int, str]]:
    """(line, imported gandalf_core layer) for every import in the file (``root``: the gandalf_core folder)."""
    package = path.relative_to(root.parent).with_suffix("").parts[:-1]  # e.g. ("gandalf_core", "render", "opengl")
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        names: list[str] = []
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - node.level + 1]
                module = ".".join([*base, *([node.module] if node.module else [])])
                names = [module] if node.module else [f"{module}.{a.name}" for a in node.names]
            elif node.module:
                names = [node.module]
        for name in names:
            parts = name.split(".")
            if parts[0] == "gandalf_core" and len(parts) > 1:
                found.append((node.lineno, parts[1]))
    return found


MODULES = sorted(p for p in ROOT.rglob("*.py") if "__pycache__" not in p.parts)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(ROOT)))
def test_imports_go_down_the_layers(path):
    own = _layer_of_module(path)
    if own not in LAYERS:
        pytest.fail(f"{path.relative_to(ROOT)}: no layer for '{own}' (add it to LAYERS)")
    for line, imported in _imports(path):
        if imported not in LAYERS or imported == own:
            continue
        if LAYERS[imported] > LAYERS[own] and (own, imported) not in ALLOWED_UPWARD:
            pytest.fail(f"gandalf_core/{path.relative_to(ROOT)}:{line} ({own}, layer {LAYERS[own]}) imports "
                        f"{imported} (layer {LAYERS[imported]}): imports must go down the layers")


def test_nothing_in_systems_imports_render():
    offenders = [f"{p.relative_to(ROOT)}:{line}" for p in (ROOT / "systems").rglob("*.py")
                 for line, layer in _imports(p) if layer == "render"]
    assert not offenders, offenders


def test_the_check_sees_a_late_relative_import(tmp_path):
    # Guards the checker: an import inside a function, written relatively, is found.
    probe = tmp_path / "gandalf_core" / "systems" / "probe.py"
    probe.parent.mkdir(parents=True)
    probe.write_text("def f():\n    from ..render import base\n")
    assert _imports(probe, tmp_path / "gandalf_core") == [(2, "render")]
