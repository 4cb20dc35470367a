"""Tests on a machine that lacks what a part needs: skipped with the launcher's sentence, and "not graded here".

A :class:`~gandalf_core.render.capabilities.CapabilityError` that ends a test (in its set-up or its call) turns
the test into a skip whose reason says what is missing and what to run instead, and tags the report so that the
grade (``gandalf_tools.grading.plugin``) leaves the test out instead of failing it. Only a gap this machine really
has counts (probed again here), and only one no exercise code raised: an exercise cannot skip its own test.
"""

from __future__ import annotations

import pytest

#: The report property that tells the grade a test was not graded here (and why).
NOT_HERE = "gandalf_not_here"


def not_here(excinfo: pytest.ExceptionInfo[BaseException]) -> str:
    """The reason the test that raised ``excinfo`` cannot run on this machine, or "" for a real failure."""
    from gandalf_core.render.capabilities import CapabilityError
    from gandalf_core.render.probe import offer_here

    exc = excinfo.value
    if not isinstance(exc, CapabilityError):
        return ""
    tb = excinfo.tb
    while tb is not None:
        if str(tb.tb_frame.f_globals.get("__name__", "")).split(".")[1:2] == ["exercises"]:
            return ""
        tb = tb.tb_next
    return str(exc) if exc.needs.missing(offer_here(exc.offer.api)) else ""


def mark_not_here(item: pytest.Item, call: pytest.CallInfo[None], report: pytest.TestReport) -> pytest.TestReport:
    """``report`` as a skip, tagged not graded here, when the test failed for a capability this machine lacks."""
    reason = not_here(call.excinfo) if call.excinfo is not None and report.failed else ""
    if reason:
        report.outcome = "skipped"
        report.longrepr = (str(item.path), item.location[1] or 0, f"Skipped: not graded here: {reason}")
        report.user_properties.append((NOT_HERE, reason))
    return report

