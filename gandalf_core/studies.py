"""What every error-against-run-time study shares: its run's metadata, matplotlib without a display, and its outputs.

A study script measures its own cases; this module writes what it found the same way for all of them:
``DIR/<stem>.json`` (the result), ``DIR/<stem>.md`` (its table, included by the step's page) and ``DIR/<stem>.png``
(its plot), then prints the table.
"""

from __future__ import annotations

import json
import platform
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any


def run_info() -> dict[str, str]:
    """Where and when a study ran, for its JSON."""
    return {"host": platform.platform(), "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())}


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
