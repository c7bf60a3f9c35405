"""Robots from URDF: a planar serial chain of revolute joints with parallel axes.

:func:`robot_from_urdf` reads a URDF file with yourdfpy (the ``urdf`` extra) and returns the
:class:`~snakecg.Robot` it describes:

* the chain: the root link is link 1 (the tail); each link has at most one child through a
  ``revolute`` or ``continuous`` joint; every joint axis is parallel to the first one (the
  plane's normal ``n``; positions are projected onto the plane);
* ``length``: for a link between two joints, the distance between them; for the two end
  links, the distance from the joint to the link's *tip*: a massless child link attached by
  a ``fixed`` joint (a tip frame); without a tip, twice the distance from the joint to the
  COM (the COM in the middle);
* ``com``: the COM's distance from the link's rear end along the link, which must lie on the
  link's axis (the line through its joints) within ``tol`` metres;
* ``mass`` and ``inertia``: the ``<inertial>`` mass and the inertia about the COM about the
  plane's normal, ``n^T R I R^T n`` with ``R`` the inertial frame's orientation;
* ``joint_limits``: a ``revolute`` joint's ``<limit lower upper>`` in snakecg's angles
  (shifted by the zero configuration's bend, and reversed for an axis opposite the first);
  a ``continuous`` joint turns freely, ``(-pi, pi)``;
* ``effort_limits``: every joint's ``<limit effort>`` (N m); when some joints give none, the
  robot has no effort limits and a warning names those joints.

Anything else (a branch, a prismatic, floating or planar joint, a joint axis not parallel to
the first, a COM off the link axis, a link without mass, a fixed joint to a link with mass)
is refused with an :class:`~snakecg.InputError` naming the element. Joint angles: snakecg's
``q_j`` is measured about ``n`` from the previous link's axis; the URDF's zero configuration
may be bent (``q_urdf = q_snakecg - offset``).
"""

from __future__ import annotations

import io
import math
import warnings

import numpy as np

from ._inputs import number
from .errors import InputError, NotPlanarError

__all__ = ["robot_from_urdf"]

_REVOLUTE = ("revolute", "continuous")


def _load(path):
    """``(path, yourdfpy's URDF)`` of the file: read once (a regular file of bounded size),
    checked to be well-formed XML without a DTD or entities, then parsed by yourdfpy from
    those bytes."""
    try:
        import yourdfpy
    except ImportError:
        from .extras import install_hint

        raise InputError("reading URDF needs the yourdfpy package (the urdf extra): "
                         f"{install_hint('urdf')}") from None
    from lxml import etree  # yourdfpy's XML library

    from .toml_file import read_bytes

    p, data = read_bytes(path, where="URDF file", kind="URDF")
    where = f"URDF file {str(p)!r}"
    # yourdfpy recovers from malformed XML silently and its parser expands entities: an
    # external entity, or any DTD, could make the file read as another robot. Refused.
    no_dtd = (f"{where} declares a DTD or entities (<!DOCTYPE ...>, <!ENTITY ...>); a robot "
              "file may not: write the values out")
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                             huge_tree=False)
    try:
        root = etree.fromstring(data, parser)
    except (etree.XMLSyntaxError, ValueError) as exc:
        if b"<!DOCTYPE" in data or b"<!ENTITY" in data:
            raise InputError(no_dtd) from None
        raise InputError(f"{where} cannot be read: not well-formed XML "
                         f"({' '.join(str(exc).split())})") from None
    info = root.getroottree().docinfo
    has_entity = any(isinstance(e, etree._Entity) for e in root.iter())
    if info.doctype or info.internalDTD is not None or info.externalDTD is not None \
            or has_entity:
        raise InputError(no_dtd)
    try:
        return p, yourdfpy.URDF.load(io.BytesIO(data), build_scene_graph=False,
                                     load_meshes=False, build_collision_scene_graph=False,
                                     load_collision_meshes=False)
    except Exception as exc:  # noqa: BLE001 - yourdfpy raises many kinds for a bad file
        raise InputError(f"{where} cannot be read: "
                         f"{' '.join(str(exc).split()) or type(exc).__name__}") from None


def _text(value) -> str:
    """A value of the file as the file wrote it (a vector as its numbers)."""
    from ._inputs import short_repr

    if isinstance(value, np.ndarray):
        return repr(" ".join(f"{x:g}" for x in value.ravel()))
    return short_repr(value)


def _origin(T) -> np.ndarray:
    return np.eye(4) if T is None else np.asarray(T, dtype=float)


def _mass(link) -> float:
    inertial = link.inertial
    return 0.0 if inertial is None or inertial.mass is None else float(inertial.mass)


def _round(x: float) -> float:
    """The shortest decimal within 64 units in the last place of ``x``: the frames' matrix
    products add rounding errors of a few ulps, which would turn the file's ``0.15`` into
    ``0.14999999999999997`` (or, rounded to 15 digits, a ``0.06`` into
    ``0.0600000000000001``); a value the file gives with up to about 14 digits comes back
    as written, a longer one moves by at most 64 ulps (1.4e-14 relative)."""
    tol = 64 * math.ulp(x)
    for digits in range(1, 18):
        y = float(f"{x:.{digits}g}")
        if abs(y - x) <= tol:
            return y
    return x


def robot_from_urdf(path, *, robot_type, tol: float = 1e-6, name: str | None = None):
    """The :class:`~snakecg.Robot` of the planar chain in the URDF file ``path`` (see the
    module doc); ``tol``: metres a COM may lie off its link's axis, and the tolerance of
    the parallel-axes test (radians). ``robot_type``: the class built,
    :class:`~snakecg.Robot` (``Robot.from_urdf`` passes itself: this module imports no
    robot)."""

    tol = number("tol", tol, lo=0, unit="m")
    if name is not None and not isinstance(name, str):
        raise InputError(f"name must be a string, got {type(name).__name__}")
    p, urdf = _load(path)
    where = f"URDF file {str(p)!r}"
    robot = urdf.robot
    for kind, items in (("link", robot.links), ("joint", robot.joints)):
        names = [x.name for x in items]
        twice = sorted({n for n in names if names.count(n) > 1})
        if twice:
            raise InputError(f"{where}: {kind} names must be unique; repeated: "
                             f"{', '.join(repr(n) for n in twice[:5])}")
    links = {ln.name: ln for ln in robot.links}
    joints = list(robot.joints)
    children: dict[str, list] = {n: [] for n in links}
    parents = {}
    for j in joints:
        if j.parent not in links or j.child not in links:
            raise InputError(f"{where}: joint {j.name!r} connects unknown links "
                             f"{j.parent!r} -> {j.child!r}")
        children[j.parent].append(j)
        parents[j.child] = j
    roots = [n for n in links if n not in parents]
    if len(roots) != 1:
        raise InputError(f"{where}: expected one root link, found {len(roots)}: "
                         f"{', '.join(roots) or 'none (the joints form a loop)'}")
    # walk the chain: one revolute child per link; massless fixed leaves are tip frames
    chain, chain_joints, tips = [roots[0]], [], {}
    while True:
        here = chain[-1]
        moving = []
        for j in children[here]:
            if j.type in _REVOLUTE:
                moving.append(j)
            elif j.type == "fixed":
                child = links[j.child]
                if _mass(child) > 0 or children[j.child]:
                    raise InputError(
                        f"{where}: fixed joint {j.name!r} attaches link {j.child!r}, which "
                        "has mass or children; merge it into link "
                        f"{here!r} (only massless tip frames may be fixed)")
                if here in tips:
                    raise InputError(f"{where}: link {here!r} has two tip frames "
                                     f"({tips[here][0].name!r} and {j.name!r})")
                tips[here] = (j, j.child)
            else:
                raise InputError(f"{where}: joint {j.name!r} is {j.type}; a snake is a "
                                 "chain of revolute joints")
        if len(moving) > 1:
            raise InputError(f"{where}: the chain branches at link {here!r} (joints "
                             f"{', '.join(repr(j.name) for j in moving)}); a snake is a "
                             "serial chain")
        if not moving:
            break
        chain_joints.append(moving[0])
        chain.append(moving[0].child)
    if not chain_joints:
        raise InputError(f"{where}: no revolute joint; a snake has at least one")
    # frames at the zero configuration, in the root link's frame
    frame = {chain[0]: np.eye(4)}
    for j in chain_joints:
        frame[j.child] = frame[j.parent] @ _origin(j.origin)
    axes = []
    for j in chain_joints:
        try:
            a = np.asarray(j.axis if j.axis is not None else (1.0, 0.0, 0.0), dtype=float)
        except (TypeError, ValueError):
            a = np.zeros(0)
        if a.shape != (3,) or not np.isfinite(a).all():
            raise InputError(f"{where}: joint {j.name!r} has axis {_text(j.axis)}; expected "
                             "three finite numbers (<axis xyz=\"0 0 1\"/>)")
        norm = np.linalg.norm(a)
        if not norm > 0:
            raise InputError(f"{where}: joint {j.name!r} has a zero axis")
        axes.append(frame[j.child][:3, :3] @ (a / norm))
    n = axes[0]
    for j, a in zip(chain_joints[1:], axes[1:]):
        if np.linalg.norm(np.cross(n, a)) > tol:
            angle = np.degrees(np.arcsin(min(1.0, np.linalg.norm(np.cross(n, a)))))
            raise NotPlanarError(f"{where}: the axis of joint {j.name!r} is {angle:.3g} deg off "
                             f"the axis of joint {chain_joints[0].name!r}; a planar snake "
                             "needs parallel joint axes")

    def planar(x):  # a point projected onto the plane through joint 1, normal n
        return x - n * (n @ x)

    joint_pos = [planar(frame[j.child][:3, 3]) for j in chain_joints]
    masses, lengths, inertias, coms, link_axes = [], [], [], [], []
    nl = len(chain)
    for k, link_name in enumerate(chain):
        link = links[link_name]
        m = _mass(link)
        if not m > 0:
            raise InputError(f"{where}: link {link_name!r} has no positive <inertial> mass")
        T = frame[link_name] @ _origin(link.inertial.origin)
        com = planar(T[:3, 3])
        Ic = np.zeros((3, 3)) if link.inertial.inertia is None else np.asarray(
            link.inertial.inertia, dtype=float)
        inertia = float(n @ T[:3, :3] @ Ic @ T[:3, :3].T @ n)
        tip = None
        if link_name in tips:
            tj, _ = tips[link_name]
            tip = planar((frame[link_name] @ _origin(tj.origin))[:3, 3])
        if 0 < k < nl - 1:
            rear, front = joint_pos[k - 1], joint_pos[k]
            if tip is not None:
                raise InputError(f"{where}: link {link_name!r} lies between two joints and "
                                 f"cannot have a tip frame ({tips[link_name][0].name!r})")
        elif k == 0:
            front = joint_pos[0]
            rear = tip if tip is not None else 2 * com - front
        else:
            rear = joint_pos[-1]
            front = tip if tip is not None else 2 * com - rear
        axis = front - rear
        length = float(np.linalg.norm(axis))
        if not length > tol:
            what = ("joints" if 0 < k < nl - 1 else
                    "joint and tip frame" if tip is not None else "joint and COM")
            raise InputError(f"{where}: link {link_name!r} has zero length (its {what} "
                             "coincide); give its end as a massless tip frame")
        e = axis / length
        c = float(e @ (com - rear))
        off = float(np.linalg.norm(com - rear - c * e))
        if off > tol:
            raise NotPlanarError(f"{where}: the COM of link {link_name!r} lies {off:.3g} m off "
                             f"the link's axis (tolerance {tol:g} m); snakecg's links carry "
                             "their COM on the line through their joints")
        if not -tol <= c <= length + tol:
            raise InputError(f"{where}: the COM of link {link_name!r} lies outside the link "
                             f"({c:.6g} m from its rear end, length {length:.6g} m)")
        link_axes.append(e)
        masses.append(m)
        lengths.append(_round(length))
        inertias.append(_round(inertia))
        coms.append(_round(min(max(c, 0.0), length)))
    joint_limits, effort_limits = _limits(where, chain_joints, axes, link_axes, n)
    try:
        return robot_type(joints=nl - 1, mass=tuple(masses), length=tuple(lengths),
                     inertia=tuple(inertias), com=tuple(coms),
                     name=name or robot.name or p.stem, joint_limits=joint_limits,
                     effort_limits=effort_limits)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None


def _limits(where, joints, axes, link_axes, n):
    """The joints' ``<limit>`` in snakecg's angles: ``q_j = delta_j + s_j q_urdf``, with
    ``delta_j`` the angle from link j's axis to link j+1's at the URDF's zero configuration
    and ``s_j = +-1`` the joint axis's direction along the plane's normal ``n``."""
    ranges, efforts, missing = [], [], []
    for j, (joint, a) in enumerate(zip(joints, axes)):
        e0, e1 = link_axes[j], link_axes[j + 1]
        delta = math.atan2(float(n @ np.cross(e0, e1)), float(e0 @ e1))
        sign = 1.0 if float(a @ n) > 0 else -1.0
        lim = joint.limit
        if joint.type == "continuous":
            ranges.append((-math.pi, math.pi))
        elif lim is None or lim.lower is None or lim.upper is None:
            raise InputError(f"{where}: revolute joint {joint.name!r} has no <limit lower=... "
                             "upper=...> (a URDF revolute joint needs both; a joint without "
                             "limits is 'continuous')")
        else:
            lo, hi = sorted((delta + sign * float(lim.lower), delta + sign * float(lim.upper)))
            if not float(lim.lower) < float(lim.upper):
                raise InputError(f"{where}: joint {joint.name!r} has <limit lower="
                                 f"{lim.lower:g} upper={lim.upper:g}>; lower must be below "
                                 "upper")
            ranges.append((_round(lo), _round(hi)))
        if lim is None or lim.effort is None:
            missing.append(joint.name)
        else:
            efforts.append(float(lim.effort))
    if missing and efforts:
        warnings.warn(f"{where}: joint(s) {', '.join(repr(m) for m in missing)} give no "
                      "<limit effort>, the others do: the robot has no effort limits "
                      "(give tau_max to a query)", stacklevel=4)
    return tuple(ranges), (tuple(efforts) if not missing else None)
