"""MkDocs hooks of the course site (``hooks:`` in mkdocs.yml): the API page's lists, and Sphinx roles as links.

* ``<!-- api: PACKAGE -->`` on a page becomes one ``::: module.Name`` block per public class and function of
  ``PACKAGE.__all__`` (in that order; constants are left out, and an object already shown on the page is not shown
  twice), so the API page covers every public name without a hand-kept list. The package is imported to find where
  each name is defined (its lazy names included).
* The engine's docstrings are written for Sphinx (``:class:`Scene```, ``:meth:`~Scene.add_entity```). mkdocstrings
  renders such a role as the text ``:class:`` before the name in code; ``on_page_content`` turns each into a link
  to the object's entry on the same page when exactly one entry matches the name, and into the name in code
  otherwise. No raw role is left on any page (tests/core/test_site.py checks it in the browser).
"""

from __future__ import annotations

import html
import importlib
import inspect
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

_MARKER = re.compile(r"^<!-- api: ([\w.]+) -->$", re.MULTILINE)
_BLOCK = re.compile(r"^::: ([\w.]+)", re.MULTILINE)
#: A role as mkdocstrings leaves it: ':class:' then the target in <code>, '~' keeping only its last part.
_ROLE = re.compile(r":(?:py:)?(class|func|meth|attr|mod|obj|data|exc|const):<code>(~?)([\w.]+)(\(\))?</code>")
_ID = re.compile(r'\bid="([\w.]+)"')


def public_objects(package: str) -> list[str]:
    """The dotted paths where the classes and functions of ``package.__all__`` are defined, in ``__all__`` order."""
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))
    module = importlib.import_module(package)
    paths = []
    for name in getattr(module, "__all__", ()):
        obj = getattr(module, name)
        if inspect.isclass(obj) or inspect.isfunction(obj):
            paths.append(f"{obj.__module__}.{obj.__qualname__}")
    return paths


def on_page_markdown(markdown: str, page, config, files) -> str:  # noqa: ANN001 (MkDocs' hook signature)
    if "<!-- api: " not in markdown:
        return markdown
    shown = set(_BLOCK.findall(markdown))

    def expand(match: re.Match[str]) -> str:
        blocks = []
        for path in public_objects(match.group(1)):
            if path not in shown:
                shown.add(path)
                blocks.append(f"::: {path}\n")
        return "\n".join(blocks)

    return _MARKER.sub(expand, markdown)


def on_page_content(content: str, page, config, files) -> str:  # noqa: ANN001
    if ":<code>" not in content:
        return content
    ids = set(_ID.findall(content))

    def link(match: re.Match[str]) -> str:
        short, target = match.group(2), match.group(3)
        shown = target.rsplit(".", 1)[-1] if short else target
        if match.group(1) in ("func", "meth"):
            shown += "()"
        candidates = [i for i in ids if i == target or i.endswith("." + target)]
        code = f"<code>{html.escape(shown)}</code>"
        return f'<a href="#{candidates[0]}">{code}</a>' if len(candidates) == 1 else code

    return _ROLE.sub(link, content)
