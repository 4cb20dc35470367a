"""gandalf_tools: the course's tooling beside the engine.

The grader (``grading``: the pytest plugin, the front end, the batch grader and the mutation check), the course
tour (``tour``), the test helpers that render and compare pictures (``testing``) and the studies' writer
(``studies``). These import the engine; the engine (``gandalf_core``) never imports them.
"""
