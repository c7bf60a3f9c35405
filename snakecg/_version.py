"""The version of the snakecg runtime (as pyproject.toml states it)."""

__version__ = "0.1.0"
