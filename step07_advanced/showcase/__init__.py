"""Step 07's showcase: PBR spheres, parallax-mapped bricks, a GPU particle fountain and shadow mapping in one scene."""

#: The step package whose ``exercises`` / ``solutions`` hold this technique's shader functions.
STEP = "step07_advanced"
