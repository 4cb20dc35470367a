"""What step 02 saves in USD scenes: declared once, read by the final step's USD layer (``step07_advanced.usd``).

``COMPONENTS`` maps a component class to the fields a file holds; ``SYSTEMS`` a system class to the constructor
settings it is rebuilt with (a scene may name only these). Nothing here imports USD: the lessons stay free
of the persistence layer, and a file names classes, never code.
"""

from __future__ import annotations

from gandalf_core.app.cli import load_impl

from . import exercises
from .components import NGonComponent

# The reference (the exercises again where a student's release has no solutions/).
_reference = load_impl(__package__)

COMPONENTS = {NGonComponent: ("sides", "radius")}
SYSTEMS = {exercises.NGonSystem: (), _reference.NGonSystem: ()}
