"""The structured (recursive) kinematics and dynamics of the spatial chain.

Everything is written in the links' *axis frames* (link ``i``'s frame turned by the fixed
rotation ``P_i`` that takes ``e_z`` to its joint axis, :mod:`.symbols`), where a link's
rotation is ``R'_{j+1} = R'_j Q_j Rz(q_j)``: one constant 3x3 product and a planar rotation per
joint, with one sine and cosine per joint angle. The world axis of joint ``j`` is the third
column of ``R'_{j+1}``.

Two coordinate choices share the recursion (``frame``):

* ``"base"``: coordinates of the base frame (``R'_1 = 1``, ``o_1 = 0``). The mass matrix and
  the bias forces in Pinocchio's free-flyer velocity (the base twist in the base frame)
  depend on the base pose only through gravity, so they are computed here, without the
  quaternion: the composite-rigid-body algorithm about the base origin (``O(n^2)``: eleven
  operations per joint pair) and the recursive Newton-Euler algorithm (``O(n)``).
* ``"world"``: world coordinates (``R'_1`` from the quaternion, ``o_1`` the base position),
  for poses, Jacobians (``LOCAL_WORLD_ALIGNED``: linear velocity of the frame origin and
  angular velocity, in world axes) and bias accelerations.

Spatial quantities are written (angular; linear) about the frame's origin: the twist of joint
``j`` is ``s_j = (u_j, o_{j+1} x u_j)``, a composite body with mass ``m``, first moment ``h``
and rotational inertia ``I_O`` about the origin has momentum ``L = I_O w + h x v``,
``p = m v - h x w`` for the twist ``(w, v)``.
"""

from __future__ import annotations

import sympy as sp

from .symbols import SpatialSymbols
from .vectors import (ZERO3, Program, column, cross, dot, identity, matmul, matTvec, matvec,
                      transpose)

__all__ = ["SpatialChain", "quaternion_rotation", "inertia_matrix"]


def quaternion_rotation(qx, qy, qz, qw):
    """Rotation matrix of the unit quaternion ``(qx, qy, qz, qw)`` (Eigen's formula)."""
    return (
        (1 - 2 * (qy**2 + qz**2), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)),
        (2 * (qx * qy + qz * qw), 1 - 2 * (qx**2 + qz**2), 2 * (qy * qz - qx * qw)),
        (2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx**2 + qy**2)),
    )


def inertia_matrix(six):
    """The symmetric 3x3 matrix of ``(xx, yy, zz, xy, xz, yz)``."""
    xx, yy, zz, xy, xz, yz = six
    return ((xx, xy, xz), (xy, yy, yz), (xz, yz, zz))


def _mat9(cols9):
    """A 3x3 matrix from 9 symbols in column-major order."""
    return tuple(tuple(cols9[3 * c + r] for c in range(3)) for r in range(3))


class SpatialChain:
    """Builds the chain's straight-line programs (one instance per generated function)."""

    def __init__(self, s: SpatialSymbols, frame: str):
        if frame not in ("base", "world"):
            raise ValueError(f"frame must be 'base' or 'world', got {frame!r}")
        self.s = s
        self.frame = frame
        self.p = Program()
        self._R: dict[int, tuple] = {}
        self._o: dict[int, tuple] = {}
        self._cache: dict = {}

    @property
    def assignments(self):
        return self.p.assignments

    def _memo(self, key, build):
        if key not in self._cache:
            self._cache[key] = build()
        return self._cache[key]

    # the base ------------------------------------------------------------------------------
    def base_rotation(self):
        """``R_b`` (world from base), from the quaternion: ``"world"`` frame only."""
        return self._memo("Rb", lambda: self.p.mat("Rb", quaternion_rotation(*self.s.quaternion)))

    def gravity(self):
        """Gravity in the chain's coordinates (``R_b^T g`` in the base frame)."""
        g = self.s.gravity
        if self.frame == "world":
            return g
        return self._memo("g", lambda: self.p.vec("gb", matTvec(self.base_rotation(), g)))

    # kinematics ----------------------------------------------------------------------------
    def cos_sin(self, j: int):
        """``cos q_j``, ``sin q_j``: the only trigonometric calls of the chain."""
        a = self.s.angles[j - 1]
        return self._memo(("cs", j), lambda: (self.p.let(f"c{j}", sp.cos(a)),
                                               self.p.let(f"s{j}", sp.sin(a))))

    def rotation(self, i: int):
        """``R'_i``: link ``i``'s axis frame, ``R'_{j+1} = R'_j Q_j Rz(q_j)``."""
        if i in self._R:
            return self._R[i]
        if i == 1:
            R = self.base_rotation() if self.frame == "world" else identity()
        else:
            j = i - 1
            A = matmul(self.rotation(j), _mat9(self.s.joint_rotation[j - 1]))
            if self.frame == "world" or j > 1:
                A = self.p.mat(f"A{j}", A)  # R'_j Q_j (for j = 1 in the base frame: Q_1)
            c, sn = self.cos_sin(j)
            # columns (a0 c + a1 s, -a0 s + a1 c, a2) of A Rz(q)
            R = self.p.mat(f"R{i}", tuple(
                (A[r][0] * c + A[r][1] * sn, A[r][1] * c - A[r][0] * sn, A[r][2])
                for r in range(3)))
        self._R[i] = R
        return R

    def origin(self, i: int):
        """``o_i``: link ``i``'s frame origin, ``o_{j+1} = o_j + R'_j (P_j^T t_j)``."""
        if i in self._o:
            return self._o[i]
        if i == 1:
            o = self.s.base_position if self.frame == "world" else ZERO3
        else:
            j = i - 1
            o = self.p.vec(f"o{i}", tuple(
                a + b for a, b in zip(self.origin(j), self.joint_step(j))))
        self._o[i] = o
        return o

    def joint_step(self, j: int):
        """``o_{j+1} - o_j = R'_j (P_j^T t_j)``."""
        return self._memo(("step", j), lambda: self.p.vec(
            f"dt{j}", matvec(self.rotation(j), self.s.joint_offset[j - 1])))

    def axis(self, j: int):
        """``u_j``: joint ``j``'s axis, the third column of ``R'_{j+1}``."""
        return column(self.rotation(j + 1), 2)

    def joint_moment_arm(self, j: int):
        """``w_j = o_{j+1} x u_j``: the linear part of the joint's twist about the origin."""
        return self._memo(("w", j), lambda: self.p.vec(
            f"w{j}", cross(self.origin(j + 1), self.axis(j))))

    def link_rotation(self, i: int):
        """``R_i = R'_i P_i^T``: link ``i``'s own frame (the file's)."""
        if i == 1:
            return self.rotation(1)
        P = _mat9(self.s.axis_frame[i - 2])
        return self._memo(("Rl", i), lambda: self.p.mat(f"Rl{i}",
                                                         matmul(self.rotation(i), transpose(P))))

    def com_offset(self, i: int):
        """``R'_i d_i``: the COM from the link origin, in the chain's coordinates."""
        return self._memo(("dc", i), lambda: self.p.vec(
            f"dc{i}", matvec(self.rotation(i), self.s.axis_com[i - 1])))

    def com(self, i: int):
        return self._memo(("com", i), lambda: self.p.vec(
            f"cm{i}", tuple(a + b for a, b in zip(self.origin(i), self.com_offset(i)))))

    def inertia(self, i: int):
        """``R'_i J_i R'_i^T``: link ``i``'s inertia about its COM in the chain's axes.

        In the base frame, where every ``R'_i`` is a product of rotations, a link's axis
        frame has no ``xy`` product of inertia (:mod:`.parameters`), and with the columns
        ``r_1, r_2, r_3`` of ``R'_i`` (``r_1 r_1^T = 1 - r_2 r_2^T - r_3 r_3^T``):
        ``R'JR'^T = J_xx 1 + (J_yy - J_xx) r_2 r_2^T + r_3 y^T + y r_3^T`` with
        ``y = J_xz r_1 + J_yz r_2 + (J_zz - J_xx)/2 r_3``: 54 operations instead of 75."""
        def build():
            R = self.rotation(i)
            J = inertia_matrix(self.s.axis_inertia[i - 1])
            if i == 1 and self.frame == "base":
                return J
            if self.frame == "base":
                xx, yy, zz, _, xz, yz = self.s.axis_inertia[i - 1]
                r1, r2, r3 = (column(R, k) for k in range(3))
                half = self.p.let(f"Jh{i}", (zz - xx) / 2)
                y = self.p.vec(f"Jy{i}", tuple(xz * a + yz * b + half * c
                                               for a, b, c in zip(r1, r2, r3)))
                z = self.p.vec(f"Jz{i}", tuple((yy - xx) * b for b in r2))
                return self.p.sym_mat(f"Ic{i}", tuple(tuple(
                    r3[r] * y[c] + y[r] * r3[c] + z[r] * r2[c] + (xx if r == c else 0)
                    for c in range(3)) for r in range(3)))
            RJ = self.p.mat(f"RJ{i}", matmul(R, J))
            return self.p.sym_mat(f"Ic{i}", matmul(RJ, transpose(R)))
        return self._memo(("I", i), build)

    # velocities and bias accelerations (zero joint and base accelerations) ------------------
    def velocity(self, i: int):
        """``(w_i, odot_i)``: angular velocity and velocity of the frame origin of link ``i``."""
        def build():
            s = self.s
            vb, wb = s.v[0:3], s.v[3:6]
            if i == 1:
                if self.frame == "base":
                    return wb, vb
                Rb = self.base_rotation()
                return self.p.vec("om1", matvec(Rb, wb)), self.p.vec("vo1", matvec(Rb, vb))
            j = i - 1
            w, od = self.velocity(j)
            qd = s.v[6 + j - 1]
            om = self.p.vec(f"om{i}", tuple(a + b * qd for a, b in zip(w, self.axis(j))))
            step = cross(w, self.joint_step(j))
            vo = self.p.vec(f"vo{i}", tuple(a + b for a, b in zip(od, step)))
            return om, vo
        return self._memo(("vel", i), build)

    def bias(self, i: int):
        """``(alpha_i, a_i)``: angular acceleration and classical acceleration of the origin of
        link ``i`` at zero accelerations (``Jdot v``)."""
        def build():
            s = self.s
            if i == 1:
                w, vo = self.velocity(1)
                return ZERO3, self.p.vec("ab1", cross(w, vo))
            j = i - 1
            al, a = self.bias(j)
            w, _ = self.velocity(j)
            qd = s.v[6 + j - 1]
            r = self.joint_step(j)
            wu = cross(w, self.axis(j))
            alpha = self.p.vec(f"al{i}", tuple(x + y * qd for x, y in zip(al, wu)))
            wr = self.p.vec(f"wr{i}", cross(w, r))
            acc = self.p.vec(f"ab{i}", tuple(
                x + y + z for x, y, z in zip(a, cross(al, r), cross(w, wr))))
            return alpha, acc
        return self._memo(("bias", i), build)

    def point_bias(self, name: str, i_terms, d):
        """Classical acceleration of a point ``d`` away from a link origin, given the link's
        ``(w, alpha, a)``: ``a + alpha x d + w x (w x d)``."""
        w, al, a = i_terms
        wd = self.p.vec(f"{name}wd", cross(w, d))
        return self.p.vec(f"{name}ab", tuple(x + y + z for x, y, z in
                                             zip(a, cross(al, d), cross(w, wd))))

    # dynamics (base frame) -----------------------------------------------------------------
    def _composite(self):
        """Suffix sums over links ``k..n_l`` of mass, first moment ``h`` and rotational
        inertia about the origin ``I_O = R'J R'^T + m (|c|^2 1 - c c^T)`` (six entries)."""
        def build():
            s = self.s
            n = s.n_links
            out = {}
            acc = None
            for k in range(n, 0, -1):
                m = s.link_mass[k - 1]
                c = self.com(k)
                h = self.p.vec(f"h{k}", tuple(m * x for x in c))
                hc = self.p.let(f"hc{k}", dot(h, c))
                Ic = self.inertia(k)
                IO = [Ic[r][cc] - h[r] * c[cc] + (hc if r == cc else 0)
                      for r, cc in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))]
                if acc is None:
                    mc, hs, Is = m, h, IO
                else:
                    mc = acc[0] + m
                    hs = tuple(a + b for a, b in zip(acc[1], h))
                    Is = [a + b for a, b in zip(acc[2], IO)]
                mc = self.p.let(f"mC{k}", mc)
                hs = self.p.vec(f"hC{k}", hs)
                Is = tuple(self.p.let(f"IC{k}_{t}", e) for t, e in zip(range(6), Is))
                acc = (mc, hs, Is)
                out[k] = acc
            return out
        return self._memo("composite", build)

    def mass_matrix(self) -> sp.Matrix:
        """``M(q)`` (``n_v x n_v``): the composite-rigid-body algorithm about the base origin.

        Base block ``[[m 1, -[h]x], [[h]x, I_O]]`` of the whole chain; joint column ``j`` is
        the momentum ``F_j = (L_j, p_j)`` of the links beyond joint ``j`` moving with
        ``s_j``: the base rows are ``(p_j, L_j)`` and ``M_ij = u_i . L_j + w_i . p_j``
        (``i <= j``)."""
        if self.frame != "base":
            raise ValueError("the mass matrix is built in the base frame")
        s = self.s
        nv, na = s.nv, s.n_joints
        comp = self._composite()
        M = sp.zeros(nv, nv)
        mt, ht, It = comp[1]
        I3 = inertia_matrix(It)
        for r in range(3):
            M[r, r] = mt
            for c in range(3):
                M[3 + r, 3 + c] = I3[r][c]
        hx = ((0, -ht[2], ht[1]), (ht[2], 0, -ht[0]), (-ht[1], ht[0], 0))
        for r in range(3):
            for c in range(3):
                M[3 + r, c] = hx[r][c]
                M[c, 3 + r] = hx[r][c]
        L, P = {}, {}
        for j in range(1, na + 1):
            mc, hc, Ic = comp[j + 1]
            u, w = self.axis(j), self.joint_moment_arm(j)
            Lj = self.p.vec(f"L{j}", tuple(a + b for a, b in
                                           zip(matvec(inertia_matrix(Ic), u), cross(hc, w))))
            Pj = self.p.vec(f"p{j}", tuple(mc * a - b for a, b in zip(w, cross(hc, u))))
            L[j], P[j] = Lj, Pj
            col = 6 + j - 1
            for r in range(3):
                M[r, col] = M[col, r] = Pj[r]
                M[3 + r, col] = M[col, 3 + r] = Lj[r]
        for j in range(1, na + 1):
            for i in range(1, j + 1):
                e = self.p.let(f"M{i}_{j}", dot(self.axis(i), L[j])
                               + dot(self.joint_moment_arm(i), P[j]))
                M[6 + i - 1, 6 + j - 1] = M[6 + j - 1, 6 + i - 1] = e
        return M

    def bias_forces(self) -> sp.Matrix:
        """``h(q, v)`` (``n_v``): the recursive Newton-Euler algorithm at zero acceleration,
        with gravity. Link forces ``f_k = m_k (a_Ck - g)``, moments about the COM
        ``n_k = I alpha + w x (I w)``, summed over the links beyond each joint about the base
        origin (``N = sum n_k + c_k x f_k``); ``h_base = (F, N)`` and ``h_j = u_j . N_{j+1}
        + w_j . F_{j+1}``."""
        if self.frame != "base":
            raise ValueError("the bias forces are built in the base frame")
        s = self.s
        n = s.n_links
        g = self.gravity()
        Fs: dict[int, tuple] = {}
        Ns: dict[int, tuple] = {}
        accF = accN = None
        for k in range(n, 0, -1):
            w, _ = self.velocity(k)
            al, a = self.bias(k)
            dc = self.com_offset(k)
            aC = self.point_bias(f"C{k}", (w, al, a), dc)
            m = s.link_mass[k - 1]
            f = self.p.vec(f"f{k}", tuple(m * (x - y) for x, y in zip(aC, g)))
            Ic = self.inertia(k)
            Iw = self.p.vec(f"Iw{k}", matvec(Ic, w))
            nk = tuple(x + y for x, y in zip(matvec(Ic, al), cross(w, Iw)))
            Nk = tuple(x + y for x, y in zip(nk, cross(self.com(k), f)))
            if accF is None:
                accF, accN = self.p.vec(f"F{k}", f), self.p.vec(f"N{k}", Nk)
            else:
                accF = self.p.vec(f"F{k}", tuple(x + y for x, y in zip(accF, f)))
                accN = self.p.vec(f"N{k}", tuple(x + y for x, y in zip(accN, Nk)))
            Fs[k], Ns[k] = accF, accN
        h = sp.zeros(s.nv, 1)
        for r in range(3):
            h[r] = Fs[1][r]
            h[3 + r] = Ns[1][r]
        for j in range(1, s.n_joints + 1):
            h[6 + j - 1] = dot(self.axis(j), Ns[j + 1]) + dot(self.joint_moment_arm(j), Fs[j + 1])
        return h
