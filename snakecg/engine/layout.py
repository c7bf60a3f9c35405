"""The layout shared by the runtime core's C (``forward.c``, ``integrate.c``) and its Python
side.

Everything the C reads or writes by position is named here once: the scene's constant
inputs (one flat vector per scene), the per-sample inputs, and the columns of one output row.
:func:`header` writes them, with the generated functions' symbols and the index of each of
their inputs and outputs (read from the model's manifest), as ``snakecg_layout.h``; the C uses
only these names.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..errors import ArtifactError

__all__ = ["Layout", "header", "INPUTS", "FUNCTIONS"]

#: Per-sample inputs of ``core_forward``, in the order of its ``in`` pointer array.
INPUTS = ("q", "v", "tau", "q_obj", "v_obj", "f_obj", "rho")

#: The generated functions the core calls, with the short name of their macros, and the
#: inputs and outputs it passes by name (checked against the manifest before compiling).
FUNCTIONS = {
    "contact_system": ("CS", (
        "q", "v", "tau", "q_obj", "v_obj", "f_obj", "K", "contact_link", "side", "object_mass",
        "object_inertia", "rho", "wheel_offset", "contact_offset", "object_distance", "placed"), (
        "M", "delassus", "b", "qdd_free", "a_obj_free", "qdd_from_lam", "a_obj_from_lam", "gap",
        "s")),
    # the same at rest (v = 0, v_obj = 0), for every sample whose velocities are zero
    "contact_system_at_rest": ("CR", (
        "q", "tau", "q_obj", "f_obj", "K", "contact_link", "side", "object_mass",
        "object_inertia", "rho", "wheel_offset", "contact_offset", "object_distance", "placed"), (
        "M", "delassus", "b", "qdd_free", "a_obj_free", "qdd_from_lam", "a_obj_from_lam", "gap",
        "s")),
    # integrate.c: the rows' velocities A V of the simulation's right-hand side
    "link_jacobians": ("LJ", ("q", "K"), ("J",)),
}

#: The generated functions a planar model's general-scene forward and time step call
#: (scene_rows.c, scene_step.c):
#: defined for a planar model (a spatial model's have other outputs, and its contact library
#: compiles no scene_rows.c).
SCENE_FUNCTIONS = {
    "link_poses": ("LP", ("q", "K"), ("poses",)),
    # scene_step.c: a time step's generalized force (at a state whose rows it has not: the
    # run's first step, or a state set by the caller), and the same from the links' cosines
    # and sines that the rows at the state took (scene_rows.h)
    "bias_forces": ("BF", ("q", "v", "K"), ("h",)),
    "bias_forces_cs": ("BC", ("cs", "q", "v", "K"), ("h",)),
    # scene_rows.c: poses, Jacobians, M_s and the links' cosines and sines in one call (the
    # joints' sines taken once)
    "scene_kinematics": ("SK", ("q", "K"), ("poses", "J", "M", "cs")),
}

_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


@dataclass(frozen=True)
class Layout:
    """Offsets of the scene vector and of an output row for one model's sizes."""

    n_joints: int
    n_coordinates: int
    n_links: int
    n_constraints: int
    n_parameters: int
    #: a spatial scene's: bounds that follow the solved forces and the rows of the norm
    #: (snakecg/spatial/analysis.py)
    spatial: bool = False

    def scene_fields(self) -> tuple[tuple[str, int], ...]:
        nl, nc = self.n_links, self.n_constraints
        spatial = (("friction", nc), ("normal_row", nc), ("in_norm", nc)) if self.spatial else ()
        return (("K", self.n_parameters), ("contact_link", nl), ("side", 1),
                ("object_mass", 1), ("object_inertia", 1), ("wheel_offset", nl),
                ("contact_offset", 1), ("object_distance", 1), ("present", nc),
                ("bounds", nc)) + spatial

    def out_fields(self) -> tuple[tuple[str, int], ...]:
        """Columns of one output row: the :class:`~snakecg.ForwardResult` fields, the row
        states (solver codes) and the sample's status (0 exact, else the code of snakecg.rows.REASONS)."""
        nc = self.n_constraints
        return (("tau", self.n_joints), ("qdd", self.n_coordinates), ("a_obj", 3), ("lam", nc),
                ("w", nc), ("norm_lambda", 1), ("norm_a_obj", 1), ("norm_qdd", 1), ("sr", 1),
                ("gap", 1), ("conditioning", 1), ("singular", 1), ("state", nc), ("status", 1))

    def optimal_in_fields(self) -> tuple[tuple[str, int], ...]:
        """The input vector of the optimal-torque query (``optimal.c``): the settings
        (:mod:`snakecg.optimize.result`'s constants), then the query, NaN where it has no
        such value (``radius``, ``tau_max``, ``direction``, ``a_min``, ``a_obj``)."""
        return (("friction_margin", 1), ("check_tol", 1), ("sr_tie", 1), ("hessian_reg", 1),
                ("lp_reg", 1), ("active_tol", 1), ("tol_stationarity", 1), ("tol_primal", 1),
                ("tol_complementarity", 1), ("tol_gap", 1), ("kind", 1), ("radius", 1),
                ("tau_max", self.n_joints), ("direction", 3), ("a_min", 1), ("a_obj", 3),
                ("slide", self.n_constraints))

    def optimal_out_fields(self) -> tuple[tuple[str, int], ...]:
        """One configuration's answer in ``optimal.c``'s output (codes in
        :mod:`snakecg.engine.optimal`), ending with the forward solve's row at the answer."""
        na, nc = self.n_joints, self.n_constraints
        return (("status", 1), ("reason", 1), ("detail", 8), ("objective_value", 1),
                ("expected", 1), ("tau", na), ("n_binding", 1), ("binding", 3 + na + nc),
                ("certificate", 1), ("certified", 1), ("stationarity", 1),
                ("primal_feasibility", 1), ("complementarity", 1), ("duality_gap", 1),
                ("resolved", 1), ("method", 1), ("qp_solves", 1), ("newton_steps", 1),
                ("states", 1), ("states_solved", 1), ("wheel_states", nc), ("a_dir", 3),
                ("k", 1), ("gain", 1), ("form", 1), ("check", 1), ("check_detail", 3),
                ("forward_status", 1), ("forward", self.out_width))

    @property
    def optimal_in(self) -> dict[str, tuple[int, int]]:
        return self._offsets(self.optimal_in_fields())[0]

    @property
    def optimal_out(self) -> dict[str, tuple[int, int]]:
        return self._offsets(self.optimal_out_fields())[0]

    @staticmethod
    def _offsets(fields):
        out, k = {}, 0
        for name, size in fields:
            out[name] = (k, size)
            k += size
        return out, k

    @property
    def scene(self) -> dict[str, tuple[int, int]]:
        return self._offsets(self.scene_fields())[0]

    @property
    def scene_width(self) -> int:
        return self._offsets(self.scene_fields())[1]

    @property
    def out(self) -> dict[str, tuple[int, int]]:
        return self._offsets(self.out_fields())[0]

    @property
    def out_width(self) -> int:
        return self._offsets(self.out_fields())[1]

    @classmethod
    def of(cls, manifest: dict) -> "Layout":
        return cls(int(manifest["n_joints"]), int(manifest["n_coordinates"]),
                   int(manifest["n_links"]), int(manifest["n_constraints"]),
                   int(manifest["n_parameters"]), manifest.get("kind") == "spatial")


def _ident(what: str, name) -> str:
    if not isinstance(name, str) or not _IDENT.match(name):
        raise ArtifactError(f"the model's manifest names {what} {name!r:.80}, which is not a C "
                            "identifier; the model folder is damaged (reinstall snakecg or "
                            "delete the snakecg cache folder)")
    return name


def header(manifest: dict) -> str:
    """``snakecg_layout.h`` for a model: sizes, symbols, and every index by name."""
    lay = Layout.of(manifest)
    sigs = {s["name"]: s for s in manifest["functions"]}
    lines = ["/* snakecg_layout.h: written by the snakecg runtime from the model's manifest",
             " * (snakecg/engine/layout.py) for the runtime core's C files (snakecg/engine). */",
             "#ifndef SNAKECG_LAYOUT_H", "#define SNAKECG_LAYOUT_H",
             f"#define SNAKECG_PREFIX {_ident('the prefix', manifest['prefix'])}",
             "/* SNAKECG_EXPORT(name): the core's exported symbol, the model's prefix first */",
             "#define SNAKECG_CAT_(a, b) a##b", "#define SNAKECG_CAT(a, b) SNAKECG_CAT_(a, b)",
             "#define SNAKECG_EXPORT(name) SNAKECG_CAT(SNAKECG_PREFIX, name)",
             f"#define SNAKECG_NA {lay.n_joints}", f"#define SNAKECG_NS {lay.n_coordinates}",
             f"#define SNAKECG_NL {lay.n_links}", f"#define SNAKECG_NC {lay.n_constraints}"]
    # q's entries: a spatial model's n_q (its base a position and a quaternion), else n_s
    lines.append(f"#define SNAKECG_NQ {int(manifest.get('nq', lay.n_coordinates))}")
    scene = {} if lay.spatial or not set(SCENE_FUNCTIONS) <= set(sigs) else SCENE_FUNCTIONS
    for fname, (short, ins, outs) in {**FUNCTIONS, **scene}.items():
        sig = sigs.get(fname)
        if sig is None:
            raise ArtifactError(f"the model has no generated function {fname!r}, which the "
                                "runtime core needs; the model folder is damaged")
        symbol = _ident(f"the symbol of {fname}", sig["symbol"])
        lines += [f"#define SNAKECG_{short} {symbol}",
                  f"#define SNAKECG_{short}_WORK {symbol}_work"]
        for kind, wanted, items in (("IN", ins, sig["inputs"]), ("OUT", outs, sig["outputs"])):
            index = {_ident(f"an argument of {fname}", it["name"]): k for k, it in enumerate(items)}
            missing = [w for w in wanted if w not in index]
            if missing:
                raise ArtifactError(f"{fname} of the model has no {kind.lower()}put "
                                    f"{', '.join(missing)}, which the runtime core needs")
            lines += [f"#define {short}_{kind}_{name} {index[name]}" for name in wanted]
    for k, name in enumerate(INPUTS):
        lines.append(f"#define IN_{name} {k}")
    for name, (off, _) in lay.scene.items():
        lines.append(f"#define SCENE_{name} {off}")
    for name, (off, _) in lay.out.items():
        lines.append(f"#define OUT_{name} {off}")
    lines.append(f"#define OUT_WIDTH {lay.out_width}")
    for prefix, fields in (("OPT_IN", lay.optimal_in_fields()),
                           ("OPT_OUT", lay.optimal_out_fields())):
        offsets, width = lay._offsets(fields)
        lines += [f"#define {prefix}_{name} {off}" for name, (off, _) in offsets.items()]
        lines.append(f"#define {prefix}_WIDTH {width}")
    lines += ["#endif", ""]
    return "\n".join(lines)
