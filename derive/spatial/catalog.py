"""The functions a spatial model defines, and its names (light: no SymPy, no CasADi).

The runtime checks a spatial model folder's manifest against :data:`SPATIAL_FUNCTIONS`
before loading it; the generator asserts that it derives exactly these.
"""

from __future__ import annotations

__all__ = ["SPATIAL_FUNCTIONS", "SPATIAL_CONTACT_FUNCTIONS", "SPATIAL_MODEL_FUNCTIONS",
           "CHECKED_IN_SPATIAL_JOINTS", "spatial_prefix", "spatial_dirname"]

#: Every generated function of a spatial model, in manifest order.
SPATIAL_FUNCTIONS = ("derived_parameters", "link_poses", "link_jacobians",
                     "link_bias_accelerations", "point_jacobian", "point_bias_acceleration",
                     "mass_matrix", "bias_forces", "kinematic_map", "ground_rows", "wheel_rows",
                     "contact_row")
#: The contact problem composed from them in CasADi (:mod:`.contact`), with the planar
#: models' layout, for the runtime core's complementarity solve.
SPATIAL_CONTACT_FUNCTIONS = ("contact_system", "contact_system_at_rest")
#: Every function of a spatial model folder, in manifest order.
SPATIAL_MODEL_FUNCTIONS = SPATIAL_FUNCTIONS + SPATIAL_CONTACT_FUNCTIONS
#: Joint counts whose spatial models are checked in under ``generated/spatial/``.
CHECKED_IN_SPATIAL_JOINTS = (1, 2, 3)


def spatial_prefix(n_links: int) -> str:
    """Prefix of every emitted C symbol of the spatial model with ``n_links`` links."""
    return f"snakecg_sp{n_links - 1}_"


def spatial_dirname(n_links: int) -> str:
    """``na<joints>``, as the planar models' folders."""
    return f"na{n_links - 1}"
