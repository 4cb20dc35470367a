"""A study's plot without a display: matplotlib on the Agg backend (imported only when a plot is drawn), and the
frame every study's figure shares: its axes, their labels and grid, and the written file."""

from __future__ import annotations

from pathlib import Path
from typing import Any


def pyplot() -> Any:
    """``matplotlib.pyplot`` on the Agg backend (studies run headless; matplotlib is imported only when plotting)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def figure(*grid: int, **kwargs: Any) -> tuple[Any, Any]:
    """``pyplot().subplots(*grid, **kwargs)`` at 100 dpi unless ``dpi`` is given: a study's (figure, axes)."""
    kwargs.setdefault("dpi", 100)
    return pyplot().subplots(*grid, **kwargs)


def label_axes(ax: Any, xlabel: str, ylabel: str, title: str | None = None, *, legend: float | None = 8) -> None:
    """Name ``ax``'s axes (and title it, at 10 pt), draw its grid and, unless ``legend`` is None, its legend at that
    font size."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title is not None:
        ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    if legend is not None:
        ax.legend(fontsize=legend)


def save_figure(fig: Any, path: Path, **kwargs: Any) -> Path:
    """Lay ``fig`` out, write it to ``path`` (``kwargs`` go to ``savefig``), close it; returns ``path``."""
    fig.tight_layout()
    fig.savefig(path, **kwargs)
    pyplot().close(fig)
    return path
