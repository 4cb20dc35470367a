"""The Entity-Component-System core: scenes of UUID entities, data-only components, systems.

No graphics library is imported here.
"""

from .component import ColumnarComponent, ColumnStore, Component
from .errors import (
    ECSError,
    HierarchyCycleError,
    MissingComponentError,
    NotAComponentError,
    UnknownEntityError,
)
from .hierarchy import LinkComponent
from .info import InfoComponent
from .manager import SceneManager
from .scene import Scene
from .system import System

__all__ = [
    "ColumnStore",
    "ColumnarComponent",
    "Component",
    "ECSError",
    "HierarchyCycleError",
    "InfoComponent",
    "LinkComponent",
    "MissingComponentError",
    "NotAComponentError",
    "Scene",
    "SceneManager",
    "System",
    "UnknownEntityError",
]
