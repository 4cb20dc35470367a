"""Turning the editor on and off for an app: where the Editor and its panel systems are brought together.

:func:`enable_editor` is the course's ``editor`` extension (``Application(editor=True)``, every launcher's
``--editor``: see :mod:`gandalf_core.app.extensions`). The panels know the Editor's type; the Editor is handed
the panel classes here, so neither module imports the other in a circle.
"""

from __future__ import annotations

import weakref
from typing import Any

from .editor import Editor

_EDITORS: weakref.WeakKeyDictionary[Any, Editor] = weakref.WeakKeyDictionary()


# --8<-- [start:enable]
def enable_editor(app: Any) -> Editor:
    """Turn the editor on for ``app`` (either backend, window or headless); returns the (only) Editor."""
    editor = editor_of(app)
    if editor is None:
        from .panels import PANEL_SYSTEMS  # imports ImGui: only when an editor is turned on

        editor = _EDITORS[app] = Editor(app, PANEL_SYSTEMS)
    return editor
# --8<-- [end:enable]


def disable_editor(app: Any) -> None:
    """Turn the editor off for ``app`` (nothing happens when it is off)."""
    editor = _EDITORS.pop(app, None)
    if editor is not None:
        editor.disable()


def editor_of(app: Any) -> Editor | None:
    """The app's enabled editor, or None (also after the app closed, which turns its editor off)."""
    editor = _EDITORS.get(app)
    return editor if editor is not None and editor.enabled else None
