"""What every error-against-run-time study shares: its command line, its run's metadata, its table and its outputs.

A study script measures its own cases (timing its frames with :func:`frame_runs_ms` / :func:`frame_ms`); this
module reads its options the same way for all of them (:class:`StudyParser`: ``--out``, ``--quick`` and the
``--backends``/``--size``/``--frames``/``--repeats`` a study takes), lays out its table (:func:`markdown_table`,
rows grouped with :func:`groups`) and writes what it found (the plot drawn with :mod:`gandalf_tools.plots`):
``DIR/<stem>.json`` (the result), ``DIR/<stem>.md`` (its table, included by the step's page) and ``DIR/<stem>.png``
(its plot), then prints the table.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import time
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any


def run_info() -> dict[str, str]:
    """Where and when a study ran, for its JSON."""
    return {"host": platform.platform(), "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())}


def frame_runs_ms(app: Any, frames: int, repeats: int) -> list[float]:
    """Mean milliseconds per frame of each of ``repeats`` runs of ``frames`` frames of ``app``, every frame waited
    for with a 1-pixel read-back (so the GPU's work is in the time)."""
    runs = []
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(frames):
            app.step()
            app.renderer.read_pixel(0, 0)
        runs.append(1000.0 * (time.perf_counter() - start) / frames)
    return runs


def frame_ms(app: Any, frames: int, repeats: int) -> float:
    """The median of :func:`frame_runs_ms`: a study's frame time."""
    return statistics.median(frame_runs_ms(app, frames, repeats))


Size = tuple[int, int]
#: The APIs a study can measure.
BACKENDS = ("opengl", "webgpu")


class StudyParser(argparse.ArgumentParser):
    """A study's command line: ``--out FOLDER`` and ``--quick``, plus those of ``--backends``, ``--size W H``,
    ``--frames`` and ``--repeats`` that the study takes.

    ``size``, ``frames`` and ``repeats`` are (full, quick) pairs: the default of the option without and with
    ``--quick``. :meth:`parse_args` fills them in, makes ``size`` a tuple of ints and rejects a number below 1.
    """

    def __init__(self, module: str, doc: str, *, outputs: str, quick: str,
                 backends: tuple[str, ...] | None = BACKENDS, size: tuple[Size, Size] | None = None,
                 frames: tuple[int, int] | None = None, repeats: tuple[int, int] | None = None,
                 out_required: bool = False) -> None:
        super().__init__(prog=f"python -m {module}", description=doc,
                         formatter_class=argparse.RawDescriptionHelpFormatter)
        out_default = {"required": True} if out_required else {"default": Path("out")}
        self.add_argument("--out", type=Path, help=f"folder for {outputs}", **out_default)
        if backends:
            self.add_argument("--backends", nargs="+", choices=backends, default=list(backends))
        self.add_argument("--quick", action="store_true", help=quick)
        self._by_quick = {name: pair for name, pair in (("size", size), ("frames", frames), ("repeats", repeats))
                          if pair is not None}
        if size is not None:
            self.add_argument("--size", type=int, nargs=2, default=None, metavar=("W", "H"),
                              help=f"default {_pair(*size, ' ')}")
        if frames is not None:
            self.add_argument("--frames", type=int, default=None,
                              help=f"frames per timed run (default {_pair(*frames)})")
        if repeats is not None:
            self.add_argument("--repeats", type=int, default=None,
                              help=f"timed runs per case (default {_pair(*repeats)})")

    def parse_args(self, args=None, namespace=None):  # noqa: ANN001, ANN201 (argparse's signature)
        parsed = super().parse_args(args, namespace)
        for name, (full, quick) in self._by_quick.items():
            if getattr(parsed, name) is None:
                setattr(parsed, name, quick if parsed.quick else full)
        if "size" in self._by_quick:
            parsed.size = (int(parsed.size[0]), int(parsed.size[1]))
        numbers = [n for name in self._by_quick for n in (parsed.size if name == "size" else [getattr(parsed, name)])]
        if min(numbers, default=1) < 1:
            self.error(f"{', '.join('--' + name for name in self._by_quick)} must be at least 1")
        return parsed


def _pair(full: object, quick: object, join: str = "") -> str:
    """``"5, quick 2"``, or ``"5"`` where the quick default is the same; tuples joined with ``join``."""
    def text(value: object) -> str:
        return join.join(map(str, value)) if isinstance(value, tuple) else str(value)

    return text(full) if full == quick else f"{text(full)}, quick {text(quick)}"


def markdown_table(header: Sequence[str], rows: Iterable[Sequence[object]], left: int = 1) -> str:
    """A markdown table: the ``header`` cells, a rule that aligns the first ``left`` columns left and the others
    right, and a line of cells (formatted already, else written with ``str``) for each of ``rows``."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * left + "---:|" * (len(header) - left)]
    lines += ["| " + " | ".join(map(str, row)) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def groups(rows: Iterable[dict[str, Any]], key: str) -> list[tuple[Any, list[dict[str, Any]]]]:
    """``rows`` grouped by their ``key``: (value, its rows) in the order the values first appear."""
    rows = list(rows)
    return [(value, [r for r in rows if r[key] == value]) for value in dict.fromkeys(r[key] for r in rows)]


def write_study(out: Path, stem: str, result: dict[str, Any], table: str,
                plot: Callable[[dict[str, Any], Path], None]) -> None:
    """Write ``out/<stem>.json``, ``.md`` (``table``) and ``.png`` (drawn by ``plot``), and print the table."""
    out.mkdir(parents=True, exist_ok=True)
    (out / f"{stem}.json").write_text(json.dumps(result, indent=1))
    (out / f"{stem}.md").write_text(table)
    plot(result, out / f"{stem}.png")
    print(table)
    print(f"wrote {out / stem}.json, .md, .png", flush=True)
