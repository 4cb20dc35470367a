"""The student's view of a failed graded test: one sentence, in words.

Each failed graded test gets one line (the same in the terminal, the grade JSON, Gradescope's ``results.json``
and the batch report), built here from the test's exception:

* an untouched stub (``NotImplementedError("exercise: X")``, from the sandbox or in process) says which function
  is still a stub and in which file: ``hsv_to_rgb is still a stub: write it in step01_window/exercises/hue.py``;
* a wrong answer says what was called with which input, what came back and what was expected: the last call of
  the student's code in the test (:func:`record_call`), then the test's own message, or a numpy comparison's
  ``x``/``y`` arrays, or pytest's ``assert left == right``;
* anything else keeps its first line, without module paths.

A sentence that does not name the exercise's function or file is prefixed with it (``brdf (step07_advanced/
exercises/brdf.glsl): ...``), and every sentence is capped at :data:`LIMIT` characters. The full traceback goes to
the grade's log file, never to the student's view.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

#: The longest sentence the student sees for one failed test.
LIMIT = 300
_VALUE_LIMIT = 90
_ROOT = Path(__file__).resolve().parents[2]

# The calls of the student's code in the running test (this process): (label, what came back), newest last.
_calls: list[tuple[str, str]] = []


def reset_calls() -> None:
    """Forget the calls recorded so far (a new test starts)."""
    _calls.clear()


def short(value: Any, limit: int = _VALUE_LIMIT) -> str:
    """``repr(value)`` on one line, numbers rounded, cut to ``limit`` characters."""
    try:
        import numpy as np

        if isinstance(value, np.ndarray):
            with np.printoptions(precision=4, suppress=True, threshold=12, edgeitems=2):
                text = np.array2string(value, separator=", ")
        elif isinstance(value, (tuple, list)) and value and all(isinstance(v, float) for v in value):
            text = "(" + ", ".join(f"{v:.4g}" for v in value) + (",)" if len(value) == 1 else ")")
        elif isinstance(value, float):
            text = f"{value:.6g}"
        else:
            text = repr(value)
    except Exception:  # noqa: BLE001 - a value whose repr fails says so
        text = f"<a {type(value).__name__}>"
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 1] + "…"


def record_call(label: str, result: Any) -> None:
    """Remember that the student's code was called (``label``: ``name(args)``) and what it returned."""
    _calls.append((label, short(result)))
    del _calls[:-4]


def last_call() -> tuple[str, str] | None:
    return _calls[-1] if _calls else None


def _one_line(text: str) -> str:
    return " ".join(part.strip() for part in text.strip().splitlines() if part.strip())


def cap(text: str, limit: int = LIMIT) -> str:
    text = _one_line(text)
    return text if len(text) <= limit else text[: limit - 1] + "…"


def _shown_path(where: str) -> str:
    """``…/step01_window/exercises/hue.py:21`` -> ``step01_window/exercises/hue.py``."""
    path = where.rsplit(":", 1)[0] if re.search(r":\d+$", where) else where
    parts = Path(path).parts
    step = next((i for i in range(len(parts) - 1, -1, -1) if parts[i].startswith("step")), None)
    return "/".join(parts[step:]) if step is not None else path


def stub_sentence(error: BaseException) -> str | None:
    """The sentence for an untouched stub's ``NotImplementedError`` (also behind a ``raise ... from``), or None."""
    seen = 0
    while error is not None and seen < 8:
        if isinstance(error, NotImplementedError):
            name = str(error).removeprefix("exercise:").strip()
            where = getattr(error, "gandalf_where", "")
            if not where:
                import traceback

                frames = [f for f in traceback.extract_tb(error.__traceback__) if "exercises" in Path(f.filename).parts]
                where = frames[-1].filename if frames else ""
                name = name or (frames[-1].name if frames else "")
            if where or str(error).startswith("exercise:"):
                shown = f"write it in {_shown_path(where)}" if where else "write it in the step's exercises/ folder"
                return f"{name or 'this exercise'} is still a stub: {shown} (its docstring says what it must do)."
        error, seen = error.__cause__ or error.__context__, seen + 1  # type: ignore[assignment]
    return None


_NUMPY = re.compile(r"^(Not equal to tolerance.*|Arrays are not .*|Items are not equal.*)$", re.M)


def _numpy_sentence(text: str) -> str | None:
    """numpy.testing's multi-line report -> ``gave X, expected Y (tolerance; N of M values differ by up to D)``."""
    head = _NUMPY.search(text)
    if head is None:
        return None
    x = re.search(r"^\s*(?:x|ACTUAL): (.*?)(?=^\s*(?:y|DESIRED): |\Z)", text, re.M | re.S)
    y = re.search(r"^\s*(?:y|DESIRED): (.*)", text, re.M | re.S)
    mismatch = re.search(r"Mismatched elements: (\d+) / (\d+)", text)
    largest = re.search(r"Max absolute difference[^:]*: *(\S+)", text)
    lines = [line.strip() for line in text[head.end():].splitlines()]
    note = next((line for line in lines if line and not line.startswith(
        ("Mismatch", "Max ", "x:", "y:", "ACTUAL", "DESIRED", "(shapes")) and line[:1] not in "[(-0123456789"), "")
    got = _one_line(x.group(1)) if x else "?"
    expected = _one_line(y.group(1)) if y else "?"
    detail = head.group(1).replace("Not equal to tolerance ", "within ").replace("Arrays are not ", "")
    extra = f"; {mismatch.group(1)} of {mismatch.group(2)} values differ" if mismatch else ""
    extra += f" by up to {largest.group(1)}" if largest else ""
    text = f"got {got[:_VALUE_LIMIT]}, expected {expected[:_VALUE_LIMIT]} ({detail}{extra})"
    return f"{note}: {text}" if note else text


_ASSERT = re.compile(r"^assert (.+?) (==|!=|<=|>=|<|>| is not | is | in | not in ) ?(.+)$")


def _assert_sentence(text: str) -> str:
    """pytest's ``assert <got> == <expected>`` introspection -> ``got …, expected …``; a test's own message wins."""
    lines = text.strip().splitlines()
    first = next((i for i, line in enumerate(lines) if line.startswith("assert ")), None)
    own = _one_line("\n".join(lines[:first] if first is not None else lines))
    if own:
        return own
    if first is None:
        return "the check failed"
    match = _ASSERT.match(lines[first])
    if match and match.group(2) == "==":
        got, expected = match.group(1), match.group(3)
        return f"got {got[:_VALUE_LIMIT]}, expected {expected[:_VALUE_LIMIT]}"
    return f"expected {lines[first].removeprefix('assert ')[: 2 * _VALUE_LIMIT]} to hold"


def _first_line(error: BaseException) -> str:
    text = str(error).strip()
    name = type(error).__name__
    if type(error).__module__ not in ("builtins",) and name in ("Failed", "XFailed"):
        return _one_line(text)
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    first = lines[0] if lines else ""
    # A driver's error ("Validation Error / Caused by: / In ... / <what>") says what went wrong in its last line.
    body = f"{first} {lines[-1]}" if len(lines) > 1 and "Caused by" in text else first
    return f"{name}: {body}" if body else name


def sentence(error: BaseException, *, exercise: str = "", file: str = "", hint: str = "") -> str:
    """One line for the student: what failed, with input, expected and got where the test gives them."""
    stub = stub_sentence(error)
    if stub is not None:
        return cap(stub)
    if isinstance(error, AssertionError):
        text = str(error)
        body = _numpy_sentence(text) or _assert_sentence(text)
        call = last_call()
        if call is not None and call[0].split("(")[0] not in body:
            label, result = call
            body = (f"{label} returned {result}: {body}" if "got" in body or "returned" in body
                    else f"{label} returned {result}; {body}")
    else:
        body = _first_line(error)
    body = re.sub(r"\b(?:[a-z_]+\.)+([A-Z]\w*(?:Error|Timeout|Exception|Warning))\b", r"\1", body)
    body = body.removeprefix("Failed: ")
    named = [n for n in (exercise, Path(file).name if file else "") if n]
    if named and not any(n in body for n in named):
        body = f"{exercise}{f' ({file})' if file else ''}: {body}"
    if hint and hint not in body:
        body = f"{body} Hint: {hint}"
    return cap(body)


def exercise_file(step: str, exercise: str, backend: str = "") -> str:
    """The exercise's file, as the student sees it (``step07_advanced/exercises/brdf.glsl``), or ``""``."""
    folder = _ROOT / step / "exercises"
    if not folder.is_dir() or not exercise:
        return ""
    word = re.compile(rf"\b{re.escape(exercise.split('.')[0])}\b")
    found = []
    for path in sorted(folder.iterdir()):
        if path.suffix not in (".py", ".glsl", ".wgsl") or path.name == "__init__.py":
            continue
        if path.stem == exercise or word.search(path.read_text(errors="replace")):
            found.append(path)
    if not found:  # a name that joins words ("reflect_refract"): the files that hold each of them
        parts = [part for part in exercise.split("_") if len(part) > 2]
        found = [p for p in sorted(folder.iterdir()) if p.suffix in (".py", ".glsl", ".wgsl")
                 and p.name != "__init__.py" and all(part in p.read_text(errors="replace") for part in parts)]
    if backend:
        wanted = {"opengl": ".glsl", "webgpu": ".wgsl"}.get(backend)
        found = [p for p in found if p.suffix in (".py", wanted)] or found
    return " / ".join(f"{step}/exercises/{p.name}" for p in found[:2])
