"""Step 05's hierarchy: a solar system built from parent links, and re-parenting that keeps the world pose.

Every body hangs from an orbit pivot, an entity with a Transform and a spin but no mesh: turning the pivot carries
its children around. ``python -m step05_scenegraph.hierarchy.opengl`` (or ``.webgpu``); press M to move the moon.
"""

#: The step package whose ``exercises`` / ``solutions`` and ``shaders/`` this concept uses.
STEP = "step05_scenegraph"
