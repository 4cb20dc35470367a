"""The bad-input catalogue: every kind of wrong input the engine takes, each with the error it must give.

One file per area (files, shaders, materials, components, cameras, the ECS, applications, USD); each holds a
table of :class:`~bad_input.catalogue.Case` rows run by one test. A case is an action and what it must give: an
exception of a stated type whose message holds stated words (the file, entity, component and field, material,
uniform or shader line at fault), a warning likewise, or a right result checked by a function. A reviewer reads
the tables; ``catalogue.py`` is the only machinery.
"""
