"""Locating and loading shader files for both backends (includes resolve in ``render/shaders``), and the files a
built shader was read from (what a shader editor opens and watches)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path

from ..resources import ResourceError, ShaderSource
from ..resources.shader_source import SHADER_EXTENSIONS

SNIPPETS_DIR = Path(__file__).resolve().parent / "shaders"


def load_shader(
    source: str | Path | ShaderSource,
    stage: str | None = None,
    lang: str | None = None,
    include_dirs: Sequence[str | Path] = (),
    generated: Mapping[str, str] | None = None,
    texts: Mapping[Path, str] | None = None,
) -> ShaderSource:
    """A ShaderSource from a path, or from text (then ``lang`` is required), or one given already.

    ``#include`` lines resolve to ``generated`` text first (the shader's Material block), then next to the file,
    then in ``include_dirs``, then in the engine's snippets. ``texts`` (resolved path -> text) stands in for the
    files' contents on disk.
    """
    if isinstance(source, ShaderSource):
        return source
    dirs = [*include_dirs, SNIPPETS_DIR]
    if isinstance(source, Path) or (isinstance(source, str) and "\n" not in source and Path(source).suffix):
        path = Path(source)
        language = SHADER_EXTENSIONS.get(path.suffix, (None, None))[0]
        if lang is not None and language is not None and language != lang:
            api = {"glsl": "OpenGL", "wgsl": "WebGPU"}[lang]
            raise ResourceError(f"shader '{path}'", "path",
                                f"is {language.upper()} (by its extension {path.suffix!r}), but the {api} renderer "
                                f"compiles {lang.upper()}: give it the {lang.upper()} file")
        return ShaderSource.from_file(source, stage=stage, include_dirs=dirs, generated=generated, texts=texts)
    if lang is None:
        raise ValueError("shader text needs lang='glsl' or 'wgsl'")
    return ShaderSource.from_text(source, lang, stage, filename=f"<{stage or lang} text>", include_dirs=dirs,
                                 generated=generated)


def engine_shader_files(stem: str, lang: str) -> tuple[Path, ...]:
    """The files of the engine's shader ``stem`` in ``render/shaders``: ``stem.vert`` and ``stem.frag`` for GLSL,
    ``stem.wgsl`` for WGSL."""
    if lang == "glsl":
        return SNIPPETS_DIR / f"{stem}.vert", SNIPPETS_DIR / f"{stem}.frag"
    if lang == "wgsl":
        return (SNIPPETS_DIR / f"{stem}.wgsl",)
    raise ValueError(f"lang: expected 'glsl' or 'wgsl', got {lang!r}")


def source_files(sources: Iterable[ShaderSource]) -> list[Path]:
    """The files on disk that ``sources`` were read from, each once, in the order they were read (a stage's file,
    then what it includes): text the engine writes (the Material block, Frame and Lights) and text given directly
    are no file."""
    from ..resources.blocks import ENGINE_SNIPPETS, MATERIAL_INCLUDES

    written = {*ENGINE_SNIPPETS, *MATERIAL_INCLUDES}
    found: dict[Path, None] = {}
    for src in sources:
        for name in src.files:
            if name not in written and not name.startswith("<") and Path(name).is_file():
                found.setdefault(Path(name).resolve())
    return list(found)


def is_engine_file(path: str | Path) -> bool:
    """Whether ``path`` is one of the engine's own snippets (``render/shaders``): shown, never edited in place."""
    return Path(path).resolve().parent == SNIPPETS_DIR
