"""Sweeps that outgrow one process: per-configuration extremes on Dask, chunked into Zarr.

``snakecg.sweep(scene, store="sweep.zarr")`` (:func:`~snakecg.sweeps.run.sweep`) evaluates
every configuration of a grid or of seeded samples; :func:`summary` and :func:`figure`
reduce a store chunk by chunk (Table 2 style and Fig. 5 style); :func:`read` loads a small
one into memory; every read checks the store's digests. A store also opens with
``xarray.open_zarr``. Needs the ``sweep`` extra (``pip install 'snakecg[sweep]'``: Dask's
``distributed``, Zarr, xarray and cryptography); importing this package does not import
them.
"""

from .plan import Plan, default_chunk, joint_values
from .reduce import figure, read, summary
from .run import LIMIT, SweepResult, sweep

__all__ = ["sweep", "SweepResult", "summary", "figure", "read", "joint_values", "Plan",
           "default_chunk", "LIMIT"]
