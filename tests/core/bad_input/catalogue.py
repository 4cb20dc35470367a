"""The table-driven helper of the bad-input catalogue: a :class:`Case` per input, :func:`params` to parametrise a
test with a table, :func:`run` to play one case.

Three kinds of case::

    error("fov-string", lambda: CameraComponent("wide"), FieldError, "CameraComponent.fov", "'wide'")
    result("scale-uniform", lambda: TransformComponent(scale=2).scale, lambda s: np.array_equal(s, [2, 2, 2]))
    warning("usd-unknown-prim", lambda: load(path), USDSceneWarning, "</World/hair>", "BasisCurves")

An error case passes when the action raises the type (or a subclass) and the message holds every word (exact
text, case-sensitive): the words are what names the thing at fault. A result case passes when ``check(value)``
returns True or None (it may assert with its own message). ``xfail="..."`` marks a known engine bug in a part this
catalogue does not own: the case is expected to fail (strictly: it fails the run once the bug is fixed, so the
mark is removed with the fix) and the reason says what is wrong.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest


@dataclass(frozen=True)
class Case:
    """One catalogue row: an action and what it must give."""

    id: str
    action: Callable[..., Any]
    raises: type[BaseException] | tuple[type[BaseException], ...] | None = None
    warns: type[Warning] | None = None
    words: tuple[str, ...] = ()
    check: Callable[[Any], Any] | None = None
    #: A known bug elsewhere: a reason (every backend), or {backend: reason} for the backends it affects.
    xfail: str | dict[str, str] | None = None

    def describe(self) -> str:
        if self.raises is not None:
            names = self.raises if isinstance(self.raises, tuple) else (self.raises,)
            return f"{' or '.join(t.__name__ for t in names)} naming {list(self.words)}"
        if self.warns is not None:
            return f"a {self.warns.__name__} naming {list(self.words)}"
        return "the right result"


def error(id: str, action: Callable[..., Any], raises: type[BaseException] | tuple[type[BaseException], ...],
          *words: str, xfail: str | dict[str, str] | None = None) -> Case:
    """The action must raise ``raises`` with every one of ``words`` in its message."""
    return Case(id, action, raises=raises, words=words, xfail=xfail)


def warning(id: str, action: Callable[..., Any], warns: type[Warning], *words: str,
            xfail: str | dict[str, str] | None = None) -> Case:
    """The action must warn with ``warns`` (one of its warnings holding every one of ``words``) and not raise."""
    return Case(id, action, warns=warns, words=words, xfail=xfail)


def result(id: str, action: Callable[..., Any], check: Callable[[Any], Any], *,
           xfail: str | dict[str, str] | None = None) -> Case:
    """The action must succeed and ``check(its result)`` hold (True or None; it may assert itself)."""
    return Case(id, action, check=check, xfail=xfail)


def _marks(case: Case, backend: str | None) -> list[Any]:
    reason = case.xfail.get(backend) if isinstance(case.xfail, dict) else case.xfail
    return [pytest.mark.xfail(strict=True, reason=reason)] if reason else []


def params(cases: Iterable[Case]) -> list[Any]:
    """``pytest.param`` per case, with the case's id and its xfail mark; ids must be unique in a table."""
    out, seen = [], set()
    for case in cases:
        assert case.id not in seen, f"case id {case.id!r} is used twice"
        seen.add(case.id)
        out.append(pytest.param(case, id=case.id, marks=_marks(case, None)))
    return out


def params_per_backend(cases: Iterable[Case], backends: tuple[str, ...] = ("opengl", "webgpu")) -> list[Any]:
    """``pytest.param(case, backend)`` for every backend and case (all of one backend first, so a module's app
    per backend is made once), each with the xfail mark the case states for that backend."""
    cases = list(cases)
    params(cases)  # the id check
    return [pytest.param(case, backend, id=f"{backend}-{case.id}", marks=_marks(case, backend))
            for backend in backends for case in cases]


def _missing(message: str, words: tuple[str, ...]) -> list[str]:
    return [w for w in words if w not in message]


def run(case: Case, *args: Any) -> Any:
    """Play ``case`` (its action called with ``args``, e.g. a shared app) and assert what it must give."""
    expected = case.describe()
    if case.raises is not None:
        try:
            value = case.action(*args)
        except case.raises as exc:
            message = str(exc)
            missing = _missing(message, case.words)
            assert not missing, (f"[{case.id}] expected {expected}; the {type(exc).__name__} does not name "
                                 f"{missing}:\n  {message}")
            return exc
        except Exception as exc:  # the wrong type: show it whole
            from gandalf_core.render.capabilities import CapabilityError

            if isinstance(exc, CapabilityError):  # this machine lacks what the case needs: a named skip
                raise
            raise AssertionError(f"[{case.id}] expected {expected}, got {type(exc).__name__}: {exc}") from exc
        raise AssertionError(f"[{case.id}] expected {expected}, but it succeeded and gave {value!r:.300}")
    if case.warns is not None:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            value = case.action(*args)
        messages = [str(w.message) for w in caught if issubclass(w.category, case.warns)]
        assert messages, (f"[{case.id}] expected {expected}; warnings given: "
                          f"{[f'{w.category.__name__}: {w.message}' for w in caught]}")
        assert any(not _missing(m, case.words) for m in messages), (
            f"[{case.id}] expected {expected}; no {case.warns.__name__} names all of them:\n  " + "\n  ".join(messages))
        return value
    value = case.action(*args)
    assert case.check is not None, f"[{case.id}] a result case needs a check"
    verdict = case.check(value)
    ok = verdict is None or (isinstance(verdict, (bool, np.bool_)) and bool(verdict))
    assert ok, f"[{case.id}] expected {expected}, got {value!r:.300}"
    return value


def quietly(action: Callable[..., Any], category: type[Warning]) -> Callable[..., Any]:
    """``action`` with its warnings of ``category`` silenced: a case about what still loads (or the error it ends
    in), whose warning has a case of its own."""
    def quiet(*args: Any) -> Any:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", category)
            return action(*args)
    return quiet


def write_files(root: Path, files: Mapping[str, str]) -> Path:
    """Write the catalogue's input files (name -> text) into the folder ``root``; returns ``root``."""
    for name, text in files.items():
        (root / name).write_text(text)
    return root
