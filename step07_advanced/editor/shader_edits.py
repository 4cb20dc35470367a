"""What the shader panel edits, without any GUI: the files of the shaders it opened, each edit an undoable command,
compile errors at their file and line, the material values re-checked, and the files watched for other editors.

A shader is opened by name (:meth:`ShaderEdits.open`): its files are the ones the renderer's shader library read
(each stage's file, then what it includes; ``renderer.shaders.files``). Saving a file (:meth:`ShaderEdits.save`)
writes it and rebuilds every opened shader that reads it (``renderer.shaders.rebuild``); a file changed on disk by
any other editor does the same when :meth:`ShaderEdits.poll` sees it (one ``stat`` per file; the panel polls only
while it is open). A compile or link error is kept per shader (:attr:`ShaderEdits.errors`) and logged whole; the
last good program keeps drawing. Undo writes the old text back and rebuilds again, so the old picture returns.

The Material block is declared with the shader in Python (``material=[...]``); the panel shows it as the include
the shader sees (``material.glsl`` / ``material.wgsl``) and :meth:`ShaderEdits.save_material` rebuilds the shader
with the declaration read back from edited text. After each good rebuild the materials of the scene that use the
shader are re-checked against its block: a new field they do not set is set to 0 (it shows in the inspector), a
value the block no longer has is dropped; both are reported, and undo takes them back.
"""

from __future__ import annotations

import dataclasses
import os
import re
import uuid
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from gandalf_core.components import MaterialComponent
from gandalf_core.render.material_block import parse_material_block
from gandalf_core.render.rebuild import KEEP
from gandalf_core.render.shader_files import is_engine_file
from gandalf_core.resources.blocks import material_snippets

from .commands import Command

_LOCATION = re.compile(r"^(?P<file>\S.*?):(?P<line>\d+): (?P<message>.*)$")


@dataclass(frozen=True)
class ShaderProblem:
    """One line of a compile error: the file and line it names (None when it names none) and its message."""

    file: str | None
    line: int | None
    message: str

    def is_in(self, path: str | Path) -> bool:
        """Whether it names ``path`` (a file's path, or an include the engine writes, by its name)."""
        if self.file is None:
            return False
        if isinstance(path, str) and os.sep not in path:
            return self.file == path
        return Path(self.file).resolve() == Path(path).resolve()


def problems(error: str) -> list[ShaderProblem]:
    """The lines of a compile error (``file:line: message``, each with the source line under it) as problems."""
    found: list[ShaderProblem] = []
    for text in error.splitlines():
        match = _LOCATION.match(text)
        if match is not None:
            found.append(ShaderProblem(match["file"], int(match["line"]), match["message"]))
        elif text.strip() and not (found and text.startswith("    ")):  # not the quoted source line
            found.append(ShaderProblem(None, None, text.strip()))
    return found


class ShaderEdits:
    """The shaders the panel opened, their files as last seen on disk, and the errors of their last builds."""

    def __init__(self, editor: Any) -> None:
        self.editor = editor
        #: shader name -> the error of its last rebuild (the last good program draws meanwhile).
        self.errors: dict[str, str] = {}
        #: What the last re-check of the materials reported (new fields set to 0, values dropped).
        self.notes: list[str] = []
        #: Bumped whenever a file's text, an error or the notes change: the panel refreshes its text editors.
        self.version = 0
        self._files: dict[str, list[Path]] = {}
        self._disk: dict[Path, tuple[int, int, str]] = {}  # path -> (mtime_ns, size, text) as last seen or written
        self._editable: dict[Path, bool] = {}
        self._material_texts: dict[str, tuple[Any, str]] = {}

    @property
    def shaders(self) -> Any:
        return self.editor.app.renderer.shaders

    @property
    def lang(self) -> str:
        return self.editor.app.renderer.shading_language

    # --- what is open -------------------------------------------------------------------------------
    def shader_of(self, entity: uuid.UUID | None) -> str | None:
        """The shader that draws ``entity``'s material (None without one, or before the renderer built it)."""
        scene = self.editor.app.scene
        if entity is None or entity not in scene:
            return None
        component = scene.try_component(entity, MaterialComponent)
        materials = self.editor.app.renderer.materials
        if component is None or component.material not in materials:
            return None
        return materials.get(component.material).shader.name

    def open(self, shader: str) -> list[Path]:
        """The files of ``shader`` (stages, then includes), read and watched from now on."""
        files = self._files.get(shader)
        if files is None:
            files = self._files[shader] = self.shaders.files(shader)
            for path in files:
                if path not in self._disk:
                    self._disk[path] = self._stat(path)
        return files

    def text(self, path: Path) -> str:
        """``path``'s text as last read or written."""
        return self._disk[path][2]

    def editable(self, path: Path) -> bool:
        """The engine's own snippets are shown, not edited in place."""
        editable = self._editable.get(path)
        if editable is None:
            editable = self._editable[path] = not is_engine_file(path)
        return editable

    def material_text(self, shader: str) -> str | None:
        """The shader's Material block as the shader sees it (the include the engine writes), or None."""
        block = self.shaders.get(shader).material_block
        if block is None:
            return None
        cached = self._material_texts.get(shader)
        if cached is None or cached[0] is not block:  # written again only for a rebuilt shader
            cached = self._material_texts[shader] = (block, material_snippets(block)[f"material.{self.lang}"])
        return cached[1]

    # --- edits ----------------------------------------------------------------------------------------
    def save(self, path: str | Path, text: str) -> bool:
        """Write ``text`` to ``path`` (a file of an opened shader) and rebuild the shaders that read it, as one
        undoable edit. Returns whether they all built (an error is kept and shown; the last good one draws)."""
        path = Path(path).resolve()
        if path not in self._disk:
            raise ValueError(f"shader panel: {path} is not a file of an opened shader")
        before = self.text(path)
        if text == before or (text == before + "\n" and not before.endswith("\n")):  # the code editor's newline
            return not self._failing([path])
        if not self.editable(path):
            raise ValueError(f"shader panel: {path.name} is one of the engine's own shader files; copy it next to "
                             "your shader to change it")
        return self._push(f"edit {path.name}", {path: text}, {path: before}, {}, {})

    def save_material(self, shader: str, text: str) -> bool:
        """Rebuild ``shader`` with the Material block read from ``text`` (GLSL or WGSL, as :meth:`material_text`
        shows it), as one undoable edit; the materials that use it are re-checked."""
        old = self.shaders.get(shader).material_block
        name = f"material.{self.lang}"
        try:
            layout = parse_material_block(text, self.lang, old, name)
        except ValueError as exc:
            self._fail(shader, str(exc))
            return False
        before = self.shaders.material_declaration(shader)
        return self._push(f"Material block of {shader}", {}, {}, {shader: layout}, {shader: before})

    def poll(self) -> list[Path]:
        """Look at the watched files once (a ``stat`` each): a file another editor changed is taken in as an edit
        (undoable, like a save). Returns the files that changed."""
        changed = []
        for path, (mtime, size, text) in list(self._disk.items()):
            stat = self._stat(path, read=False)
            if stat[:2] == (mtime, size):
                continue
            new = self._stat(path)
            self._disk[path] = (new[0], new[1], text)  # the text stays the old one until the edit runs
            if new[2] != text:
                changed.append((path, new[2], text))
        for path, new, old in changed:
            self._push(f"{path.name} changed on disk", {path: new}, {path: old}, {}, {})
        return [path for path, _new, _old in changed]

    def _push(self, label: str, texts: dict[Path, str], old_texts: dict[Path, str], material: dict[str, Any],
              old_material: dict[str, Any]) -> bool:
        """Run and record one edit: ``texts`` written and ``material`` declarations set, the shaders rebuilt."""
        shaders = self._affected(texts, material)
        materials: dict[str, Any] = {}  # the scene's materials as they were before the first run's re-check

        def do() -> None:
            materials.update(self._apply(texts, material, shaders))

        def undo() -> None:
            self._apply(old_texts, old_material, shaders, restore=materials)

        self.editor.commands.push(Command(label, do, undo))
        return not self._failing(list(texts) or None, shaders)

    def _affected(self, texts: Mapping[Path, str], material: Mapping[str, Any]) -> list[str]:
        return [shader for shader, files in self._files.items() if shader in material or set(texts) & set(files)]

    def _apply(self, texts: Mapping[Path, str], material: Mapping[str, Any], shaders: list[str],
               restore: Mapping[str, Any] | None = None) -> dict[str, Any]:
        """Write ``texts``, rebuild ``shaders`` (with ``material`` declarations where given) and re-check the
        scene's materials (or put back ``restore``, what they were). A program that builds but that a material of the
        scene cannot use (a texture it samples that the material does not bind) is an error too: the last good one
        is built again. Returns the materials the re-check changed, as they were before."""
        last_good = {path: self._disk[path][2] for path in texts if path in self._disk}
        for path, text in texts.items():
            current = self._stat(path)
            if current[2] != text:  # a change another editor made is on disk already: not written again
                path.write_text(text, encoding="utf-8")
                current = self._stat(path)
            self._disk[path] = current
        changed: dict[str, Any] = {}
        if restore is None:
            self.notes = []
        assets = self.editor.app.scene.assets
        for shader in shaders:
            declaration = self.shaders.material_declaration(shader)
            before = {name: data for name, data in assets.materials.items() if data.shader == shader}
            error = self.shaders.rebuild(shader, material=material.get(shader, KEEP))
            if error is None:
                rechecked = self._recheck(shader) if restore is None else {}
                self._put_back({name: data for name, data in (restore or {}).items() if name in before})
                error = self._materials_fail(shader)
                if error is not None:  # the program builds, a material of it does not: the last good one again
                    self._put_back(before)
                    self.shaders.rebuild(shader, last_good, material=declaration)
                else:
                    changed.update(rechecked)
            if error is not None:
                self._fail(shader, str(error))
                continue
            if self.errors.pop(shader, None) is not None:
                self.editor._report(f"shader '{shader}' built again", error=False)
            self._files[shader] = self.shaders.files(shader)  # an include may have come or gone
            for path in self._files[shader]:
                self._disk.setdefault(path, self._stat(path))
        self.version += 1
        return changed

    def _put_back(self, materials: Mapping[str, Any]) -> None:
        """Give the scene's materials their data of before a re-check."""
        assets = self.editor.app.scene.assets
        for name, data in materials.items():
            assets.material(name, data)

    def _materials_fail(self, shader: str) -> Exception | None:
        """Build the scene's materials drawn with ``shader`` now (a texture or buffer the new program reads
        differently is an error naming the material): the error, or None."""
        renderer, assets = self.editor.app.renderer, self.editor.app.scene.assets
        for name, data in assets.materials.items():
            if data.shader == shader:
                try:
                    renderer.resolve_material(name, assets)
                except Exception as exc:  # noqa: BLE001 - a ResourceError names the material and what does not fit
                    return exc
        return None

    def _recheck(self, shader: str) -> dict[str, Any]:
        """The scene's materials drawn with ``shader`` against its new Material block: a field they do not set
        (and that has no default) is set to 0, a value the block no longer has is dropped; both are reported.
        Returns the changed materials' data as it was."""
        block = self.shaders.get(shader).material_block
        fields = {f.name: f for f in block.fields} if block is not None else {}
        assets = self.editor.app.scene.assets
        before: dict[str, Any] = {}
        notes = []
        for name, data in list(assets.materials.items()):
            if data.shader != shader:
                continue
            params = dict(data.params)
            added = [f for key, f in fields.items() if key != "color" and key not in params and not f.has_default]
            removed = {key: value for key, value in params.items() if key not in fields}
            if not added and not removed:
                continue
            for f in added:
                size = block.view(block.new(), f.name).size
                params[f.name] = 0.0 if size == 1 else (0.0,) * size
                notes.append(f"material '{name}': new Material field '{f.name}' of shader '{shader}' set to 0; "
                             "give it a value in the inspector")
            for key, value in removed.items():
                del params[key]
                notes.append(f"material '{name}': '{key}' (was {value}) is no longer a field of shader "
                             f"'{shader}''s Material block; its value was dropped (undo brings it back)")
            before[name] = data
            assets.material(name, dataclasses.replace(data, params=params))
        for note in notes:
            self.editor.log.add("warning", "shader panel", note)
        self.notes += notes
        return before

    def _fail(self, shader: str, message: str) -> None:
        """Keep ``message`` (lines of ``file:line: ...``) as the shader's error and log it, naming the shader."""
        self.errors[shader] = message
        self.version += 1
        self.editor._report(f"shader '{shader}': {message}", error=True)

    def _failing(self, paths: list[Path] | None, shaders: list[str] | None = None) -> bool:
        shaders = shaders if shaders is not None else self._affected(dict.fromkeys(paths or ()), {})
        return any(shader in self.errors for shader in shaders)

    @staticmethod
    def _stat(path: Path, read: bool = True) -> tuple[int, int, str]:
        """(mtime in ns, size, text) of ``path``; ``read=False`` leaves the text out (a poll's cheap look)."""
        try:
            stat = path.stat()
        except OSError:
            return (-1, -1, "")
        return (stat.st_mtime_ns, stat.st_size, path.read_text(encoding="utf-8") if read else "")
