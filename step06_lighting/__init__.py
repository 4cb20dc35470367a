"""Step 06 — lighting: meshes from files, Blinn-Phong with many lights, a skybox and environment mapping."""
