"""Shader source text (GLSL or WGSL) with its file name, a small ``#include`` preprocessor and a line map.

Shader compilers report errors as a line in the text they were given. After ``#include "name"`` lines have
been expanded that line number means nothing to the reader, so :class:`ShaderSource` keeps, for every line of
the expanded text, the file and line it came from (:meth:`ShaderSource.source_map`), and
:meth:`ShaderSource.format_error` turns a compiler's line into ``"file:line: message"`` plus the offending
source line.

Includes are resolved relative to the including file, then in ``include_dirs``. A file's text may be handed in
(``texts``, by resolved path) instead of read from disk: a shader editor compiles what it holds. Each file is
included at most once per shader (later ``#include`` lines of the same file become comments), so snippet
libraries may include each other freely; a file that includes itself, directly or through others, is an error
naming the chain.
The same ``#include`` syntax is used in GLSL and WGSL files: it is expanded here, before either compiler sees it.

Some includes are written by the engine rather than read from a file (``generated``): the uniform blocks declared
in Python (``"blocks.glsl"``/``"blocks.wgsl"``: Frame and Lights, :mod:`.blocks`; ``"material.glsl"``/
``"material.wgsl"``: the shader's own Material block, given when the shader is built). They resolve first.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType

from gandalf_core.resources.errors import ResourceError

# File extension -> (language, stage); a WGSL module may hold several entry points, so it has no single stage.
SHADER_EXTENSIONS: dict[str, tuple[str, str | None]] = {
    ".vert": ("glsl", "vertex"),
    ".frag": ("glsl", "fragment"),
    ".geom": ("glsl", "geometry"),
    ".tesc": ("glsl", "tess_control"),
    ".tese": ("glsl", "tess_evaluation"),
    ".comp": ("glsl", "compute"),
    ".wgsl": ("wgsl", None),
}
LANGUAGES = ("glsl", "wgsl")
STAGES = ("vertex", "fragment", "geometry", "tess_control", "tess_evaluation", "compute")

_INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"\s*(//.*)?$')


def format_compile_error(filename: str, source: str, line: int, message: str) -> str:
    """``"filename:line: message"`` followed by the offending source line (indented) when ``line`` exists."""
    lines = source.splitlines()
    text = f"{filename}:{line}: {message}"
    if 1 <= line <= len(lines):
        text += f"\n    {lines[line - 1].rstrip()}"
    return text


def _read_text(path: Path, label: str, field: str) -> str:
    if not path.is_file():
        raise ResourceError(label, field, f"file not found: {str(path)!r}")
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise ResourceError(label, field, f"cannot read {str(path)!r} as UTF-8 text: {exc}") from exc


class _Expander:
    """Expands ``#include`` lines recursively, recording where every output line came from."""

    def __init__(self, root_name: str, include_dirs: Sequence[Path], generated: Mapping[str, str],
                 texts: Mapping[Path, str] | None = None) -> None:
        self.root_name = root_name
        self.generated = generated
        self.texts = texts or {}
        self.include_dirs = include_dirs
        self.lines: list[str] = []
        self.line_map: list[tuple[str, int]] = []
        self.files: dict[str, tuple[str, ...]] = {}
        self.included: set[Path | str] = set()

    def _resolve(self, name: str, base_dir: Path | None, where: str) -> Path:
        candidates = ([base_dir / name] if base_dir is not None else []) + [d / name for d in self.include_dirs]
        for c in candidates:
            if c.is_file():
                return c
        searched = ", ".join(repr(str(c.parent)) for c in candidates) or "nowhere (no base directory)"
        if name in ("material.glsl", "material.wgsl"):
            searched += " (the Material block is written when the shader is built by its library)"
        raise ResourceError(f"shader '{self.root_name}'", "include", f'{where}: "{name}" not found in {searched}')

    def expand(self, text: str, filename: str, base_dir: Path | None, chain: list[tuple[Path | str, str]]) -> None:
        lines = text.splitlines()
        self.files[filename] = tuple(lines)
        for number, line in enumerate(lines, 1):
            match = _INCLUDE.match(line)
            if match is None:
                self.lines.append(line)
                self.line_map.append((filename, number))
                continue
            if match.group(1) in self.generated:
                target: Path | str = match.group(1)
                key: Path | str = f"<generated {target}>"
            else:
                target = self._resolve(match.group(1), base_dir, f"{filename}:{number}")
                key = target.resolve()
            if any(key == k for k, _ in chain):
                names = " -> ".join([n for _, n in chain] + [str(target)])
                raise ResourceError(f"shader '{self.root_name}'", "include", f"include cycle: {names}")
            self.line_map.append((filename, number))
            # The marker comments avoid the literal `#include "..."`: moderngl would try to resolve it again.
            if key in self.included:
                self.lines.append(f"// included already: {match.group(1)}")
                continue
            self.lines.append(f"// begin included file: {match.group(1)}")
            self.included.add(key)
            if isinstance(target, str):
                self.expand(self.generated[target], target, None, chain + [(key, target)])
                continue
            sub = self.texts.get(key)
            if sub is None:
                sub = _read_text(target, f"shader '{self.root_name}'", "include")
            self.expand(sub, str(target), target.parent, chain + [(key, str(target))])


@dataclass(frozen=True, eq=False)
class ShaderSource:
    """One shader's text after include expansion, with its origin.

    ``filename`` names the top-level file (or a label for text given directly), ``lang`` is ``"glsl"`` or
    ``"wgsl"``, ``stage`` a name from :data:`STAGES` (``None`` for a WGSL module with several entry points).
    ``line_map[i]`` is the ``(file, line)`` of expanded line ``i + 1``; ``files`` holds each file's own lines.
    Build it with :meth:`from_file` or :meth:`from_text`.
    """

    text: str
    filename: str
    lang: str
    stage: str | None
    line_map: tuple[tuple[str, int], ...]
    files: Mapping[str, tuple[str, ...]]

    @classmethod
    def from_file(
        cls, path: str | Path, stage: str | None = None, include_dirs: Sequence[str | Path] = (),
        generated: Mapping[str, str] | None = None, texts: Mapping[Path, str] | None = None,
    ) -> ShaderSource:
        """Load a shader file; language and stage follow from the extension (see :data:`SHADER_EXTENSIONS`).

        ``stage`` overrides the extension's stage (e.g. to name the entry stage of a ``.wgsl`` file). ``texts``
        maps resolved paths to text used instead of the file's (the file itself or any file it includes).
        """
        p = Path(path)
        label = f"shader '{p}'"
        if p.suffix not in SHADER_EXTENSIONS:
            raise ResourceError(
                label, "path", f"unknown shader extension {p.suffix!r}; expected one of {', '.join(SHADER_EXTENSIONS)}"
            )
        lang, default_stage = SHADER_EXTENSIONS[p.suffix]
        texts = texts or {}
        text = texts.get(p.resolve())
        if text is None:
            text = _read_text(p, label, "path")
        return cls._build(text, str(p), lang, stage or default_stage, p.parent, include_dirs, p.resolve(), generated,
                          texts)

    @classmethod
    def from_text(
        cls,
        text: str,
        lang: str,
        stage: str | None = None,
        filename: str = "<text>",
        base_dir: str | Path | None = None,
        include_dirs: Sequence[str | Path] = (),
        generated: Mapping[str, str] | None = None,
    ) -> ShaderSource:
        """Wrap shader text given directly; ``filename`` labels it in errors, includes resolve from ``base_dir``."""
        return cls._build(
            text, filename, lang, stage, None if base_dir is None else Path(base_dir), include_dirs, filename,
            generated,
        )

    @classmethod
    def _build(
        cls,
        text: str,
        filename: str,
        lang: str,
        stage: str | None,
        base_dir: Path | None,
        include_dirs: Sequence[str | Path],
        key: Path | str,
        generated: Mapping[str, str] | None = None,
        texts: Mapping[Path, str] | None = None,
    ) -> ShaderSource:
        label = f"shader '{filename}'"
        if lang not in LANGUAGES:
            raise ResourceError(label, "lang", f"{lang!r} is not one of {', '.join(repr(x) for x in LANGUAGES)}")
        if stage is not None and stage not in STAGES:
            raise ResourceError(label, "stage", f"{stage!r} is not one of {', '.join(repr(s) for s in STAGES)}")
        if lang == "glsl" and stage is None:
            raise ResourceError(label, "stage", "a GLSL shader needs a stage (vertex, fragment, ...)")
        if not isinstance(text, str):
            raise ResourceError(label, "text", f"expected str, got {type(text).__name__}")
        from .blocks import ENGINE_SNIPPETS  # the engine's blocks, written from their declaration

        expander = _Expander(filename, [Path(d) for d in include_dirs], {**ENGINE_SNIPPETS, **(generated or {})}, texts)
        expander.expand(text, filename, base_dir, [(key, filename)])
        return cls(
            text="\n".join(expander.lines) + "\n",
            filename=filename,
            lang=lang,
            stage=stage,
            line_map=tuple(expander.line_map),
            files=MappingProxyType(expander.files),
        )

    def source_map(self, line: int) -> tuple[str, int]:
        """The ``(file, line)`` that line ``line`` (1-based) of the expanded text came from."""
        if not 1 <= line <= len(self.line_map):
            raise ResourceError(
                f"shader '{self.filename}'", "line", f"{line} is outside the expanded text (1..{len(self.line_map)})"
            )
        return self.line_map[line - 1]

    def format_error(self, line: int, message: str) -> str:
        """A compiler message for expanded line ``line`` as ``"file:line: message"`` in the original file.

        A line the map does not know (some drivers report line 0) is reported against the top-level file.
        """
        if 1 <= line <= len(self.line_map):
            file, original = self.line_map[line - 1]
        else:
            file, original = self.filename, line
        return format_compile_error(file, "\n".join(self.files[file]), original, message)
