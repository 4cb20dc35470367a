"""Extensions: layers a course part adds on top of an app, found by name so the engine never imports them.

The engine offers two hooks and knows neither implementation: ``editor`` (``enable_editor(app)``, behind
``Application(editor=True)`` and every launcher's ``--editor``) and ``save_scene`` (``save_scene(scene, path)``,
behind every launcher's ``--save``). A distribution declares what fills them in its entry points, group
``gandalf_core.extensions`` (this course: ``step07_advanced.editor`` and ``step07_advanced.usd``, in
``pyproject.toml``); :func:`extension` loads one on first use.
"""

from __future__ import annotations

from collections.abc import Callable
from importlib.metadata import entry_points
from typing import Any

GROUP = "gandalf_core.extensions"
#: The hooks the engine calls, and what each is called with.
HOOKS = {"editor": "enable_editor(app)", "save_scene": "save_scene(scene, path)"}


class ExtensionMissingError(LookupError):
    """No installed distribution declares the extension a program asked for."""


def extension(name: str) -> Callable[..., Any]:
    """The callable installed for hook ``name`` (one of :data:`HOOKS`); raises ExtensionMissingError naming it."""
    if name not in HOOKS:
        raise ValueError(f"extension: {name!r} is not a hook the engine offers (one of {sorted(HOOKS)})")
    found = sorted(entry_points(group=GROUP, name=name), key=lambda ep: ep.value)
    if not found:
        raise ExtensionMissingError(
            f"no '{name}' extension is installed (entry point group '{GROUP}'): install the course with "
            f"'pip install -e .' (the course's editor and USD live in step07_advanced), or declare one that "
            f"provides {HOOKS[name]}")
    return found[0].load()
