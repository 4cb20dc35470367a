"""Facts typed into the course site's pages agree with the code they describe (no browser needed).

* A step page's table ``| exercise | tests | what they check |`` gives, per exercise, the number of graded tests;
  pytest's collection of that step's tests (items marked ``@pytest.mark.exercise(name)``) must give the same number.
* The getting-started page's options table lists every option a step variant accepts (``run_variant``'s parser).
"""

from __future__ import annotations

import inspect
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
STEP_PAGES = sorted((ROOT / "docs" / "steps").glob("step0*.md"))
_ROW = re.compile(r"^\| `([\w.]+)` \| (\d+) \|", re.MULTILINE)
#: Counts graded tests per exercise without running them (a collection only).
_COUNT = """
import collections, json, sys
import pytest

class Count:
    def pytest_collection_finish(self, session):
        counts = collections.Counter(item.get_closest_marker("exercise").args[0] for item in session.items
                                     if item.get_closest_marker("exercise"))
        print("COUNTS " + json.dumps(counts))

sys.exit(pytest.main(["--collect-only", "-q", "-p", "no:cacheprovider", sys.argv[1]], plugins=[Count()]))
"""


def _typed_counts(page: Path) -> dict[str, int]:
    text = page.read_text()
    if "| exercise | tests |" not in text:
        return {}
    table = text[text.index("| exercise | tests |"):].split("\n\n", 1)[0]
    return {name: int(n) for name, n in _ROW.findall(table)}


@pytest.mark.parametrize("page", [p for p in STEP_PAGES if _typed_counts(p)], ids=lambda p: p.stem)
def test_the_test_counts_a_step_page_gives_are_the_collected_ones(page: Path) -> None:
    typed = _typed_counts(page)
    result = subprocess.run([sys.executable, "-c", _COUNT, str(ROOT / "tests" / page.stem)], cwd=ROOT,
                            capture_output=True, text=True, timeout=300)
    line = next((line for line in result.stdout.splitlines() if line.startswith("COUNTS ")), None)
    assert line is not None, f"collecting tests/{page.stem} failed:\n{result.stdout[-2000:]}\n{result.stderr[-2000:]}"
    collected = json.loads(line[len("COUNTS "):])
    wrong = {name: (n, collected.get(name, 0)) for name, n in typed.items() if collected.get(name, 0) != n}
    assert not wrong, (f"docs/steps/{page.name} says (typed, collected): {wrong}; "
                       "write the collected numbers into its table")


def test_the_options_table_lists_every_option_of_a_step_variant() -> None:
    from gandalf_core.app import cli

    options = set(re.findall(r'add_argument\("(--[\w-]+)"', inspect.getsource(cli.run_variant)))
    assert options, "found no option in run_variant"
    page = (ROOT / "docs" / "getting-started.md").read_text()
    missing = sorted(option for option in options if f"| `{option}" not in page)
    assert not missing, f"docs/getting-started.md's options table lacks {missing}"
