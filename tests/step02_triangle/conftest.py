"""Step 02 tests get the implementation under test (solutions, or exercises with --student) as ``impl``."""

from gandalf_tools.grading.plugin import impl_fixture

impl = impl_fixture("step02_triangle")
