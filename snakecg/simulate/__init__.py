"""Pushing over time: the coupled snake + object dynamics integrated from a state.

The paper analyses one instant from rest; here the same equations are integrated over time,
with the velocity terms the instant analysis leaves out (``h_s``, the object's velocity terms,
``Adot v``), and with the transitions of the contact and of the wheels handled as events.

State and equations
-------------------
``y = (q, q_obj, v, v_obj, W)``: the snake's coordinates ``q`` (n_s) and velocities ``v``, the
object's pose ``q_obj = (x_o, y_o, psi)`` and twist ``v_obj`` (COM velocity and angular rate,
world frame, so ``d q_obj / dt = v_obj``), and three work integrals ``W`` (joint torques,
kinetic friction of sliding wheels, the external wrench on the object). The contact point is
fixed in the object frame (``rho``, from the scene's placement at ``t = 0``); it slides along
the contact link without friction (assumption 2).

Within a *mode* (which rows hold) the accelerations are those of eq. (12) with the held rows'
accelerations ``w_F = 0`` (eq. 13 with equality), computed by the compiled
``constrained_dynamics`` for that active set. Constraint drift is kept in check by Baumgarte
stabilisation of the held rows: the contact holds ``gddot = -2 alpha gdot - alpha^2 g`` and a
sticking wheel ``udot = -2 alpha u`` (``alpha = stabilization``, 1/s; the exact solution has
``g = gdot = u = 0``, so the term only acts on the integration error). At every event the
positions are projected back onto ``g = 0`` and the velocities onto the held rows (mass-weighted
projection), and the largest residual along the trajectory is reported.

Modes and events (``scipy.integrate.solve_ivp`` with terminal events, the mode re-solved at
each event):

* contact held: ``lam_c`` crossing zero downwards -> the contact separates; the contact point
  leaving the link (``s`` outside ``[0, l_k]``) -> the contact is lost for good;
* contact separated: the gap reaching zero with the point on the link -> plastic impact: the
  normal relative velocity is removed by an impulse that conserves momentum (bilateral ideal
  wheels take impulses too; wheels with bounded friction cannot, their force being finite),
  the kinetic energy lost ``1/2 Lam^T G_FF Lam`` is recorded;
* wheel sticking (``wheels`` scenario): ``|lam_i|`` reaching ``mu m_i g`` -> it breaks away and
  slides with kinetic friction ``-mu m_i g sign(u_i)`` opposing its lateral velocity ``u_i``;
* wheel sliding: ``u_i`` returning to zero -> it sticks again, or slides the other way.

At an event the new active set is the solution of the acceleration-level complementarity
problem (:func:`snakecg.solver.solve_active_set`) over the rows whose status is not fixed by
the velocities (a sliding wheel with ``u_i != 0`` is fixed; a separated contact with a positive
gap is fixed).

Torques: a constant vector, a function of time ``tau(t)``, or a feedback law ``tau(t, state)``
(:class:`State`), evaluated continuously or held over ``control_period`` (zero-order hold: the
law is called once per period with the state at the start of the period).

Geometry: the model's one contact does not keep the links out of the object or out of each
other; ``contact_check`` measures it at every step, sample and event and, by default, ends
the run at the first overlap beyond its tolerance (status ``penetration`` or
``self_contact``, :class:`Violation`).

The package: ``simulator`` (the integration loop), ``dynamics`` (the equations at a state),
``events`` (event functions, impacts, the active set at an event), ``contact_check`` (the
geometry at every step, sample and event), ``modes``, ``torques``,
``inputs`` (argument checks and limits), ``assembly`` (trajectory and summary), ``records``,
``controllers``, ``gaits`` (serpenoid PD tracking, torque tables), ``batch`` (many runs in
one call). The drawing,
:func:`save_figures` and :func:`save_animation`, is
:mod:`snakecg.figures.simulation`, imported on first use (matplotlib is not needed to
simulate).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .controllers import LeastSlipPush, least_slip_push_controller
from .batch import RunBatch, simulate_batch
from .gaits import Serpenoid, SerpenoidPD, TorqueTable, serpenoid_controller
from .inputs import MAX_FRAMES as MAX_FRAMES  # the limits, where they were before
from .inputs import MAX_OUTPUT_SAMPLES as MAX_OUTPUT_SAMPLES
from .inputs import MAX_PERIODS as MAX_PERIODS
from .inputs import MAX_STEPS as MAX_STEPS
from .inputs import RTOL_MIN as RTOL_MIN
from .inputs import STABILIZATION_MAX as STABILIZATION_MAX
from .records import SCHEMA, SimEvent, SimulationError, State, Trajectory, Violation
from .simulator import simulate

if TYPE_CHECKING:  # imported on first use (matplotlib), see __getattr__
    from ..figures.simulation import save_animation, save_figures

__all__ = [
    "simulate",
    "simulate_batch",
    "RunBatch",
    "Serpenoid",
    "SerpenoidPD",
    "TorqueTable",
    "serpenoid_controller",
    "Trajectory",
    "SimEvent",
    "Violation",
    "State",
    "SimulationError",
    "least_slip_push_controller",
    "LeastSlipPush",
    "save_figures",
    "save_animation",
    "SCHEMA",
]

_DRAWING = ("save_figures", "save_animation")


def __getattr__(name):
    if name in _DRAWING:
        from ..figures import simulation

        return getattr(simulation, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_DRAWING))
