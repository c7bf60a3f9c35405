"""Optimal torque queries: the paper's closing question as a millisecond query.

"For a given task and configuration, an analysis can be carried out to find the optimal input
(vector of joint torques) to minimize or maximize slippage of the system" (Reyes & Ma 2017,
Discussion). Three queries, all at rest (``v = 0``, no external wrench on the object):

* ``"max_sr"``: the torque that maximises the slippage ratio ``sr`` (eq. 30) over the input
  region, with the contact kept and, in the ``wheels`` scenario, every wheel within its
  friction bound unless it is explicitly allowed to slide;
* ``"least_slip_push"``: the torque that gives the object a requested acceleration (at least
  ``a_min`` along a direction, or a full planar acceleration) with the least snake motion
  ``||qdd_s||^2 = qdd^T M_s qdd`` (eq. 26), every wheel sticking;
* ``"strongest_push"``: the largest object acceleration along a direction with no wheel sliding
  and the torques within their limits (ties broken by the least ``||qdd_s||^2``).

The input region is the ellipsoid of eq. (31), ``tau^T N tau <= radius^2`` with
``N = B^T M_s^-1 B`` (``radius = 1`` is the paper's region), the box ``|tau_j| <= tau_max_j``,
or both.

Structure used (see docs/optimize.md for the derivations):

1. With every constraint row held (contact kept, wheels sticking) the system at rest is
   linear in ``tau`` (eqs. 17, 22, 24): ``lam = L tau``, ``a_obj = A tau``,
   ``qdd = Q tau``; "contact kept" is ``L_c tau >= 0`` and "no wheel slides" is
   ``|L_i tau| <= mu m_i g``: linear inequalities. ``least_slip_push`` is then a convex QP
   and ``strongest_push`` an LP (qpOASES through ``casadi.conic``). With the ellipsoid they
   are convex QCQPs: the linear relaxation (the ellipsoid's bounding box) is solved first;
   if its answer leaves the ellipsoid, the ellipsoid's multiplier ``mu`` is found by root
   finding on ``tau(mu)^T N tau(mu) = r^2``, each step a QP (exact to solver precision).
2. One frictionless point contact (assumptions 2 and 6) pushes the object only along its
   normal: ``a_obj = a_dir * lam_c`` for a fixed ``a_dir``, so every push task is a bound on
   the contact force ``lam_c = L_c tau``, and a requested acceleration off ``a_dir`` is
   infeasible whatever the torques (reported as such).
3. ``sr`` with everything held is the generalized Rayleigh quotient
   ``tau^T Omega tau / tau^T (Omega + Xi) tau`` (eqs. 28-30), homogeneous of degree 0: the
   top generalized eigenvector of ``(Omega, Omega + Xi)``, signed so that ``lam_c >= 0``,
   is the maximiser over every region that is star-shaped about 0, including the friction
   polytope; it is returned at the largest magnitude that keeps every limit (exact).
4. When wheels may slide, the map is piecewise affine: each wheel state (stick, slide+,
   slide-) has its own affine map, valid on a polyhedral cone of ``z = (tau, 1)``. With the
   rank-one numerator ``||a_obj||^2 = k lam_c^2``, ``max sr`` on one state is the convex
   problem ``min z^T Xi_h z`` subject to ``lam_c(z) = 1``, the state's validity cone and the
   region in homogeneous form (Charnes-Cooper): a QP per state; where the ellipsoid cuts
   the state's optimum, tangent-plane cuts, then a convex NLP (IPOPT) if the state can still
   win. States are pruned by an exact upper bound (the problem without the cone) before any
   solve; the candidates are ranked by the exact forward solve.

Every answer that claims to be optimal carries a :class:`Certificate`, checked on the
original problem after the solve (KKT residuals, feasibility, and for the convex kinds the
duality gap; :mod:`snakecg.optimize.certificate`). When it fails the query is solved again
from scratch by a fresh solver; when that fails too the status is ``"failed"`` with the reason.
Every answer is then checked with :meth:`SceneModel.forward`; a disagreement (a wheel that
slides although it was kept, a different objective value, a violated limit) turns the status
into ``"failed"`` with the reason.

No answer depends on what ran before, in any order and from any thread: the solvers are built
once per problem size and shared, but every solve starts from the same solver state (qpOASES
is reset by a problem of the same constraint pattern with a known answer before each solve,
under a lock, and its active set is solved exactly; IPOPT starts from the given point), see
:mod:`snakecg.optimize.solvers`.

Modules: :mod:`~snakecg.optimize.query` (input validation), :mod:`~snakecg.optimize.problems`
(the maps and constraint rows), :mod:`~snakecg.optimize.solvers` (qpOASES, IPOPT, the
ellipsoid multiplier), :mod:`~snakecg.optimize.max_sr` and :mod:`~snakecg.optimize.push` (the
three kinds), :mod:`~snakecg.optimize.certificate`, :mod:`~snakecg.optimize.api`
(:func:`optimize`), :mod:`~snakecg.optimize.result`.
"""

from __future__ import annotations

from .api import optimize
from .result import (
    CHECK_TOL,
    CONTACT,
    ELLIPSOID,
    FRICTION_MARGIN,
    NORMAL,
    OBJECTIVES,
    SCHEMA,
    STATUSES,
    Certificate,
    OptimizeResult,
)

__all__ = ["optimize", "OptimizeResult", "Certificate", "OBJECTIVES", "STATUSES", "SCHEMA",
           "CONTACT", "ELLIPSOID", "NORMAL", "FRICTION_MARGIN", "CHECK_TOL"]
