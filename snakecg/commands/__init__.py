"""Sub-commands of the ``snakecg`` CLI; each module has ``register(subparsers)``."""
