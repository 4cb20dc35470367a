"""A time budget per call of a student's function: a runaway exercise fails fast, in words, instead of holding
every test up to the run's per-test timeout.

When the grader grades a student's package (``--student``, a submission, a mutant), :func:`guard` wraps each of
its functions and each method its classes define: a call that has not returned after ``budget`` seconds is
interrupted (an :class:`ExerciseTimeout` raised in the calling thread, at the next Python instruction), and that
function is remembered as hung, so every later call of it fails at once with the same sentence::

    hsv_to_rgb(0.5, 1.0, 1.0) did not return within 5 s (a loop that never ends?)

so a step whose exercise loops for ever is graded in about one budget per hung function (per worker), whichever
command ran it. A hang inside native code (a C loop, a driver) cannot be interrupted this way; the per-test
timeout and the front end's hard timeout still end those.
"""

from __future__ import annotations

import ctypes
import functools
import inspect
import sys
import threading
import time
from collections.abc import Callable
from types import ModuleType
from typing import Any

from . import feedback

#: Seconds a student's function may run in one call (``--grade-call-budget``): far above what any exercise's
#: reference needs (the slowest takes well under 0.5 s a call on a 2-core machine).
DEFAULT_BUDGET = 5.0
_ARGS_LIMIT = 120
_GUARDED = "__gandalf_guarded__"


class ExerciseTimeout(BaseException):
    """A student's function ran past its time budget (or had done so before). Not an ``Exception``: a loop that
    catches every ``Exception`` cannot swallow it (and it is raised again every half second until the call
    ends, for a loop that catches even this)."""


#: The functions that ran past their budget (by module and qualified name: another step's function of the same name
#: is another function) -> the sentence every later call fails with.
_hung: dict[str, str] = {}
_depth = threading.local()


def reset() -> None:
    """Forget which functions hung (a new grading session)."""
    _hung.clear()


def _describe(name: str, args: tuple[Any, ...], kwargs: dict[str, Any]) -> str:
    parts = [_shown(a) for a in args if not _is_self_like(a)] + [f"{k}={_shown(v)}" for k, v in kwargs.items()]
    text = ", ".join(parts)
    return f"{name}({text if len(text) <= _ARGS_LIMIT else text[: _ARGS_LIMIT - 1] + '…'})"


describe_call = _describe  # the same words for a call of sandboxed code


def _shown(value: Any) -> str:
    """An argument as the student wrote it; a numpy array short and rounded (``[[0.3892, -0.3211, …], …]``)."""
    return feedback.short(value, 60) if type(value).__module__ == "numpy" else repr(value)


def _is_self_like(value: Any) -> bool:
    # A method's ``self`` and the engine objects handed to systems say nothing to a student.
    return not isinstance(value, (int, float, complex, str, bytes, tuple, list, dict, bool, type(None))) and (
        type(value).__module__.split(".")[0] not in ("numpy", "builtins"))


def _interrupt(thread_id: int) -> None:
    ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(thread_id), ctypes.py_object(ExerciseTimeout))


class _Watcher:
    """One thread for the whole process (a thread per call would cost more than most calls): interrupts each
    armed thread when its deadline passes, and again every half second until it is disarmed."""

    def __init__(self) -> None:
        self._lock = threading.Condition()
        self._armed: dict[int, float] = {}  # thread id -> deadline (time.monotonic)
        self._wake = float("inf")  # when the watcher wakes next (it is woken sooner only for a sooner deadline)
        self._thread: threading.Thread | None = None

    def arm(self, budget: float) -> None:
        deadline = time.monotonic() + budget
        with self._lock:
            self._armed[threading.get_ident()] = deadline
            if self._thread is None:
                self._thread = threading.Thread(target=self._run, name="gandalf-watchdog", daemon=True)
                self._thread.start()
            if deadline < self._wake:
                self._lock.notify()

    def disarm(self) -> None:
        with self._lock:  # the watcher interrupts only under this lock: none lands after this returns
            self._armed.pop(threading.get_ident(), None)

    def _run(self) -> None:
        with self._lock:
            while True:
                now = time.monotonic()
                for thread, deadline in list(self._armed.items()):
                    if deadline <= now:
                        _interrupt(thread)
                        self._armed[thread] = now + 0.5
                self._wake = min(self._armed.values(), default=float("inf"))
                self._lock.wait(None if self._wake == float("inf") else self._wake - now)


_watcher = _Watcher()


def _wrap(fn: Callable[..., Any], name: str, budget: float) -> Callable[..., Any]:
    key = f"{fn.__module__}.{fn.__qualname__}"

    @functools.wraps(fn)
    def guarded(*args: Any, **kwargs: Any) -> Any:
        if key in _hung:
            raise ExerciseTimeout(_hung[key])
        depth = getattr(_depth, "value", 0)
        if depth:  # only the outermost student call runs the clock
            return fn(*args, **kwargs)
        label = _describe(name, args, kwargs)
        message = f"{label} did not return within {budget:g} s (a loop that never ends?)"
        _depth.value = 1
        _watcher.arm(budget)
        try:
            try:
                result = fn(*args, **kwargs)
            finally:
                _watcher.disarm()  # first: no interrupt may land after the call has ended
        except ExerciseTimeout:
            _hung[key] = message
            raise ExerciseTimeout(message) from None
        except Exception as error:
            feedback.record_raise(label, error)  # for a failed check's sentence: what was called, what it raised
            raise
        finally:
            _depth.value = 0
        feedback.record_call(label, result)  # for a failed check's sentence: what was called, what came back
        return result

    setattr(guarded, _GUARDED, True)
    return guarded


def guard(package: ModuleType, budget: float = DEFAULT_BUDGET) -> ModuleType:
    """Put a time budget on every function and method defined in ``package`` and its modules (in place, once);
    returns ``package``. ``budget <= 0`` leaves it as it is."""
    if budget <= 0 or getattr(package, _GUARDED, None) == budget:
        return package
    for module in _modules_of(package):
        for attr, value in list(vars(module).items()):
            if not _inside(str(getattr(value, "__module__", None)), package.__name__):
                continue
            if inspect.isfunction(value) and not getattr(value, _GUARDED, False):
                setattr(module, attr, _wrap(value, value.__name__, budget))
            elif inspect.isclass(value):
                for cls in value.__mro__:  # a subclass of the package's own class: its inherited methods too
                    if _inside(cls.__module__, package.__name__):
                        _guard_class(cls, budget)
    setattr(package, _GUARDED, budget)
    return package


def _guard_class(cls: type, budget: float) -> None:
    for attr, value in list(vars(cls).items()):
        if attr.startswith("__") or not inspect.isfunction(value) or getattr(value, _GUARDED, False):
            continue
        setattr(cls, attr, _wrap(value, f"{cls.__name__}.{attr}", budget))


def _inside(module: str, package: str) -> bool:
    """Whether ``module`` is ``package`` or one of its modules."""
    return module == package or module.startswith(package + ".")


def _modules_of(package: ModuleType) -> list[ModuleType]:
    """The package and its imported modules."""
    return [m for name, m in list(sys.modules.items()) if isinstance(m, ModuleType) and _inside(name, package.__name__)]
