"""The set of functions the generator defines for a joint count (names, in manifest order).

Light on purpose (no SymPy, no CasADi): the runtime checks a model folder's manifest against
it before loading, and ``snakecg show`` lists it. The generator asserts that what it builds is
exactly this list (:func:`snakecg_derive.render.render_model`), so the two cannot drift; the
signatures themselves (names, shapes, order of inputs and outputs) are read from the CasADi
functions into the manifest.
"""

from __future__ import annotations

__all__ = ["LINK_FUNCTIONS", "COUPLED_FUNCTIONS", "EXTREMES_MAX_JOINTS", "function_names"]

#: Per-link closed forms derived with SymPy (:mod:`snakecg_derive.model`).
LINK_FUNCTIONS = ("derived_parameters", "link_poses", "link_jacobians",
                  "link_bias_accelerations", "mass_matrix", "bias_forces", "scene_kinematics",
                  "bias_forces_cs",
                  "contact_row_local", "wheel_row_local")
#: The coupled system of eqs. (8)-(31) (:mod:`snakecg_derive.coupled`).
COUPLED_FUNCTIONS = ("constrained_dynamics", "interaction_maps", "metric_forms", "place_object",
                     "contact_system", "contact_system_at_rest", "metric_extremes")
#: ``metric_extremes`` solves the eigenproblems of eq. (31) in closed form, up to 3 x 3.
EXTREMES_MAX_JOINTS = 3


def function_names(n_joints: int) -> tuple[str, ...]:
    """Names of every generated function for ``n_joints``, in manifest order."""
    coupled = COUPLED_FUNCTIONS if n_joints <= EXTREMES_MAX_JOINTS else COUPLED_FUNCTIONS[:-1]
    return LINK_FUNCTIONS + coupled
