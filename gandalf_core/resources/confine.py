"""Files a file names stay in its folder: the one rule every loader applies to the paths inside what it reads (a
glTF's buffer and image URIs, an OBJ's material library and the images that names), resolved after following
symbolic links, unless the caller opts in with ``allow_outside=True``."""

from __future__ import annotations

from pathlib import Path

from .errors import ResourceError


def inside_folder(owner: Path, name: str, label: str, where: str, what: str = "the path",
                  allow_outside: bool = False) -> Path:
    """The file ``name`` names (relative to ``owner``'s folder, or absolute), resolved with its symlinks followed;
    a :class:`ResourceError` (``label``, ``where``) naming ``what``, ``name`` and the resolved path when it lies
    outside ``owner``'s folder, unless ``allow_outside``."""
    folder = owner.parent.resolve()
    file = (folder / name).resolve()  # symlinks followed: a link to a file elsewhere lies elsewhere
    if not allow_outside and not file.is_relative_to(folder):
        raise ResourceError(label, where, f"{what} '{name}' ({file}) lies outside the file's folder {folder}: "
                                          "refused (allow_outside=True allows it)")
    return file
