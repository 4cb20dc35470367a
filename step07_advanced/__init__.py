"""Step 07 — advanced: normal and parallax occlusion mapping, physically based shading, and compute shaders."""
