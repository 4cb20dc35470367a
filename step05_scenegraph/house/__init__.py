"""Step 05's capstone: the house of the paper's user study, in five milestones (the step's exercise).

A brick-textured cube with an orange pyramid roof turns about its y-axis, seen through a perspective camera.
``exercises/house.py`` holds the five milestones; ``scene.py`` assembles them
(``python -m step05_scenegraph.house.opengl --student`` runs yours). ``minimal.py`` is the same house in 38
lines with the core's ready materials and no shader (``python -m step05_scenegraph.house.minimal --help``).
"""

#: The step package whose ``exercises`` / ``solutions`` and ``shaders/`` this concept uses.
STEP = "step05_scenegraph"
