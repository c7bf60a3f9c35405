"""Spatial serial chains from URDF (yourdfpy) and MJCF (MuJoCo's own parser).

Both readers return a :class:`~snakecg.SpatialRobot`: the root link (body) is the floating
base, link 1; each link has at most one child through a revolute joint (URDF ``revolute`` or
``continuous``, MJCF ``hinge``); joint origins, axes, masses, COMs and full inertias are kept
as the file gives them, with the joints' position limits (``joint_limits``) and effort limits
(``effort_limits``; MJCF: a hinge's ``actuatorfrcrange``, else the bound of the actuators
driving it; infinite where the file gives none). Anything else is refused with an
:class:`~snakecg.InputError` naming the element: a branch, a loop (MJCF: the equality that
closes it), a prismatic, ball, planar or floating joint (MJCF: a free joint anywhere but on
the root body), two joints in one body, a fixed joint to a link with mass (URDF; massless tip
frames are skipped), a body without a joint beyond the root (MJCF). An MJCF joint's armature
is left out, with a warning naming the joint.

:func:`planar_robot` turns a spatial chain whose joint axes are all parallel and point the
same way, straight in its zero configuration, into the planar :class:`~snakecg.Robot` (the
form today's planar pipeline takes, the same joint angles and limits), or says why it cannot.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import InputError, NotPlanarError

__all__ = ["spatial_from_urdf", "spatial_from_mjcf", "planar_robot", "rpy_of",
           "spatial_chain_or_planar"]

_REVOLUTE = ("revolute", "continuous")


def rpy_of(R) -> tuple[float, float, float]:
    """Roll, pitch, yaw with ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (URDF's convention)."""
    R = np.asarray(R, dtype=float)
    pitch = float(np.arctan2(-R[2, 0], np.hypot(R[0, 0], R[1, 0])))
    if np.hypot(R[0, 0], R[1, 0]) > 1e-12:
        roll = float(np.arctan2(R[2, 1], R[2, 2]))
        yaw = float(np.arctan2(R[1, 0], R[0, 0]))
    else:  # gimbal lock: the yaw absorbs the roll
        roll, yaw = 0.0, float(np.arctan2(-R[0, 1], R[1, 1]))
    return roll, pitch, yaw


def _six(I) -> list[float]:
    return [I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]]


def _robot(robot_type, where, name, links, joints, gravity=(0.0, 0.0, -9.81)):
    try:
        return robot_type(
            joints=len(joints), mass=[lk["mass"] for lk in links],
            com=[lk["com"] for lk in links], inertia=[lk["inertia"] for lk in links],
            joint_xyz=[j["xyz"] for j in joints], joint_rpy=[j["rpy"] for j in joints],
            joint_axis=[j["axis"] for j in joints], gravity=gravity,
            joint_limits=[j["limits"] for j in joints],
            effort_limits=[j["effort"] for j in joints], name=name,
            link_names=tuple(lk["name"] for lk in links),
            joint_names=tuple(j["name"] for j in joints))
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None


# ------------------------------------------------------------------------------------------
# URDF
# ------------------------------------------------------------------------------------------
def spatial_from_urdf(path, *, robot_type, name: str | None = None):
    """The spatial chain of a URDF file (see the module doc), a ``robot_type``
    (:class:`~snakecg.SpatialRobot`); needs the ``urdf`` extra."""
    from ..urdf import _load  # the planar reader's checked loading (XML, yourdfpy)

    p, urdf = _load(path)
    where = f"URDF file {str(p)!r}"
    robot = urdf.robot
    links = {ln.name: ln for ln in robot.links}
    children: dict[str, list] = {n: [] for n in links}
    parents: dict[str, object] = {}
    for j in robot.joints:
        if j.parent not in links or j.child not in links:
            raise InputError(f"{where}: joint {j.name!r} connects unknown links "
                             f"{j.parent!r} -> {j.child!r}")
        if j.child in parents:
            raise InputError(f"{where}: link {j.child!r} has two parent joints "
                             f"({parents[j.child].name!r}, {j.name!r}): a loop")
        children[j.parent].append(j)
        parents[j.child] = j
    roots = [n for n in links if n not in parents]
    if len(roots) != 1:
        raise InputError(f"{where}: expected one root link, found {len(roots)}: "
                         f"{', '.join(roots) or 'none (the joints form a loop)'}")
    chain, chain_joints = [roots[0]], []
    while True:
        here = chain[-1]
        moving = []
        for j in children[here]:
            if j.type in _REVOLUTE:
                moving.append(j)
            elif j.type == "fixed":
                child = links[j.child]
                mass = 0.0 if child.inertial is None else float(child.inertial.mass or 0.0)
                if mass > 0 or children[j.child]:
                    raise InputError(f"{where}: fixed joint {j.name!r} attaches link "
                                     f"{j.child!r}, which has mass or children; merge it into "
                                     f"link {here!r} (only massless tip frames may be fixed)")
            else:
                raise InputError(f"{where}: joint {j.name!r} is {j.type}; a snake is a chain "
                                 "of revolute joints")
        if len(moving) > 1:
            raise InputError(f"{where}: the chain branches at link {here!r} (joints "
                             f"{', '.join(repr(j.name) for j in moving)})")
        if not moving:
            break
        chain_joints.append(moving[0])
        chain.append(moving[0].child)
    if not chain_joints:
        raise InputError(f"{where}: no revolute joint; a snake has at least one")
    out_links = []
    for ln in chain:
        link = links[ln]
        inertial = link.inertial
        m = 0.0 if inertial is None or inertial.mass is None else float(inertial.mass)
        T = np.eye(4) if inertial is None or inertial.origin is None else np.asarray(
            inertial.origin, dtype=float)
        Ic = np.zeros((3, 3)) if inertial is None or inertial.inertia is None else \
            np.asarray(inertial.inertia, dtype=float)
        out_links.append({"name": ln, "mass": m, "com": T[:3, 3],
                          "inertia": _six(T[:3, :3] @ Ic @ T[:3, :3].T)})
    out_joints = []
    for j in chain_joints:
        T = np.eye(4) if j.origin is None else np.asarray(j.origin, dtype=float)
        lim = j.limit
        lower = getattr(lim, "lower", None) if j.type == "revolute" else None
        upper = getattr(lim, "upper", None) if j.type == "revolute" else None
        effort = getattr(lim, "effort", None)
        out_joints.append({"name": j.name, "xyz": T[:3, 3], "rpy": rpy_of(T[:3, :3]),
                           "axis": (1.0, 0.0, 0.0) if j.axis is None else j.axis,
                           "limits": (-np.inf if lower is None else float(lower),
                                      np.inf if upper is None else float(upper)),
                           "effort": np.inf if effort is None else float(effort)})
    return _robot(robot_type, where, name or robot.name or p.stem, out_links,
                  out_joints)


# ------------------------------------------------------------------------------------------
# MJCF
# ------------------------------------------------------------------------------------------
def _mujoco():
    try:
        import mujoco
    except ImportError:
        raise InputError("reading MJCF needs MuJoCo: pip install 'snakecg[mjcf]'") from None
    return mujoco


def spatial_from_mjcf(path, *, robot_type, name: str | None = None):
    """The spatial chain of a MuJoCo XML file, compiled by ``mujoco.MjModel.from_xml_path``
    (see the module doc), a ``robot_type`` (:class:`~snakecg.SpatialRobot`); needs the
    ``mjcf`` extra."""
    mujoco = _mujoco()
    p = Path(path)
    where = f"MJCF file {str(p)!r}"
    if not p.is_file():
        raise InputError(f"{where} does not exist or is not a file")
    try:
        m = mujoco.MjModel.from_xml_path(str(p))
    except Exception as exc:  # noqa: BLE001 - MuJoCo reports every problem as one kind
        raise InputError(f"{where} cannot be read: {' '.join(str(exc).split())}") from None
    def body_name(b):
        return mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b) or f"body {b}"

    def joint_name(j):
        return mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, j) or f"joint {j}"

    kids: dict[int, list[int]] = {b: [] for b in range(m.nbody)}
    for b in range(1, m.nbody):
        kids[int(m.body_parentid[b])].append(b)
    if len(kids[0]) != 1:
        raise InputError(f"{where}: expected one body in the worldbody, found "
                         f"{len(kids[0])}: {', '.join(body_name(b) for b in kids[0]) or 'none'}")
    chain = [kids[0][0]]
    while kids[chain[-1]]:
        if len(kids[chain[-1]]) > 1:
            raise InputError(f"{where}: the chain branches at body {body_name(chain[-1])!r} "
                             f"(children {', '.join(repr(body_name(b)) for b in kids[chain[-1]])})")
        chain.append(kids[chain[-1]][0])
    if m.neq:
        raise InputError(f"{where}: {_equality_text(mujoco, m, 0)} closes a loop; a snake is a "
                         "serial chain")
    FREE, HINGE = mujoco.mjtJoint.mjJNT_FREE, mujoco.mjtJoint.mjJNT_HINGE
    joint_of = {}
    for k, b in enumerate(chain):
        js = [j for j in range(m.njnt) if m.jnt_bodyid[j] == b]
        for j in js:
            if m.jnt_type[j] == FREE and k == 0:
                continue
            if m.jnt_type[j] != HINGE:
                kind = {int(FREE): "free", int(mujoco.mjtJoint.mjJNT_BALL): "ball",
                        int(mujoco.mjtJoint.mjJNT_SLIDE): "slide"}.get(int(m.jnt_type[j]), "?")
                raise InputError(f"{where}: joint {joint_name(j)!r} of body "
                                 f"{body_name(b)!r} is a {kind} joint; a snake is a chain of "
                                 "hinges on a free root")
        hinges = [j for j in js if m.jnt_type[j] == HINGE]
        if k == 0:
            if hinges:
                raise InputError(f"{where}: the root body {body_name(b)!r} has a hinge "
                                 f"({joint_name(hinges[0])!r}); its base is floating")
            continue
        if len(hinges) != 1:
            raise InputError(f"{where}: body {body_name(b)!r} has {len(hinges)} joints; each "
                             "body after the root needs exactly one hinge")
        joint_of[b] = hinges[0]
    if len(chain) < 2:
        raise InputError(f"{where}: no hinge; a snake has at least one")
    armature = [joint_name(j) for j in range(m.njnt) if np.any(m.dof_armature[
        m.jnt_dofadr[j]:m.jnt_dofadr[j] + _NDOF[int(m.jnt_type[j])]])]
    if armature:
        import warnings

        warnings.warn(f"{where}: the armature of joint(s) {', '.join(map(repr, armature))} is "
                      "not part of a SpatialRobot and is left out (MuJoCo adds it to the mass "
                      "matrix's diagonal)", stacklevel=3)
    mat = lambda quat: _quat_matrix(mujoco, quat)  # noqa: E731
    # each link's frame sits on its joint's axis: the body frame moved by jnt_pos
    shift = {b: (np.zeros(3) if k == 0 else np.asarray(m.jnt_pos[joint_of[b]], dtype=float))
             for k, b in enumerate(chain)}
    links, joints = [], []
    for k, b in enumerate(chain):
        R_i = mat(m.body_iquat[b])
        Ic = R_i @ np.diag(m.body_inertia[b]) @ R_i.T
        links.append({"name": body_name(b), "mass": float(m.body_mass[b]),
                      "com": np.asarray(m.body_ipos[b]) - shift[b], "inertia": _six(Ic)})
        if k == 0:
            continue
        j = joint_of[b]
        R = mat(m.body_quat[b])
        parent = chain[k - 1]
        xyz = np.asarray(m.body_pos[b]) - shift[parent] + R @ shift[b]
        limited = bool(m.jnt_limited[j])
        effort = _effort(mujoco, m, j)
        joints.append({"name": joint_name(j), "xyz": xyz, "rpy": rpy_of(R),
                       "axis": np.asarray(m.jnt_axis[j], dtype=float),
                       "limits": tuple(map(float, m.jnt_range[j])) if limited
                       else (-np.inf, np.inf), "effort": effort})
    return _robot(robot_type, where, name or p.stem, links, joints,
                  gravity=tuple(map(float, m.opt.gravity)))


#: Degrees of freedom of MuJoCo's joint types (free, ball, slide, hinge).
_NDOF = {0: 6, 1: 3, 2: 1, 3: 1}


def _equality_text(mujoco, m, e) -> str:
    """``equality 'name' (connect: bodies 'a' and 'b')``: the element a loop is closed by."""
    kinds = {int(mujoco.mjtEq.mjEQ_CONNECT): "connect", int(mujoco.mjtEq.mjEQ_WELD): "weld",
             int(mujoco.mjtEq.mjEQ_JOINT): "joint", int(mujoco.mjtEq.mjEQ_TENDON): "tendon"}
    kind = kinds.get(int(m.eq_type[e]), "constraint")
    obj = {"connect": mujoco.mjtObj.mjOBJ_BODY, "weld": mujoco.mjtObj.mjOBJ_BODY,
           "joint": mujoco.mjtObj.mjOBJ_JOINT, "tendon": mujoco.mjtObj.mjOBJ_TENDON}.get(kind)
    if kind in ("connect", "weld") and int(m.eq_objtype[e]) == int(mujoco.mjtObj.mjOBJ_SITE):
        obj = mujoco.mjtObj.mjOBJ_SITE
    name = mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_EQUALITY, e)
    text = f"equality {name!r}" if name else f"equality constraint {e + 1} (unnamed)"
    if obj is None:
        return f"{text} ({kind})"
    what = {mujoco.mjtObj.mjOBJ_BODY: "bodies", mujoco.mjtObj.mjOBJ_SITE: "sites",
            mujoco.mjtObj.mjOBJ_JOINT: "joints", mujoco.mjtObj.mjOBJ_TENDON: "tendons"}[obj]
    ids = [int(m.eq_obj1id[e]), int(m.eq_obj2id[e])]
    names = [repr(mujoco.mj_id2name(m, obj, i) or f"{i}") for i in ids if i >= 0]
    return f"{text} ({kind}: {what} {' and '.join(names)})"


def _effort(mujoco, m, j) -> float:
    """The largest torque about hinge ``j``: its ``actuatorfrcrange``, else the sum over the
    actuators driving it directly of ``|gear|`` times their force bound (``forcerange``, or
    ``ctrlrange`` times the gain of a plain motor); infinite where nothing bounds it."""
    if m.jnt_actfrclimited[j]:
        return float(np.abs(m.jnt_actfrcrange[j]).max())
    total = 0.0
    fixed, none = int(mujoco.mjtGain.mjGAIN_FIXED), int(mujoco.mjtBias.mjBIAS_NONE)
    for a in range(m.nu):
        if int(m.actuator_trntype[a]) != int(mujoco.mjtTrn.mjTRN_JOINT) \
                or int(m.actuator_trnid[a, 0]) != j:
            continue
        gear = abs(float(m.actuator_gear[a, 0]))
        if m.actuator_forcelimited[a]:
            total += gear * float(np.abs(m.actuator_forcerange[a]).max())
        elif (m.actuator_ctrllimited[a] and int(m.actuator_gaintype[a]) == fixed
              and int(m.actuator_biastype[a]) == none):
            total += gear * abs(float(m.actuator_gainprm[a, 0])) * float(
                np.abs(m.actuator_ctrlrange[a]).max())
        else:
            return np.inf
    return total if total > 0 else np.inf


def _quat_matrix(mujoco, quat) -> np.ndarray:
    out = np.zeros(9)
    mujoco.mju_quat2Mat(out, np.asarray(quat, dtype=float))
    return out.reshape(3, 3)


# ------------------------------------------------------------------------------------------
# the planar form
# ------------------------------------------------------------------------------------------
def planar_robot(robot, *, robot_type, tol: float = 1e-6):
    """The planar :class:`~snakecg.Robot` of a chain whose joint axes are all parallel (every
    joint origin and COM in one plane normal to them, each COM on the line through its link's
    joints; the end links' COMs in their middle), a ``robot_type`` (:class:`~snakecg.Robot`),
    or a string saying why it is not planar."""

    R, o = np.eye(3), np.zeros(3)
    frames = [(R, o)]
    axes, origins = [], []
    for j in range(robot.joints):
        o = o + R @ np.asarray(robot.joint_xyz[j])
        roll, pitch, yaw = robot.joint_rpy[j]
        R = R @ _rpy_matrix(roll, pitch, yaw)
        axes.append(R @ np.asarray(robot.joint_axis[j]))
        origins.append(o)
        frames.append((R, o))
    n = axes[0] / np.linalg.norm(axes[0])
    if any(np.linalg.norm(np.cross(n, a / np.linalg.norm(a))) > tol for a in axes[1:]):
        return "the joint axes are not parallel"
    for j, a in enumerate(axes):
        if n @ a < 0:  # the planar angle would be the file's with its sign turned
            return f"joint {j + 1} turns about the opposite of joint 1's axis"
    coms = [Rk @ np.asarray(c) + ok for (Rk, ok), c in zip(frames, robot.com)]
    if any(abs(n @ (x - origins[0])) > tol for x in origins + coms):
        return "the joints and COMs do not lie in one plane normal to the axes"
    nl = robot.n_links
    lengths, cs, inertias, heads = [], [], [], []
    for i in range(nl):
        Rk = frames[i][0]
        Ic = _matrix(robot.inertia[i])
        inertias.append(float(n @ Rk @ Ic @ Rk.T @ n))
        if 0 < i < nl - 1:
            rear, front = origins[i - 1], origins[i]
        elif i == 0:
            front = origins[0]
            rear = 2 * coms[0] - front
        else:
            rear = origins[-1]
            front = 2 * coms[-1] - rear
        length = float(np.linalg.norm(front - rear))
        if not length > tol:
            return f"link {i + 1} has zero length"
        e = (front - rear) / length
        c = float(e @ (coms[i] - rear))
        if np.linalg.norm(coms[i] - rear - c * e) > tol or not -tol <= c <= length + tol:
            return f"the COM of link {i + 1} is off the line through its joints"
        lengths.append(length)
        cs.append(min(max(c, 0.0), length))
        heads.append(e)
    for j in range(robot.joints):  # the planar angle is the file's only if straight at zero
        e0, e1 = heads[j], heads[j + 1]
        if abs(np.arctan2(n @ np.cross(e0, e1), e0 @ e1)) > tol:
            return f"the chain is bent at joint {j + 1} in its zero configuration"
    if any(m <= 0 for m in robot.mass):
        return "a link has no mass"
    limits = None
    if robot.joint_limits is not None and np.isfinite(robot.joint_limits).any():
        # a free hinge turns about the whole circle, as a URDF continuous joint
        limits = tuple((max(lo, -np.pi) if np.isinf(lo) else lo,
                        min(hi, np.pi) if np.isinf(hi) else hi)
                       for lo, hi in robot.joint_limits)
    efforts = None
    if robot.effort_limits is not None and np.isfinite(robot.effort_limits).all():
        efforts = tuple(robot.effort_limits)
    return robot_type(joints=robot.joints, mass=robot.mass, length=tuple(lengths),
                      inertia=tuple(inertias), com=tuple(cs), name=robot.name,
                      joint_limits=limits, effort_limits=efforts)


def _rpy_matrix(roll, pitch, yaw):
    cr, sr, cp, sp_, cy, sy = (np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch),
                               np.cos(yaw), np.sin(yaw))
    return (np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
            @ np.array([[cp, 0, sp_], [0, 1, 0], [-sp_, 0, cp]])
            @ np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]]))


def _matrix(six):
    xx, yy, zz, xy, xz, yz = six
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])


def spatial_chain_or_planar(kind: str, path, name, planar_reader, *, planar_type, spatial_type,
                            tol: float = 1e-6):
    """``Robot.from_urdf``/``from_mjcf``. URDF: the planar reader ``planar_reader`` (its
    checks and refusals stand), and the chain in 3-D where it is not planar
    (:class:`~snakecg.errors.NotPlanarError`). MJCF: the chain read in its spatial form, as a
    planar :class:`~snakecg.Robot` when it is planar. ``planar_type`` and ``spatial_type``:
    the classes built (:class:`~snakecg.Robot`, :class:`~snakecg.SpatialRobot`; passed in,
    so that the readers import neither)."""
    from .._inputs import number

    if planar_reader is not None:
        try:
            return planar_reader()
        except NotPlanarError:
            return spatial_from_urdf(path, robot_type=spatial_type, name=name)
    tol = number("tol", tol, lo=0, unit="m")
    spatial = spatial_from_mjcf(path, robot_type=spatial_type, name=name)
    planar = planar_robot(spatial, robot_type=planar_type, tol=tol)
    return spatial if isinstance(planar, str) else planar
