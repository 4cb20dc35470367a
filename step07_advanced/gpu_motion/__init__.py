"""Step 07 technique: GPU-driven motion — a crowd of spinning cubes turned by a compute pass, not by Python.

The same ``SpinSystem`` runs on one of three paths: per entity (the teaching form), batched with numpy, or on the
GPU, where the entities' Transforms stay static on the CPU (never recomputed or uploaded again) and the engine's
compute pass (``gandalf_core/render/shaders/motion_spin.comp`` / ``.wgsl``) turns their instance rows each frame
before the draws read them. ``python -m step07_advanced.gpu_motion.opengl [--path gpu|batch|entity]`` / ``.webgpu``.
"""

#: The step package whose ``exercises`` / ``solutions`` the launcher loads (this technique has no exercise).
STEP = "step07_advanced"
