"""A configuration's contacts and constraint rows as Python objects (:class:`Contact`,
:class:`Rows`: what a :class:`~snakecg.scenes.metrics.SceneResult` reports for checks), read
from the engine that finds and builds them (``snakecg/engine/scene_rows.c``): at rest
(the objects placed by the scene) or at a simulation's state (the objects where they are, the
run's tolerance) through :class:`StateRows`; and the links' ends at a configuration (what the
drawing shows; the objects' placement is the engine's,
:meth:`~snakecg.scenes.model.GeneralSceneModel.object_poses`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..engine.binding import SceneStateCall, address
from ..errors import BuildError, InputError
from .description import GeneralScene
from .packing import BODY_KINDS, CR_W, FRICTION_STATES, MAX_ROWS

__all__ = ["Contact", "Rows", "StateRows", "read_rows", "link_ends"]

#: the engine's rows' outputs (scene_rows.c's RO_*): status, contacts, rows, blocks, an
#: overlap's record, then the objects' poses and the contacts
RO_NC, RO_M, RO_NB, RO_OVERLAP, RO_POSE = 1, 2, 3, 4, 10
#: the engine's statuses of a state: an overlap beyond the tolerance, more contacts than the
#: room, a generated function that refused
_OVERLAP, _MORE, _FAILED = 3, 4, 6


@dataclass
class Contact:
    """A contact between bodies ``a`` and ``b`` (``("link", i)``, ``("object", j)``,
    ``("obstacle", k)``, 0-based), at surface points ``point_a``/``point_b`` with the unit
    normal from a to b, and its row index; where the scene has contact friction, the pair's
    ``mu`` and the last solve's ``friction`` force (an impact's: impulse) along the tangent
    ``(-n_y, n_x)`` on ``b`` and its state (``stick``, ``slip``, ``open``; ``none`` where the
    pair has no friction); else ``mu`` 0, ``friction`` 0 and ``friction_state`` None."""

    a: tuple
    b: tuple
    point_a: np.ndarray
    point_b: np.ndarray
    normal: np.ndarray
    gap: float
    row: int
    mu: float = 0.0
    friction: float = 0.0
    friction_state: str | None = None


@dataclass
class Rows:
    """The rows ``A`` (m x n) and their blocks ``kind``, ``start``, ``par`` (nb x 3), the
    contacts, and what each block is (``labels``)."""

    A: np.ndarray
    kind: list
    start: list
    par: list
    contacts: list
    labels: list


def link_ends(scene: GeneralScene, poses) -> np.ndarray:
    """Rear and front ends of every link (n_l, 2, 2) from the COM poses."""
    r = scene.robot
    out = np.empty((r.n_links, 2, 2))
    for i, (x, y, phi) in enumerate(poses):
        t = np.array([np.cos(phi), np.sin(phi)])
        rear = np.array([x, y]) - r.com[i] * t
        out[i] = (rear, rear + r.length[i] * t)
    return out


def read_rows(model, out, A, par, kind, start) -> Rows:
    """The :class:`Rows` of the engine's outputs at a state (``out``: ``RO_*``, the objects'
    poses, the contacts' records; the rows ``A``, the blocks' ``par``, ``kind``, ``start``)."""
    no = model.scene.n_objects
    nc, m, nb = int(out[RO_NC]), int(out[RO_M]), int(out[RO_NB])
    off = RO_POSE + 3 * no
    friction = model.packed.friction
    contacts = []
    for c in range(nc):
        r = out[off + CR_W * c: off + CR_W * (c + 1)]
        fr = (float(r[13]), float(r[14]), FRICTION_STATES[int(r[15])] if r[13] > 0
              else "none") if friction else ()
        contacts.append(Contact((BODY_KINDS[int(r[0])], int(r[1])),
                                (BODY_KINDS[int(r[2])], int(r[3])), r[4:6].copy(),
                                r[6:8].copy(), r[8:10].copy(), float(r[10]), c, *fr))
    return Rows(A[:m].copy(), kind[:nb].tolist(), start[:nb].tolist(),
                [tuple(p) for p in par[:nb].tolist()], contacts,
                [("contact", c) for c in range(nc)] + list(model.packed.labels))


class StateRows:
    """The engine's rows and pairs' distances at states of one general scene model
    (``core_scene_rows``, ``core_scene_gaps`` of ``snakecg/engine/scene_rows.c``), with its
    buffers made once: a simulation's workspace (one per run), or one query's.

    ``tol`` (m): the contact tolerance (default the scene's, ``tolerance`` times its size)."""

    def __init__(self, model, tol: float | None = None):
        core = model.core
        if getattr(core, "scene_rows", None) is None:
            raise BuildError("a general scene's rows are built by the compiled engine; load "
                             "it with a C compiler (set CC) and the compiled backend")
        self.model = model
        pk = model.packed
        self.ns, self.no = model.n_coordinates, model.scene.n_objects
        self.n = n = self.ns + 3 * self.no
        self.tol = pk.tolerance if tol is None else float(tol)
        nl, nob = model.n_links, len(model.scene.obstacles)
        pairs = (nl * (nl - 1) // 2 - (nl - 1) + nl * (self.no + nob)
                 + self.no * (self.no - 1) // 2 + self.no * nob)
        room = (MAX_ROWS - pk.ground_rows) // (2 if pk.friction else 1)
        self.ccap = max(1, min(4 * pairs, room))  # every pair's
        self.mcap = pk.rows_room(self.ccap)
        self.gcap = max(1, pairs)
        self.q = np.zeros(self.ns)
        self.qo = np.zeros(max(1, 3 * self.no))
        self.out = np.zeros(RO_POSE + 3 * self.no + CR_W * self.ccap)
        self.gap_buf = np.zeros(5 * self.gcap)
        self.M = np.zeros((n, n))
        self.A = np.zeros((self.mcap, n))
        self.par = np.zeros((self.mcap, 3))
        self.kind = np.zeros(self.mcap, dtype=np.int64)
        self.start = np.zeros(self.mcap, dtype=np.int64)
        self.args = SceneStateCall(model._pk, self.q.ctypes.data, self.qo.ctypes.data,
                                   self.tol, 0.0, self.ccap, self.mcap, -1, -1,
                                   self.out.ctypes.data, self.M.ctypes.data,
                                   self.A.ctypes.data, self.par.ctypes.data,
                                   self.kind.ctypes.data, self.start.ctypes.data)
        self._address = address(self.args)
        self._rows, self._gaps = core.scene_rows, core.scene_gaps
        self._index = {}
        for k in range(nl + self.no + nob):
            kind = 0 if k < nl else (1 if k < nl + self.no else 2)
            self._index[(BODY_KINDS[kind], k - (0 if kind == 0 else nl if kind == 1
                                                else nl + self.no))] = k

    def _state(self, q, obj_poses):
        self.q[:] = q
        if obj_poses is None:
            self.args.qo = None
        else:
            self.args.qo = self.qo.ctypes.data
            self.qo[:3 * self.no] = np.asarray(obj_poses, dtype=float).reshape(-1)

    def rows(self, q, obj_poses=None, *, mass=True, index=None):
        """``(rows, M, obj_poses)`` at ``q`` (n_s,) with the objects at ``obj_poses``
        (n_objects, 3; default: placed by the scene): the :class:`Rows` (contacts within the
        tolerance first, one unilateral row each, then the ground's blocks), the bodies'
        inertia ``M`` (n x n; None unless ``mass``) and the objects' poses. Raises
        :class:`InputError` where a pair overlaps beyond the tolerance (``index``: the
        sample's, named in the message)."""
        self._state(q, obj_poses)
        self.args.M = self.M.ctypes.data if mass else None
        code = self._rows(self._address)
        out = self.out
        if code != 0:
            if code == -3:
                raise InputError("the state is not finite (q or the objects' poses)")
            raise MemoryError("the scene's rows ran out of memory") if code == -1 else \
                ValueError(f"core_scene_rows refused its sizes ({code})")
        if int(out[0]) != 0:
            raise InputError(self.refusal(out, index))
        poses = out[RO_POSE:RO_POSE + 3 * self.no].reshape(self.no, 3).copy()
        return (read_rows(self.model, out, self.A, self.par, self.kind, self.start),
                (self.M.copy() if mass else None), poses)

    def refusal(self, out, index=None) -> str:
        """Why the engine refused the rows of a state (``out``: its outputs)."""
        status = int(out[0])
        if status == _OVERLAP:
            return self.model.overlap_message(out[RO_OVERLAP:RO_OVERLAP + 6], index)
        if status == _MORE:
            return (f"more than {self.ccap} contacts at this state, beyond the rows the solve "
                    "takes")
        return "a generated function refused the state"

    def gaps(self, q, obj_poses, margin: float) -> list:
        """``[(body_a, body_b, d)]``: the signed distance of every pair of bodies that can
        touch (links that are not neighbours, links with objects and obstacles, objects with
        each other and obstacles) whose bounding circles are within ``margin`` (m) of each
        other, at ``q`` and the objects' poses, overlapping or not."""
        self._state(q, obj_poses)
        self.args.margin = float(margin)
        self.args.pair_a = self.args.pair_b = -1
        return self._read_gaps(self._call_gaps())

    def gap(self, q, obj_poses, a, b) -> float:
        """The signed distance (m) of bodies ``a`` and ``b`` (``("link", i)``, ...) at
        ``q`` and the objects' poses."""
        self._state(q, obj_poses)
        self.args.pair_a, self.args.pair_b = self._index[a], self._index[b]
        found = self._call_gaps()
        self.args.pair_a = self.args.pair_b = -1
        if found != 1:
            raise ValueError(f"{a} and {b} are not a pair that can touch")
        return float(self.gap_buf[4])

    def _call_gaps(self) -> int:
        self.args.ccap, out = self.gcap, self.args.out
        self.args.out = self.gap_buf.ctypes.data
        try:
            found = self._gaps(self._address)
        finally:
            self.args.ccap, self.args.out = self.ccap, out
        if found < 0:
            if found == -3:
                raise InputError("the state is not finite (q or the objects' poses)")
            raise MemoryError("the scene's gaps ran out of memory") if found == -1 else \
                ValueError(f"core_scene_gaps refused ({found})")
        return min(found, self.gcap)

    def _read_gaps(self, k) -> list:
        g = self.gap_buf[:5 * k].reshape(k, 5)
        return [((BODY_KINDS[int(r[0])], int(r[1])), (BODY_KINDS[int(r[2])], int(r[3])),
                 float(r[4])) for r in g]
