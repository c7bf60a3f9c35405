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

One home: every query, for one configuration or a batch, is one call of the compiled
runtime core (``snakecg/engine/optimal.c``, ``wheel_states.c``, ``maps.c`` on the QP block
``qp.c`` and the linear algebra of ``linalg.h``; bound in :mod:`snakecg.engine.optimal`), which
per configuration builds the maps, solves, certifies the answer on the original problem, runs
the exact forward solve at the answer and checks it. This package validates the query
(:mod:`~snakecg.optimize.query`, :mod:`~snakecg.optimize.arguments`), builds the call's inputs
(:mod:`~snakecg.optimize.api`) and words the answers (:mod:`~snakecg.optimize.answers`,
:mod:`~snakecg.optimize.result`). A batch of one is the single call, bit for bit.

Structure used (see docs/how-to/optimize.md for the derivations):

1. With every constraint row held (contact kept, wheels sticking) the system at rest is
   linear in ``tau`` (eqs. 17, 22, 24): ``lam = L tau``, ``a_obj = A tau``,
   ``qdd = Q tau``; "contact kept" is ``L_c tau >= 0`` and "no wheel slides" is
   ``|L_i tau| <= mu m_i g``: linear inequalities. ``least_slip_push`` is then a convex QP
   and ``strongest_push`` an LP, solved by a dense dual active-set method (Goldfarb-Idnani)
   and, on the ellipsoid, through the ellipsoid's multiplier (a monotone secular equation,
   Newton's method on each piece of constant active set).
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
   the state's optimum, the state's value function in ``t`` is minimised, each point a QCQP.
   States are pruned by an exact upper bound (the problem without the cone) before any
   solve; the candidates are ranked by the exact forward solve.

Every answer that claims to be optimal carries a :class:`Certificate`, computed in C on the
original problem (KKT residuals, feasibility, and for the convex kinds the duality gap);
``"optimal"`` is only returned when it holds. Every answer is then checked with the exact
forward solve; a disagreement (a wheel that slides although it was kept, a different objective
value, a violated limit) turns the status into ``"failed"`` with the reason. The compiled
call keeps no state between calls: every answer is a function of the query alone.
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
    TOLERANCE,
    Certificate,
    OptimizeResult,
)

__all__ = ["optimize", "OptimizeResult", "Certificate", "OBJECTIVES", "STATUSES", "SCHEMA",
           "CONTACT", "ELLIPSOID", "NORMAL", "FRICTION_MARGIN", "CHECK_TOL", "TOLERANCE"]
