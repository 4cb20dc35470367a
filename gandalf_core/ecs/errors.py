"""Errors raised by the ECS; each message names the entity and component type involved."""


class ECSError(Exception):
    """Base class of every ECS error."""


class NotAComponentError(ECSError, TypeError):
    """Something that is not a :class:`Component` was given where a component is expected."""


class UnknownEntityError(ECSError, KeyError):
    """The entity is not (or no longer) part of the scene."""

    def __str__(self) -> str:  # KeyError would quote the whole message
        return str(self.args[0])


class MissingComponentError(ECSError, KeyError):
    """The entity has no component of the requested type."""

    def __str__(self) -> str:
        return str(self.args[0])


class HierarchyCycleError(ECSError, ValueError):
    """Parenting would make an entity its own ancestor."""
