"""The console's source: the engine's log records (python ``logging``), warnings, and the editor's own errors.

:class:`EditorLog` is a logging handler on the root logger and a hook on ``warnings.showwarning`` while the editor
is on (both are put back when it goes). It keeps the last ``limit`` entries. An error's text is kept whole: a
shader error starts with its ``file:line:``, and :func:`file_line` finds it for the console to show.
"""

from __future__ import annotations

import logging
import re
import warnings
from collections import deque
from dataclasses import dataclass
from typing import Any

_FILE_LINE = re.compile(r"([\w./\\:-]+\.\w+):(\d+)")


@dataclass(frozen=True)
class LogEntry:
    level: str  # "info", "warning" or "error"
    source: str  # the logger's name, "warnings" or "editor"
    text: str


def file_line(text: str) -> tuple[str, int] | None:
    """The first ``file.ext:line`` in ``text`` (a shader error's location), or None."""
    match = _FILE_LINE.search(text)
    return (match.group(1), int(match.group(2))) if match else None


class EditorLog(logging.Handler):
    """Collects log records and warnings into :attr:`entries` (newest last)."""

    def __init__(self, limit: int = 500) -> None:
        super().__init__(level=logging.INFO)
        self.entries: deque[LogEntry] = deque(maxlen=limit)
        self.version = 0  # bumped on every entry: the console redraws its cache only then
        self._showwarning: Any = None

    def emit(self, record: logging.LogRecord) -> None:
        level = "error" if record.levelno >= logging.ERROR else "warning" if record.levelno >= logging.WARNING \
            else "info"
        try:
            text = record.getMessage()
        except Exception:  # noqa: BLE001 - a bad format string must not break logging
            text = str(record.msg)
        if record.exc_info and record.exc_info[1] is not None:
            text += f"\n{type(record.exc_info[1]).__name__}: {record.exc_info[1]}"
        self.add(level, record.name, text)

    def add(self, level: str, source: str, text: str) -> None:
        self.entries.append(LogEntry(level, source, str(text)))
        self.version += 1

    def error(self, text: str) -> None:
        self.add("error", "editor", text)

    def install(self) -> None:
        logging.getLogger().addHandler(self)
        self._showwarning = warnings.showwarning

        def show(message: Any, category: type, filename: str, lineno: int, file: Any = None,
                 line: Any = None) -> None:
            self.add("warning", "warnings", f"{category.__name__}: {message} ({filename}:{lineno})")
            self._showwarning(message, category, filename, lineno, file, line)

        warnings.showwarning = show

    def uninstall(self) -> None:
        logging.getLogger().removeHandler(self)
        if self._showwarning is not None:
            warnings.showwarning = self._showwarning
            self._showwarning = None

    def clear(self) -> None:
        self.entries.clear()
        self.version += 1
