"""Planar chain kinematics and inertia, in two independent forms.

* The **structured** form keeps the chain's structure as intermediate assignments (link
  orientations as rotation products of one sine and cosine per angle, joint positions, suffix
  sums over the chain): ``O(n^2)`` operations for the inertia
  matrix, like a composite-rigid-body algorithm.
* The **closed** form is eq. (4) of Reyes & Ma 2017 written out,
  ``M_s = sum_i J_i^T diag(m_i, m_i, I_i) J_i``, with each ``J_i`` obtained by differentiating
  the link pose; it is ``O(n^3)`` and used for inspection, for the operation-count comparison
  and as an independent check of the structured form.
"""

from __future__ import annotations

import sympy as sp

from .symbols import SnakeSymbols

__all__ = [
    "derived_parameter_values",
    "readable_mass_matrix",
    "StructuredChain",
    "closed_form_poses",
    "closed_form_jacobians",
    "closed_form_mass_matrix",
]


def derived_parameter_values(s: SnakeSymbols) -> dict[sp.Symbol, sp.Expr]:
    """Configuration-independent constants in terms of the raw link parameters.

    ``mtot = sum m_i``, ``beta_j = sum_{i>=j} m_i a_ij``,
    ``gamma_jk = sum_{i>=max(j,k)} m_i a_ij a_ik`` and ``Jrot_j = gamma_jj + I_j``.
    """
    n = s.n_links
    m, inertia = s.link_mass, s.link_inertia
    out: dict[sp.Symbol, sp.Expr] = {s.total_mass: sp.Add(*m)}
    for j in range(1, n + 1):
        out[s.first_moments[j - 1]] = sp.Add(*(m[i - 1] * s.lever(i, j) for i in range(j, n + 1)))
    for j in range(1, n + 1):
        for k in range(j, n + 1):
            out[s.second_moment(j, k)] = sp.Add(
                *(m[i - 1] * s.lever(i, j) * s.lever(i, k) for i in range(k, n + 1))
            )
    for j in range(1, n + 1):
        out[s.rotational_diagonal[j - 1]] = out[s.second_moment(j, j)] + inertia[j - 1]
    return out


class StructuredChain:
    """Builds the structured (recursive) kinematics and dynamics as assignment lists.

    Every method returns ``(assignments, outputs)``; assignments are ``(Symbol, Expr)`` pairs
    in dependency order. Symbols of intermediates are named after what they hold
    (``phi3``, ``cphi3`` = cos(phi_3), ``px2`` = x of the COM of link 2, ...).
    """

    def __init__(self, s: SnakeSymbols):
        self.s = s
        self.assignments: list[tuple[sp.Symbol, sp.Expr]] = []
        self._names: dict[str, sp.Symbol] = {}

    def _let(self, name: str, expr: sp.Expr) -> sp.Symbol:
        if name in self._names:
            return self._names[name]
        sym = sp.Symbol(name, real=True)
        self._names[name] = sym
        self.assignments.append((sym, expr))
        return sym

    # angles ------------------------------------------------------------------------------
    def phi(self, i: int) -> sp.Symbol:
        """Absolute angle of link ``i``: ``phi_1 = theta``, ``phi_{i+1} = phi_i + q_i``."""
        q = self.s.q
        if i == 1:
            return q[2]
        return self._let(f"phi{i}", self.phi(i - 1) + q[2 + i - 1])

    def _cos_sin_coordinate(self, r: int) -> tuple[sp.Symbol, sp.Symbol]:
        """``cos``, ``sin`` of rotational coordinate ``r`` (``theta`` for ``r = 0``, joint
        ``r`` after): the only trigonometric calls of the chain, one pair per angle."""
        a = self.s.q[2 + r]
        return self._let(f"cq{r}", sp.cos(a)), self._let(f"sq{r}", sp.sin(a))

    def cos_phi(self, i: int) -> sp.Symbol:
        """``cos(phi_i)`` as a rotation product: ``cos(phi_{i-1} + q_{i-1})`` =
        ``c_{i-1} cos q_{i-1} - s_{i-1} sin q_{i-1}`` (no trigonometric call of a cumulative
        angle: the arguments stay as small as the joint angles, and the compiler turns each
        pair into one ``sincos`` call)."""
        if i == 1:
            return self._cos_sin_coordinate(0)[0]
        if f"cphi{i}" in self._names:
            return self._names[f"cphi{i}"]
        cq, sq = self._cos_sin_coordinate(i - 1)
        return self._let(f"cphi{i}", self.cos_phi(i - 1) * cq - self.sin_phi(i - 1) * sq)

    def sin_phi(self, i: int) -> sp.Symbol:
        """``sin(phi_i) = s_{i-1} cos q_{i-1} + c_{i-1} sin q_{i-1}`` (see :meth:`cos_phi`)."""
        if i == 1:
            return self._cos_sin_coordinate(0)[1]
        if f"sphi{i}" in self._names:
            return self._names[f"sphi{i}"]
        cq, sq = self._cos_sin_coordinate(i - 1)
        return self._let(f"sphi{i}", self.sin_phi(i - 1) * cq + self.cos_phi(i - 1) * sq)

    def omega(self, i: int) -> sp.Symbol:
        """Absolute angular velocity of link ``i`` (cumulative joint rates)."""
        v = self.s.v
        if i == 1:
            return v[2]
        return self._let(f"omega{i}", self.omega(i - 1) + v[2 + i - 1])

    # positions ---------------------------------------------------------------------------
    def com(self, i: int) -> tuple[sp.Expr, sp.Expr]:
        """COM of link ``i``: ``p_{i+1} = p_i + (l_i - c_i) e_i + c_{i+1} e_{i+1}``."""
        s = self.s
        if i == 1:
            return s.q[0], s.q[1]
        jx, jy = self.joint(i - 1)
        c = s.link_com[i - 1]
        return (
            self._let(f"px{i}", jx + c * self.cos_phi(i)),
            self._let(f"py{i}", jy + c * self.sin_phi(i)),
        )

    def joint(self, j: int) -> tuple[sp.Expr, sp.Expr]:
        """Position of joint ``j`` (front end of link ``j``)."""
        s = self.s
        px, py = self.com(j)
        d = s.link_length[j - 1] - s.link_com[j - 1]
        return (
            self._let(f"jx{j}", px + d * self.cos_phi(j)),
            self._let(f"jy{j}", py + d * self.sin_phi(j)),
        )

    def pivot(self, r: int) -> tuple[sp.Expr, sp.Expr]:
        """Point about which rotational coordinate ``r`` turns the links beyond it.

        ``r = 0`` is ``theta`` (turns the whole chain about the COM of link 1, since ``(x, y)``
        is held), ``r = j >= 1`` is joint ``j``.
        """
        return self.com(1) if r == 0 else self.joint(r)

    # outputs -----------------------------------------------------------------------------
    def link_poses(self) -> sp.Matrix:
        """``3 x n_l``: column ``i`` is ``(x_i, y_i, phi_i)`` of the COM of link ``i``."""
        cols = []
        for i in range(1, self.s.n_links + 1):
            px, py = self.com(i)
            cols.append([px, py, self.phi(i)])
        return sp.Matrix(cols).T

    def link_jacobian(self, i: int) -> sp.Matrix:
        """``J_i`` (3 x n_s), eq. (3): COM twist ``(v_x, v_y, omega)`` of link ``i``.

        Column ``2 + r`` for rotational coordinate ``r < i`` is ``k x (p_i - pivot_r)``.
        """
        s = self.s
        J = sp.zeros(3, s.n_coordinates)
        J[0, 0] = 1
        J[1, 1] = 1
        px, py = self.com(i)
        for r in range(0, i):
            ox, oy = self.pivot(r)
            J[0, 2 + r] = -(py - oy)
            J[1, 2 + r] = px - ox
            J[2, 2 + r] = 1
        return J

    def link_jacobians(self) -> sp.Matrix:
        """All ``J_i`` stacked: ``(3 n_l) x n_s``, rows ``3(i-1) .. 3i-1`` for link ``i``."""
        return sp.Matrix.vstack(*(self.link_jacobian(i) for i in range(1, self.s.n_links + 1)))

    def link_bias_accelerations(self) -> sp.Matrix:
        """``3 x n_l``: ``Jdot_i qdot`` for each link (COM acceleration at zero ``qddot``).

        Planar chain: ``b_{i+1} = b_i - (l_i - c_i) w_i^2 e_i - c_{i+1} w_{i+1}^2 e_{i+1}``,
        angular part zero.
        """
        s = self.s
        cols = []
        bx, by = sp.Integer(0), sp.Integer(0)
        for i in range(1, s.n_links + 1):
            if i > 1:
                d = s.link_length[i - 2] - s.link_com[i - 2]
                c = s.link_com[i - 1]
                w0 = self.omega(i - 1) ** 2
                w1 = self.omega(i) ** 2
                bx = self._let(
                    f"bx{i}", bx - d * w0 * self.cos_phi(i - 1) - c * w1 * self.cos_phi(i)
                )
                by = self._let(
                    f"by{i}", by - d * w0 * self.sin_phi(i - 1) - c * w1 * self.sin_phi(i)
                )
            cols.append([bx, by, sp.Integer(0)])
        return sp.Matrix(cols).T

    def bias_forces(self) -> sp.Matrix:
        """``h_s`` of eq. (4): ``sum_i J_i^T diag(m_i, m_i, I_i) Jdot_i qdot`` (n_s x 1).

        Written with suffix sums over the chain: the force ``F_i = m_i b_i`` of every link
        beyond a pivot contributes its moment about that pivot.
        """
        s = self.s
        n = s.n_links
        b = self.link_bias_accelerations()
        m = s.link_mass
        # suffix sums of forces and of moments about the origin
        Fx = [None] * (n + 2)
        Fy = [None] * (n + 2)
        Mz = [None] * (n + 2)
        Fx[n + 1] = Fy[n + 1] = Mz[n + 1] = sp.Integer(0)
        for i in range(n, 0, -1):
            px, py = self.com(i)
            fx = m[i - 1] * b[0, i - 1]
            fy = m[i - 1] * b[1, i - 1]
            Fx[i] = self._let(f"hFx{i}", Fx[i + 1] + fx)
            Fy[i] = self._let(f"hFy{i}", Fy[i + 1] + fy)
            Mz[i] = self._let(f"hMz{i}", Mz[i + 1] + px * fy - py * fx)
        h = sp.zeros(s.n_coordinates, 1)
        h[0] = Fx[1]
        h[1] = Fy[1]
        for r in range(0, n):
            ox, oy = self.pivot(r)
            i0 = r + 1  # links turned by coordinate r: i >= r + 1
            h[2 + r] = Mz[i0] - (ox * Fy[i0] - oy * Fx[i0])
        return h

    def mass_matrix(self) -> sp.Matrix:
        """``M_s`` of eq. (4) in about ``2 n^2`` operations (composite bodies about pivots).

        Coordinate ``t`` (``theta`` for ``t = 0``, joint ``t`` after) turns links
        ``t+1 .. n`` about its pivot ``o_t`` (``o_0`` the COM of link 1, ``o_t`` joint ``t``).
        With the first moment of those links about ``o_t``, ``S_t = sum_{k>t} beta_k e_k``, and
        their rotational inertia about it, ``H_t``:

        * ``M_pp = mtot 1`` and ``M_p,t = k x S_t = (-S_t.y, S_t.x)``;
        * ``M_tt = H_t`` and, for ``r < t``, ``M_rt = H_t + (o_t - o_r).S_t`` (the composite
          body beyond ``t`` turned about pivot ``r``), summed one pivot step at a time:
          ``M_rt = M_{r+1,t} + u_{r+1}.S_t`` with ``u_k = o_k - o_{k-1} = d_k e_k``
          (``d_1 = l_1 - c_1``, ``d_k = l_k``);
        * ``H_{t-1} = H_t + Jrot_t + 2 u_t.S_t`` (parallel-axis theorem) ``= M_{t-1,t} +
          u_t.S_t + Jrot_t``, reusing the step ``u_t.S_t`` of ``M_{t-1,t}``.

        Four operations per entry of the rotational block, ``O(n)`` for the rest; no pivot
        position is formed.
        """
        s = self.s
        n = s.n_links
        ns = s.n_coordinates
        c = [None] + [self.cos_phi(i) for i in range(1, n + 1)]
        sn = [None] + [self.sin_phi(i) for i in range(1, n + 1)]
        beta = s.first_moments
        M = sp.zeros(ns, ns)
        M[0, 0] = M[1, 1] = s.total_mass
        # S_t as (My_t, -Mx_t): the coupling block M[(x, y), 2 + t] = (Mx_t, My_t)
        Mx: list = [None] * n
        My: list = [None] * n
        accx = accy = sp.Integer(0)
        for t in range(n - 1, -1, -1):
            accx = self._let(f"Mx{t}", accx - beta[t] * sn[t + 1])
            accy = self._let(f"My{t}", accy + beta[t] * c[t + 1])
            Mx[t], My[t] = accx, accy
            M[0, 2 + t] = M[2 + t, 0] = accx
            M[1, 2 + t] = M[2 + t, 1] = accy
        # pivot steps u_k = d_k e_k
        d = [None] + [s.link_length[0] - s.link_com[0]] + list(s.link_length[1:])
        ux: list = [None] * n
        uy: list = [None] * n
        for k in range(1, n):
            ux[k] = self._let(f"ux{k}", d[k] * c[k])
            uy[k] = self._let(f"uy{k}", d[k] * sn[k])
        # columns t = n-1 .. 0: diagonal H_t, then M_rt = M_{r+1,t} + u_{r+1}.S_t upwards
        H = s.rotational_diagonal[n - 1]
        for t in range(n - 1, -1, -1):
            M[2 + t, 2 + t] = H
            acc = H
            for r in range(t - 1, -1, -1):
                step = self._let(f"uS{r + 1}_{t}", ux[r + 1] * My[t] - uy[r + 1] * Mx[t])
                acc = self._let(f"Mrot{r}_{t}", acc + step)
                M[2 + r, 2 + t] = M[2 + t, 2 + r] = acc
                if r == t - 1:
                    H_next = self._let(f"H{t - 1}", acc + step + s.rotational_diagonal[t - 1])
            if t > 0:
                H = H_next
        return M

    def mass_matrix_suffix_sums(self) -> sp.Matrix:
        """``M_s`` of eq. (4) in ``O(n^2)`` as suffix sums of ``gamma_jk cos(phi_j - phi_k)``
        (about ``3.5 n^2`` operations; fewer than :meth:`mass_matrix` up to a few joints).

        In absolute angles ``phi`` the inertia is ``M_pp = mtot 1``,
        ``M_p,phi_j = beta_j e_j^perp`` and ``M_phi_j phi_k = gamma_jk cos(phi_j - phi_k)``
        (``Jrot_j`` on the diagonal). With ``phi_j = theta + sum_{l<j} q_l`` the rotational
        block is a two-dimensional suffix sum and the coupling block a one-dimensional one.
        """
        s = self.s
        n = s.n_links
        ns = s.n_coordinates
        c = [None] + [self.cos_phi(i) for i in range(1, n + 1)]
        sn = [None] + [self.sin_phi(i) for i in range(1, n + 1)]

        def mphi(j: int, k: int) -> sp.Expr:
            if j == k:
                return s.rotational_diagonal[j - 1]
            a, b = min(j, k), max(j, k)
            cd = self._let(f"cdphi{a}_{b}", c[a] * c[b] + sn[a] * sn[b])
            return self._let(f"Mphi{a}_{b}", s.second_moment(a, b) * cd)

        # R[j][r] = sum_{k >= r+1} Mphi_jk for r = 0..n-1
        R: dict[tuple[int, int], sp.Expr] = {}
        for j in range(1, n + 1):
            acc = sp.Integer(0)
            for r in range(n - 1, -1, -1):
                acc = mphi(j, r + 1) if r == n - 1 else self._let(f"R{j}_{r}", acc + mphi(j, r + 1))
                R[j, r] = acc
        M = sp.zeros(ns, ns)
        # rotational block, upper triangle: Mrot[r][t] = sum_{j >= r+1} R[j][t], r <= t
        for t in range(0, n):
            acc = sp.Integer(0)
            for r in range(n - 1, -1, -1):
                acc = R[r + 1, t] if r == n - 1 else self._let(f"Mrot{r}_{t}", acc + R[r + 1, t])
                if r <= t:
                    M[2 + r, 2 + t] = acc
                    M[2 + t, 2 + r] = acc
        # coupling block: M[(x,y), 2+r] = sum_{j >= r+1} beta_j (-sin phi_j, cos phi_j)
        accx = accy = sp.Integer(0)
        for r in range(n - 1, -1, -1):
            beta = s.first_moments[r]
            accx = self._let(f"Mx{r}", accx - beta * sn[r + 1])
            accy = self._let(f"My{r}", accy + beta * c[r + 1])
            M[0, 2 + r] = M[2 + r, 0] = accx
            M[1, 2 + r] = M[2 + r, 1] = accy
        M[0, 0] = M[1, 1] = s.total_mass
        return M


# ------------------------------------------------------------------------------------------
# Closed form (independent): differentiate the poses, eq. (3)-(4).
# ------------------------------------------------------------------------------------------
def closed_form_poses(s: SnakeSymbols) -> list[tuple[sp.Expr, sp.Expr, sp.Expr]]:
    """``(x_i, y_i, phi_i)`` of every link COM as explicit expressions of ``q``."""
    q = s.q
    phis = [q[2]]
    for j in range(1, s.n_joints + 1):
        phis.append(phis[-1] + q[2 + j])
    poses = []
    for i in range(1, s.n_links + 1):
        px = q[0] + sp.Add(*(s.lever(i, j) * sp.cos(phis[j - 1]) for j in range(1, i + 1)))
        py = q[1] + sp.Add(*(s.lever(i, j) * sp.sin(phis[j - 1]) for j in range(1, i + 1)))
        poses.append((px, py, phis[i - 1]))
    return poses


def closed_form_jacobians(s: SnakeSymbols) -> list[sp.Matrix]:
    """``J_i = d(x_i, y_i, phi_i) / dq`` (3 x n_s), eq. (3)."""
    q = sp.Matrix(s.q)
    return [sp.Matrix(list(pose)).jacobian(q) for pose in closed_form_poses(s)]


def closed_form_mass_matrix(s: SnakeSymbols) -> sp.Matrix:
    """Eq. (4): ``M_s = sum_i J_i^T diag(m_i, m_i, I_i) J_i`` in the raw link parameters."""
    M = sp.zeros(s.n_coordinates, s.n_coordinates)
    for i, J in enumerate(closed_form_jacobians(s)):
        D = sp.diag(s.link_mass[i], s.link_mass[i], s.link_inertia[i])
        M += J.T * D * J
    return M.applyfunc(lambda e: sp.expand(e))


def readable_mass_matrix(s: SnakeSymbols, *, substitute: bool = True) -> sp.Matrix:
    """``M_s`` written in absolute link angles, for reading (``snakecg show``, the docs).

    ``M_pp = mtot 1``, ``M_p,r = sum_{j>r} beta_j (-sin phi_j, cos phi_j)`` and
    ``M_rs = sum_{j>r} sum_{k>s} gamma_jk cos(phi_j - phi_k)`` (``Jrot_j`` for ``j = k``),
    with ``phi_j = theta + q_1 + ... + q_{j-1}``. With ``substitute`` the constants
    ``mtot, beta, gamma, Jrot`` are replaced by their expressions in the link parameters
    (factored per constant, no global simplification).
    """
    n = s.n_links
    q = s.q
    phi = [q[2]]
    for j in range(1, s.n_joints + 1):
        phi.append(phi[-1] + q[2 + j])
    M = sp.zeros(s.n_coordinates, s.n_coordinates)
    M[0, 0] = M[1, 1] = s.total_mass
    for r in range(n):
        M[0, 2 + r] = M[2 + r, 0] = sp.Add(*(-s.first_moments[j] * sp.sin(phi[j])
                                             for j in range(r, n)))
        M[1, 2 + r] = M[2 + r, 1] = sp.Add(*(s.first_moments[j] * sp.cos(phi[j])
                                             for j in range(r, n)))
        for t in range(r, n):
            terms = []
            for j in range(r, n):
                for k in range(t, n):
                    if j == k:
                        terms.append(s.rotational_diagonal[j])
                    else:
                        terms.append(s.second_moment(j + 1, k + 1) * sp.cos(phi[j] - phi[k]))
            M[2 + r, 2 + t] = M[2 + t, 2 + r] = sp.Add(*terms)
    if substitute:
        values = {k: sp.factor_terms(v) for k, v in derived_parameter_values(s).items()}
        M = M.xreplace(values)
    return M
