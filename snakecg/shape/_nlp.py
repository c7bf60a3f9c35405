"""The shape problem as a CasADi NLP: the generated functions composed symbolically, IPOPT.

Decision variables ``x = (q_1..q_na [, tau] [, slabs])``; parameters ``p`` (see
:data:`P_LAYOUT`): the fixed pose, the objective's scale and the task. Two forms:

* ``reduced`` (no torque variable): the inner problem over the torque has a closed form.
  ``max_sr``: with every row held, ``Omega = k c c^T`` (a point contact pushes along its
  normal: ``a_obj = a_dir lam_c``, ``lam_c = c tau``), so the top generalized eigenvalue of
  ``(Omega, Omega + Xi)`` is ``k sigma / (1 + k sigma)`` with ``sigma = c Xi^+ c^T``; with
  wheels ``Xi`` is singular (torques that only load the wheels move nothing), so
  ``sigma_eps = c (Xi + eps N)^-1 c^T`` is maximised (``eps`` relative, :data:`SR_EPS`) and
  the value is re-evaluated exactly at the answer. ``max_a_obj`` and ``strongest_push`` on
  the ellipsoid alone: ``r^2 k c N^-1 c^T`` and ``r gamma sqrt(c N^-1 c^T)``.
  ``least_slip_push`` (``d . a_obj >= a_min``) when no limit binds: ``a_min^2 / (gamma^2
  sigma_eps)`` with ``gamma = d . a_dir``.
* ``joint`` (torque variable): wheel friction bounds, torque boxes and ``least_slip_push``.

Geometric constraints are exact smooth reformulations: two convex sets (two link segments, or
a segment and the plate) are at least ``c`` apart iff a slab of width ``c`` separates them,
``n . v <= b - c/2`` for the vertices of one and ``n . v >= b + c/2`` for the other, with
``n = (cos alpha, sin alpha)``; ``(alpha, b)`` are decision variables per pair.
"""

from __future__ import annotations

import contextlib
import io
import math

import numpy as np

#: Relative Tikhonov weight of ``N`` in ``Xi + eps N`` (max_sr and least_slip_push).
SR_EPS = 1e-12
#: Relative back-off from the friction bounds (as :mod:`snakecg.optimize`).
FRICTION_MARGIN = 1e-7
#: Layout of the parameter vector: pose (3), objective scale, direction (3), a_min,
#: a_obj (3), radius, clearance.
P_LAYOUT = {"pose": slice(0, 3), "scale": 3, "direction": slice(4, 7), "a_min": 7,
            "a_obj": slice(8, 11), "radius": 11, "clearance": 12}
N_P = 13

IPOPT_OPTIONS = {
    "print_time": False, "error_on_fail": False, "show_eval_warnings": False,
    "ipopt.print_level": 0, "ipopt.sb": "yes", "ipopt.tol": 1e-10,
    "ipopt.acceptable_tol": 1e-8, "ipopt.acceptable_iter": 5, "ipopt.max_iter": 300,
    "ipopt.mu_strategy": "adaptive", "ipopt.bound_relax_factor": 0.0,
}

#: With the separating slabs: a monotone barrier from a small initial value (the adaptive
#: strategy takes long steps in the slab angles and ends in local infeasibility).
IPOPT_GEOMETRY_OPTIONS = {"ipopt.mu_strategy": "monotone", "ipopt.mu_init": 1e-3}



def generated_function(model, name: str):
    """The generated CasADi function ``name`` of ``model`` and its fixed inputs.

    The one place where this package reaches into the generated layer (CasADi's own
    deserialized functions, evaluated symbolically): it returns ``(function, fixed)`` where
    ``fixed`` maps the names of the inputs that are not configuration-dependent to the values
    :class:`~snakecg.SceneModel` passes (parameter vector ``K``, contact link one-hot, side,
    object mass and inertia, wheel offsets, contact offset and object distance, the held-row
    mask ``free`` of "every row held", no fixed forces, no regularization, at rest): the
    public :meth:`~snakecg.SceneModel.casadi_function` and
    :meth:`~snakecg.SceneModel.function_inputs`.
    """
    fn = model.casadi_function(name)
    fixed = model.function_inputs(name)  # the values the runtime passes, by input name
    return fn, fixed


def _call(model, name, **var):
    fn, fixed = generated_function(model, name)
    return fn.call({**fixed, **var})


def chol_quad(A, b):
    """``b A^-1 b^T`` for a symmetric positive definite ``A`` (SX or MX), by a Cholesky
    factorization written out (stable without pivoting, unlike a general symbolic solve)."""
    import casadi as ca

    zero = type(A)(0)
    n = A.shape[0]
    L = [[None] * n for _ in range(n)]
    for j in range(n):
        # the floor only guards rounding at trial points far from the data (never active
        # for a positive definite A in exact arithmetic)
        d = A[j, j] - sum((L[j][k] ** 2 for k in range(j)), zero)
        L[j][j] = ca.sqrt(ca.fmax(d, 1e-300 + 1e-15 * ca.fabs(A[j, j])))
        for i in range(j + 1, n):
            L[i][j] = (A[i, j] - sum((L[i][k] * L[j][k] for k in range(j)), zero)) / L[j][j]
    y = []
    for i in range(n):
        y.append((b[i] - sum((L[i][k] * y[k] for k in range(i)), zero)) / L[i][i])
    return sum((yi ** 2 for yi in y), zero)


def symbol_class(model, names):
    """``casadi.SX``, or ``casadi.MX`` where one of the generated functions ``names`` keeps
    its matrices (the ``mx`` algebra of the larger models: their linear solves, CasADi's
    ``ldl``, cannot be evaluated on SX arguments)."""
    import casadi as ca

    mx = any(model.casadi_function(n).is_a("MXFunction") for n in names)
    return ca.MX if mx else ca.SX


def geometry_pairs(model):
    """``[(kind, i, j)]``: non-adjacent link pairs (``"links"``) and link/object pairs
    (``"object"``, every link but the contacting one), 0-based link indices."""
    nl = model.n_links
    out = [("links", i, j) for i in range(nl) for j in range(i + 2, nl)]
    k = model.scene.contact_link - 1
    out += [("object", i, -1) for i in range(nl) if i != k]
    return out


class Problem:
    """One built NLP (solver, KKT helper functions, row names); reused for every query with
    the same structure."""

    def __init__(self, model, objective: str, form: str, *, feasible: bool, box: bool,
                 ellipsoid: bool, task: str | None):
        import casadi as ca

        from ..geometry import OBJECT_SIDE

        self.objective, self.form, self.feasible = objective, form, feasible
        na, nl = model.n_joints, model.n_links
        self.na = na
        need_maps = form == "joint" or objective in ("strongest_push", "least_slip_push")
        self.pairs = geometry_pairs(model) if feasible else []
        S = symbol_class(model, ["place_object", "interaction_maps" if need_maps else
                                 "metric_forms"] + (["link_poses"] if self.pairs else []))
        qj = S.sym("q_joints", na)
        p = S.sym("p", N_P)
        q = ca.vertcat(p[P_LAYOUT["pose"]], qj)
        place = _call(model, "place_object", q=q)
        wheels = [i for i in range(1, model.n_constraints)
                  if model.present[i] and math.isfinite(model.bounds[i])]
        if need_maps:
            m = _call(model, "interaction_maps", q=q, q_obj=place["q_obj"], rho=place["rho"])
            Lm = m["lam_from_tau"]
            c = Lm[0, :]
        else:
            m = _call(model, "metric_forms", q=q, q_obj=place["q_obj"], rho=place["rho"])
            c = m["contact_from_tau"]
        Om, Xi, N = m["omega_tau"], m["xi_tau"], m["input_metric"]
        cc = ca.mtimes(c, c.T)
        k = ca.trace(Om) / cc  # Omega = k c^T c (eq. 29 with a_obj = a_dir lam_c)
        gamma = None
        if need_maps:
            a_dir = ca.mtimes(m["a_obj_from_tau"], c.T) / cc
            d = p[P_LAYOUT["direction"]]
            # a zero direction parameter means "along a_dir" (strongest_push's default)
            dn = ca.dot(d, d)
            gamma = ca.if_else(dn > 0, ca.dot(d, a_dir), ca.sqrt(ca.dot(a_dir, a_dir)))
        scale = p[P_LAYOUT["scale"]]
        r = p[P_LAYOUT["radius"]]
        xs = [qj]
        g, lbg, ubg, names = [], [], [], []
        self.has_tau = form == "joint"
        tau = None
        if self.has_tau:
            tau = S.sym("tau", na)
            xs.append(tau)
        eps_xi = SR_EPS * ca.trace(Xi) / ca.trace(N)
        if form == "reduced":
            if objective == "max_sr":
                value = k * chol_quad(Xi + eps_xi * N, c)  # k sigma; sr = k sigma/(1+k sigma)
            elif objective == "max_a_obj":
                value = r * ca.sqrt(k * chol_quad(N, c))  # sqrt(norm_a_obj)
            elif objective == "strongest_push":
                value = r * gamma * ca.sqrt(chol_quad(N, c))
            else:  # least_slip_push, d . a_obj >= a_min: a_min^2 / value^2 is ||qdd||^2
                value = gamma * ca.sqrt(chol_quad(Xi + eps_xi * N, c))
            f = -value / scale
        else:
            lam_c = ca.mtimes(c, tau)
            if objective == "max_a_obj":
                value = ca.sqrt(k) * lam_c  # sqrt(norm_a_obj) on lam_c >= 0
                f = -value / scale
            elif objective == "strongest_push":
                value = gamma * lam_c
                f = -value / scale
            else:  # least_slip_push
                value = ca.bilin(Xi + eps_xi * N, tau, tau)
                f = value / scale
            g.append(lam_c)
            lbg.append(0.0)
            ubg.append(np.inf)
            names.append("contact would separate")
            if ellipsoid:
                g.append(ca.bilin(N, tau, tau) / (r * r))
                lbg.append(-np.inf)
                ubg.append(1.0)
                names.append("input ellipsoid (eq. 31)")
            for i in wheels:
                u = model.bounds[i] * (1 - FRICTION_MARGIN)
                g.append(ca.mtimes(Lm[i, :], tau) / u)
                lbg.append(-1.0)
                ubg.append(1.0)
                names.append(f"friction bound of the wheel on link {i}")
            if objective == "least_slip_push":
                if task == "a_obj":
                    a_t = p[P_LAYOUT["a_obj"]]
                    res = ca.mtimes(m["a_obj_from_tau"], tau) - a_t
                    for j in range(3):
                        g.append(res[j])
                        lbg.append(0.0)
                        ubg.append(0.0)
                        names.append(f"required object acceleration (component {j + 1})")
                else:
                    a_min = p[P_LAYOUT["a_min"]]
                    g.append(gamma * lam_c - a_min)
                    lbg.append(0.0)
                    ubg.append(np.inf)
                    names.append("required push (d . a_obj >= a_min)")
        # geometry: separating slabs
        if self.pairs:
            poses = _call(model, "link_poses", q=q)["poses"]  # (3, n_l)
            rob = model.robot
            ends = []
            for i in range(nl):
                e = ca.vertcat(ca.cos(poses[2, i]), ca.sin(poses[2, i]))
                rear = poses[:2, i] - rob.com[i] * e
                ends.append((rear, rear + rob.length[i] * e))
            qo = place["q_obj"]
            h = OBJECT_SIDE / 2
            R = ca.vertcat(ca.horzcat(ca.cos(qo[2]), -ca.sin(qo[2])),
                           ca.horzcat(ca.sin(qo[2]), ca.cos(qo[2])))
            corners = [qo[:2] + ca.mtimes(R, ca.DM([sx * h, sy * h]))
                       for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
            slab = S.sym("slab", 2 * len(self.pairs))
            xs.append(slab)
            clear = p[P_LAYOUT["clearance"]]
            lref = float(np.mean(rob.length))
            for n_, (kind, i, j) in enumerate(self.pairs):
                al, b = slab[2 * n_], slab[2 * n_ + 1]
                nv = ca.vertcat(ca.cos(al), ca.sin(al))
                if kind == "links":
                    A, B, half = ends[i], ends[j], clear / 2
                    what = f"clearance between links {i + 1} and {j + 1}"
                else:
                    A, B, half = ends[i], corners, 0.0
                    what = f"link {i + 1} touching the object"
                for v in A:
                    g.append((b - half - ca.dot(nv, v)) / lref)
                    lbg.append(0.0)
                    ubg.append(np.inf)
                    names.append(what)
                for v in B:
                    g.append((ca.dot(nv, v) - b - half) / lref)
                    lbg.append(0.0)
                    ubg.append(np.inf)
                    names.append(what)
        x = ca.vertcat(*xs)
        G = ca.vertcat(*g) if g else S(0, 1)
        self.nx = x.shape[0]
        self.lbg, self.ubg, self.names = np.array(lbg, float), np.array(ubg, float), names
        nlp = {"x": x, "p": p, "f": f, "g": G}
        opts = dict(IPOPT_OPTIONS, **(IPOPT_GEOMETRY_OPTIONS if self.pairs else {}))
        self.solver = ca.nlpsol(f"shape_{objective}_{form}", "ipopt", nlp, opts)
        lam_g = S.sym("lam_g", G.shape[0])
        grad = ca.gradient(f, x) + (ca.mtimes(ca.jacobian(G, x).T, lam_g) if g else 0)
        self.kkt = ca.Function("kkt", [x, p, lam_g], [grad, G, f])
        self.value_fn = ca.Function("value", [x, p], [value])

    def solve(self, x0, p, lbx, ubx):
        """One IPOPT run: ``(x, lam_g, lam_x, status, iterations)``."""
        with contextlib.redirect_stdout(io.StringIO()):
            r = self.solver(x0=x0, p=p, lbx=lbx, ubx=ubx, lbg=self.lbg, ubg=self.ubg)
        st = self.solver.stats()
        return (np.asarray(r["x"]).ravel(), np.asarray(r["lam_g"]).ravel(),
                np.asarray(r["lam_x"]).ravel(), str(st["return_status"]),
                int(st.get("iter_count", 0)))

    def certificate(self, x, p, lam_g, lam_x, lbx, ubx, tol=1e-7):
        """KKT residuals of the solved NLP at ``x`` and the names of the active constraints.

        Stationarity ``||grad f + J_g^T lam_g + lam_x||_inf``; primal infeasibility (rows and
        bounds); complementarity ``max |lam_i| * slack_i`` over the inequalities.
        """
        grad, G, _ = self.kkt(x, p, lam_g)
        grad, G = np.asarray(grad).ravel(), np.asarray(G).ravel()
        stat = float(np.max(np.abs(grad + lam_x))) if grad.size else 0.0
        viol = np.concatenate([np.maximum(self.lbg - G, 0), np.maximum(G - self.ubg, 0),
                               np.maximum(lbx - x, 0), np.maximum(x - ubx, 0), [0.0]])
        lo, up = G - self.lbg, self.ubg - G
        comp = np.where(lam_g < 0, -lam_g * np.where(np.isfinite(lo), lo, 0), 0.0)
        comp = np.maximum(comp, np.where(lam_g > 0, lam_g * np.where(np.isfinite(up), up, 0),
                                         0.0))
        eq = self.lbg == self.ubg
        comp[eq] = 0.0
        xlo, xup = x - lbx, ubx - x
        compx = np.maximum(np.where(lam_x < 0, -lam_x * np.where(np.isfinite(xlo), xlo, 0), 0),
                           np.where(lam_x > 0, lam_x * np.where(np.isfinite(xup), xup, 0), 0))
        active = [nm for nm, a, b, e in zip(self.names, lo, up, eq)
                  if not e and (abs(a) <= tol or abs(b) <= tol)]
        for j in range(self.na):
            if abs(x[j] - lbx[j]) <= tol:
                active.append(f"lower joint limit on joint {j + 1}")
            if abs(ubx[j] - x[j]) <= tol:
                active.append(f"upper joint limit on joint {j + 1}")
        return {
            "stationarity": stat,
            "primal_infeasibility": float(np.max(viol)),
            "complementarity": float(max(np.max(comp, initial=0.0), np.max(compx, initial=0.0))),
            "active": tuple(dict.fromkeys(active)),
        }

    def value(self, x, p) -> float:
        return float(self.value_fn(x, p))
