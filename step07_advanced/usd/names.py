"""Valid, unique USD prim names (and texture file names) from arbitrary entity and asset names."""

from __future__ import annotations

import re

_INVALID = re.compile(r"[^A-Za-z0-9_]")


def sanitize(name: str, fallback: str = "entity") -> str:
    """``name`` as an ASCII USD identifier: other characters become ``_``; a leading digit gets a ``_`` prefix.

    ASCII only (USD also accepts some Unicode identifiers, other tools may not); the original name is kept
    in the prim's ``gandalf:name`` attribute.
    """
    ident = _INVALID.sub("_", name) or fallback
    return f"_{ident}" if ident[0].isdigit() else ident


class UniqueNames:
    """Hands out sanitized names that are unique within one scope (case-insensitively, for file systems)."""

    def __init__(self, reserved: tuple[str, ...] = ()) -> None:
        self._used = {r.lower() for r in reserved}

    def take(self, name: str, fallback: str = "entity") -> str:
        base = sanitize(name, fallback)
        candidate, n = base, 1
        while candidate.lower() in self._used:
            candidate = f"{base}_{n}"
            n += 1
        self._used.add(candidate.lower())
        return candidate
