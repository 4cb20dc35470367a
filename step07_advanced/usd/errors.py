"""The errors and warnings of USD saving and loading; every message names the file, prim and attribute."""

from __future__ import annotations

from pathlib import Path


class USDSceneError(ValueError):
    """A scene could not be saved to or loaded from a USD file.

    The message reads ``"<file>: <prim>: <attribute>: <detail>"`` (parts that do not apply are left out);
    the parts stay available as attributes for tools such as the editor.
    """

    def __init__(self, file: str | Path, detail: str, *, prim: str | None = None, attribute: str | None = None) -> None:
        self.file = str(file)
        self.prim = prim
        self.attribute = attribute
        self.detail = detail
        parts = [self.file]
        if prim is not None:
            parts.append(f"prim <{prim}>")
        if attribute is not None:
            parts.append(f"attribute '{attribute}'")
        super().__init__(": ".join([*parts, detail]))


class USDSceneWarning(UserWarning):
    """Something in a scene or file was left out (a component with no USD mapping, an unknown component)."""
