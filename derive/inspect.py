"""Symbolic inspection: the closed forms behind the generated code, by name.

Names (``n`` = joint count): ``M`` (eq. 4, in absolute link angles), ``M_expanded``
(eq. 4 written out as ``sum J_i^T D_i J_i``), ``J1`` .. ``J<n+1>`` (eq. 3), ``h`` (eq. 4),
``K`` (derived parameters), ``contact`` (link-level contact row: ``a_link``, ``G^T`` row and
``Adot v``), ``contact<k>`` (the contact row ``-J_s`` on link ``k``, eq. 10, in ``q``),
``wheel<i>`` (the wheel row of link ``i`` in ``q``, and its ``Adot v``).
"""

from __future__ import annotations

import re

import sympy as sp

from .constraints import ContactSymbols, contact_row_local, wheel_row_local
from .kinematics import (
    StructuredChain,
    closed_form_jacobians,
    closed_form_mass_matrix,
    closed_form_poses,
    derived_parameter_values,
    readable_mass_matrix,
)
from .symbols import SnakeSymbols

__all__ = ["expression", "names"]


def names(n_joints: int) -> list[str]:
    nl = n_joints + 1
    return (["M", "M_expanded", "h", "K", "contact"] + [f"J{i}" for i in range(1, nl + 1)]
            + [f"contact{k}" for k in range(1, nl + 1)] + [f"wheel{i}" for i in range(1, nl + 1)])


def _link_subs(s: SnakeSymbols, i: int) -> dict:
    """Link-level symbols of link ``i`` in terms of ``q`` and ``v`` (closed form)."""
    C = ContactSymbols
    pose = closed_form_poses(s)[i - 1]
    J = closed_form_jacobians(s)[i - 1]
    v = sp.Matrix(s.v)
    twist = J * v
    bias = (J * v).jacobian(sp.Matrix(s.q)) * v
    subs = dict(zip(C.link_pose, pose))
    subs.update(dict(zip(C.link_twist, twist)))
    subs.update(dict(zip(C.link_bias, bias)))
    subs[C.link_com] = s.link_com[i - 1]
    return subs


def expression(n_joints: int, what: str) -> dict[str, sp.Expr | sp.Matrix]:
    """The named closed form(s) for a snake with ``n_joints`` joints: ``{label: expression}``."""
    s = SnakeSymbols(n_joints)
    nl = s.n_links
    if what == "M":
        return {"M_s (eq. 4)": readable_mass_matrix(s)}
    if what == "M_expanded":
        return {"M_s = sum_i J_i^T diag(m_i, m_i, I_i) J_i (eq. 4)": closed_form_mass_matrix(s)}
    if what == "h":
        ch = StructuredChain(s)
        h = ch.bias_forces()
        subs = {}
        for sym, expr in ch.assignments:
            subs[sym] = expr.xreplace(subs)
        h = h.xreplace(subs).xreplace(derived_parameter_values(s))
        return {"h_s (eq. 4)": h.applyfunc(sp.expand)}
    if what == "K":
        dp = derived_parameter_values(s)
        return {str(k): v for k, v in dp.items()}
    if what == "contact":
        cr = contact_row_local()
        return {"a_link": cr["a_link"], "G^T row": cr["g_obj"], "Adot v": cr["adot_v"],
                "gap": cr["gap"], "s": cr["s"]}
    m = re.fullmatch(r"(J|contact|wheel)(\d+)", what)
    if m and 1 <= int(m.group(2)) <= nl:
        kind, i = m.group(1), int(m.group(2))
        if kind == "J":
            return {f"J_{i} (eq. 3)": closed_form_jacobians(s)[i - 1]}
        subs = _link_subs(s, i)
        J = closed_form_jacobians(s)[i - 1]
        if kind == "contact":
            cr = contact_row_local()
            a = cr["a_link"].xreplace(subs)
            return {f"-J_s row, contact on link {i} (eq. 10)": (a * J).applyfunc(sp.expand),
                    "G^T row (eq. 9)": cr["g_obj"].xreplace(subs)}
        wr = wheel_row_local()
        a = wr["a_w"].xreplace(subs)
        return {f"A row, wheel on link {i}": (a * J).applyfunc(sp.expand),
                "Adot v (eq. 13)": sp.expand(wr["adot_v"].xreplace(subs))}
    raise ValueError(
        f"unknown expression {what!r} for {n_joints} joints; choose one of: "
        + ", ".join(names(n_joints))
    )
