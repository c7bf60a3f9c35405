"""The Python side of the optimal-torque queries in C (``optimal.c``, ``wheel_states.c``,
``maps.c``, ``qp.c``): one compiled call answers a batch of configurations
(:meth:`OptimalKernel.solve`), every objective and input region; and the building blocks
alone (the QP and QCQP solver, the KKT certificate, the symmetric eigensolver, the maps of a
row state) for tests against independent references.

The query and the answers are flat float64 vectors laid out by
:meth:`snakecg.engine.Layout.optimal_in_fields` and :meth:`~snakecg.engine.Layout.optimal_out_fields`
(the same names in ``snakecg_layout.h``); the codes below mirror ``engine.h``.
"""

from __future__ import annotations


import numpy as np

from .layout import Layout
from .threads import pool, threads

__all__ = ["OptimalKernel", "MAX_SR", "LEAST_SLIP_PUSH", "STRONGEST_PUSH", "KINDS",
           "OPTIMAL", "INFEASIBLE", "FAILED", "REASON", "CHECK", "CERTIFICATE", "METHOD",
           "BIND_CONTACT", "BIND_ELLIPSOID", "BIND_NORMAL", "BIND_JOINT", "QP_STATUS"]

#: Query kinds (``OPT_IN_kind``).
MAX_SR, LEAST_SLIP_PUSH, STRONGEST_PUSH = 0, 1, 2
KINDS = {"max_sr": MAX_SR, "least_slip_push": LEAST_SLIP_PUSH,
         "strongest_push": STRONGEST_PUSH}
#: Statuses (``OPT_OUT_status``).
OPTIMAL, INFEASIBLE, FAILED = 0, 1, 2
#: Reasons (``OPT_OUT_reason``), engine.h's SC_REASON_*.
REASON = {"none": 0, "singular": 1, "no_push": 2, "off_normal": 3, "against_normal": 4,
          "direction": 5, "out_of_reach": 6, "no_strong_push": 7, "solver": 8,
          "within_reach": 9, "certificate": 10, "forward_check": 11, "not_finite": 12,
          "no_answer": 13, "unanswerable": 14}
#: Forward checks (``OPT_OUT_check``), SC_CHECK_*.
CHECK = {"passed": 0, "pending": -1, "tau_max": 1, "ellipsoid": 2, "separates": 3,
         "slides": 4, "objective": 5, "a_obj": 6, "a_min": 7}
#: Certificate kinds (``OPT_OUT_certificate``), SC_CERT_*.
CERTIFICATE = {0: "none", 1: "kkt (convex QP)", 2: "kkt (LP)", 3: "kkt (convex QCQP)",
               4: "generalized eigenproblem", 5: "kkt of the winning wheel state"}
#: Method flags (``OPT_OUT_method``), SC_METHOD_*.
METHOD = {"rank_one": 1, "eigen": 2, "qp": 4, "lp": 8, "secular": 16,
          "closed_ellipsoid": 32, "tie_break": 64, "diagnosis": 128, "states": 256,
          "scale": 512}
#: Binding codes (``OPT_OUT_binding``): then joint j (from 0) at BIND_JOINT + j and the wheel
#: of link i (from 1) at BIND_JOINT + n_a + i - 1.
BIND_CONTACT, BIND_ELLIPSOID, BIND_NORMAL, BIND_JOINT = 0, 1, 2, 3
#: The QP block's statuses (engine.h SC_QP_*).
QP_STATUS = {0: "optimal", 1: "the linear limits have no common point",
             2: "the Hessian is not positive definite", 3: "no convergence",
             4: "the ellipsoid and the linear limits do not intersect",
             5: "the problem is too large"}

#: Configurations per thread below which a batch is not split (SNAKECG_THREADS set above 1).
PARALLEL_MIN = 1024


def _workers(n: int) -> int:
    """Threads for a batch of ``n`` configurations: one, unless ``SNAKECG_THREADS`` asks for
    more and each of them gets ``PARALLEL_MIN`` configurations at least. A configuration takes
    a few microseconds, so the split pays only with cores to spare, which a shared machine
    rarely has: on the 2-core machine of docs/reference/performance.md, shared with other work, two
    threads never ran faster than one (16,000 configurations: 4.6 us per configuration
    either way; the second core was busy), so one thread is the default."""
    return threads(n, PARALLEL_MIN)


def _ptr(a):
    return None if a is None else a.ctypes.data


class OptimalKernel:
    """The optimal-torque entry points of one compiled model library."""

    def __init__(self, lib, layout: Layout):
        self.layout = layout
        self.in_width = layout._offsets(layout.optimal_in_fields())[1]
        self.out_width = layout._offsets(layout.optimal_out_fields())[1]
        self.IN = layout.optimal_in
        self.OUT = layout.optimal_out
        self._solve = lib.entry("core_optimal")
        self._check = lib.entry("core_optimal_check")
        self._qp = lib.entry("core_qp_solve")
        self._kkt = lib.entry("core_kkt_certificate")
        self._eigen = lib.entry("core_eigen_symmetric")
        self._maps = lib.entry("core_state_maps")

    # the query -----------------------------------------------------------------------------
    def solve(self, model, query_in: np.ndarray, qa: np.ndarray) -> np.ndarray:
        """The answers ``(N, width)`` of the query vector ``query_in`` at the configurations
        ``qa`` (C-contiguous float64 ``(N, n_s)``): one C call, split across the shared
        threads only when asked (:func:`_workers`; each configuration is answered alone, so
        the split does not change a bit)."""
        n = qa.shape[0]
        out = np.empty((n, self.out_width))
        args = (model.scene_address, model.core.constants_address, model.max_iter,
                query_in.ctypes.data)
        workers = _workers(n)
        if workers == 1:
            status = self._solve(n, *args, qa.ctypes.data, out.ctypes.data)
        else:
            bounds = np.linspace(0, n, workers + 1).astype(np.int64)
            qp, op = qa.ctypes.data, out.ctypes.data
            ns, w = qa.shape[1], self.out_width
            jobs = [(int(lo), int(hi)) for lo, hi in zip(bounds[:-1], bounds[1:]) if hi > lo]
            status = min(pool().map(
                lambda j: self._solve(j[1] - j[0], *args, qp + 8 * ns * j[0], op + 8 * w * j[0]),
                jobs))
        if status != 0:
            raise MemoryError("the optimal-torque query could not allocate its workspace")
        return out

    def check(self, query_in: np.ndarray, out: np.ndarray) -> None:
        """The forward check of the answers whose forward row was left to the reference path
        (now in place in ``out``)."""
        self._check(out.shape[0], query_in.ctypes.data, out.ctypes.data)

    # the building blocks alone, for tests ---------------------------------------------------
    def qp(self, H, g, A, lo, hi, *, N=None, rho2=0.0, mu0=1.0):
        """``min 1/2 x^T H x + g^T x`` s.t. ``lo <= A x <= hi`` (and ``x^T N x <= rho2`` when
        ``N`` is given: the ellipsoid's multiplier, for a problem whose optimum without it lies
        outside): ``(status, x, lam, info)`` with the rows' signed multipliers and ``info`` =
        (active rows, QP solves or active-set changes, Newton steps, mu)."""
        H, g, A, lo, hi = (np.ascontiguousarray(a, dtype=float) for a in (H, g, A, lo, hi))
        n = g.size
        A = A.reshape(-1, n)
        m = A.shape[0]
        Nc = None if N is None else np.ascontiguousarray(N, dtype=float)
        x, lam, info = np.zeros(n), np.zeros(m), np.zeros(4)
        st = self._qp(n, m, H.ctypes.data, g.ctypes.data, A.ctypes.data, lo.ctypes.data,
                      hi.ctypes.data, _ptr(Nc), float(rho2), float(mu0), x.ctypes.data,
                      lam.ctypes.data, info.ctypes.data)
        return st, x, lam, info

    def kkt_certificate(self, x, H, c, G, lo, hi, *, Q=None, r2=0.0, convex=True,
                        active=1e-7, stationarity_tol=1e-7):
        """qp.c's certificate of ``x``: ``(values, lam, mu)``, values = (stationarity,
        primal feasibility, complementarity, duality gap or NaN)."""
        x, c, G, lo, hi = (np.ascontiguousarray(a, dtype=float) for a in (x, c, G, lo, hi))
        n = x.size
        G = G.reshape(-1, n)
        m = G.shape[0]
        Hc = None if H is None else np.ascontiguousarray(H, dtype=float)
        Qc = None if Q is None else np.ascontiguousarray(Q, dtype=float)
        values, lam, mu = np.zeros(4), np.zeros(m), np.zeros(1)
        self._kkt(n, x.ctypes.data, _ptr(Hc), c.ctypes.data, m, G.ctypes.data, lo.ctypes.data,
                  hi.ctypes.data, _ptr(Qc), float(r2), int(convex), active, stationarity_tol,
                  values.ctypes.data, lam.ctypes.data, mu.ctypes.data)
        return values, lam, float(mu[0])

    def eigen_symmetric(self, S):
        """Eigenvalues (ascending) and eigenvectors (columns) of a symmetric matrix."""
        A = np.array(S, dtype=float, order="C")
        n = A.shape[0]
        w, V = np.zeros(n), np.zeros((n, n))
        self._eigen(n, A.ctypes.data, w.ctypes.data, V.ctypes.data)
        return w, V

    def state_maps(self, model, q, state):
        """maps.c's maps at ``q`` for the row states ``state`` (solver codes): ``(code, maps)``
        with ``L``, ``l0``, ``W``, ``w0``, ``Q``, ``q0``, ``A``, ``a0``, ``Xi_h``, ``Omega``,
        ``N``, ``pivot_ratio``; code 0 when defined."""
        na, nc, ns = model.n_joints, model.n_constraints, model.n_coordinates
        q = np.ascontiguousarray(q, dtype=float)
        st = np.ascontiguousarray(state, dtype=float)
        shapes = (("L", (nc, na)), ("l0", (nc,)), ("W", (nc, na)), ("w0", (nc,)),
                  ("Q", (ns, na)), ("q0", (ns,)), ("A", (3, na)), ("a0", (3,)),
                  ("Xi_h", (na + 1, na + 1)), ("Omega", (na, na)), ("N", (na, na)))
        buf = np.zeros(sum(int(np.prod(s)) for _, s in shapes) + 1)
        code = self._maps(model.scene_address, q.ctypes.data, st.ctypes.data, buf.ctypes.data)
        out, k = {}, 0
        for name, shape in shapes:
            size = int(np.prod(shape))
            out[name] = buf[k:k + size].reshape(shape)
            k += size
        out["pivot_ratio"] = float(buf[k])
        return int(code), out
