"""Step 05's integrators: a mass on a damped spring advanced four ways, side by side, and two studies.

``methods.py`` holds the lesson (explicit and implicit Euler, the exact solution, energy, stability limits);
semi-implicit Euler and RK4 are the exercise (``exercises/integrators.py``). The springs scene shows all four
(``python -m step05_scenegraph.integrators.opengl``); ``python -m step05_scenegraph.integrators.study`` measures
accuracy against cost and stability, ``python -m step05_scenegraph.integrators.study_fixed_step`` the fixed step.
"""

#: The step package whose ``exercises`` / ``solutions`` and ``shaders/`` this concept uses.
STEP = "step05_scenegraph"
