"""What a simulation gives back: :class:`Trajectory`, its :class:`SimEvent` records, the
:class:`Violation` of the contact check, the :class:`State` a feedback law sees,
:class:`SimulationError`, and the JSON form of the summary (schema :data:`SCHEMA`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import SnakecgError

__all__ = ["SCHEMA", "Deferred", "SimEvent", "SimulationError", "State", "Trajectory",
           "Violation", "jsonable"]

#: Version of the summary dictionary (``Trajectory.summary``, ``snakecg simulate --json``).
SCHEMA = "snakecg.simulate/1"


class SimulationError(SnakecgError, RuntimeError):
    """The integration failed (integrator error, a torque law that returned bad values...)."""


@dataclass(frozen=True)
class State:
    """What a feedback law ``tau(t, state)`` sees.

    ``q`` (n_s), ``v`` (n_s), ``q_obj`` (3), ``v_obj`` (3), ``rho`` (2, the contact point in
    the object frame), ``contact`` (the contact is held in the current mode) and
    ``wheel_state`` (n_l strings, as in :class:`snakecg.ForwardResult`).
    """

    t: float
    q: np.ndarray
    v: np.ndarray
    q_obj: np.ndarray
    v_obj: np.ndarray
    rho: np.ndarray
    contact: bool
    wheel_state: tuple


@dataclass
class SimEvent:
    """A transition: ``kind`` is ``"impact"`` (the contact closes with a plastic impact),
    ``"touch"`` (it closes with no normal velocity), ``"separation"``, ``"off_link"`` (the
    contact point left the link), ``"breakaway"``, ``"stick"``, ``"reverse"`` (a sliding
    wheel that stops and slides back) or ``"projection"`` (velocities made consistent with
    the held rows by an impulse, e.g. initial velocities against ideal wheels); ``row`` is
    the constraint row (0 the contact, ``i`` the wheel of link ``i``); ``before``/``after``
    describe the modes; ``data`` holds numbers such as the impulse and the energy lost."""

    t: float
    kind: str
    row: int
    before: str
    after: str
    data: dict = field(default_factory=dict)

    def to_dict(self) -> dict:
        return {"t": self.t, "kind": self.kind, "row": self.row, "before": self.before,
                "after": self.after, **{k: jsonable(v) for k, v in self.data.items()}}


@dataclass(frozen=True)
class Violation:
    """The first time two bodies overlapped by more than the contact check's tolerance
    (:class:`snakecg.geometry.ContactCheck`).

    ``kind``: ``"penetration"`` (a link and the object) or ``"self_contact"`` (two links
    that are not neighbours); ``t`` (s): when, located between the checks (every step's end,
    every output sample, the state after every event) on the integrator's dense output;
    ``bodies``: ``(link, "object")`` or ``(link, link)``, links numbered from 1 (the tail);
    ``depth`` (m): the overlap there, the ``tolerance`` (m) to the root finder's accuracy
    (more when the overlap appeared at once, at an event); ``y``: the state there.
    """

    kind: str
    t: float
    bodies: tuple
    depth: float
    tolerance: float
    y: np.ndarray = field(repr=False, compare=False)

    def describe(self) -> str:
        """One line: what overlapped, by how much, when."""
        a, b = self.bodies
        what = (f"link {a} entered the object" if b == "object"
                else f"links {a} and {b} crossed")
        return (f"{what} at t = {self.t:.6g} s (overlap {self.depth:.3g} m, tolerance "
                f"{self.tolerance:.3g} m)")

    def to_dict(self) -> dict:
        return jsonable({"kind": self.kind, "t": self.t, "bodies": list(self.bodies),
                         "depth": self.depth, "tolerance": self.tolerance,
                         "description": self.describe()})


@dataclass
class Trajectory:
    """A simulated trajectory, sampled at ``t`` (N,) (uniform output times plus both sides of
    every event, so a time may repeat).

    * state: ``q`` (N, n_s), ``v`` (N, n_s), ``q_obj`` (N, 3), ``v_obj`` (N, 3); ``rho`` (2,);
    * input and forces: ``tau`` (N, n_a), ``lam`` (N, n_c) (row 0 the contact, row ``i`` the
      wheel of link ``i``), accelerations ``qdd`` (N, n_s), ``a_obj`` (N, 3);
    * flags: ``contact`` (N,) bool (held), ``wheel_state`` (N, n_l) (``"none"``, ``"stick"``,
      ``"slide+"``, ``"slide-"``: force at ``+-mu m g``), ``events`` (list of :class:`SimEvent`);
    * metrics: instantaneous ``sr`` (eq. 30), ``norm_a_obj``, ``norm_qdd``; the
      displacement-based slippage ratio ``sr_displacement`` (see docs/how-to/simulate.md); the
      snake's COM ``com`` (N, 2); ``link_poses`` (N, n_l, 3);
    * constraint rows: ``gap`` (N,), ``s`` (N,) (contact position along the link),
      ``row_velocity`` (N, n_c) (``gdot``, lateral wheel velocities ``u_i``);
    * energy: ``kinetic_energy`` (N,), ``power_tau``, ``power_friction`` (N,), cumulative
      ``work_tau``, ``work_friction``, ``work_object``, ``impact_loss``
      (N,) and ``energy_residual`` = kinetic energy gained minus all of those;
    * ``summary``: a JSON-ready dictionary (schema ``snakecg.simulate/1``, docs/how-to/simulate.md),
      computed from the arrays above on first access (given as a function of the trajectory,
      it is called then; a run that never reads it does not pay for it);
    * ``violation``: the contact check's first :class:`Violation`, or ``None`` (its kind is
      then the ``summary``'s status; with ``geometry_check="stop"`` it is the last sample).

    Any other field may be given as a :class:`Deferred`: it is computed when first read
    (``simulate`` defers the fields that need the mass matrices and link poses of the samples,
    the ones from the modes' tables and ``geometry``); a copy, a pickle, ``arrays()`` and
    ``save()`` compute them first.
    """

    t: np.ndarray
    q: np.ndarray
    v: np.ndarray
    q_obj: np.ndarray
    v_obj: np.ndarray
    rho: np.ndarray
    tau: np.ndarray
    lam: np.ndarray
    qdd: np.ndarray
    a_obj: np.ndarray
    contact: np.ndarray
    wheel_state: np.ndarray
    sr: np.ndarray
    norm_a_obj: np.ndarray
    norm_qdd: np.ndarray
    sr_displacement: np.ndarray
    com: np.ndarray
    link_poses: np.ndarray
    gap: np.ndarray
    s: np.ndarray
    row_velocity: np.ndarray
    kinetic_energy: np.ndarray
    power_tau: np.ndarray
    power_friction: np.ndarray
    work_tau: np.ndarray
    work_friction: np.ndarray
    work_object: np.ndarray
    power_constraint: np.ndarray
    impact_loss: np.ndarray
    energy_residual: np.ndarray
    events: list
    summary: dict
    geometry: dict = field(repr=False, default_factory=dict)
    violation: Violation | None = None

    def __post_init__(self):
        d = self.__dict__
        if callable(self.summary):  # computed on first access (__getattr__)
            d["_summarize"] = d.pop("summary")
        deferred = {k: v for k, v in d.items() if type(v) is Deferred}
        if deferred:  # computed on first access (__getattr__)
            for k in deferred:
                del d[k]
            d["_deferred"] = deferred

    def __getattr__(self, name):
        # only reached for a field not computed yet (or a name that is no field)
        d = self.__dict__
        deferred = d.get("_deferred")
        if deferred and name in deferred:
            group = deferred[name]
            for k, v in group.compute().items():
                if deferred.get(k) is group:
                    del deferred[k]
                    d.setdefault(k, v)  # unless set meanwhile
            if not deferred:
                del d["_deferred"]
            return d[name]
        summarize = d.get("_summarize")
        if name != "summary" or summarize is None:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        self.summary = summarize(self)
        del d["_summarize"]
        return self.summary

    def __getstate__(self):
        for name in list(self.__dict__.get("_deferred", ())):
            getattr(self, name)  # computed before a copy or a pickle
        self.summary  # noqa: B018 - computed before a copy or a pickle
        return self.__dict__

    @property
    def n_samples(self) -> int:
        return int(self.t.shape[0])

    def at(self, t: float) -> int:
        """Index of the last sample at or before time ``t``."""
        return int(max(0, np.searchsorted(self.t, t, side="right") - 1))

    def arrays(self) -> dict[str, np.ndarray]:
        """Every per-sample array by name (for ``numpy.savez``)."""
        skip = {"events", "summary", "geometry", "violation"}
        return {k: np.asarray(getattr(self, k)) for k in self.__dataclass_fields__
                if k not in skip}

    def save(self, path) -> None:
        """Write the arrays to a ``.npz`` file (the summary goes to JSON separately),
        atomically: a unique temporary name in the same folder, then ``os.replace``."""
        from .._files import atomic_path

        with atomic_path(path) as tmp, open(tmp, "wb") as fh:
            np.savez_compressed(fh, **self.arrays())


class Deferred:
    """Fields of a :class:`Trajectory` computed together when one of them is first read:
    ``compute()`` returns them by name (the same :class:`Deferred` is given for each)."""

    __slots__ = ("compute",)

    def __init__(self, compute):
        self.compute = compute


def jsonable(x):
    """``x`` with NumPy scalars and arrays turned into Python numbers and lists, and
    non-finite floats into ``None`` (strict JSON)."""
    if isinstance(x, dict):
        return {k: jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return jsonable(x.tolist())
    if isinstance(x, (np.bool_, bool)):
        return bool(x)
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        x = float(x)
        return x if math.isfinite(x) else None
    return x
