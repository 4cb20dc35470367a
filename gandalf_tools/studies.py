"""What every error-against-run-time study shares: its run's metadata, matplotlib without a display, and its outputs.

A study script measures its own cases (timing its frames with :func:`frame_runs_ms` / :func:`frame_ms`); this
module writes what it found the same way for all of them:
``DIR/<stem>.json`` (the result), ``DIR/<stem>.md`` (its table, included by the step's page) and ``DIR/<stem>.png``
(its plot), then prints the table.
"""

from __future__ import annotations

import json
import platform
import statistics
import time
from collections.abc import Callable
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


def pyplot() -> Any:
    """``matplotlib.pyplot`` on the Agg backend (studies run headless; matplotlib is imported only when plotting)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def write_study(out: Path, stem: str, result: dict[str, Any], table: str,
                plot: Callable[[dict[str, Any], Path], None]) -> None:
    """Write ``out/<stem>.json``, ``.md`` (``table``) and ``.png`` (drawn by ``plot``), and print the table."""
    out.mkdir(parents=True, exist_ok=True)
    (out / f"{stem}.json").write_text(json.dumps(result, indent=1))
    (out / f"{stem}.md").write_text(table)
    plot(result, out / f"{stem}.png")
    print(table)
    print(f"wrote {out / stem}.json, .md, .png", flush=True)
