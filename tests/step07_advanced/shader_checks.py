"""What the step 07 graders of shader functions share: each API's shading language, the folder of the
implementation under test, one graded check, and whether a mutant of a solution file fails a check."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from pathlib import Path
from types import ModuleType
from typing import Any

from gandalf_core.app.cli import load_impl

#: backend -> the language of its shader files.
LANGUAGE = {"opengl": "glsl", "webgpu": "wgsl"}
#: A check: (language, folder of the shader files) -> None, or what is wrong.
Check = Callable[[str, Path], "str | None"]


def impl_dir(impl: ModuleType | Any) -> Path:
    """The folder of the implementation under test (its shader files lie beside its ``__init__``)."""
    return Path(impl.__file__).resolve().parent


def grade(check: Check, impl: ModuleType, backend: str, file: str) -> None:
    """Run ``check`` on ``impl``'s ``file``.glsl or .wgsl (by ``backend``); fail with what it found."""
    language = LANGUAGE[backend]
    message = check(language, impl_dir(impl))
    assert message is None, f"{file}.{language}: {message}"


def mutant_fails(tmp_path: Path, stem: str, language: str, edits: Iterable[tuple[str, str, str]],
                 checks: Iterable[Check]) -> bool:
    """Write the reference ``stem``.``language`` with the mutant's ``(file, old, new)`` edits of that file into
    ``tmp_path`` (each ``old`` must occur exactly once, so a changed solution breaks a stale mutant loudly); True
    when one of ``checks`` fails on it."""
    source = impl_dir(load_impl("step07_advanced")) / f"{stem}.{language}"
    text = source.read_text()
    for file, old, new in edits:
        if file == source.name:
            assert text.count(old) == 1, f"{old!r} must occur once in {source}"
            text = text.replace(old, new)
    (tmp_path / source.name).write_text(text)
    return any(check(language, tmp_path) is not None for check in checks)
