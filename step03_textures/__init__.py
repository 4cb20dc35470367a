"""Step 03 — textures: texels and UVs, samplers (filtering, wrapping, mipmaps), a textured quad and cube."""
