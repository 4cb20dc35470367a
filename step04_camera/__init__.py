"""Step 04 — the camera: view and projection matrices, a look-at camera, an orbit camera and camera switching.

The same scene is seen through a perspective camera that orbits the objects under the mouse and an
orthographic camera placed with a look-at; pressing C switches between them.
"""
