"""The student's view of a failed graded test: one sentence, in words.

Each failed graded test gets one line (the same in the terminal, the grade JSON, Gradescope's ``results.json``
and the batch report), built here from the test's exception:

* an untouched stub (``NotImplementedError("exercise: X")``, from the sandbox or in process) says which function
  is still a stub and in which file: ``hsv_to_rgb is still a stub: write it in step01_window/exercises/hue.py``;
* a wrong answer says what was called with which input, what came back and what was expected: the last call of
  the student's code in the test (:func:`record_call`), then the test's own message, or a numpy comparison's
  ``x``/``y`` arrays, or pytest's ``assert left == right``, or an ordering's bound (``got worst = 3, expected ≤ 1``);
* a call that should have raised and returned, or raised the wrong error (:func:`record_raise`), says what it did
  and what the ``pytest.raises`` around it waits for (:func:`raises_expected`);
* anything else keeps its first line, without module paths.

:func:`teaching_gaps` says which of input, expected and got a sentence leaves out: the mutation check counts them
over every mutant's first failed test.

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

# The calls of the student's code in the running test (this process): (label, what came back), newest last; what
# came back is "raised <error>" for a call that raised (its error object kept in _raised).
_calls: list[tuple[str, str]] = []
_raised: list[BaseException] = []
_last_result: list[Any] = []  # [function name, the value it returned] of the newest call


def _shorter(label: str, limit: int) -> str:
    return label if len(label) <= limit else label[: limit - 2] + "…)"


def _clip(text: str, limit: int) -> str:
    return text if len(text) <= limit else text[: limit - 1] + "…"


def reset_calls() -> None:
    """Forget the calls recorded so far (a new test starts)."""
    _calls.clear()
    _last_result.clear()
    _raised.clear()


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
        elif isinstance(value, (bytes, bytearray, memoryview)):  # packed GPU data: its size says more than its bytes
            text = f"{len(bytes(value))} bytes"
        else:
            text = repr(value)
    except Exception:  # noqa: BLE001 - a value whose repr fails says so
        text = f"<a {type(value).__name__}>"
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 1] + "…"


def record_call(label: str, result: Any) -> None:
    """Remember that the student's code was called (``label``: ``name(args)``) and what it returned."""
    if label.split("(", 1)[0].rsplit(".", 1)[-1].startswith("_"):
        return  # a private helper of the student's package, called by the function the test called
    label = re.sub(r"<function (?:[\w.]+\.<locals>\.)?([\w.]+) at 0x[0-9a-f]+>", r"\1", label)  # a callback by name
    _calls.append((label, short(result, 60)))
    del _calls[:-4]
    _last_result[:] = [label.split("(", 1)[0], result]


def record_raise(label: str, error: BaseException) -> None:
    """Remember that a call of the student's code (``label``) raised ``error`` instead of returning."""
    if label.split("(", 1)[0].rsplit(".", 1)[-1].startswith("_") or type(error).__name__ == "ExerciseTimeout":
        return
    label = re.sub(r"<function (?:[\w.]+\.<locals>\.)?([\w.]+) at 0x[0-9a-f]+>", r"\1", label)
    _calls.append((label, f"raised {type(error).__name__}: {_one_line(str(error))}".rstrip(": ")))
    del _calls[:-4]
    _raised[:] = [error]


def last_call() -> tuple[str, str] | None:
    return _calls[-1] if _calls else None


def _verb(result: str) -> str:
    """``returned X`` or, for a call that raised, ``raised …`` (``result`` already says it)."""
    return result if result.startswith("raised ") else f"returned {result}"


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


def _readable(text: str) -> str:
    """pytest's reprs made short: ``approx((0.9 ± 1e-09, 0.27 ± 1e-09))`` -> ``(0.9, 0.27)``; long floats rounded."""
    text = re.sub(r" ± [\d.e+-]+", "", text)
    text = re.sub(r"\bapprox\((.*)\)", r"\1", text)
    return re.sub(r"-?\d+\.\d{7,}(?:e[+-]?\d+)?", lambda m: f"{float(m.group()):.6g}", text)


def _assert_sentence(text: str) -> str:
    """pytest's ``assert <got> == <expected>`` introspection -> ``got …, expected …``, after the test's own message
    (which alone is enough when it already says what was expected)."""
    lines = text.strip().splitlines()
    first = next((i for i, line in enumerate(lines) if line.startswith("assert ")), None)
    own = _one_line("\n".join(lines[:first] if first is not None else lines))
    if own and ("expected" in own or first is None):
        return own
    if first is None:
        return "the check failed"
    match = _ASSERT.match(_readable(lines[first]))
    if match and match.group(2) == "==":
        got, expected = match.group(1), match.group(3)
        parsed = f"got {got[:_VALUE_LIMIT]}, expected {expected[:_VALUE_LIMIT]}"
    else:
        parsed = f"expected {_readable(lines[first]).removeprefix('assert ')[: 2 * _VALUE_LIMIT]} to hold"
    return f"{own}: {parsed}" if own else parsed


_UNUSED_BINDINGS = re.compile(r"number of bindings in bind group|\d+ buffer\(s\) given: \d+ binding", re.I)
#: The grader's own exceptions whose message is already a sentence (pytest's Failed, the budget, the sandbox's).
_SENTENCES = ("Failed", "XFailed", "ExerciseTimeout", "StudentError")


def _first_line(error: BaseException) -> str:
    text = str(error).strip()
    name = type(error).__name__
    if name in _SENTENCES and type(error).__module__ not in ("builtins",):  # already a sentence for the student
        return _one_line(text)
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    first = lines[0] if lines else ""
    # A driver's error ("Validation Error / Caused by: / In ... / <what>") says what went wrong in its last line.
    body = f"{first} {lines[-1]}" if len(lines) > 1 and "Caused by" in text else first
    return f"{name}: {body}" if body else name


def _raises_sentence(error: BaseException, expected_raise: str) -> str | None:
    """``pytest.raises``/``pytest.warns`` failed: the student's call returned instead of raising (or warning), or raised
    with a message that does not say what the test looks for. None for any other failure."""
    text = str(error)
    call = last_call()
    first = text.strip().splitlines()[0] if text.strip() else ""
    missing = re.match(r"DID NOT (RAISE|WARN)\.? ?(.*?)(?: were emitted\..*)?$", first)
    regex = re.search(r"Regex pattern did not match\.\s*(?:Expected )?[Rr]egex: (.+?)\s*(?:Actual|Input|Emitted)"
                      r" (?:message|warnings)?:? (.+)", text, re.S)
    if missing:
        what = expected_raise or missing.group(2).removeprefix("No warnings of type ").strip()
        body = f"expected it to {missing.group(1).lower()} {what}"
        if call is not None:
            body = f"{_shorter(call[0], 110)} {_verb(_clip(call[1], 70))}; {body}"
        return body
    if regex:
        got = _clip(_one_line(regex.group(2)), 110)
        body = f"expected an error message matching {regex.group(1).strip()}, got {got}"
        return f"{_shorter(call[0], 100)}: {body}" if call is not None else body
    return None


def sentence(error: BaseException, *, exercise: str = "", file: str = "", hint: str = "", values: str = "",
             expected_raise: str = "") -> str:
    """One line for the student: what failed, with input, expected and got where the test gives them (``values``:
    :func:`values_sentence`'s words for a bare assert; ``expected_raise``: the error a ``pytest.raises`` block around
    the failing line waits for, :func:`raises_expected`)."""
    stub = stub_sentence(error)
    if stub is not None:
        return cap(stub)
    raised = _raises_sentence(error, expected_raise)
    if raised is not None:
        body = raised
    elif isinstance(error, AssertionError):
        text = str(error)
        numpy = _numpy_sentence(text)
        body = numpy or _assert_sentence(text)
        own = _one_line(text.split("\nassert ")[0]) if not text.startswith("assert ") else ""
        if numpy:  # numpy's report: only the test's own err_msg is the test's words
            own = numpy.split(": got ", 1)[0] if not numpy.startswith("got ") else ""
        if values.startswith("expected `") and not re.search(r"expected (np\.)?False_? to hold", body):
            values = ""  # pytest's own words show the values; the source adds nothing
        if values and "expected" not in own:
            body = f"{own}: {values}" if own else values
        elif own and " to hold" in body and "expected" in own:
            body = own
        call = last_call()
        if call is not None and call[1] == "None" and not teaching_gaps(body):
            call = None  # a system's hook that returns nothing: the test's own words already say it all
        if call is not None and call[0].split("(")[0] not in body:
            label, result = call
            lead = len(exercise) + len(file) + 5  # the exercise and its file, when the sentence must be led by them
            room = max(LIMIT - len(body) - lead - 20, 50)
            label = _shorter(label, max(room * 2 // 3, 40))
            result = _clip(result, max(room - len(label), 20))
            joint = ":" if re.match(r"(at |got )", body) else ";"
            body = f"{label} {_verb(result)}{joint} {body}"
    else:
        body = _first_line(error)
        call = last_call()
        if call is not None and _raised and _raised[0] is error:  # the student's own call raised it
            want = f"it to raise {expected_raise}" if expected_raise else "a result, not an error"
            body = f"{_shorter(call[0], 110)} {_clip(call[1], 110)}; expected {want}"
        elif call is not None and call[0].split("(")[0] not in body and type(error).__name__ != "ExerciseTimeout":
            label = _shorter(call[0], 80)  # the student's answer, then what the engine made of it
            body = f"{label} {_verb(_clip(call[1], 60))}; expected an answer the engine accepts, but then {body}"
        elif expected_raise and type(error).__name__ != "ExerciseTimeout":
            body = f"{body}; expected {expected_raise}"
    body = re.sub(r"\b(?:[a-z_]+\.)+([A-Z]\w*(?:Error|Timeout|Exception|Warning))\b", r"\1", body)
    if file.endswith((".glsl", ".wgsl")) and _UNUSED_BINDINGS.search(body):
        # The shader compiler drops the inputs a function does not read yet: the engine's bindings no longer match.
        body = (f"{exercise} in {file} is probably still a stub: its shader leaves inputs unused, so the engine's "
                f"bindings do not match ({_clip(body, 110)})")
    body = body.removeprefix("Failed: ")
    body = body.replace(f"{_ROOT}/", "")  # paths as the student sees them, from the checkout
    body = _plain_numbers(body)
    named = [n for n in (exercise, Path(file).name if file else "") if n]
    if named and not any(re.search(rf"(?<![\w/]){re.escape(n)}\b", body) for n in named):
        body = f"{exercise}{f' ({file})' if file else ''}: {body}"
    if hint and hint not in body:
        body = f"{body} Hint: {hint}"
    return cap(body)


_GOT = re.compile(r"\b(got|returned|gave|raised)\b| = ")
_INPUT = re.compile(r"\b[A-Za-z_][\w.]*\((?!\d+ of )"  # a call with its input: hsv_to_rgb(30, 0.7, 0.9), f()
                    r"|\b(for|with|after|input|radius|case)\b [\w(\[-]"  # or the case in words: "for a sphere …"
                    r"|\b\w+=[\w(\[-]")  # or its values: "uv=[0.2, 0.4], view=[…]"


def _plain_numbers(text: str) -> str:
    """numpy's scalar reprs as plain numbers: ``np.float64(1.5)`` -> ``1.5``."""
    return re.sub(r"\bnp\.(?:float|int|uint|bool_)\d*\(([^()]*)\)", r"\1", text)


def teaching_gaps(message: str) -> list[str]:
    """What a wrong answer's sentence fails to say, of ``input``, ``expected`` and ``got`` (empty: it says all
    three). A stub's sentence is judged elsewhere: it has no answer to show."""
    message = _plain_numbers(message)  # np.float32(1.0) is a number, not a call with its input
    gaps = []
    if not _INPUT.search(message):
        gaps.append("input")
    if "expected" not in message:
        gaps.append("expected")
    if not _GOT.search(message):
        gaps.append("got")
    return gaps


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


# ---------------------------------------------------------------------------------------------------
# A bare ``assert np.allclose(got, expected)`` or ``assert got == expected``: its values, found again
# ---------------------------------------------------------------------------------------------------

_COMPARISONS = ("allclose", "array_equal", "isclose", "assert_array_almost_equal", "assert_allclose",
                "assert_array_equal")


def _difference(got: Any, expected: Any, atol: float, rtol: float) -> str | None:
    """Where two arrays differ: the first differing element (or row), with the count and the tolerance."""
    import numpy as np

    try:
        a, b = np.asarray(got), np.asarray(expected)
        if a.dtype == object or b.dtype == object:
            return None
        a, b = np.broadcast_arrays(a, b)
    except ValueError:
        return f"got shape {np.shape(got)}, expected shape {np.shape(expected)}"
    if a.dtype.kind in "fc" or b.dtype.kind in "fc":
        bad = ~np.isclose(a.astype(np.float64), b.astype(np.float64), atol=atol, rtol=rtol, equal_nan=False)
    else:
        bad = a != b
    if not bad.any():
        return None
    where = tuple(int(i) for i in np.argwhere(bad)[0])
    if a.ndim >= 2:  # show the whole row of the last axis: a colour, a vertex, a matrix row
        row = where[:-1]
        place, mine, theirs = f"at row {list(row) if len(row) > 1 else row[0]}", a[row], b[row]
    elif a.ndim == 1 and a.size <= 4:  # a colour, a point: the whole of it
        place, mine, theirs = "", tuple(a.tolist()), tuple(b.tolist())
    else:
        place, mine, theirs = (f"at index {where[0]}" if a.ndim else ""), a[where], b[where]
    tolerance = f"; tolerance {atol:g}" + (f" + {rtol:g}·|expected|" if rtol else "") if a.dtype.kind in "fc" else ""
    lead = f"{place}: " if place else ""
    return (f"{lead}got {short(mine, 70)}, expected {short(theirs, 70)} ({int(bad.sum())} of {bad.size} values "
            f"differ{tolerance})")


def _keyword(call: Any, name: str, default: float, scope: tuple[dict, dict]) -> float:
    import ast

    for keyword in call.keywords:
        if keyword.arg == name:
            try:
                return float(eval(compile(ast.Expression(keyword.value), "<assert>", "eval"), *scope))  # noqa: S307
            except Exception:  # noqa: BLE001
                return default
    return default


_ORDER: dict[type, tuple[str, str]] = {}  # an ordering comparison -> (its sign, the sign seen from the other side)


def _orders() -> None:
    import ast

    _ORDER.update({ast.Lt: ("<", ">"), ast.LtE: ("≤", "≥"), ast.Gt: (">", "<"), ast.GtE: ("≥", "≤"),
                   ast.NotEq: ("≠", "≠"), ast.IsNot: ("not", "not")})


def _is_bound(node: Any) -> bool:
    """Whether an expression is a bound the test states (numbers, constants in capitals, a tolerance), not a value
    measured from the student's answer."""
    import ast

    names = [n.id for n in ast.walk(node) if isinstance(n, ast.Name)]
    words = ("tol", "bound", "limit", "allowed", "expected", "want", "need", "minimum", "maximum")
    return all(n.isupper() or any(w in n.lower() for w in words) for n in names) and not any(
        isinstance(n, (ast.Call, ast.Subscript)) and "impl" in ast.unparse(n) for n in ast.walk(node))


def _order_sentence(node: Any, left: Any, right: Any) -> str | None:
    """``assert worst <= 1`` failed -> ``got worst = 3, expected ≤ 1``; with no side a stated bound,
    ``expected a < b, got 3 < 1``."""
    import ast

    try:
        if bool(_compare(node.ops[0], left, right)):
            return None
    except Exception:  # noqa: BLE001 - arrays: numpy's truth value; say it the plain way
        pass
    sign, flipped = _ORDER[type(node.ops[0])]
    if isinstance(node.ops[0], ast.IsNot):
        return f"got {_clip(ast.unparse(node.left), 50)} = {short(left)}, expected not {short(right)}"
    if _is_bound(node.comparators[0]) and not _is_bound(node.left):
        return f"got {_clip(ast.unparse(node.left), 50)} = {short(left)}, expected {sign} {short(right)}"
    if _is_bound(node.left) and not _is_bound(node.comparators[0]):
        return f"got {_clip(ast.unparse(node.comparators[0]), 50)} = {short(right)}, expected {flipped} {short(left)}"
    return f"expected {_clip(ast.unparse(node), 80)}, got {short(left)} {sign} {short(right)}"


def _compare(op: Any, left: Any, right: Any) -> Any:
    import operator

    return {"Lt": operator.lt, "LtE": operator.le, "Gt": operator.gt, "GtE": operator.ge, "NotEq": operator.ne,
            "IsNot": operator.is_not}[type(op).__name__](left, right)


def values_sentence(statement: str, global_names: dict[str, Any], local_names: dict[str, Any]) -> str | None:
    """For a failed ``assert`` without a message: evaluate the arguments of its comparison again (never an
    expression that calls the student's code, ``impl``) and say where got and expected differ."""
    import ast

    try:
        tree = ast.parse(statement.strip())
    except SyntaxError:
        return None
    if not tree.body:
        return None
    checked = tree.body[0]
    if isinstance(checked, ast.Expr) and isinstance(checked.value, ast.Call):  # np.testing.assert_allclose(...)
        checked = ast.Assert(test=checked.value)
    if not isinstance(checked, ast.Assert):
        return None
    scope = (global_names, dict(local_names))
    if not _ORDER:
        _orders()

    class _Recorded(ast.NodeTransformer):
        """``impl.f(...)`` -> the value the newest call of ``f`` returned (never a second call)."""

        def visit_Call(self, node: Any) -> Any:
            func = node.func
            if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name) and func.value.id == "impl":
                if not _last_result or _last_result[0] != func.attr:
                    raise LookupError("calls the student's code")
                return ast.copy_location(ast.Name("__gandalf_result__", ast.Load()), node)
            return self.generic_visit(node)

    def value(node: Any) -> Any:
        node = _Recorded().visit(ast.fix_missing_locations(node))
        if "impl" in ast.unparse(node):
            raise LookupError("calls the student's code")
        names = {**scope[1], "__gandalf_result__": _last_result[1] if _last_result else None}
        found = eval(compile(ast.Expression(node), "<assert>", "eval"), scope[0], names)  # noqa: S307 - the test's
        return found

    for node in ast.walk(checked.test):
        try:
            if isinstance(node, ast.Call) and len(node.args) >= 2 and getattr(
                    node.func, "attr", getattr(node.func, "id", "")) in _COMPARISONS:
                name = getattr(node.func, "attr", getattr(node.func, "id", ""))
                exact = name in ("array_equal", "assert_array_equal")
                atol = 0.0 if exact else _keyword(node, "atol", 0.0 if name == "assert_allclose" else 1e-8, scope)
                rtol = 0.0 if exact else _keyword(node, "rtol", 1e-7 if name == "assert_allclose" else 1e-5, scope)
                if name == "assert_array_almost_equal":
                    atol, rtol = 1.5 * 10.0 ** -_keyword(node, "decimal", 6, scope), 0.0
                text = _difference(value(node.args[0]), value(node.args[1]), atol, rtol)
            elif isinstance(node, ast.Compare) and len(node.ops) == 1 and type(node.ops[0]) in _ORDER:
                text = _order_sentence(node, value(node.left), value(node.comparators[0]))
            elif isinstance(node, ast.Compare) and len(node.ops) == 1 and isinstance(node.ops[0], ast.Eq):
                left, right = value(node.left), value(node.comparators[0])
                if hasattr(right, "expected") and hasattr(right, "abs"):  # pytest.approx(expected, abs=..., rel=...)
                    atol, rtol = float(right.abs or 1e-12), float(right.rel if right.rel is not None else 1e-6)
                    text = _difference(left, right.expected, atol, rtol)
                elif hasattr(left, "shape") or hasattr(right, "shape"):
                    text = _difference(left, right, 0.0, 0.0)
                else:
                    text = f"got {short(left)}, expected {short(right)}" if left != right else None
            else:
                continue
        except Exception:  # noqa: BLE001 - a value that cannot be found again: the other shapes still apply
            continue
        if text:
            return text
    source = " ".join(ast.unparse(checked.test).split())
    return f"expected `{_clip(source, 120)}` to hold" if isinstance(checked.test, (ast.Call, ast.Compare)) else None


def raises_expected(source: str, line: int, global_names: dict[str, Any], local_names: dict[str, Any]) -> str:
    """The error a ``with pytest.raises(E, match=...)`` block around ``line`` of ``source`` (a test function's text,
    line 1 its first) waits for, in words (``ValueError with a message matching 'fovy'``), or ``""``."""
    import ast
    import textwrap

    try:
        tree = ast.parse(textwrap.dedent(source))
    except SyntaxError:
        return ""
    for node in ast.walk(tree):
        if not isinstance(node, (ast.With, ast.AsyncWith)) or not node.body:
            continue
        if not node.lineno <= line <= (node.body[-1].end_lineno or node.body[-1].lineno):  # the with line: its exit
            continue
        for item in node.items:
            call = item.context_expr
            name = getattr(call.func, "attr", getattr(call.func, "id", "")) if isinstance(call, ast.Call) else ""
            if name not in ("raises", "warns") or not call.args:
                continue
            try:
                expected = eval(compile(ast.Expression(call.args[0]), "<raises>", "eval"),  # noqa: S307 - the test's
                                global_names, dict(local_names))
                names = [e.__name__ for e in (expected if isinstance(expected, tuple) else (expected,))]
                words = " or ".join(names)
                match = next((k.value for k in call.keywords if k.arg == "match"), None)
                if match is not None:
                    pattern = eval(compile(ast.Expression(match), "<raises>", "eval"),  # noqa: S307
                                   global_names, dict(local_names))
                    words += f" with a message matching {pattern!r}"
                return words
            except Exception:  # noqa: BLE001 - an argument that cannot be found again: the block's source
                return _clip(ast.unparse(call.args[0]), 60)
    return ""
