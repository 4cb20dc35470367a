"""Step 05's several scenes: one app holds the step's four scenes and switches between them on a key.

A SceneSwitchSystem in every scene asks the app to switch (keys 1-4, TAB cycles); the switch happens at the start
of the next frame. The scenes share one renderer, which caches GPU objects by name: switching 1,000 times creates
none. ``python -m step05_scenegraph.several_scenes.opengl`` (also the step's default: ``step05_scenegraph.opengl``).
"""

#: The step package whose ``exercises`` / ``solutions`` and ``shaders/`` this concept uses.
STEP = "step05_scenegraph"
