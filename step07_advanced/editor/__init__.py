"""The editor layer: ImGui panels over a running app, on OpenGL and WebGPU alike (step 07's last concept).

``from step07_advanced.editor import enable_editor``; ``editor = enable_editor(app)`` turns it on. Every step's
launcher turns it on with ``--editor`` through the engine's ``editor`` hook (:mod:`gandalf_core.app.extensions`),
without importing this package. Panels are entities (:class:`EditorPanelComponent`) drawn by one system per panel
kind; the inspector is generated from the components' fields; every edit is an undoable command. Importing this
package loads no GUI or GPU library: ImGui and the backend's GUI renderer are imported when an editor is enabled.
"""

from .components import PANEL_KINDS, EditorPanelComponent, is_editor_entity
from .editor import Editor
from .enable import disable_editor, editor_of, enable_editor

__all__ = [
    "PANEL_KINDS",
    "Editor",
    "EditorPanelComponent",
    "disable_editor",
    "editor_of",
    "enable_editor",
    "is_editor_entity",
]
