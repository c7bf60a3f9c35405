"""The forward analysis of a scene (eqs. 12-30): accelerations, constraint forces, active set,
norms and the slippage ratio, for one sample or a batch.

Every sample is solved by the compiled engine (:mod:`snakecg.engine`): one C call for the
whole batch, the rare samples (dependent or weakly independent held rows, no convergence, an
ill-conditioned mass matrix, an impossible result) included (``rows.c``). On the CasADi
backend every sample takes the pure-Python engine: the vectorized active-set iteration of
:mod:`snakecg.solver` on the generated ``constrained_dynamics``, completed by
:mod:`snakecg.rows` (rows factored directly, conditioning, physical checks).

Results are rows of one float64 array (:class:`ForwardResult` views into it), laid out by
:class:`snakecg.engine.Layout`; ``out=`` reuses the array of an earlier result.
"""

from __future__ import annotations


import numpy as np

from . import kernels
from ._inputs import CHUNK_ROWS, as_batch, broadcast_batches, check_batch_memory
from .engine import Data
from .engine.binding import address, empty_pointers, int64s
from .errors import InputError
from .rows import finish as finish_rows
from .rows import reason_of
from .solver import (HELD, check_input_range, check_position_range, default_max_iter,
                     solve_active_set)

__all__ = ["ForwardResult", "forward", "forward_one", "model_forward", "WHEEL_STATE_NAMES"]

_STATE_NAMES = np.array(["none", "stick", "lost", "slide+", "slide-"])
#: Names of the wheel rows' states (a wheel row is never "lost"; read as "none").
WHEEL_STATE_NAMES = np.where(_STATE_NAMES == "lost", "none", _STATE_NAMES)
_ORDER = ("tau", "qdd", "a_obj", "lam", "w", "contact", "wheel_state", "norm_lambda",
          "norm_a_obj", "norm_qdd", "sr", "gap", "singular", "conditioning")


class _Columns:
    """Where each field of a :class:`ForwardResult` lies in an output row."""

    __slots__ = ("width", "slices", "index", "state", "wheels", "status", "singular")

    def __init__(self, layout):
        self.width = layout.out_width
        self.slices = {k: slice(o, o + s) for k, (o, s) in layout.out.items()}
        self.index = {k: o for k, (o, s) in layout.out.items()}
        o, s = layout.out["state"]
        self.state, self.wheels = o, slice(o + 1, o + s)
        self.status = layout.out["status"][0]
        self.singular = layout.out["singular"][0]


def _vector(name):
    def get(self):
        return self._raw[..., self._cols.slices[name]]

    def put(self, value):
        self._raw[..., self._cols.slices[name]] = value

    return property(get, put, doc=f"``{name}`` (a view into the result's row)")


def _scalar(name):
    def get(self):
        r = self._raw
        return r[self._cols.index[name]] if r.ndim == 1 else r[:, self._cols.index[name]]

    def put(self, value):
        self._raw[..., self._cols.index[name]] = value

    return property(get, put, doc=f"``{name}``")


class ForwardResult:
    """Outcome of :meth:`SceneModel.forward` for one sample or a batch (leading axis N).

    * ``qdd`` (n_s): snake accelerations; ``a_obj`` (3): object acceleration (x, y, psi);
      ``tau`` (n_a): the torque it answers;
    * ``lam`` (n_c): constraint forces, row 0 the contact (N, pushes the object along the
      normal), row ``i`` the lateral force of the wheel of link ``i`` (N, along
      ``(-sin phi_i, cos phi_i)``); ``w`` (n_c): the rows' accelerations;
    * ``contact``: the contact is kept (``lam_c >= 0``) or lost; ``wheel_state`` (n_l):
      ``"none"``, ``"stick"``, ``"slide+"`` / ``"slide-"`` (force at ``+-mu m g``);
    * norms: ``norm_lambda = lam^T G_c lam``, ``norm_a_obj = a_obj^T I_obj a_obj`` (eq. 27),
      ``norm_qdd = qdd^T M_s qdd`` (eq. 26), slippage ratio ``sr`` (eq. 30, 0 when the
      contact is lost); ``gap``: the contact's normal gap (m);
    * ``conditioning``: the estimated accuracy, results carry a relative error of about
      ``1e-16 / conditioning``: the smallest of the held rows' pivot ratio (its square root
      where weakly independent rows are solved from the rows themselves, ``snakecg.rows``) and
      the mass matrix's; ``singular``: not an exact answer (conditioning 0): rows dependent even
      when factored directly (least-norm forces), a numerically singular mass matrix, or a
      physically impossible result (docs/explanation/scenarios.md).

    The fields are views into one float64 array (``result.raw``, a row per sample);
    ``result[i]`` is sample ``i`` of a batch.
    """

    __slots__ = ("_raw", "_cols")

    def __init__(self, raw: np.ndarray, columns: _Columns):
        self._raw = raw
        self._cols = columns

    tau = _vector("tau")
    qdd = _vector("qdd")
    a_obj = _vector("a_obj")
    lam = _vector("lam")
    w = _vector("w")
    norm_lambda = _scalar("norm_lambda")
    norm_a_obj = _scalar("norm_a_obj")
    norm_qdd = _scalar("norm_qdd")
    sr = _scalar("sr")
    gap = _scalar("gap")
    conditioning = _scalar("conditioning")

    @property
    def raw(self) -> np.ndarray:
        """The result's rows (``(width,)`` or ``(N, width)``), laid out by
        :class:`snakecg.engine.Layout`."""
        return self._raw

    @property
    def contact(self):
        r = self._raw
        return (r[self._cols.state] if r.ndim == 1 else r[:, self._cols.state]) == HELD

    @property
    def wheel_state(self) -> np.ndarray:
        return WHEEL_STATE_NAMES[self._raw[..., self._cols.wheels].astype(np.intp)]

    @property
    def singular(self):
        r = self._raw
        return (r[self._cols.singular] if r.ndim == 1 else r[:, self._cols.singular]) != 0.0

    @property
    def reason(self):
        """Why a ``singular`` sample is not an exact answer, in one line ('' for an exact
        answer; an array of them for a batch). The results of a sample that cannot be
        answered at all are NaN."""
        r = self._raw
        if r.ndim == 1:
            return reason_of(r[self._cols.status])
        return np.array([reason_of(c) for c in r[:, self._cols.status]], dtype=object)

    @property
    def sliding(self) -> np.ndarray:
        return np.isin(self.wheel_state, ("slide+", "slide-"))

    @property
    def batched(self) -> bool:
        return self._raw.ndim == 2

    def __len__(self) -> int:
        if self._raw.ndim != 2:
            raise TypeError("a one-sample ForwardResult has no length")
        return self._raw.shape[0]

    def __getitem__(self, i) -> "ForwardResult":
        """Sample ``i`` (or a slice of samples) of a batch."""
        if self._raw.ndim != 2:
            raise TypeError("a one-sample ForwardResult cannot be indexed")
        return ForwardResult(self._raw[i], self._cols)

    def __getstate__(self):
        return {"raw": self._raw, "columns": {k: getattr(self._cols, k)
                                              for k in _Columns.__slots__}}

    def __setstate__(self, st):
        cols = _Columns.__new__(_Columns)
        for k, v in st["columns"].items():
            setattr(cols, k, v)
        self._raw, self._cols = st["raw"], cols

    def to_dict(self) -> dict:
        """JSON-ready dictionary (schema in docs/reference/cli.md): every result field and, per
        sample, ``reason`` ('' for an exact answer, else why the sample is flagged or NaN)."""
        out = {k: np.asarray(getattr(self, k)).tolist() for k in _ORDER if k != "gap"}
        reason = self.reason
        out["reason"] = reason if isinstance(reason, str) else [str(r) for r in reason]
        return out

    def __repr__(self) -> str:
        if self._raw.ndim == 2:
            return f"<ForwardResult of {self._raw.shape[0]} samples>"
        return (f"ForwardResult(contact={bool(self.contact)}, wheel_state="
                f"{self.wheel_state.tolist()}, norm_a_obj={float(self.norm_a_obj):.6g}, "
                f"norm_qdd={float(self.norm_qdd):.6g}, sr={float(self.sr):.6g}, "
                f"singular={bool(self.singular)})")


# ------------------------------------------------------------------------------------------
_F64 = np.dtype(np.float64)


def _plain(x, size: int) -> bool:
    """A list or tuple of ``size`` Python floats or ints (the one-sample fast path)."""
    if len(x) != size:
        return False
    for e in x:
        t = type(e)
        if t is not float and t is not int:
            return False
    return True


def model_forward(model, q, tau, *, v=None, v_obj=None, f_obj=None, q_obj=None, rho=None,
                  max_iter: int | None = None, data: Data | None = None,
                  out: ForwardResult | None = None) -> ForwardResult:
    """Accelerations, constraint forces, active set and norms (eqs. 12-30).

    ``q`` ``(n_s,)`` or ``(N, n_s)``; ``tau`` ``(n_a,)`` or ``(N, n_a)`` (one broadcasts
    against the other). Optional: snake velocities ``v``, object twist ``v_obj``, external
    wrench on the object ``f_obj`` (F_x, F_y, torque). The object's pose ``q_obj`` and the
    contact point in its frame ``rho`` default to the scene's placement (the object
    touching the contact link at ``contact_offset``). ``data``: a workspace from
    :meth:`~snakecg.SceneModel.create_data` (one per thread); ``out``: an earlier result of
    the same shape whose array is overwritten (no allocation). Solved in compiled code per
    sample (:mod:`snakecg.engine`). (:meth:`SceneModel.forward` is this function.)
    """
    core = model.core
    if (core is not None and v is None and v_obj is None and f_obj is None and q_obj is None
            and rho is None and max_iter is None and out is None):
        # one sample of float64 arrays or plain lists: straight into a workspace's buffers,
        # one C call, one copy of the result row (the C checks finiteness and range)
        tq, tt = type(q), type(tau)
        if ((tq is np.ndarray and q.dtype is _F64 and q.shape == model._shape_q
             or (tq is list or tq is tuple) and _plain(q, model.n_coordinates))
                and (tt is np.ndarray and tau.dtype is _F64 and tau.shape == model._shape_tau
                     or (tt is list or tt is tuple) and _plain(tau, model.n_joints))):
            res = forward_one(model, core, q, tau, data)
            if res is not None:
                return res
    return forward(model, q, tau, v=v, v_obj=v_obj, f_obj=f_obj, q_obj=q_obj, rho=rho,
                   max_iter=max_iter, data=data, out=out)


def forward(model, q, tau, *, v=None, v_obj=None, f_obj=None, q_obj=None, rho=None,
            max_iter=None, data: Data | None = None, out: ForwardResult | None = None):
    """:meth:`SceneModel.forward` (see there) on its general path: every input validated and
    converted, one C call for the batch (split over threads when large); every sample of the
    CasADi backend on the pure-Python engine. (``data`` serves the
    one-sample path only: a batch needs no workspace.)"""
    extras = {"v": v, "v_obj": v_obj, "f_obj": f_obj, "q_obj": q_obj, "rho": rho}
    core = model.core
    parts, n, batched = _validate(model, q, tau, extras, max_iter,
                                  check_finite=core is None)
    iters = default_max_iter(model.n_constraints) if max_iter is None else int(max_iter)
    cols = model.columns
    check_batch_memory("forward", n, 8 * cols.width, what="results")
    raw = _output(out, n, batched, cols)
    raw2 = raw.reshape(n, cols.width)
    if core is None:  # CasADi backend: the pure-Python engine for every sample
        for lo in range(0, n, CHUNK_ROWS):
            hi = min(n, lo + CHUNK_ROWS)
            idx = np.arange(lo, hi)
            _reference_into(model, raw2, idx, parts, max_iter)
        return ForwardResult(raw, cols)
    status = _core_batch(model, core, parts, n, iters, raw2)
    if status != 0:
        if status == -1:
            raise MemoryError("snakecg: the runtime core could not allocate its work arrays")
        _validate(model, q, tau, extras, max_iter)  # raises, naming the input
        raise InputError(f"forward: an input of sample {-2 - status} is not finite or beyond "
                         f"the force limit")
    return ForwardResult(raw, cols)


def forward_one(model, core, q, tau, data):
    """One sample (``q``, ``tau`` already known to be numeric of the right sizes) through a
    workspace's buffers: one C call, one copy of the output row. None when the C refuses the
    inputs (non-finite, beyond range): the general path then names the problem."""
    d = data
    own = d is None
    if own:
        d = model.data()
        if not d.lock.acquire(False):  # another thread is using it: a workspace of our own
            d, own = model.create_data(), False
    try:
        if d.owner is not model:
            d.bind(model)
        try:
            d.q[:] = q
            d.tau[:] = tau
        except (TypeError, ValueError, OverflowError):
            return None
        if core.call_packed(d.call_address) != 0:
            return None
        raw = d.out.copy()
    finally:
        if own:
            d.lock.release()
    return ForwardResult(raw, model.columns)


def _validate(model, q, tau, extras: dict, max_iter, *, check_finite=True):
    """Every input checked and converted: ``(parts, n, batched)`` with ``parts`` the
    ``(N_i, size)`` arrays by name. ``check_finite=False`` leaves finiteness to the C core
    (which refuses the call; this then runs again with the check, for the message)."""
    na = model.n_joints
    if max_iter is not None and (isinstance(max_iter, bool)
                                 or not isinstance(max_iter, (int, np.integer)) or max_iter < 1):
        raise InputError(f"max_iter must be an integer >= 1 (active-set iterations before"
                         f" enumerating), or None for the default; got {max_iter!r}")
    what = f" = (n_joints + 3,) for a {na}-joint robot"
    parts = {"q": as_batch("q", q, model.n_coordinates, what=what, check_finite=check_finite),
             "tau": as_batch("tau", tau, na, what=f" (one torque per joint, n_a = {na})",
                             check_finite=check_finite)}
    sizes = {"v": model.n_coordinates, "v_obj": 3, "f_obj": 3, "q_obj": 3, "rho": 2}
    for name, val in extras.items():
        if val is not None:
            parts[name] = as_batch(name, val, sizes[name], check_finite=check_finite)
    n = broadcast_batches(**parts)
    batched = any(b for _, b in parts.values())
    if check_finite:
        check_input_range(parts)
    check_position_range(parts)
    if ("q_obj" in parts) != ("rho" in parts):
        raise InputError("q_obj and rho go together: give both or neither")
    return {k: a for k, (a, _) in parts.items()}, n, batched


def _output(out, n, batched, cols) -> np.ndarray:
    """The result array: ``out``'s (checked) or a new one."""
    shape = (n, cols.width) if batched else (cols.width,)
    if out is None:
        return np.empty(shape)
    if not isinstance(out, ForwardResult) or out._cols.width != cols.width:
        raise InputError(f"out must be a ForwardResult of this model (from an earlier forward "
                         f"call), got {type(out).__name__}")
    raw = out._raw
    if raw.shape != shape or not raw.flags.c_contiguous or not raw.flags.writeable:
        raise InputError(f"out holds results of shape {raw.shape}, this call needs {shape}")
    return raw


#: Batches at least this large are split across threads (SNAKECG_THREADS).
PARALLEL_MIN = 512


def _core_batch(model, core, parts: dict, n: int, iters: int, raw: np.ndarray) -> int:
    """The C core over the batch (in chunks on threads for a large one): its status."""
    from .engine.layout import INPUTS
    from .engine.threads import pool, threads

    zeros = model.zero_inputs
    arrays = []
    for name in INPUTS:
        a = parts.get(name)
        if a is None:
            a = None if name in ("q_obj", "rho") else zeros[name]
        arrays.append(a)
    workers = threads(n, PARALLEL_MIN)
    bounds = np.linspace(0, n, workers + 1).astype(np.int64)

    def job(lo, hi):
        ptr = empty_pointers(len(INPUTS))
        strides = int64s(len(INPUTS))
        for k, a in enumerate(arrays):
            if a is None:
                continue
            step = a.shape[1] if a.shape[0] > 1 else 0
            strides[k] = step
            ptr[k] = a.ctypes.data + 8 * lo * step
        return core(hi - lo, model.scene_address, iters, address(ptr), address(strides),
                    raw.ctypes.data + 8 * lo * raw.shape[1])

    if workers == 1:
        return job(0, n)
    results = list(pool().map(lambda b: job(int(b[0]), int(b[1])),
                              [(lo, hi) for lo, hi in zip(bounds[:-1], bounds[1:]) if hi > lo]))
    for r, lo in zip(results, bounds[:-1]):
        if r == -1:
            return -1
        if r < -1:
            return r - int(lo)
    return 0


# ------------------------------------------------------------------------------------------
def _reference_into(model, raw: np.ndarray, idx: np.ndarray, parts: dict, max_iter) -> None:
    """The reference path (:func:`~snakecg.solver.solve_active_set` on the generated
    ``constrained_dynamics``, completed by :func:`snakecg.rows.finish`) for samples ``idx``,
    written into their rows of ``raw``."""
    if idx.size == 0:
        return
    m = idx.size
    sub = {k: (a if a.shape[0] == 1 else np.ascontiguousarray(a[idx])) for k, a in parts.items()}
    sub["q"], moved = kernels.at_origin(sub["q"], sub.get("q_obj"))  # (the core's rule)
    if "q_obj" not in sub:
        q_obj, rho = model.place(sub["q"])[:2]
        sub["q_obj"], sub["rho"] = q_obj, rho
    else:
        sub["q_obj"] = moved
    base = {"q": sub["q"], "v": sub.get("v", np.zeros((1, model.n_coordinates))),
            "tau": sub["tau"], "q_obj": sub["q_obj"], "v_obj": sub.get("v_obj", np.zeros((1, 3))),
            "f_obj": sub.get("f_obj", np.zeros((1, 3))), "rho": sub["rho"]}
    sol = _reference_solve(model, base, m, max_iter)
    o, cols = sol.outputs, model.columns
    rows = raw[idx]
    contact = sol.state[:, 0] == HELD
    rows[:, cols.slices["tau"]] = np.broadcast_to(sub["tau"], (m, model.n_joints))
    for k in ("qdd", "a_obj", "lam", "w"):
        rows[:, cols.slices[k]] = o[k]
    for k in ("norm_lambda", "norm_a_obj", "norm_qdd", "gap"):
        rows[:, cols.index[k]] = o[k]
    rows[:, cols.index["sr"]] = np.where(contact | np.isnan(o["sr"]), o["sr"], 0.0)  # eq. 30
    rows[:, cols.index["conditioning"]] = sol.conditioning
    rows[:, cols.singular] = sol.singular
    rows[:, cols.slices["state"]] = sol.state
    # answered by the reference path (1), or flagged: the code of the reason (rows.REASONS)
    rows[:, cols.status] = np.maximum(sol.reason, 1)
    raw[idx] = rows


def _reference_solve(model, base: dict, n: int, max_iter):
    order = ["q", "v", "tau", "q_obj", "v_obj", "f_obj"]

    def pick(arr, idx):
        if arr.shape[0] == 1:
            return arr[0]
        m = len(idx)
        if m == arr.shape[0] and idx[0] == 0 and idx[-1] == m - 1:  # sorted: all samples
            return arr
        return np.ascontiguousarray(arr[idx])

    fixed = {k: model.scene_inputs[k] for k in ("K", "contact_link", "side", "object_mass",
                                                "object_inertia", "wheel_offset")}

    def call(idx, free, lam_fixed, reg):
        m = len(idx)
        outs = kernels.call(
            model.backend, "constrained_dynamics", m, **{k: pick(base[k], idx) for k in order},
            **fixed, rho=pick(base["rho"], idx), free=free, lam_fixed=lam_fixed,
            regularization=np.asarray(reg, dtype=float).reshape(m, 1))
        res = {}
        for name_, o in outs.items():  # views, no copies
            if o.shape[1:] == (1, 1):
                res[name_] = o[:, 0, 0]
            elif o.shape[2] == 1:
                res[name_] = o[:, :, 0]
            else:
                res[name_] = o
        return res

    sol = solve_active_set(call, n, model.present, model.bounds, max_iter=max_iter)
    return finish_rows(model, base, n, sol, max_iter)  # weak rows, mass matrix, sanity

