"""One exception hierarchy for the package."""

from __future__ import annotations

__all__ = ["SnakecgError", "InputError", "BuildError", "ArtifactError", "SingularConstraintsError",
           "NotPlanarError"]


class SnakecgError(Exception):
    """Base class of every error snakecg raises on purpose."""


class InputError(SnakecgError, ValueError):
    """Bad input: the message names the argument and the expected form."""


class NotPlanarError(InputError):
    """A robot file describes a chain that is not planar (joint axes not parallel, a COM off
    its link's axis): the planar reader refuses it, ``Robot.from_urdf`` reads it in 3-D."""


class BuildError(SnakecgError, RuntimeError):
    """Generating or compiling a model failed; carries the command and its output."""

    def __init__(self, message: str, *, command: list[str] | None = None, stderr: str = ""):
        super().__init__(message)
        self.command = command
        self.stderr = stderr


class ArtifactError(SnakecgError, RuntimeError):
    """A generated or cached artefact is missing, truncated or does not match its manifest."""


class SingularConstraintsError(SnakecgError, ArithmeticError):
    """The held constraint rows are linearly dependent (singular Delassus matrix)."""
