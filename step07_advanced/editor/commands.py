"""Undo and redo: every edit the editor makes is a :class:`Command` on the editor's :class:`CommandStack`.

A command knows how to apply itself (``redo``) and how to take itself back (``undo``); the stack runs it once when
it is pushed. A drag (a transform field, a gizmo) makes one command per frame; consecutive commands with the same
``merge_key`` are folded into one until the stack is sealed (the editor seals it when no widget is held), so one
drag is one undo step.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any


# --8<-- [start:command]
@dataclass
class Command:
    """One edit: ``do`` applies it (again, on redo), ``undo`` takes it back; ``label`` names it in the Edit menu.

    Commands that set one thing (a field, a transform, a colour) carry a ``merge_key`` naming it, so that the
    frames of one drag fold into one command.
    """

    label: str
    do: Callable[[], Any]
    undo: Callable[[], Any]
    merge_key: Any = None
# --8<-- [end:command]


class CommandStack:
    """The undo and redo lists of one editor (at most ``limit`` steps are kept)."""

    def __init__(self, limit: int = 200) -> None:
        self.limit = limit
        self.done: list[Command] = []
        self.undone: list[Command] = []
        self._sealed = True
        #: Bumped on every change: panels that show the stack compare it.
        self.version = 0

    # --8<-- [start:push]
    def push(self, command: Command, merge: bool = False) -> Command:
        """Run ``command`` and record it; with ``merge``, fold it into the last one if it edits the same
        thing."""
        command.do()
        top = self.done[-1] if self.done else None
        if merge and not self._sealed and top is not None and command.merge_key is not None \
                and top.merge_key == command.merge_key:
            top.do = command.do  # undo keeps the first command's "before"
        else:
            self.done.append(command)
            del self.done[:-self.limit]
        self._sealed = not merge
        self.undone.clear()
        self.version += 1
        return command
    # --8<-- [end:push]

    def seal(self) -> None:
        """End the current drag: the next command starts a new undo step."""
        self._sealed = True

    def undo(self) -> str | None:
        """Take back the last edit; returns its label (None when there is nothing to undo)."""
        return self._move(self.done, self.undone, "undo")

    def redo(self) -> str | None:
        """Apply the last undone edit again; returns its label (None when there is nothing to redo)."""
        return self._move(self.undone, self.done, "do")

    def _move(self, source: list, target: list, action: str) -> str | None:
        """Pop the last command of ``source``, run its ``action`` (``undo`` or ``do``) and push it on ``target``."""
        if not source:
            return None
        command = source.pop()
        getattr(command, action)()
        target.append(command)
        self._sealed = True
        self.version += 1
        return command.label

    @property
    def can_undo(self) -> bool:
        return bool(self.done)

    @property
    def can_redo(self) -> bool:
        return bool(self.undone)

    def clear(self) -> None:
        """Forget every step (a new or loaded scene starts a fresh history)."""
        self.done.clear()
        self.undone.clear()
        self._sealed = True
        self.version += 1
