"""The buffers and C structs of the compiled simulation of one model (a :class:`Workspace`):
what the C of ``integrate.c``, ``events.c`` and ``run.c`` reads and writes, set up once per
model and lent to one run at a time.

A run takes a workspace with :func:`take` (from the model's pool, or a new one) and gives it
back with :func:`give` when it is done; two runs at the same time (threads) hold two
workspaces, so nothing is shared between them. The pool is the model's data's
(``model.data().simulation_pool``, :mod:`snakecg.engine.data`): the run that holds a
workspace keeps its model, and so the scene vector whose address the structs store, alive.
"""

from __future__ import annotations


import numpy as np

from ..engine.binding import Run, Segment, Settle, address, int64s
from ..solver import PIVOT_TOL, REGULARIZATION, REL_TOL, default_max_iter

__all__ = ["START_IMPACT", "START_WIDTH", "Workspace", "give", "take"]

#: Workspaces kept per model for later runs (more at once are made and dropped).
POOL_SIZE = 4
#: Largest output buffer a pooled workspace keeps (bytes; a run with more output samples
#: allocates its own, dropped when the workspace goes back to the pool).
KEEP_BYTES = 4 << 20
#: The start as core_run records it (``sc_run.start_out``, ``START_*`` of run.c): gap, s,
#: touching, off_link; impact (0/1), its closing velocity, the kinetic energy before it and
#: its change, the impulses' count, then n_c impulses (from START_IMPACT); the rows
#: projected, their drift, vtol, the drift's row, the kinetic energy before the projection
#: and its change, then n_c impulses (from ``START_PROJECTION = START_IMPACT + 5 + n_c``).
#: ``START_WIDTH`` doubles without the 2 n_c impulses.
START_IMPACT = 4
START_WIDTH = 15

class Workspace:
    """Everything the compiled segments, settles and runs of ``model`` read and write, with
    the constants of the model set once: the struct of a segment (``seg``), a settle (``st``)
    and a run (``run``), the small arrays they point at (``shared``: by name, for
    :class:`~snakecg.simulate.compiled.CompiledSegments`), the pointer arrays of the batch
    drivers of ``mass_matrix`` and ``link_poses``, and the output arrays of a whole run
    (:meth:`run_buffer`, grown when a run needs more)."""

    def __init__(self, model):
        core = model.core
        ns, nc = model.n_coordinates, model.n_constraints
        nx = ns + 3
        ny = 2 * nx + 3
        self.ny, self.nc = ny, nc
        scene = model.scene
        k = scene.contact_link - 1
        c_k, l_k = float(scene.robot.com[k]), float(scene.robot.length[k])
        # every small array the C reads or writes, as views of one buffer
        self.start_width = START_WIDTH + 2 * nc
        sizes = {"y0": ny, "y_end": ny, "tau": model.n_joints, "state": nc, "f_obj": 3,
                 "rho": 2, "s_y": ny, "s_y_out": ny, "s_prev": nc, "s_forced": nc,
                 "s_state": nc, "s_forced_out": nc, "s_impact_lam": nc,
                 "s_projection_lam": nc, "y_start": ny, "start_out": self.start_width}
        buf = np.zeros(sum(sizes.values()))
        base, addr, off = buf.ctypes.data, {}, 0
        shared = {}
        for name, size in sizes.items():
            shared[name] = buf[off:off + size]
            addr[name] = base + 8 * off
            off += size
        events = np.zeros((2, nc + 3), dtype=np.int64)
        shared["ev_kind"], shared["ev_row"] = events
        seg = Segment()
        seg.scene = model.scene_address
        seg.tau, seg.f_obj, seg.rho = addr["tau"], addr["f_obj"], addr["rho"]
        seg.state = addr["state"]
        seg.ev_kind = events.ctypes.data
        seg.ev_row = seg.ev_kind + 8 * (nc + 3)
        seg.contact_index, seg.c_k, seg.l_k = k, c_k, l_k
        seg.pivot_tol, seg.regularization = PIVOT_TOL, REGULARIZATION
        seg.y0, seg.y_end = addr["y0"], addr["y_end"]
        st = Settle()
        st.scene, st.tau, st.f_obj, st.rho = (model.scene_address, addr["tau"], addr["f_obj"],
                                              addr["rho"])
        st.contact_index, st.c_k, st.l_k = k, c_k, l_k
        st.pivot_tol, st.rel_tol, st.max_iter = PIVOT_TOL, REL_TOL, default_max_iter(nc)
        st.regularization = REGULARIZATION
        st.y, st.forced = addr["s_y"], addr["s_forced"]
        st.y_out, st.state, st.forced_out = addr["s_y_out"], addr["s_state"], addr["s_forced_out"]
        st.impact_lam, st.projection_lam = addr["s_impact_lam"], addr["s_projection_lam"]
        run = Run()
        run.sg, run.st = address(seg), address(st)
        run.y, run.start_out = addr["y_start"], addr["start_out"]
        self.seg, self.st, self.run = seg, st, run
        self.run_address = address(run)
        shared.update(
            seg=seg, st=st, _address=address(seg),
            _settle_address=address(st), _prev_address=addr["s_prev"],
            _fn=core.integrate_segment, _samples=core.mode_samples, _run=core.run,
            _settle=core.settle)
        # the batch drivers of mass_matrix and link_poses (inputs q, K): their pointer arrays
        be = model.backend
        fns = getattr(be, "_fns", {})
        has_kinematics = all(
            name in fns and be.signatures[name].in_names in (["q", "K"], ["K", "q"])
            for name in ("mass_matrix", "link_poses"))
        shared["has_kinematics"] = has_kinematics
        if has_kinematics:
            K = np.ascontiguousarray(model.parameters, dtype=float)
            kin = []
            for name in ("mass_matrix", "link_poses"):
                i = be.signatures[name].in_names.index("q")
                strides = int64s(2)  # q's stride n_s, K broadcast
                strides[i] = ns
                kin.append((fns[name], K.ctypes.data, i, strides))
            shared["_K"], shared["_kin"] = K, kin
        self.shared = shared
        self._buf = buf, events  # keeps the arrays alive
        self._out = np.empty(0), 0
        self.modes = {}  # the Mode of a row of core_run's table of modes (its bytes)

    def run_buffer(self, size: int) -> tuple[np.ndarray, int]:
        """At least ``size`` doubles for a whole run's inputs and outputs, and its address
        (kept for the next run; the caller copies out what it returns)."""
        if len(self._out[0]) < size:
            out = np.empty(size)
            self._out = out, out.ctypes.data
        return self._out


def take(model) -> Workspace:
    """A workspace of ``model``: one from its pool, or a new one."""
    pool = model.data().simulation_pool
    if pool:
        try:
            return pool.pop()
        except IndexError:  # another thread took the last one
            pass
    return Workspace(model)


def give(model, ws: Workspace) -> None:
    """Give ``ws`` back to the pool of ``model`` (dropped when the pool is full; its output
    buffer dropped when above :data:`KEEP_BYTES`)."""
    pool = model.data().simulation_pool
    if len(pool) < POOL_SIZE:
        if ws._out[0].nbytes > KEEP_BYTES:
            ws._out = np.empty(0), 0
        pool.append(ws)
