"""The fairness check: every correct alternative solution of an exercise must pass all of its graded tests.

``python -m gandalf_tools.grading.fairness [--step STEP] [--exercise NAME] [-k TEXT] [--jobs N] [--json FILE]``

The mutation check (:mod:`gandalf_tools.grading.mutants`) proves the tests catch plausible bugs; this one proves
they accept correct work written differently from the reference: another valid formula, another order of the
same arithmetic, another convention the exercise leaves open (where a joint sits, where the camera stands). An
*alternative* is defined like a mutant, in ``tests/fairness/<step>.py`` (a list ``ALTERNATIVES``), with
:func:`alternative` (a Python replacement of one function, method or class of the copied solutions) or
:func:`shader_alternative` (textual edits of the copied shader files), and graded the same way: a copy of the
step's solutions with the change applied, in its own process, on its exercise's graded tests only.

An alternative that fails a graded test is *rejected*: the test grades something the exercise does not state
(fix the test, or state the rule in the stub and then fix the alternative). The run exits with 1 when one is
rejected or cannot be built, or when the unchanged solutions (the control, graded first) fail.
"""

from __future__ import annotations

import json
import sys
import time

from .mutants import (
    ROOT,
    Mutant,
    Outcome,
    command_parser,
    exercises_by_step,
    mutant,
    run_jobs,
    selected,
    shader_mutant,
)

DEFAULT_DIR = ROOT / "tests" / "fairness"

#: Register ``fn(package)`` as a correct alternative: ``@alternative(ALTERNATIVES, step, exercise, name, text)``.
alternative = mutant
#: Register a correct alternative made of shader edits ``(file, old, new)`` in the copied package.
shader_alternative = shader_mutant


def _verdict(outcome: Outcome) -> str:
    """A mutant's outcome read for an alternative: passing every graded test is what it must do."""
    if outcome.mutant.is_control:
        return outcome.status
    return {"survived": "accepted", "killed": "rejected"}.get(outcome.status, outcome.status)


def main(argv: list[str] | None = None) -> int:
    args = command_parser(
        "fairness", "Grade every correct alternative solution of the exercises; fail if one is rejected.",
        "alternatives", DEFAULT_DIR,
    ).parse_args(argv)
    chosen = selected(args, "ALTERNATIVES", "alternatives")
    if isinstance(chosen, int):
        return chosen
    by_step = exercises_by_step(chosen)
    steps = list(by_step)
    jobs: list[tuple[Mutant | None, str, list[str]]] = [] if args.no_control else [(None, s, by_step[s]) for s in steps]
    jobs += [(m, m.step, [m.exercise]) for m in chosen]
    print(f"fairness check: {len(chosen)} alternatives of {sum(map(len, by_step.values()))} exercises in "
          f"{len(steps)} steps, {args.jobs} at a time", flush=True)
    start = time.perf_counter()

    def progress(done: int, total: int, outcome: Outcome) -> None:
        mark = _verdict(outcome)
        mark = "ok" if mark in ("accepted", "passed") else mark.upper()
        print(f"[{done:>3}/{total}] {mark:<8} {outcome.mutant.ident:<58} {outcome.seconds:5.1f} s", flush=True)

    outcomes = run_jobs(jobs, args.jobs, args.timeout, progress)
    verdicts = [(o, _verdict(o)) for o in outcomes]
    controls = [(o, v) for o, v in verdicts if o.mutant.is_control]
    results = sorted(((o, v) for o, v in verdicts if not o.mutant.is_control), key=lambda ov: ov[0].mutant.ident)
    print(f"\n{'alternative':<58} {'status':<9} {'tests':>5}  first failure / note")
    for o, v in results + controls:
        ident = o.mutant.step + ":control" if o.mutant.is_control else o.mutant.ident
        print(f"{ident:<58} {v:<9} {o.tests:>5}  {(o.detail or '').replace(chr(10), ' ')[:90]}")
    accepted = sum(v == "accepted" for _, v in results)
    bad = [(o, v) for o, v in results if v != "accepted"] + [(o, v) for o, v in controls if v != "passed"]
    print(f"\n{accepted}/{len(results)} alternatives accepted, {len(bad)} rejected or in error "
          f"in {time.perf_counter() - start:.1f} s")
    for o, v in bad:
        print(f"{v.upper()} {o.mutant.ident}: {o.mutant.description} — {o.detail}")
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps([
            {"alternative": o.mutant.ident, "description": o.mutant.description,
             "kind": "shader" if o.mutant.edits else "python", "status": v, "tests": o.tests, "failed": o.failed,
             "seconds": round(o.seconds, 2), "detail": o.detail}
            for o, v in results + controls], indent=2))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
