"""Rebuilding a shader from new text, the same way in both backends, without losing the last good one.

Both backends' shader libraries remember how each shader was built (its files, include folders, entry points and
Material declaration). :meth:`RebuildableShaders.rebuild` compiles the shader again from its files, or from text
handed in for any of them (a shader editor's), optionally with a new Material declaration. A compile or link error
is returned, not raised, and changes nothing: the old program keeps drawing. A good build takes the old one's place
(:meth:`~gandalf_core.render.library.ResourceLib.replace`): the materials built with it and the renderer's
pipelines or vertex arrays made for it are dropped and made again on their next use.

Nothing here runs unless a shader is rebuilt: the recipe is a tuple kept per shader.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from ..resources import ResourceError
from .errors import ShaderCompileError
from .shader_files import source_files

#: ``rebuild(material=KEEP)``: the shader keeps the Material declaration it was built with.
KEEP: Any = object()


class RebuildableShaders:
    """Mixed into each backend's ``ShaderLib`` (which provides ``_compile``, ``replace``, ``data_of``, ``stats``)."""

    kind: str
    stats: Any
    _recipes: dict[str, tuple[tuple[Any, ...], dict[str, Any]]]

    def _remember(self, name: str, args: tuple[Any, ...], kwargs: dict[str, Any]) -> None:
        self._recipes[name] = (args, kwargs)

    def _recipe(self, name: str) -> tuple[tuple[Any, ...], dict[str, Any]]:
        recipe = self._recipes.get(name)
        if recipe is None:
            raise KeyError(f"shader '{name}' was not built by this library's build(): nothing to rebuild it from")
        return recipe

    def material_declaration(self, name: str) -> Any:
        """The Material declaration shader ``name`` was (last) built with (None: the colour alone)."""
        return self._recipe(name)[1].get("material")

    # --8<-- [start:rebuild]
    def rebuild(self, name: str, sources: Mapping[str | Path, str] | None = None, material: Any = KEEP,
                ) -> ShaderCompileError | ResourceError | None:
        """Compile shader ``name`` again: from its files on disk, with ``sources`` (path -> text) in place of any of
        them (a stage or an included file), and with a new Material ``material`` declaration if one is given.

        Returns the error (its message starts with ``file:line:`` in the file where it is, through includes) and
        leaves the last good shader in place; or None once the new one has replaced it.
        """
        args, kwargs = self._recipe(name)
        if material is not KEEP:
            kwargs = {**kwargs, "material": material}
        texts = {Path(path).resolve(): text for path, text in (sources or {}).items()}
        try:
            shader, data = self._compile(name, *args, texts=texts, **kwargs)  # type: ignore[attr-defined]
        except (ShaderCompileError, ResourceError) as exc:
            return exc
        self.replace(name, shader, data)  # type: ignore[attr-defined]
        self._remember(name, args, kwargs)
        self.stats["shaders_rebuilt"] += 1
        return None
    # --8<-- [end:rebuild]

    def files(self, name: str) -> list[Path]:
        """The files on disk shader ``name`` was built from: each stage's file, then what it includes, each once."""
        data = self.data_of(name)  # type: ignore[attr-defined]
        if data is None:
            raise KeyError(f"shader '{name}' has not been built")
        return source_files(data.values() if isinstance(data, Mapping) else [data])
