"""The rules both engines share: the solver's tolerances, the row states, the input limits and
the codes of a sample's status (why it is flagged, or why it has no answer).

The compiled engine receives the tolerances as :data:`CONSTANTS` (in the order of its
``sc_constants``, ``engine.h``); the pure-Python engine of ``backend="casadi"``
(:mod:`snakecg.solver`, :mod:`snakecg.rows`) reads them here. One home, so that the two
engines decide by the same numbers.
"""

from __future__ import annotations

import numpy as np

__all__ = ["PIVOT_TOL", "REGULARIZATION", "REL_TOL", "ROUND_REL", "ABSENT", "HELD", "LOST",
           "SLIDE_POS", "SLIDE_NEG", "FORCE_LIMIT", "POSITION_LIMIT", "ROW_TOL", "MASS_TOL",
           "WEAK", "SANE_TOL", "REASONS", "DEPENDENT", "MASS_SINGULAR", "IMPOSSIBLE",
           "NOT_FINITE", "NO_ANSWER", "reason_of", "default_max_iter", "CONSTANTS",
           "STATUS_EXACT", "STATUS_FALLBACK"]

#: Pivot ratio below which the held rows are treated as linearly dependent.
PIVOT_TOL = 1e-10
#: Relative regularization used for a singular sample (times the largest G_c diagonal).
REGULARIZATION = 1e-10
#: Relative tolerance of the active-set decisions (times each row's own force scale).
REL_TOL = 1e-9

# row states
ABSENT, HELD, LOST, SLIDE_POS, SLIDE_NEG = 0, 1, 2, 3, 4

#: Largest magnitude accepted for the forces (``tau``, ``f_obj``) and, square-rooted, for the
#: velocities: the norms are quadratic in them and must stay inside float64's range.
FORCE_LIMIT = 1e150

#: Largest magnitude accepted for the object's pose ``q_obj`` and contact point ``rho`` (m,
#: rad): the contact row carries ``rho`` as a moment arm, squared in the Delassus matrix.
POSITION_LIMIT = 1e100


def default_max_iter(nc: int) -> int:
    """Active-set passes before the remaining samples are enumerated."""
    return 4 * nc + 4


#: Weight of the rounding term of a row's scale in :func:`_tolerances`: ``REL_TOL ROUND_REL``
#: (1e-14) of the row's largest force term, a few roundings of its sum.
ROUND_REL = 1e-5

#: Pivot ratio of the held rows (``diag(R_1)^2 / |column|^2``) below which they are treated as
#: dependent even when factored directly (relative accuracy ~ 1e-16 / sqrt(ratio) = 1e-6).
ROW_TOL = 1e-20

#: Mass matrix pivot ratio below which ``M_s`` is numerically singular.
MASS_TOL = 1e-13

#: Why a sample is flagged ``singular``, by the code in its result row's ``status`` column
#: (0: answered by the compiled fast path, 1: answered exactly by the rare-sample rules, the
#: compiled ``rows.c`` or, on the CasADi backend, :mod:`snakecg.rows`).
REASONS = (
    "", "",
    "the held constraint rows are linearly dependent (the forces are the least-norm ones)",
    ("the mass matrix is numerically singular in float64 (masses, lengths or inertias too "
     "far apart): no answer"),
    ("the result is physically impossible in float64 (non-finite, a negative squared norm or "
     "sr outside [0, 1]): no answer"),
    ("the system is not finite in float64 (a scene parameter or an input too large or too "
     "small, e.g. a subnormal mass or kappa, or a huge wheel offset): no answer"),
)
DEPENDENT, MASS_SINGULAR, IMPOSSIBLE, NOT_FINITE = 2, 3, 4, 5
#: Codes whose results are NaN (every code but DEPENDENT, whose accelerations are unique).
NO_ANSWER = (MASS_SINGULAR, IMPOSSIBLE, NOT_FINITE)


def reason_of(code) -> str:
    """The one-line cause of a result row's ``status`` code ('' when answered)."""
    c = int(code) if np.isfinite(code) else 0
    return REASONS[c] if 0 <= c < len(REASONS) else ""


#: Delassus pivot ratio below which a sample is re-solved from its rows (the squared
#: system's relative error, 1e-16 / ratio, would exceed 1e-10).
WEAK = 1e-6

#: Rounding allowed in the physical checks (norms >= 0, 0 <= sr <= 1; snakecg.rows._sane).
SANE_TOL = 1e-12
#: The solver constants passed to the C, in the order of its ``sc_constants``.
CONSTANTS = np.array([PIVOT_TOL, WEAK, REL_TOL, MASS_TOL, SANE_TOL, FORCE_LIMIT, ROW_TOL,
                      REGULARIZATION])
#: A sample's status: answered by the fast path, or exactly by the rare-sample rules.
STATUS_EXACT, STATUS_FALLBACK = 0, 1
