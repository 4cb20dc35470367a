"""Drawing helpers shared by the course's diagrams (scripts/make_diagrams.py): colours, boxes, arrows, SVG output.

Every diagram is an SVG file whose text stays text (``svg.fonttype: none``): small, sharp at any zoom, searchable.
The files are reproducible: no date in their metadata and fixed element ids, so redrawing an unchanged diagram
changes no byte.
"""

from __future__ import annotations

from pathlib import Path

# Colours shared by every diagram: programmable stages, fixed-function stages, missing stages, data.
PROGRAMMABLE = "#c9daf8"
FIXED = "#e6e6e6"
MISSING = "#ffffff"
DATA = "#fce5cd"
SYSTEM = "#d9ead3"
EDGE = "#333333"
#: Text in the box diagrams is drawn this much larger than its nominal size: the site shows them at about half
#: their pixel width, so nominal 8 pt would read as 4.
TEXT_SCALE = 1.3


def box(ax, x: float, y: float, w: float, h: float, text: str, color: str, *, dashed: bool = False,
         size: float = 9.0, weight: str = "normal", text_color: str = "black") -> None:
    from matplotlib.patches import FancyBboxPatch

    ax.add_patch(FancyBboxPatch((x, y), w, h, boxstyle="round,pad=0.02,rounding_size=0.08", facecolor=color,
                                edgecolor="#999999" if dashed else EDGE, linestyle="--" if dashed else "-",
                                linewidth=1.0))
    ax.text(x + w / 2, y + h / 2, text, ha="center", va="center", fontsize=size * TEXT_SCALE, weight=weight,
            color=text_color,
            wrap=True)


def arrow(ax, x0: float, y0: float, x1: float, y1: float, *, color: str = EDGE, style: str = "-|>",
           dashed: bool = False, text: str = "", text_offset: tuple[float, float] = (0.0, 0.12)) -> None:
    ax.annotate("", xy=(x1, y1), xytext=(x0, y0),
                arrowprops={"arrowstyle": style, "color": color, "lw": 1.2, "linestyle": "--" if dashed else "-",
                            "shrinkA": 0, "shrinkB": 0})
    if text:
        ax.text((x0 + x1) / 2 + text_offset[0], (y0 + y1) / 2 + text_offset[1], text, ha="center", va="bottom",
                fontsize=8, color=color)


def canvas(width: float, height: float, xlim: float, ylim: float):
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(width, height))
    ax.set_xlim(0, xlim)
    ax.set_ylim(0, ylim)
    ax.set_aspect("equal")
    ax.axis("off")
    return fig, ax


def save(fig, path: Path) -> None:
    import matplotlib
    import matplotlib.pyplot as plt

    matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text: small files, sharp and searchable
    matplotlib.rcParams["svg.hashsalt"] = "gandalf"  # fixed ids: an unchanged diagram redraws byte for byte
    fig.savefig(path, format="svg", dpi=110, facecolor="white", bbox_inches="tight", pad_inches=0.1,
                metadata={"Date": None})
    plt.close(fig)
