"""Step 01 — the window: a frame loop that clears the screen to a colour that changes over time."""
