"""What the optimal-torque pieces of a general scene share (:mod:`snakecg.scenes.optimize`):
the tolerances, the blocks' roles, the pieces' states and how far a force is out in its set."""

from __future__ import annotations

import itertools

import numpy as np

from ..errors import InputError
from .extremes_coulomb import contact_choices
from .solve import BOX, DISC, HELD, SLIDE, SPLIT, UNILATERAL, ZERO

__all__ = ["MARGIN", "CHECK_TOL", "IPOPT_TOL", "MAX_STATES", "roles", "contact_states",
           "gauge"]

#: Relative back-off from the friction sets' boundaries, so the forward solve sees them stick.
MARGIN = 1e-7
#: Relative agreement of the forward solve with the objective value.
CHECK_TOL = 1e-6
#: IPOPT's tolerance.
IPOPT_TOL = 1e-10
#: Contact states searched at most.
MAX_STATES = 4096


def roles(p):
    """Per block: 'contact', 'link' (a link's ground set) or 'object' (an object's ground
    friction), and whether its set has size 0."""
    out = []
    for k, par, lab in zip(p.kind, p.par, p.rows.labels):
        zero = (k == BOX and not par[0] > 0) or (k == DISC and not par[0] > 0) or (
            k == SPLIT and not (par[2] > 0 and (par[0] > 0 or par[1] > 0)))
        role = {"contact": "contact", "object_ground": "object"}.get(lab[0], "link")
        out.append((role, zero))
    return out


def gauge(kind, par, lam) -> float:
    """How far ``lam`` is out along its set (1 on the boundary, 0 at the centre)."""
    if kind == BOX:
        return abs(lam[0]) / par[0] if par[0] > 0 else 0.0
    if kind == DISC:
        return float(np.hypot(*lam[:2])) / par[0] if par[0] > 0 else 0.0
    if kind == SPLIT and par[2] > 0:
        st = par[0] if lam[0] < 0 else par[1]
        return float(np.hypot(lam[0] / st if st > 0 else 0.0, lam[1] / par[2]))
    return 0.0


def contact_states(p, roles, objects_slide=()):
    """Every combination of block states: contacts held/open (with Coulomb friction: stick,
    open, slip+, slip-), links' sets sticking (size 0: none), objects' ground friction
    sticking or sliding (``objects_slide``: blocks that may slide)."""
    choices = []
    for b, ((role, zero), k) in enumerate(zip(roles, p.kind)):
        if zero:
            choices.append((ZERO,))
        elif role == "contact" and k == UNILATERAL:
            choices.append(contact_choices(p, b))  # with Coulomb friction: four
        elif role == "object" and b in objects_slide:
            choices.append((HELD, SLIDE))
        else:
            choices.append((HELD,))
    n = int(np.prod([len(c) for c in choices]))
    if n > MAX_STATES:
        raise InputError(f"this configuration has {n} contact states (more than "
                         f"{MAX_STATES}) to search; move the bodies apart")
    return list(itertools.product(*choices))
