"""The contact check of a run: whether two bodies overlap by more than a tolerance.

The model knows one contact (a point fixed in the object against the contact link's face);
nothing in its equations keeps the links out of the object or out of each other. The check
measures what it leaves out, from the geometry the scene already has
(:class:`snakecg.geometry.ContactCheck`: every link against the object, the contact link
included, and every pair of links that are not neighbours, as overlap depths), at the start,
at every step's end, at every output sample and at the state after every event. The first
time an overlap exceeds the tolerance (:func:`snakecg.geometry.contact_tolerance`) is located
between the last two checks by Brent's method on the integrator's dense output.

``geometry_check`` (:func:`~snakecg.simulate.simulate`) says what then happens:

* ``"stop"`` (the default): the run ends there, with status ``"penetration"`` or
  ``"self_contact"``; its last sample is the state at that time;
* ``"report"``: the run goes on as without the check (the same trajectory), the first
  violation is reported all the same (and is the status);
* ``"off"``: no check; the status is ``"completed (geometry not checked)"``.

In compiled segments the check runs in C (``geometry.c``, ``sc_geometry``); this class holds
its struct and does the same in Python for the segments that ``solve_ivp`` integrates.
"""

from __future__ import annotations


import numpy as np

from ..engine.binding import Geometry, address, array_address
from ..engine.segment import GEO_OFF, GEO_RECORD, GEO_STOP
from ..errors import InputError
from ..geometry import ContactCheck
from .records import Violation

__all__ = ["MODES", "RunCheck"]

#: The values of ``geometry_check``.
MODES = ("stop", "report", "off")
_CODES = {"stop": GEO_STOP, "report": GEO_RECORD, "off": GEO_OFF}
_XTOL = 4 * float(np.finfo(float).eps)  # Brent's method as the events' (scipy's brentq)


def _shape_of(model):
    """The :class:`~snakecg.geometry.ContactCheck` of a model and its link lengths, made once
    (kept in the model's data)."""
    derived = model.data().derived
    got = derived.get("simulate.shapes")
    if got is None:
        robot = model.scene.robot
        got = derived["simulate.shapes"] = (ContactCheck.of_scene(model.scene),
                                np.ascontiguousarray(robot.length, dtype=float),
                                float(robot.com[0]))
    return got


class RunCheck:
    """The contact check of one run of ``model`` in ``mode`` (:data:`MODES`); ``ns``, ``ny``:
    the sizes of ``q`` and of the integrated state ``y = (q, q_obj, ...)``.

    ``struct``: the :class:`~snakecg.engine.segment.Geometry` the compiled segments read and
    fill (its address ``address``); the first violation is kept there, by C or by Python.
    ``shape``: another :class:`~snakecg.geometry.ContactCheck` of the model's scene (its
    tolerance, segments instead of capsules) in place of the model's own.
    """

    def __init__(self, model, mode: str, ns: int, ny: int, shape: ContactCheck | None = None):
        self.mode = mode
        self.shape, self._length, com1 = _shape_of(model)
        if shape is not None:
            self.shape = shape
        self.tolerance = self.shape.tolerance
        self.ns, self.ny = ns, ny
        # the state of the first violation; then one state checked (_one), its depth and pair
        self._y = np.zeros(2 * ny + 2)
        base = self._y.ctypes.data
        self._one_addresses = (base + 8 * ny, base + 16 * ny, base + 8 * (2 * ny + 1))
        g = self.struct = Geometry()
        g.mode = _CODES[mode]
        g.tol, g.half, g.radius = self.tolerance, self.shape.half, self.shape.radius
        g.length, g.com1 = self._length.ctypes.data, com1
        g.y = self._y.ctypes.data
        self.address = address(g)
        core = getattr(model, "core", None)
        self._c = getattr(core, "contact_depth", None)
        self._first = getattr(core, "contact_first", None)

    @property
    def active(self) -> bool:
        """Looking for a first violation (on, and none found yet)."""
        return self.struct.mode != GEO_OFF and not self.struct.found

    @property
    def stops(self) -> bool:
        """A violation was found and ends the run (``"stop"``)."""
        return bool(self.struct.found) and self.struct.mode == GEO_STOP

    def reset(self) -> None:
        """Forget a violation found (a run done again by the Python loop)."""
        self.struct.found = 0

    def deepest(self, Y) -> tuple[np.ndarray, np.ndarray]:
        """The largest overlap of each state ``Y`` ``(n, n_y)`` (or ``(n_y,)``) and the index
        of its pair (:attr:`snakecg.geometry.ContactCheck.pairs`): in C when the model has
        its compiled library, else in NumPy."""
        Y = np.ascontiguousarray(Y, dtype=float).reshape(-1, self.ny)
        if self._c is not None:
            depth, pair = np.empty(len(Y)), np.empty(len(Y))
            self._c(self.address, len(Y), Y.ctypes.data, depth.ctypes.data, pair.ctypes.data)
            return depth, pair.astype(np.intp)
        return self.shape.deepest(Y[:, :self.ns], Y[:, self.ns:self.ns + 3])

    def first_beyond(self, states, tol: float) -> tuple[int | None, float, int]:
        """The first of ``states`` ``(n, >= n_s + 3)`` (rows of ``q``, ``q_obj``, then
        anything; a view with its rows apart is read in place where compiled) whose largest
        overlap exceeds ``tol``: its index (None where none), that overlap and its pair."""
        states = np.asarray(states, dtype=float)
        if self._first is None or states.strides[1] != 8 or states.strides[0] % 8:
            depth, pair = self._deepest_of(states)
            beyond = np.flatnonzero(depth > tol)
            if not beyond.size:
                return None, 0.0, -1
            k = int(beyond[0])
            return k, float(depth[k]), int(pair[k])
        out = np.empty(2)  # (its own: a check may be shared by threads)
        k = self._first(self.address, len(states), states.ctypes.data, states.strides[0] // 8,
                        float(tol), array_address(out))
        if k >= len(states):
            return None, 0.0, -1
        return k, float(out[0]), int(out[1])

    def _deepest_of(self, states) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`deepest` of states ``(n, >= n_s + 3)`` (``q``, ``q_obj`` first)."""
        Y = np.zeros((len(states), self.ny))
        Y[:, :self.ns + 3] = states[:, :self.ns + 3]
        return self.deepest(Y)

    def _record(self, t, y, depth, pair) -> None:
        g = self.struct
        g.found, g.t, g.depth, g.pair = 1, float(t), float(depth), int(pair)
        self._y[:self.ny] = y

    def _one(self, y) -> tuple[float, int]:
        """:meth:`deepest` of one contiguous state (one C call when compiled)."""
        if self._c is None:
            d, p = self.deepest(y)
            return float(d[0]), int(p[0])
        ny = self.ny
        self._y[ny:2 * ny] = y
        self._c(self.address, 1, *self._one_addresses)
        return float(self._y[2 * ny]), int(self._y[2 * ny + 1])

    def check_start(self, y) -> None:
        """The initial state: an :class:`~snakecg.InputError` naming the bodies when they
        overlap beyond the tolerance (``"off"`` runs it anyway)."""
        if self.struct.mode == GEO_OFF:
            return
        d, p = self._one(y)
        if d > self.tolerance:
            kind, (a, b) = self.shape.kind(p), self.shape.bodies(p)
            what = (f"link {a} penetrates the object" if kind == "penetration"
                    else f"links {a} and {b} cross")
            raise InputError(f"the initial state is not physical: {what} by {d:.3g} m "
                             f"(tolerance {self.tolerance:.3g} m); move the robot or the "
                             "object (q0, q_obj0), or pass geometry_check='off' to simulate "
                             "it anyway")

    def at(self, t, y) -> bool:
        """Check one state (after an event); whether the run stops there."""
        if self.active:
            d, p = self._one(y)
            if d > self.tolerance:
                self._record(t, y, d, p)
        return self.stops

    def scan(self, t0, y0, times, Y, interpolant) -> float | None:
        """Check a segment from ``(t0, y0)`` at the increasing ``times`` (its steps' ends and
        output samples) with the states ``Y`` there, ``interpolant(t)`` its dense output:
        the time of the first violation (recorded), located by Brent's method between the
        last check within the tolerance and the first beyond it, or ``None``."""
        if not self.active:
            return None
        if self.at(t0, y0) or self.struct.found:
            return float(t0)
        depth, _ = self.deepest(Y)
        beyond = np.flatnonzero(depth > self.tolerance)
        if not beyond.size:
            return None
        from scipy.optimize import brentq

        j = int(beyond[0])
        ta, tb = (times[j - 1] if j else t0), times[j]
        tol = self.tolerance

        def margin(s):
            return tol - self.deepest(interpolant(s))[0][0]

        root = brentq(margin, ta, tb, xtol=_XTOL, rtol=_XTOL) if margin(ta) >= 0 else ta
        y = np.asarray(interpolant(root), dtype=float).reshape(self.ny)
        d, p = self.deepest(y)
        self._record(root, y, d[0], p[0])
        return float(root)

    def event(self):
        """The check as an event function of :func:`scipy.integrate.solve_ivp`: the
        tolerance less the largest overlap, crossing zero downwards (terminal with
        ``"stop"``), evaluated at every step's end and located on the dense output."""
        tol, one = self.tolerance, self._one

        def margin(t, y):
            return tol - one(y)[0]

        margin.terminal = self.struct.mode == GEO_STOP
        margin.direction = -1
        return margin

    def solved(self, t0, y0, ts, Y, root, rerun) -> float | None:
        """The check of a segment that solve_ivp integrated from ``(t0, y0)`` with
        :meth:`event`: its output samples ``ts``, ``Y`` and ``root``, ``(t, y)`` of the
        event's first root (or ``None``). A sample beyond the tolerance before that root
        (between two steps' ends, where the event is not evaluated) is located on the dense
        output of ``rerun()``, the same segment again with it. The time of the first
        violation (recorded), or ``None``."""
        if not self.active:
            return None
        end = root[0] if root is not None else np.inf
        keep = (ts > t0) & (ts <= end)
        beyond = np.flatnonzero(self.deepest(Y[keep])[0] > self.tolerance) if keep.any() \
            else ()
        if len(beyond):
            dense = rerun().sol
            tb = ts[keep][beyond[0]]
            steps = np.asarray(dense.ts)
            pts = np.union1d(steps[(steps > t0) & (steps <= tb)], ts[keep & (ts <= tb)])
            return self.scan(t0, y0, pts, dense(pts).T, dense)
        if root is not None:
            d, p = self._one(root[1])
            self._record(root[0], root[1], d, p)
            return root[0]
        return None

    @property
    def violation(self) -> Violation | None:
        """The first violation found, or ``None``."""
        g = self.struct
        if not g.found:
            return None
        return Violation(kind=self.shape.kind(int(g.pair)), t=float(g.t),
                         bodies=self.shape.bodies(int(g.pair)), depth=float(g.depth),
                         tolerance=self.tolerance, y=self._y[:self.ny].copy())

    def status(self, status: str) -> str:
        """The run's status given the integration's (``"completed"`` or where it stopped):
        the first violation's kind when there is one, and says so when nothing was
        checked."""
        if self.struct.found:
            return self.shape.kind(int(self.struct.pair))
        if self.struct.mode == GEO_OFF and status == "completed":
            return "completed (geometry not checked)"
        return status

    def describe(self) -> dict:
        """What was checked, for the summary."""
        return {"mode": self.mode, "tolerance": self.tolerance,
                "object": f"square plate of side {2 * self.shape.half:g} m",
                "link_radius": self.shape.radius}
