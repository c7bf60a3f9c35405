"""The loaded model of a general scene: the robot's generated functions and the scene packed
once (:mod:`snakecg.scenes.packing`) for the engine's forward at rest
(``snakecg/engine/scene_rows.c``: contacts from geometry, rows, the exact solve and the
metrics per sample, one C call for a batch, split over threads as the engine's other batched
calls are)."""

from __future__ import annotations

import weakref

import numpy as np

from .._inputs import as_batch, broadcast_batches, check_batch_memory
from ..engine.binding import SceneCall, address
from ..errors import BuildError, InputError
from ..robot_model import RobotModel
from ..solver import check_input_range
from .contacts import Contact, Rows
from .description import GeneralScene
from .metrics import SceneResult
from .packing import BODY_KINDS, CONTACTS_FIRST, CR_W, SO_NC, SP_SIZE, pack
from .solve import INFO, UNILATERAL

#: a base position at most this many times the scene's size from the origin (the engine's
#: scene_inputs.h POSITION_SPAN)
POSITION_SPAN = 1e6

__all__ = ["GeneralSceneModel"]

_REFUSED = ("optimize_shape", "com_polar")
#: Samples per thread below which a batch is not split (SNAKECG_THREADS; snakecg.forward's)
PARALLEL_MIN = 512
#: A batch's solves start from the last sample's pieces (neighbours of a map or a sweep have
#: nearly the same), but every WARM_CHUNK-th sample of an engine call starts cold: the threads'
#: spans start on its multiples, so that the answers do not depend on the split
WARM_CHUNK = 256
#: A batch's first pass has room for the most contacts a sample of this model has met so far
#: and ROOM_MARGIN more (at most CONTACTS_FIRST; CONTACTS_FIRST before any): the output rows
#: are written whole, and room for contacts that never come is memory written for nothing
ROOM_MARGIN = 2
_F64 = np.dtype(np.float64)


class GeneralSceneModel(RobotModel):
    """``forward``, ``maps``, ``extremes`` and ``optimize`` on a
    :class:`~snakecg.scenes.GeneralScene` (at rest)."""

    def __init__(self, scene: GeneralScene, *, backend: str = "compiled", progress=None):
        if not isinstance(scene, GeneralScene):
            raise InputError(f"scene must be a snakecg.scenes.GeneralScene, got "
                             f"{type(scene).__name__}")
        super().__init__(scene.robot, backend=backend, progress=progress)
        self.scene = scene
        self.core = getattr(self.backend, "core", None)
        self.masses = np.asarray(scene.robot.mass, dtype=float)
        self.object_inertia = np.array([[o.mass, o.mass, o.plate_inertia]
                                        for o in scene.objects]).reshape(-1, 3)
        self.packed = pack(scene, self.parameters, self.n_coordinates)
        """The scene as the engine reads it (:class:`~snakecg.scenes.packing.Packed`)."""
        self._engine = getattr(self.core, "scene_forward", None)
        self._pk = self.packed.vector.ctypes.data
        self._zero_f = np.zeros((1, 3 * scene.n_objects))
        if getattr(self.core, "scene_forward_call", None) is not None:
            # the method's fast way for one sample, in the instance (no second call)
            self.forward = _one_sample(self)
        self._met = -1
        """The most contacts a sample of this model's batches has met (-1: no batch yet): the
        first pass's room (a speed hint only: no answer depends on the room, :meth:`_run`)."""
        self._steppers: list = []
        """The time stepping's workspaces not lent to a run (:mod:`snakecg.scenes.stepping`)."""

    def __getattr__(self, name):
        if name in _REFUSED:
            raise InputError(f"{name} is not available on a general scene yet (forward, "
                             "maps, extremes, optimize, simulate and plot are); use a "
                             "snakecg.Scene of the paper's scenarios")
        raise AttributeError(name)

    def overlap_message(self, rec, index) -> str:
        """The line that refuses an overlap (``rec``: the engine's record of it)."""
        a = self.scene.body_name(BODY_KINDS[int(rec[0])], int(rec[1]))
        b = self.scene.body_name(BODY_KINDS[int(rec[2])], int(rec[3]))
        where = "" if index is None else f" in sample {index}"
        return (f"{a} and {b} overlap by {rec[4]:.3g} m{where} (contacts hold within "
                f"{rec[5]:.3g} m); move them apart")

    def object_poses(self, q) -> np.ndarray:
        """Every object's pose ``(x, y, theta)`` at ``q`` as the forward solve places it (a
        ``pose``, or ``touching`` a link: on its named side, the contact at ``offset`` from
        the rear end, a box with a face along the link): ``(n_objects, 3)``, or
        ``(N, n_objects, 3)`` for ``q`` ``(N, n_s)``. The engine's placement
        (``core_scene_place``), the one the forward, the drawing and a simulation's start
        read."""
        P = self.link_poses(q)  # checks q
        if getattr(self.core, "scene_place", None) is None:
            raise BuildError("a general scene's objects are placed by the compiled engine; "
                             "load it with a C compiler (set CC) and the compiled backend")
        P3 = np.ascontiguousarray(P.reshape(-1, self.n_links, 3))
        out = np.empty((P3.shape[0], self.scene.n_objects, 3))
        if self.core.scene_place(self._pk, P3.shape[0], P3.ctypes.data, out.ctypes.data):
            raise MemoryError("the scene's placement ran out of memory")
        return out if P.ndim == 3 else out[0]

    def simulate(self, q0, duration, **kwargs):
        """Simulate the scene over time: :func:`snakecg.scenes.stepping.simulate_scene`
        (velocity-level time stepping on the same exact solve, contact onset by root finding,
        inelastic impacts)."""
        from .stepping import simulate_scene

        return simulate_scene(self, q0, duration, **kwargs)

    def maps(self, q, *, state=None) -> dict:
        """The linear maps at ``q`` for a block state (:func:`snakecg.scenes.maps.maps`)."""
        from .maps import maps
        return maps(self, q, state=state)

    def extremes(self, q, **kwargs):
        """Extremes of the metrics on the input ellipsoid (:mod:`snakecg.scenes.extremes`)."""
        from .extremes import extremes
        return extremes(self, q, **kwargs)

    def optimize(self, q, objective="max_sr", **kwargs):
        """Optimal torques for a task (:func:`snakecg.scenes.optimize.optimize`)."""
        from .optimize import optimize
        return optimize(self, q, objective, **kwargs)

    def forward(self, q, tau, *, f_obj=None, v=None) -> SceneResult:
        """Accelerations, forces, contact states, norms, sr and the certificate at rest.

        ``q`` ``(n_s,)`` or ``(N, n_s)``; ``tau`` ``(n_a,)`` or ``(N, n_a)``; ``f_obj``: an
        external wrench (F_x, F_y, torque) on every object, ``(n_objects, 3)`` (or batched).
        A sample whose shapes overlap is refused (one sample: :class:`InputError`; in a batch:
        NaN with status ``overlap`` and the reason). (A loaded model answers one sample of
        float64 arrays through its engine's kept scratch first, bound in the instance.)"""
        if v is not None and np.any(np.asarray(v, dtype=float) != 0):
            raise InputError("v: a general scene is solved at rest (v = 0); velocities are not "
                             "supported yet")
        na, ns, no = self.n_joints, self.n_coordinates, self.scene.n_objects
        qa, bq = as_batch("q", q, ns, what=f" = (n_joints + 3,) for a {na}-joint robot",
                          check_finite=False)
        ta, bt = as_batch("tau", tau, na, what=f" (one torque per joint, n_a = {na})",
                          check_finite=False)
        if f_obj is None:
            fo, bf = self._zero_f, False
        else:
            arr = np.asarray(f_obj, dtype=float)
            batched_f = arr.ndim == 3
            fo, bf = as_batch("f_obj", arr.reshape(arr.shape[0], -1) if batched_f
                              else arr.reshape(-1), 3 * no, check_finite=False,
                              what=f" = (n_objects, 3) wrenches, {no} objects")
        N = broadcast_batches(q=(qa, bq), tau=(ta, bt), f_obj=(fo, bf))
        batched = bq or bt or bf
        check_batch_memory("forward", N, 8 * self.packed.width(CONTACTS_FIRST), what="results")
        if self._engine is None:
            raise BuildError("a general scene is solved by the compiled engine; load it with a "
                             "C compiler (set CC) and the compiled backend")
        out = self._run(qa, ta, fo, N, batched)
        if out is None:  # an input refused by the engine: named by the checks
            for name, val, size in (("q", q, ns), ("tau", tau, na), ("f_obj", fo, 3 * no)):
                as_batch(name, val, size)
            check_input_range({"tau": (ta, bt), "f_obj": (fo, bf)})
            self.check_base(qa)
            raise InputError("forward: an input is not finite")
        return self._result(out, batched, (np.broadcast_to(qa, (N, ns)),
                                           np.broadcast_to(ta, (N, na)),
                                           np.broadcast_to(fo, (N, 3 * no))))

    def check_base(self, q) -> None:
        """Refuse a base position beyond POSITION_SPAN times the scene's size (the engine's
        scene_inputs.h): farther, the contacts' geometry rounds beyond their tolerance."""
        lim = POSITION_SPAN * self.packed.vector[SP_SIZE]
        qa = np.atleast_2d(q)
        far = ~(np.abs(qa[:, :2]) <= lim)
        if far.any():
            idx = tuple(int(i) for i in np.argwhere(far)[0])
            where = idx if np.ndim(q) == 2 else (idx[1],)
            raise InputError(f"q: the base position (x, y) must be within +-{lim:.3g} m (a "
                             f"million times the scene's size: farther, the contact geometry's "
                             f"rounding exceeds the contacts' tolerance), found "
                             f"{qa[idx]:.3e} at index {where}")

    def _result(self, out, batched, inputs) -> SceneResult:
        if not batched and out[0, 0] == 3:
            raise InputError(self.overlap_message(out[0, 13:19], None))
        return SceneResult(self, out, self._ccap_of(out), batched, inputs)

    def _ccap_of(self, out) -> int:
        return (out.shape[1] - self.packed.width(0)) // CR_W

    def _call(self, q, tau, fo, N, ccap, out, detail=None, chunk=WARM_CHUNK) -> int:
        """One engine call over samples 0..N of the inputs (broadcast where one row), into
        ``out``; the batch split over threads when large (on multiples of ``chunk``: every
        chunk-th sample starts cold, the others from the last one's pieces; 1: all cold). Its
        status."""
        from ..engine.threads import pool, threads

        mcap = self.packed.rows_room(ccap)
        steps = [a.shape[1] if a.shape[0] > 1 else 0 for a in (q, tau, fo)]
        workers = threads(N, PARALLEL_MIN) if detail is None else 1
        n = self.n_coordinates + 3 * self.scene.n_objects

        def job(lo, hi):
            ptrs = [a.ctypes.data + 8 * lo * st for a, st in zip((q, tau, fo), steps)]
            det = [0, 0, 0, 0] if detail is None else [
                detail["A"].ctypes.data + 8 * lo * mcap * n] + [
                detail[k].ctypes.data + 8 * lo * mcap for k in ("lam", "w", "state")]
            return self._engine(self._pk, hi - lo, ptrs[0], steps[0], ptrs[1], steps[1],
                                ptrs[2], steps[2], ccap, mcap,
                                out.ctypes.data + 8 * lo * out.shape[1], *det, chunk)

        if workers == 1:
            return job(0, N)
        step = max(1, chunk)
        bounds = np.minimum(N, np.round(np.linspace(0, N, workers + 1) / step)
                            .astype(np.int64) * step)
        bounds[-1] = N
        spans = [(int(lo), int(hi)) for lo, hi in zip(bounds[:-1], bounds[1:]) if hi > lo]
        codes = list(pool().map(lambda b: job(*b), spans))
        for code, (lo, _) in zip(codes, spans):
            if code < -2:
                return code - lo
            if code != 0:
                return code
        return 0

    def _run(self, q, tau, fo, N, batched, chunk=WARM_CHUNK):
        """The engine's outputs of N samples (None where an input is not finite): a first
        pass with room for the contacts met so far and ROOM_MARGIN more; where some samples
        found more, the batch solved again with room for every pair's (the whole batch where
        samples start from their neighbours' pieces, so that the chain of starts is the one
        :meth:`details` meets; only those samples where every sample starts cold)."""
        pk = self.packed
        ccap = min(CONTACTS_FIRST, pk.contacts_max,
                   self._met + ROOM_MARGIN if self._met >= 0 else CONTACTS_FIRST)
        # not zeroed here: the engine writes every column of a sample's row (the record room
        # after its contacts zeros), the same bytes whatever the threads' split
        out = np.empty((N, pk.width(ccap)))
        code = self._call(q, tau, fo, N, ccap, out, chunk=chunk)
        if code <= -3:
            return None
        if code != 0:
            raise MemoryError("the general scene's forward ran out of memory") if code == -1 \
                else ValueError(f"core_scene_forward refused its sizes ({code})")
        more = np.flatnonzero(out[:, 0] == 4)
        if more.size == 0:
            self._meet(out)
            return out
        full = pk.contacts_max
        wide = np.zeros((N, pk.width(full)))
        if chunk > 1:  # a sample out of room broke its neighbours' chain of starts
            code = self._call(q, tau, fo, N, full, wide, chunk=chunk)
            if code != 0:
                raise MemoryError("the general scene's forward ran out of memory")
            wide[wide[:, 0] == 4, 0] = 5  # more than the solve takes
            self._meet(wide)
            return wide
        wide[:, :out.shape[1]] = out
        pick = [a if a.shape[0] == 1 else np.ascontiguousarray(a[more]) for a in (q, tau, fo)]
        redo = np.zeros((more.size, pk.width(full)))
        self._call(*pick, more.size, full, redo, chunk=chunk)
        redo[redo[:, 0] == 4, 0] = 5  # more than the solve takes
        wide[more] = redo
        self._meet(wide)
        return wide

    def _meet(self, out) -> None:
        """The most contacts met, raised by a batch's samples (``out``)."""
        if out.shape[0]:
            self._met = max(self._met, int(np.nanmax(out[:, SO_NC], initial=0)))

    def details(self, out, inputs) -> dict:
        """The rows, forces, row accelerations and block states of every sample of a result
        (``out``, its inputs), solved again with them kept: ``{"raw", "rows"}``. The batch
        is solved again as one call, so each sample starts from the same neighbour's pieces
        as in the forward and meets the same forces; a one-sample result taken from a batch
        (:meth:`SceneResult.sample`) is solved from scratch, and where its forces are one
        basic solution of a dependent face (flag 2, rare) it may meet another one."""
        pk = self.packed
        N = out.shape[0]
        n = self.n_coordinates + 3 * self.scene.n_objects
        ok = (out[:, 0] != 3) & (out[:, 0] < 5)
        nc = out[:, SO_NC].astype(int)
        ccap = max(1, int(nc[ok].max()) if ok.any() else 1)
        mcap = pk.rows_room(ccap)
        det = {"A": np.zeros((N, mcap, n)), "lam": np.zeros((N, mcap)),
               "w": np.zeros((N, mcap)), "state": np.zeros((N, mcap))}
        again = np.zeros((N, pk.width(ccap)))
        q, tau, fo = (np.ascontiguousarray(a) for a in inputs)
        self._call(q, tau, fo, N, ccap, again, det)
        starts = np.cumsum((0,) + pk.sizes)
        off = pk.offset["contacts"]
        rows = []
        for s in range(N):
            if not ok[s]:
                rows.append(None)
                continue
            k = nc[s]
            contacts = []
            for c in range(k):
                r = out[s, off + CR_W * c: off + CR_W * (c + 1)]
                contacts.append(Contact((BODY_KINDS[int(r[0])], int(r[1])),
                                        (BODY_KINDS[int(r[2])], int(r[3])), r[4:6].copy(),
                                        r[6:8].copy(), r[8:10].copy(), float(r[10]), c))
            rows.append(Rows(det["A"][s, :k + pk.ground_rows],
                             [UNILATERAL] * k + list(pk.kinds),
                             list(range(k)) + [k + int(x) for x in starts[:-1]],
                             [(0.0, 0.0, 0.0)] * k + list(pk.pars), contacts,
                             [("contact", c) for c in range(k)] + list(pk.labels)))
        raw = {"lam": det["lam"], "w": det["w"], "state": det["state"].astype(np.int64),
               "info": {name: out[:, i] for i, name in enumerate(INFO)}}
        return {"raw": raw, "rows": rows}


def _one_sample(model: GeneralSceneModel):
    """The model's ``forward``, bound in the instance: one sample of float64 arrays of the
    right shapes straight to the engine, every other input (and a sample when the buffer is
    busy, or with more contacts than the first pass's room) the class's general way. q, tau
    and the output row side by side in one buffer, the engine's arguments pointing into it,
    built once. The buffer is taken as a one-token list's token (``list.pop`` and ``append``
    are atomic: a second thread that finds it empty goes the general way; a third of a
    non-blocking lock's cost). A closure: its fields are its own variables, no lookups per
    call. The engine keeps its scratch from the first call to the next (the fixed bodies
    placed, the objects' inertia set; a call at the last call's q, the same bytes, keeps its
    contacts, rows, Z and G as a batch's samples at one q do, with the same answers), freed
    with the closure."""
    pk = model.packed
    ccap = min(CONTACTS_FIRST, pk.contacts_max)
    ns, na = model.n_coordinates, model.n_joints
    buf = np.zeros(ns + na + pk.width(ccap))
    bq, bt, at = buf[:ns], buf[ns:ns + na], ns + na  # at: where the output row starts
    base = buf.ctypes.data
    args = SceneCall(model._pk, 1, base, 0, base + 8 * ns, 0, model._zero_f.ctypes.data, 0,
                     ccap, pk.rows_room(ccap), base + 8 * at, 0, 0, 0, 0, 1)
    where, call = address(args), model.core.scene_forward_call
    token = [True]
    take, put = token.pop, token.append
    shape_q, shape_tau, ndarray = (ns,), (na,), np.ndarray
    general, new = GeneralSceneModel.forward, object.__new__

    def forward(q, tau, *, f_obj=None, v=None):
        if (type(q) is ndarray and type(tau) is ndarray and q.dtype is _F64
                and tau.dtype is _F64 and q.shape == shape_q and tau.shape == shape_tau
                and f_obj is None and v is None):
            try:
                take()
            except IndexError:  # busy: another thread's call
                return general(model, q, tau)
            try:  # straight to the engine (which checks finiteness)
                bq[...] = q  # ([...]: a third cheaper than [:] from Python)
                bt[...] = tau
                code = call(where)
                out = buf.copy()  # the inputs and the output row in one copy
            finally:
                put(True)
            if code == 0:
                status = out.item(at)
                if status == 3:
                    raise InputError(model.overlap_message(out[at + 13:at + 19], None))
                if status != 4:  # else: more contacts than the first pass's room
                    # a one-sample result: its four fields, its views made when first read
                    res = new(SceneResult)
                    res._model, res._buf, res._ccap, res.batched = model, out, ccap, False
                    return res
        return general(model, q, tau, f_obj=f_obj, v=v)

    forward.__doc__, forward.__wrapped__ = general.__doc__, general
    forward.__qualname__ = general.__qualname__
    forward.args = args  # the engine reads it: kept alive with the closure
    # the engine's scratch kept in args.keep, freed with the closure
    forward.free = weakref.finalize(forward, _free_kept, call, args)
    return forward


def _free_kept(call, args) -> None:
    """Free the scratch the engine kept between one-sample calls (a call with n = 0)."""
    args.n = 0
    call(address(args))
