"""All-or-nothing file writes: every file goes to a temporary file in its own folder first, then
``os.replace`` puts them in place (an atomic rename on one file system). On any failure the temporary
files are removed and the files already there stay as they were.
"""

from __future__ import annotations

import os
import secrets
import shutil
from pathlib import Path


class StagedFiles:
    """Temporary files waiting to replace their targets; use as a context manager around the writing."""

    def __init__(self) -> None:
        self._pending: list[tuple[Path, Path]] = []
        self._made_dirs: list[Path] = []

    def temp_for(self, target: Path) -> Path:
        """A new, empty temporary file next to ``target`` (same folder, same suffix, hidden name)."""
        folder = target.parent
        if not folder.exists() and folder.parent.is_dir():
            folder.mkdir()
            self._made_dirs.append(folder)
        while True:
            temp = folder / f".{target.stem}.{secrets.token_hex(4)}.tmp{target.suffix}"
            try:
                # Created like any new file (mode 0o666 less the umask), not 0o600 as mkstemp would.
                os.close(os.open(temp, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o666))
            except FileExistsError:
                continue
            break
        self._pending.append((temp, target))
        if target.is_file():
            shutil.copymode(target, temp)
        return temp

    # --8<-- [start:commit]
    def commit(self) -> None:
        """Move every temporary file onto its target, in the order they were made; all or nothing.

        Each existing target is first renamed to a backup; if any step fails, the files already moved are
        put back (or removed when they were new), so the previous files stay exactly as they were.
        """
        done: list[tuple[Path, Path | None]] = []  # (target, its backup, or None when it was new)
        try:
            for temp, target in self._pending:
                backup = None
                if target.exists() and target.is_file():
                    backup = target.with_name(f".{target.name}.{secrets.token_hex(4)}.bak")
                    os.replace(target, backup)
                done.append((target, backup))
                os.replace(temp, target)
        except BaseException:
            for target, backup in reversed(done):
                if backup is not None:
                    os.replace(backup, target)
                elif target.exists() and target.is_file():
                    target.unlink()
            raise
        for _target, backup in done:
            if backup is not None:
                backup.unlink(missing_ok=True)
        self._pending.clear()
    # --8<-- [end:commit]

    def discard(self) -> None:
        """Remove the temporary files not yet committed (and folders this object made, when left empty)."""
        for temp, _ in self._pending:
            temp.unlink(missing_ok=True)
        self._pending.clear()
        for folder in reversed(self._made_dirs):
            try:
                folder.rmdir()
            except OSError:
                pass  # not empty: it holds committed files
        self._made_dirs.clear()

    def __enter__(self) -> StagedFiles:
        return self

    def __exit__(self, exc_type: object, exc: object, tb: object) -> None:
        if exc_type is not None:
            self.discard()
