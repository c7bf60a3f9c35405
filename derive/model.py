"""Derive the full model of a planar snake with ``n_a`` joints: one :class:`ModelSpec`."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .build import build_function, cse_program, operation_count as casadi_operation_count
from .constraints import ContactSymbols, contact_row_local, wheel_row_local
from .kinematics import StructuredChain, closed_form_mass_matrix, derived_parameter_values
from .spec import FunctionSpec, ModelSpec, topological_assignments
from .symbols import MAX_SYMBOLIC_JOINTS, SnakeSymbols

__all__ = ["derive_model", "ModelDerivation", "program_operation_count", "CLOSED_FORM_MAX_JOINTS"]

#: Beyond this joint count the ``O(n^3)`` closed form and the suffix-sum form of ``M_s`` are not
#: derived for the operation-count comparison (they lose by more at every joint count above
#: one, and cost derivation time; see docs/performance.md for the measured counts).
CLOSED_FORM_MAX_JOINTS = 8


def program_operation_count(f: FunctionSpec) -> int:
    """SymPy ``count_ops`` of the straight-line program of ``f`` that the CasADi function is
    built from (:func:`.build.cse_program`: CSE over assignments and outputs together)."""
    ordered, outs = cse_program(f)
    return (sum(sp.count_ops(e) for _, e in ordered)
            + sum(sp.count_ops(e) for _, _, _, elements in outs for e in elements))


@dataclass(frozen=True)
class ModelDerivation:
    """The spec plus the symbolic objects that inspection and the docs use."""

    symbols: SnakeSymbols
    spec: ModelSpec


def _fn(name, doc, inputs, outputs, assignments=(), equation="") -> FunctionSpec:
    ins = tuple(inputs)
    known = {s for _, syms, _ in ins for s in syms}
    ordered = topological_assignments(list(assignments), known)
    # keep only assignments the outputs need (structured chains share a builder)
    needed: set[sp.Symbol] = set()
    for _, mat, _ in outputs:
        for e in mat:
            needed |= e.free_symbols
    keep = []
    for sym, expr in reversed(ordered):
        if sym in needed:
            keep.append((sym, expr))
            needed |= expr.free_symbols
    f = FunctionSpec(
        name=name,
        doc=doc,
        inputs=ins,
        outputs=tuple(outputs),
        assignments=tuple(reversed(keep)),
        equation=equation,
    )
    f.check_closed()
    return f


class _ChainFromSines(StructuredChain):
    """A chain whose links' cosines and sines are inputs (``cs``, 2 per link) instead of
    rotation products of the coordinates' own (the same values where ``cs`` comes from
    ``scene_kinematics`` at the same ``q``). The inputs are named as the chain names them
    (``cq0``, ``sq0``, then ``cphi2``, ``sphi2``, ...): SymPy orders a sum's terms by name, so
    the expressions, and their rounding, are those of the chain's own."""

    def __init__(self, s: SnakeSymbols):
        super().__init__(s)
        names = [("cq0", "sq0")] + [(f"cphi{i}", f"sphi{i}") for i in range(2, s.n_links + 1)]
        self.cs = [sp.Symbol(w, real=True) for pair in names for w in pair]

    def cos_phi(self, i: int) -> sp.Symbol:
        return self.cs[2 * (i - 1)]

    def sin_phi(self, i: int) -> sp.Symbol:
        return self.cs[2 * (i - 1) + 1]


def derive_model(n_joints: int, *, max_joints: int = MAX_SYMBOLIC_JOINTS) -> ModelDerivation:
    """Derive every generated function for a snake with ``n_joints`` joints.

    Raises :class:`ValueError` for a joint count below 1 or above ``max_joints``.
    """
    if isinstance(n_joints, bool) or not isinstance(n_joints, int):
        raise ValueError(f"n_joints must be an integer >= 1, got {n_joints!r}")
    if n_joints < 1 or n_joints > max_joints:
        raise ValueError(
            f"n_joints must be between 1 and {max_joints} (the configurable derivation limit),"
            f" got {n_joints}"
        )
    s = SnakeSymbols(n_joints)
    nl = s.n_links
    spec_prefix = f"snakecg_na{n_joints}_"
    q_in = ("q", s.q, f"generalized coordinates (x, y, theta, q1..q{n_joints})")
    v_in = ("v", s.v, "generalized velocities, same order as q")
    K_in = ("K", s.parameters, "model parameters: raw link parameters, then derived constants")

    functions: list[FunctionSpec] = []

    # derived parameters ------------------------------------------------------------------
    dp = derived_parameter_values(s)
    functions.append(
        _fn(
            "derived_parameters",
            "Parameter vector K from the raw link parameters (computed once per robot).",
            [
                ("link_mass", s.link_mass, "m_i [kg]"),
                ("link_length", s.link_length, "l_i [m]"),
                ("link_inertia", s.link_inertia, "I_i about the COM [kg m^2]"),
                ("link_com", s.link_com, "c_i, COM distance from the rear end [m]"),
            ],
            [("K", sp.Matrix(list(s.raw_parameters) + [dp[d] for d in s.derived_parameters]),
              "parameter vector")],
        )
    )

    # kinematics --------------------------------------------------------------------------
    ch = StructuredChain(s)
    poses = ch.link_poses()
    functions.append(
        _fn("link_poses", "COM position and absolute angle of every link.", [q_in, K_in],
            [("poses", poses, "3 x n_l, column i = (x_i, y_i, phi_i)")], ch.assignments)
    )
    ch = StructuredChain(s)
    J = ch.link_jacobians()
    functions.append(
        _fn("link_jacobians", "Link Jacobians J_i stacked (eq. 3).", [q_in, K_in],
            [("J", J, "3 n_l x n_s; rows 3(i-1)..3i-1 map qdot to the twist of link i")],
            ch.assignments, equation="(3)")
    )
    ch = StructuredChain(s)
    bias = ch.link_bias_accelerations()
    functions.append(
        _fn("link_bias_accelerations", "Jdot_i qdot of every link.", [q_in, v_in, K_in],
            [("bias", bias, "3 x n_l, column i = Jdot_i qdot")], ch.assignments)
    )

    # inertia ----------------------------------------------------------------------------
    # Candidate forms of M_s; the one generated is the one whose CasADi function (what the C
    # computes) has the fewest operations. SymPy's count after CSE is recorded beside it.
    def mass_fn(M, assignments) -> FunctionSpec:
        return _fn("mass_matrix", "Inertia matrix M_s of the snake (eq. 4).", [q_in, K_in],
                    [("M", M, "n_s x n_s, symmetric positive definite")], assignments,
                    equation="(4)")

    # each form of M_s built on a chain (the closed form needs none of its assignments)
    forms = {"structured": lambda ch: ch.mass_matrix(),
             "suffix_sums": lambda ch: ch.mass_matrix_suffix_sums(),
             "closed": lambda ch: closed_form_mass_matrix(s)}
    candidates: dict[str, FunctionSpec] = {}
    ch = StructuredChain(s)
    candidates["structured"] = mass_fn(forms["structured"](ch), ch.assignments)
    if n_joints <= CLOSED_FORM_MAX_JOINTS:
        # the suffix-sum form (about 3.5 n^2) wins for one joint; both it and the closed form
        # lose by more at every further joint count measured
        ch = StructuredChain(s)
        candidates["suffix_sums"] = mass_fn(forms["suffix_sums"](ch), ch.assignments)
        candidates["closed"] = mass_fn(forms["closed"](ch), ())
    counts = {}
    counts_casadi = {}
    for name, f in candidates.items():
        counts[name] = program_operation_count(f)
        counts_casadi[name] = casadi_operation_count(build_function(f, spec_prefix))
    form = min(candidates, key=counts_casadi.get)  # ties: the first listed
    functions.append(candidates[form])

    ch = StructuredChain(s)
    h = ch.bias_forces()
    functions.append(
        _fn("bias_forces", "Coriolis and centripetal terms h_s of eq. (4).", [q_in, v_in, K_in],
            [("h", h, "n_s x 1")], ch.assignments, equation="(4)")
    )
    # a general scene's per-sample kinematics in one function: poses, Jacobians and M_s (the
    # form chosen above) from one chain, so that the joints' sines and cosines are taken once;
    # with the links' cosines and sines, which the scene's placement and its next step's bias
    # forces (below) read instead of taking them again
    ch = StructuredChain(s)
    poses, J = ch.link_poses(), ch.link_jacobians()
    M = forms[form](ch)
    cs = sp.Matrix([[ch.cos_phi(i), ch.sin_phi(i)] for i in range(1, nl + 1)]).T
    functions.append(
        _fn("scene_kinematics", "Link poses, Jacobians and M_s at once (one set of sines).",
            [q_in, K_in],
            [("poses", poses, "3 x n_l, as link_poses"), ("J", J, "3 n_l x n_s, as link_jacobians"),
             ("M", M, "n_s x n_s, as mass_matrix"),
             ("cs", cs, "2 x n_l, column i = (cos phi_i, sin phi_i)")], ch.assignments,
            equation="(3), (4)")
    )
    # h_s from the links' cosines and sines at q (scene_kinematics' cs): no trigonometric call
    ch = _ChainFromSines(s)
    h = ch.bias_forces()
    functions.append(
        _fn("bias_forces_cs", "Coriolis and centripetal terms h_s of eq. (4), from the links' "
            "cosines and sines.",
            [("cs", ch.cs, "2 x n_l, column i = (cos phi_i, sin phi_i), scene_kinematics' cs"),
             q_in, v_in, K_in],
            [("h", h, "n_s x 1")], ch.assignments, equation="(4)")
    )

    # constraint rows (link level) ----------------------------------------------------------
    C = ContactSymbols
    cr = contact_row_local()
    functions.append(
        _fn(
            "contact_row_local",
            "Frictionless contact row of one link against a point fixed in the object "
            "(eqs. 8-13).",
            [
                ("link_pose", C.link_pose, "(x, y, phi) of the link COM"),
                ("link_twist", C.link_twist, "(v_x, v_y, omega) of the link COM"),
                ("link_bias", C.link_bias, "Jdot qdot of the link"),
                ("link_com", (C.link_com,), "COM distance from the rear end of the link"),
                ("object_pose", C.object_pose, "(x_o, y_o, psi) of the object COM"),
                ("object_twist", C.object_twist, "object twist"),
                ("rho", C.rho, "contact point in the object frame, from its COM"),
                ("side", (C.side,), "+1: object on the left of the link, -1: on the right"),
            ],
            [
                ("a_link", cr["a_link"], "row on the link twist (J_s row = -a_link J_k)"),
                ("g_obj", cr["g_obj"], "G^T row on the object twist"),
                ("adot_v", sp.Matrix([cr["adot_v"]]), "Adot v of the row (eq. 13)"),
                ("gap", sp.Matrix([cr["gap"]]), "normal gap"),
                ("s", sp.Matrix([cr["s"]]), "contact position along the link from its rear end"),
            ],
            equation="(8)-(13)",
        )
    )
    wr = wheel_row_local()
    functions.append(
        _fn(
            "wheel_row_local",
            "Lateral (non-holonomic) passive-wheel row of one link.",
            [
                ("link_pose", C.link_pose, "(x, y, phi) of the link COM"),
                ("link_twist", C.link_twist, "(v_x, v_y, omega) of the link COM"),
                ("link_bias", C.link_bias, "Jdot qdot of the link"),
                ("wheel_offset", (C.wheel_offset,), "wheel position from the COM along the link"),
            ],
            [
                ("a_w", wr["a_w"], "row on the link twist (A row = a_w J_i)"),
                ("adot_v", sp.Matrix([wr["adot_v"]]), "Adot v of the row (eq. 13)"),
            ],
            equation="(8)-(13)",
        )
    )

    spec = ModelSpec(
        n_joints=n_joints,
        prefix=spec_prefix,
        functions=tuple(functions),
        meta={
            "n_links": nl,
            "n_coordinates": s.n_coordinates,
            "n_parameters": len(s.parameters),
            "mass_matrix_form": form,
            "mass_matrix_operation_counts": counts,
            "mass_matrix_operation_counts_casadi": counts_casadi,
        },
    )
    return ModelDerivation(symbols=s, spec=spec)
