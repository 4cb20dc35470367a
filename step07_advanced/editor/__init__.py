"""The editor layer: ImGui panels over a running app, on OpenGL and WebGPU alike.

``from step07_advanced.editor import enable_editor``; ``editor = enable_editor(app)`` turns it on. Importing
this package loads no GUI or GPU library: ImGui and the backend's GUI renderer are imported when an
editor is enabled.
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
