"""Step 02 — the triangle: vertex data and its layout, a vertex and a fragment shader, the first triangle,
a quad drawn through an index buffer, and an n-gon built by a system of your own."""
