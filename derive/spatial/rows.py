"""Constraint rows of a spatial snake lying on the ground, for the contact analysis.

Each row is ``A v`` (a velocity that the constraint holds at zero, or bounds) with its
``Adot v``, so that ``A vdot + Adot v`` is the row's acceleration (the 3-D counterpart of
eqs. 8-13 of Reyes & Ma 2017); points are given in their link's frame, rows in world axes,
``z`` up:

* ``ground_rows``: the vertical velocity of a support point on every link (bilateral: the
  snake stays on the ground), with the points' heights;
* ``wheel_rows``: the velocity of a wheel point on every link along the lateral direction
  in the ground plane, ``l = e_z x h / |e_z x h|`` with ``h`` the link's heading (a direction
  given in the link frame); ``Adot v`` includes the turning of ``l``;
* ``contact_row``: the gap rate ``n . (v_obj_point - v_point)`` of one point of one link
  against an object point (``rho`` from the object's COM, both world axes) with the
  object's normal ``n``; ``A = [a_snake, g_obj]`` on ``(v, v_obj)``, the object's twist being
  (linear velocity of its COM, angular velocity) in world axes and ``n``, ``rho`` turning
  with the object.
"""

from __future__ import annotations

import sympy as sp

from .vectors import cross, dot, matTvec, matvec

__all__ = ["point_terms", "ground_rows", "wheel_rows", "contact_row"]


def _mat9(cols9):
    return tuple(tuple(cols9[3 * c + r] for c in range(3)) for r in range(3))


def _axis_frame(s, i):
    if i == 1:
        one, zero = sp.Integer(1), sp.Integer(0)
        return ((one, zero, zero), (zero, one, zero), (zero, zero, one))
    return _mat9(s.axis_frame[i - 2])


def _jacobian_columns(ch, p, joints):
    """``3 x n_v`` Jacobian of a world point ``p`` carried by a link; ``joints`` maps each joint
    ``j`` that moves the link to a weight (1, or the one-hot mask of a selection)."""
    s = ch.s
    J = sp.zeros(3, s.nv)
    Rb = ch.base_rotation()
    r = tuple(a - b for a, b in zip(p, s.base_position))
    for c in range(3):
        col = tuple(Rb[k][c] for k in range(3))
        lin = cross(col, r)
        for k in range(3):
            J[k, c] = Rb[k][c]
            J[k, 3 + c] = lin[k]
    for j, weight in joints.items():
        d = tuple(a - b for a, b in zip(p, ch.origin(j + 1)))
        lin = cross(ch.axis(j), d)
        for k in range(3):
            J[k, 6 + j - 1] = weight * lin[k]
    return J


def point_terms(ch, link_sym, point_sym, name, *, velocity: bool):
    """A point of the link selected by the one-hot ``link_sym``: world position, Jacobian and
    (``velocity``) its velocity, bias acceleration and the link's angular velocity."""
    s = ch.s
    nl = s.n_links
    sel = lambda f, nm: ch.p.vec(nm, tuple(  # noqa: E731 - one-hot selection of a vector
        sp.Add(*(link_sym[i - 1] * f(i)[k] for i in range(1, nl + 1))) for k in range(3)))
    Rsel = ch.p.mat(f"{name}R", tuple(tuple(sp.Add(*(link_sym[i - 1] * ch.rotation(i)[r][c]
                                                     for i in range(1, nl + 1)))
                                            for c in range(3)) for r in range(3)))
    Psel = tuple(tuple(sp.Add(*(link_sym[i - 1] * _axis_frame(s, i)[r][c]
                                for i in range(1, nl + 1))) for c in range(3)) for r in range(3))
    rp = ch.p.vec(f"{name}rl", matTvec(ch.p.mat(f"{name}P", Psel), point_sym))
    d = ch.p.vec(f"{name}d", matvec(Rsel, rp))
    o = sel(ch.origin, f"{name}o")
    p = ch.p.vec(f"{name}p", tuple(a + b for a, b in zip(o, d)))
    masks, acc = {}, sp.Integer(0)
    for j in range(s.n_joints, 0, -1):
        acc = ch.p.let(f"{name}mask{j}", acc + link_sym[j])  # links j+1.. are moved by j
        masks[j] = acc
    J = _jacobian_columns(ch, p, dict(sorted(masks.items())))
    terms = {}
    if velocity:
        w = sel(lambda i: ch.velocity(i)[0], f"{name}w")
        al = sel(lambda i: ch.bias(i)[0], f"{name}al")
        a = sel(lambda i: ch.bias(i)[1], f"{name}a")
        vo = sel(lambda i: ch.velocity(i)[1], f"{name}vo")
        terms["omega"] = w
        terms["velocity"] = ch.p.vec(f"{name}v", tuple(x + y for x, y in zip(vo, cross(w, d))))
        terms["bias"] = ch.point_bias(name, (w, al, a), d)
    return p, J, terms


def _link_point(ch, i, local, name, *, velocity: bool):
    """A point fixed in link ``i`` (``local`` in the link's frame): world position, Jacobian
    and (``velocity``) velocity and bias acceleration."""
    s = ch.s
    rp = ch.p.vec(f"{name}rl", matTvec(_axis_frame(s, i), local))
    d = ch.p.vec(f"{name}d", matvec(ch.rotation(i), rp))
    p = ch.p.vec(f"{name}p", tuple(a + b for a, b in zip(ch.origin(i), d)))
    J = _jacobian_columns(ch, p, {j: 1 for j in range(1, i)})
    if not velocity:
        return p, J, None, None
    w, vo = ch.velocity(i)
    al, a = ch.bias(i)
    vel = ch.p.vec(f"{name}v", tuple(x + y for x, y in zip(vo, cross(w, d))))
    return p, J, vel, ch.point_bias(name, (w, al, a), d)


def ground_rows(s, q_in, v_in, K_in, link_in, point_in):
    from ..model import _fn
    from .chain import SpatialChain

    ch = SpatialChain(s, "world")
    pts = tuple(sp.Symbol(f"sp{i}{a}", real=True) for i in range(1, s.n_links + 1) for a in "xyz")
    rows, adot, height = [], [], []
    for i in range(1, s.n_links + 1):
        p, J, _, bias = _link_point(ch, i, pts[3 * i - 3: 3 * i], f"g{i}", velocity=True)
        rows.append(J[2, :])
        adot.append(bias[2])
        height.append(p[2])
    return _fn("ground_rows", "Vertical velocity of a support point on every link "
               "(bilateral ground rows).",
               [q_in, v_in, K_in, ("support_points", pts, "support point of each link in its "
                                   "frame, 3 per link [m]")],
               [("A", sp.Matrix.vstack(*rows), "n_l x n_v"),
                ("adot_v", sp.Matrix(adot), "n_l: Adot v"),
                ("height", sp.Matrix(height), "n_l: height of each support point [m]")],
               ch.assignments)


def wheel_rows(s, q_in, v_in, K_in, link_in, point_in):
    from ..model import _fn
    from .chain import SpatialChain

    ch = SpatialChain(s, "world")
    pts = tuple(sp.Symbol(f"wp{i}{a}", real=True) for i in range(1, s.n_links + 1) for a in "xyz")
    heads = tuple(sp.Symbol(f"wh{i}{a}", real=True) for i in range(1, s.n_links + 1)
                  for a in "xyz")
    rows, adot = [], []
    for i in range(1, s.n_links + 1):
        p, J, vel, bias = _link_point(ch, i, pts[3 * i - 3: 3 * i], f"wl{i}", velocity=True)
        hl = ch.p.vec(f"wh{i}r", matTvec(_axis_frame(s, i), heads[3 * i - 3: 3 * i]))
        h = ch.p.vec(f"wh{i}", matvec(ch.rotation(i), hl))
        inv = ch.p.let(f"wrho{i}", 1 / sp.sqrt(h[0] ** 2 + h[1] ** 2))
        lat = (ch.p.let(f"wlx{i}", -h[1] * inv), ch.p.let(f"wly{i}", h[0] * inv))
        w, _ = ch.velocity(i)
        hd = ch.p.vec(f"whd{i}", cross(w, h))
        # l = (-h_y, h_x) / rho: ldot = (e - l (l . e)) / rho with e = (-hdot_y, hdot_x)
        e = (-hd[1], hd[0])
        le = ch.p.let(f"wle{i}", lat[0] * e[0] + lat[1] * e[1])
        ldot = ((e[0] - lat[0] * le) * inv, (e[1] - lat[1] * le) * inv)
        rows.append(lat[0] * J[0, :] + lat[1] * J[1, :])
        adot.append(lat[0] * bias[0] + lat[1] * bias[1] + ldot[0] * vel[0] + ldot[1] * vel[1])
    return _fn("wheel_rows", "Lateral velocity of a wheel point on every link in the ground "
               "plane (passive wheels).",
               [q_in, v_in, K_in,
                ("wheel_points", pts, "wheel point of each link in its frame, 3 per link [m]"),
                ("wheel_heading", heads, "rolling direction of each wheel in its link's frame, "
                 "3 per link (not vertical)")],
               [("A", sp.Matrix.vstack(*rows), "n_l x n_v"),
                ("adot_v", sp.Matrix(adot), "n_l: Adot v")],
               ch.assignments)


def contact_row(s, q_in, v_in, K_in, link_in, point_in):
    from ..model import _fn
    from .chain import SpatialChain
    from .rows import point_terms

    ch = SpatialChain(s, "world")
    n = tuple(sp.Symbol(f"n{a}", real=True) for a in "xyz")
    rho = tuple(sp.Symbol(f"rho{a}", real=True) for a in "xyz")
    vobj = tuple(sp.Symbol(f"vo{a}", real=True) for a in ("x", "y", "z", "wx", "wy", "wz"))
    p, J, t = point_terms(ch, link_in[1], point_in[1], "ct", velocity=True)
    vo, wo = vobj[:3], vobj[3:]
    a_snake = -(sp.Matrix([n]) * J)
    g_obj = sp.Matrix([list(n) + list(cross(rho, n))])
    wrho = ch.p.vec("cwr", cross(wo, rho))
    rel = tuple(a + b - c for a, b, c in zip(vo, wrho, t["velocity"]))
    # d/dt n . (v_o + w_o x rho - pdot) at zero accelerations, n and rho turning with w_o
    adot = dot(cross(wo, n), rel) + dot(n, tuple(a - b for a, b in
                                                  zip(cross(wo, wrho), t["bias"])))
    return _fn("contact_row", "Gap rate of one point of one link against an object's surface "
               "(normal n, object point rho from its COM).",
               [q_in, v_in, K_in, link_in, point_in,
                ("normal", n, "the object's outward unit normal at the contact, world axes"),
                ("rho", rho, "the contact point from the object's COM, world axes [m]"),
                ("v_obj", vobj, "object twist: velocity of its COM, angular velocity (world)")],
               [("a_snake", a_snake, "1 x n_v: row on v"),
                ("g_obj", g_obj, "1 x 6: row on v_obj"),
                ("adot_v", sp.Matrix([adot]), "Adot v of the row"),
                ("position", sp.Matrix(p), "the link's contact point in the world [m]")],
               ch.assignments)
