"""Step 05 — the scene graph: hierarchies, custom components and systems, integrators, several scenes.

Three scenes in one app (keys 1/2/3 or TAB switch): a solar system built from parent links, the house of
the paper's user study (the capstone exercise), and damped springs integrated four ways beside falling,
bouncing balls. ``python -m step05_scenegraph.study`` measures the integrators.
"""
