"""No command a student or an instructor runs from the README or the site leaves them looking at a silent terminal
for more than 5 s: each is run here in a pseudo-terminal (as a person runs it) and the time between one piece of its
output and the next is measured, from its start to its exit.

The commands are the short forms of those on the pages: a launcher's ``--help``, a step run headless for a few
frames, the doctor, the grader's front end on one step, the tour of one step, the mutation check on one mutant and
the student release. (The first set-up, ``./run.sh``, takes about 1.5 minutes: too long for a test; it prints each
of its steps.)

The 5 s are a person's patience on an idle 2-core machine. A loaded machine (this suite's other worker, other
jobs) stretches every silence by the share of a core the command gets, so the bound is 5 s times the slowdown a
fixed CPU-bound calibration shows just before and just after the command: its wall time over its CPU time (about
1 on an idle machine).
"""

from __future__ import annotations

import os
import pty
import select
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PATIENCE = 5.0  # seconds of silence a person waits without wondering whether the command hangs
CALIBRATION = ("import time\nt = time.process_time()\nwhile time.process_time() - t < 0.3: pass\n"
               "print(time.process_time() - t)")


@dataclass
class Run:
    """A command's output as it came: the longest silence, what was printed last before it, the whole run."""

    longest: float = 0.0
    after: str = "(its start)"
    seconds: float = 0.0
    code: int | None = None
    lines: list[str] = field(default_factory=list)


def run_in_terminal(command: list[str], timeout: float = 240.0, cwd: Path = ROOT) -> Run:
    """Run ``command`` with a pseudo-terminal as its stdout and stderr; time the gaps between pieces of output."""
    main, child = pty.openpty()
    env = {**os.environ, "COLUMNS": "120"}
    env.pop("PYTEST_XDIST_WORKER", None)
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=child, stderr=child, stdin=subprocess.DEVNULL, cwd=cwd, env=env)
    os.close(child)
    run, last, pending = Run(), start, b""
    try:
        while time.monotonic() - start < timeout:
            ready, _, _ = select.select([main], [], [], 0.1)
            if not ready:
                continue
            try:
                data = os.read(main, 65536)
            except OSError:  # the command closed its end: it has exited
                break
            if not data:
                break
            now = time.monotonic()
            if now - last > run.longest:
                shown = _last_state(pending) or (run.lines or [""])[-1]
                run.longest, run.after = now - last, shown or "(its start)"
            last = now
            *complete, pending = (pending + data).split(b"\n")
            # A line rewritten in place (a progress count after "\r") counts as its last state.
            run.lines += [_last_state(line) for line in complete if line.strip()]
    finally:
        os.close(main)
        if process.poll() is None and time.monotonic() - start >= timeout:
            process.kill()
        run.code = process.wait()
    end = time.monotonic()
    run.seconds = end - start
    if end - last > run.longest:
        run.longest, run.after = end - last, f"{run.lines[-1] if run.lines else ''} (until it exited)"
    return run


def _last_state(line: bytes) -> str:
    """A terminal line as it ends up: the text after its last carriage return (the terminal's own ``\\r\\n`` aside)."""
    return line.decode(errors="replace").rstrip("\r").split("\r")[-1].strip()


def slowdown() -> float:
    """How much this machine stretches a CPU-bound piece of work now: wall time over CPU time of a 0.3 s loop."""
    start = time.monotonic()
    cpu = float(subprocess.run([sys.executable, "-S", "-c", CALIBRATION], capture_output=True, text=True,
                               check=True).stdout)
    return max(1.0, (time.monotonic() - start - 0.02) / cpu)  # 20 ms: an interpreter's start without site


def _python(*args: str) -> list[str]:
    return [sys.executable, *args]


COMMANDS = {
    "launcher help": _python("-m", "step04_camera.opengl", "--help"),
    "a step headless": _python("-m", "step01_window.webgpu", "--headless", "--frames", "3"),
    "the doctor": _python("-m", "gandalf_tools.doctor"),
    "grading one step": _python("-m", "gandalf_tools.grading", "tests/step01_window"),
    "the tour of one step": _python("-m", "gandalf_tools.tour", "--headless", "--steps", "step01_window", "--out",
                                    "{tmp}/tour"),
    "one mutant": _python("-m", "gandalf_tools.grading.mutants", "-k", "hsv_to_rgb:radians", "--no-control"),
    "the student release": _python("-m", "gandalf_tools.release", "{tmp}/release"),
}


@pytest.mark.parametrize("name", list(COMMANDS))
def test_the_command_is_never_silent_for_long(name, tmp_path):
    command = [part.replace("{tmp}", str(tmp_path)) for part in COMMANDS[name]]
    before = slowdown()
    run = run_in_terminal(command)
    factor = max(before, slowdown())
    shown = " ".join(command[1:])
    assert run.code == 0, f"{shown} exited with {run.code}:\n" + "\n".join(run.lines[-20:])
    assert run.longest <= PATIENCE * factor, (
        f"{shown} was silent for {run.longest:.1f} s after {run.after!r} (allowed {PATIENCE:g} s × this machine's "
        f"slowdown {factor:.2f}); it ran {run.seconds:.1f} s")


def test_the_measure_sees_a_silence():
    """The measure itself: a command that sleeps between two lines is caught, one that talks is not."""
    quiet = run_in_terminal(_python("-c", "import time; print('a', flush=True); time.sleep(1.5); print('b')"))
    assert 1.4 < quiet.longest < 5.0 and quiet.after == "a" and quiet.lines == ["a", "b"]
    talking = run_in_terminal(_python("-c", "import time\nfor i in range(6):\n    print(i, flush=True)\n"
                                            "    time.sleep(0.25)"))
    assert talking.longest < 1.2 and talking.lines == [str(i) for i in range(6)]
