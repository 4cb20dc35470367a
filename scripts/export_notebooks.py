"""Export the intro notebooks as pages of the course site, with their outputs: ``python scripts/export_notebooks.py``.

Each ``notebooks/NN_name.ipynb`` is run from top to bottom in a fresh kernel (nbclient, ``GANDALF_BACKEND=opengl``,
headless) and written as ``docs/notebooks/NN_name.md``: its Markdown cells as they are, its code cells as Python
blocks, and what they showed — pictures as PNG files under ``docs/images/notebooks/``, text as text blocks. The
notebooks themselves are stored without outputs (small diffs); these pages are where a reader sees the pictures.

``tests/core/test_site.py`` checks that every page's code is still its notebook's code (re-run this script after
changing a notebook) and that the site shows every page with its pictures. Options: ``--only NAME`` (repeatable),
``--timeout S`` per cell. Needs the dev extra (nbclient, ipykernel).
"""

from __future__ import annotations

import argparse
import base64
import os
import re
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOKS = ROOT / "notebooks"
PAGES = ROOT / "docs" / "notebooks"
PICTURES = ROOT / "docs" / "images" / "notebooks"
_ANSI = re.compile(r"\x1b\[[0-9;]*m")


def _outputs(cell, stem: str, counter: list[int]) -> list[str]:  # noqa: ANN001
    parts = []
    for output in cell.get("outputs", []):
        kind = output.get("output_type")
        if kind == "stream":
            parts.append(f"```text\n{_ANSI.sub('', output['text']).rstrip()}\n```")
        elif kind in ("display_data", "execute_result"):
            data = output.get("data", {})
            if "image/png" in data:
                counter[0] += 1
                name = f"{stem}-{counter[0]}.png"
                (PICTURES / name).write_bytes(base64.b64decode(data["image/png"]))
                parts.append(f"![Output {counter[0]} of {stem}](../images/notebooks/{name})")
            elif "text/plain" in data:
                parts.append(f"```text\n{data['text/plain'].rstrip()}\n```")
        elif kind == "error":
            raise RuntimeError(f"{stem}: a cell failed: {output.get('ename')}: {output.get('evalue')}")
    return parts


def export(path: Path, timeout: int) -> Path:
    """Run one notebook and write its page; returns the page's path."""
    import nbclient
    import nbformat

    notebook = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(notebook, kernel_name="python3", timeout=timeout,
                                     resources={"metadata": {"path": str(path.parent)}})
    os.environ["GANDALF_BACKEND"] = "opengl"
    client.execute()
    stem = path.stem
    for old in PICTURES.glob(f"{stem}-*.png"):
        old.unlink()
    counter = [0]
    parts = []
    for index, cell in enumerate(notebook.cells):
        if cell.cell_type == "markdown":
            parts.append(cell.source.strip())
            if index == 0:
                parts.append(f"*This page is the notebook `notebooks/{path.name}` run from top to bottom (OpenGL, "
                             f"headless), with what it shows. Open the notebook itself to change and re-run it: "
                             f"see [the notebooks](../notebooks.md).*")
        elif cell.cell_type == "code":
            parts.append(f"```python\n{cell.source.rstrip()}\n```")
            parts += _outputs(cell, stem, counter)
    page = PAGES / f"{stem}.md"
    page.write_text("\n\n".join(parts) + "\n")
    return page


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--only", action="append", help="export only this notebook (its file name without .ipynb)")
    parser.add_argument("--timeout", type=int, default=120, help="seconds one cell may take (default 120)")
    args = parser.parse_args(argv)
    try:
        import nbclient  # noqa: F401
        import nbformat  # noqa: F401
    except ImportError:
        print("export_notebooks: needs nbclient and ipykernel (pip install -e '.[dev]')", file=sys.stderr)
        return 2
    paths = sorted(NOTEBOOKS.glob("*.ipynb"))
    if args.only:
        paths = [p for p in paths if p.stem in args.only]
    PAGES.mkdir(parents=True, exist_ok=True)
    PICTURES.mkdir(parents=True, exist_ok=True)
    for path in paths:
        start = time.perf_counter()
        print(f"running {path.relative_to(ROOT)} ...", flush=True)
        page = export(path, args.timeout)
        print(f"  wrote {page.relative_to(ROOT)} in {time.perf_counter() - start:.1f} s", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
