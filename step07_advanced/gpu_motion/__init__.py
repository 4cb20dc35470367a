"""Step 07 technique: GPU-driven motion — a crowd of spinning cubes turned by a compute pass, not by Python.

The same spin runs on one of three paths: per entity (the teaching form) or batched with numpy (the engine's
``SpinSystem``), or on the GPU (this technique's ``GpuSpinSystem``, :mod:`.system`), where the entities'
Transforms stay static on the CPU (never recomputed or uploaded again) and a compute pass
(``shaders/motion_spin.comp`` / ``.wgsl``; :mod:`.motion`, :mod:`.motion_gl`, :mod:`.motion_wgpu`) turns their
instance rows each frame before the draws read them: the render system runs it through its ``instance_pass`` hook.
``python -m step07_advanced.gpu_motion.opengl [--path gpu|batch|entity]`` / ``.webgpu``.
"""

#: The step package whose ``exercises`` / ``solutions`` the launcher loads (this technique has no exercise).
STEP = "step07_advanced"
