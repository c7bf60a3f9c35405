"""Independent references for the general scenes' tests: random scenes, a dense NumPy model of
the KKT conditions, brute-force enumeration of the polyhedral pieces and the primal Gauss
problem in cvxpy (solved by Clarabel). None of it calls the code under test's solver."""

from __future__ import annotations

import itertools
import warnings

import numpy as np

import snakecg
from snakecg import Robot
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject
from snakecg.scenes.solve import BOX, DISC, FREE, SPLIT, UNILATERAL

POLYHEDRAL = ("frictionless", "wheels", "ideal_wheels")
ALL_MODELS = POLYHEDRAL + ("coulomb", "anisotropic")


def random_scene(rng, models=ALL_MODELS, n_joints=None):
    """A random scene of n_a 1-5 joints with 1-4 bodies touching links (discs, boxes, pegs),
    a ground model per link from ``models``, and a random configuration (q, tau)."""
    na = int(rng.integers(1, 6)) if n_joints is None else n_joints
    robot = Robot(joints=na, mass=list(rng.uniform(0.5, 2.0, na + 1)),
                  length=list(rng.uniform(0.1, 0.2, na + 1)),
                  inertia=list(rng.uniform(0.001, 0.004, na + 1)))
    ground = tuple(Ground(model=str(rng.choice(models)), mu=float(rng.uniform(0.05, 0.6)),
                          mu_forward=float(rng.uniform(0.05, 0.5)),
                          mu_backward=float(rng.uniform(0.05, 0.5)),
                          mu_lateral=float(rng.uniform(0.05, 0.8)),
                          wheel_offset=float(rng.uniform(-0.03, 0.03)))
                   for _ in range(na + 1))
    q = np.r_[rng.normal(size=2), rng.uniform(-np.pi, np.pi), rng.uniform(-1.2, 1.2, na)]
    tau = rng.normal(size=na) * rng.choice([0.1, 1.0, 5.0])
    objects, pegs = [], []
    for _ in range(int(rng.integers(1, 5))):
        link = int(rng.integers(1, na + 2))
        side = str(rng.choice(["left", "right"]))
        off = float(rng.uniform(0.1, 0.9)) * robot.length[link - 1]
        kind = rng.choice(["disc", "box", "peg"])
        if kind == "peg":
            pegs.append((link, off, side, float(rng.uniform(0.01, 0.05))))
        elif kind == "disc":
            objects.append(SceneObject(shape="disc", radius=float(rng.uniform(0.02, 0.06)),
                                       mass=float(rng.uniform(0.5, 50)),
                                       touching={"link": link, "offset": off, "side": side},
                                       mu=float(rng.uniform(0.1, 0.5))
                                       if "coulomb" in models and rng.random() < 0.3
                                       else None))
        else:
            objects.append(SceneObject(shape="box", size=(float(rng.uniform(0.02, 0.08)),
                                                          float(rng.uniform(0.02, 0.08))),
                                       mass=float(rng.uniform(0.5, 50)),
                                       touching={"link": link, "offset": off, "side": side}))
    return robot, ground, tuple(objects), pegs, q, tau


def peg_obstacles(model, pegs, q):
    """Pegs touching their links at configuration q (placed from the link poses)."""
    P = model.link_poses(q)
    out = []
    for link, off, side, r in pegs:
        x, y, phi = P[link - 1]
        t = np.array([np.cos(phi), np.sin(phi)])
        n = np.array([-np.sin(phi), np.cos(phi)]) * (1 if side == "left" else -1)
        rear = np.array([x, y]) - model.robot.com[link - 1] * t
        c = rear + off * t + (r + model.scene.radius) * n
        out.append(Obstacle(shape="peg", center=tuple(c), radius=r))
    return tuple(out)


def inertia_and_force(model, q, tau, f_obj=None):
    """The full inertia (M_s, then m, m, I per object: eq. 12) and the generalized force
    (B tau, the objects' wrenches) of a general scene at q, in NumPy."""
    ns, no = model.n_coordinates, model.scene.n_objects
    n = ns + 3 * no
    M = np.zeros((n, n))
    M[:ns, :ns] = model.mass_matrix(np.asarray(q))
    for j, o in enumerate(model.scene.objects):
        M[ns + 3 * j:ns + 3 * j + 3, ns + 3 * j:ns + 3 * j + 3] = np.diag(
            [o.mass, o.mass, o.plate_inertia])
    f = np.zeros(n)
    f[3:ns] = tau
    if f_obj is not None:
        f[ns:] = np.ravel(f_obj)
    return M, f


def pegs_row():
    """The obstacle-aided locomotion example (examples/scenes/pegs_row.toml): its scene, its
    model and its start (the serpenoid's shape at t = 0: 0.5 sin(2 pi k / 5) per joint)."""
    from pathlib import Path

    from snakecg.scenes import load_scene
    from snakecg.scenes.toml_reading import read_scene

    scene = read_scene(Path(__file__).resolve().parents[1] / "examples" / "scenes"
                       / "pegs_row.toml")
    q0 = np.zeros(13)
    q0[3:] = 0.5 * np.sin(np.arange(10) * 2 * np.pi / 5)
    return scene, load_scene(scene), q0


def indeterminate_scene(q, joints=10, ground=None):
    """The forward benchmark's statically indeterminate scene (benchmarks/bench_scenes.py),
    built apart: a box against link 1 and a disc against link n + 1 (both rubbing the
    ground), pegs against four links on alternating sides, Coulomb ground (or ``ground``),
    at q."""
    robot = Robot(joints=joints)
    objects = (SceneObject(shape="box", size=(0.1, 0.08), mass=2.0, mu=0.2,
                           touching={"link": 1, "offset": 0.075, "side": "left"}),
               SceneObject(shape="disc", radius=0.04, mass=1.0, mu=0.2,
                           touching={"link": joints + 1, "offset": 0.075, "side": "right"}))
    ground = Ground(model="coulomb", mu=0.3) if ground is None else ground
    P = snakecg.load(GeneralScene(robot, ground=ground, objects=objects)).link_poses(q)
    pegs = []
    for k in range(4):
        x, y, phi = P[1 + (k * (joints - 1)) // 4]
        n = np.array([-np.sin(phi), np.cos(phi)]) * (1.0 if k % 2 else -1.0)
        c = np.array([x, y]) + 0.03 * n
        pegs.append(Obstacle(shape="peg", center=(float(c[0]), float(c[1])), radius=0.03))
    return GeneralScene(robot, ground=ground, objects=objects, obstacles=tuple(pegs))


def dense_problem(res, model, tau, f_obj=None):
    """M (full), f, A, blocks of the one-sample result's rows, and G, b, a_free in NumPy."""
    r = res._rows[0]
    M, f = inertia_and_force(model, res._q, tau, f_obj)
    return problem_of(M, f, r.A, r.kind, r.start, r.par)


def problem_of(M, f, A, kind, start, par, c=None):
    """The dense problem of M, f, the rows A and their blocks (kind, start, par): with
    G = A M^-1 A^T, b = A M^-1 f + c, a_free = M^-1 f and M^-1, in NumPy. c: the rows'
    offsets (a simulation step's gaps over h: the rows read w = A a + c), default none."""
    Minv = np.linalg.inv(M)
    c = np.zeros(len(A)) if c is None else np.asarray(c, dtype=float)
    return dict(M=M, f=f, A=A, c=c, G=A @ Minv @ A.T, b=A @ Minv @ f + c, a_free=Minv @ f,
                Minv=Minv, blocks=list(zip(kind, start, par)))


def kkt_violations(p, lam, a, tol=1e-8):
    """Every KKT condition the (lam, a) pair violates, checked densely: a = a_free + M^-1 A^T
    lam; contact forces >= 0, their accelerations >= 0 and complementary; stick forces inside
    their sets with zero sliding acceleration; sliding forces on the boundary, opposing the
    sliding acceleration (maximum dissipation)."""
    out = []
    w = p["G"] @ lam + p["b"]
    F = max(1.0, np.abs(lam).max())
    W = max(1.0, np.abs(p["b"]).max(), np.abs(w).max())
    a_ref = p["a_free"] + p["Minv"] @ p["A"].T @ lam
    if not np.allclose(a, a_ref, rtol=1e-9, atol=1e-9 * max(1, np.abs(a_ref).max())):
        out.append("a != a_free + M^-1 A^T lam")
    for kind, s, par in p["blocks"]:
        if kind == FREE:
            if abs(w[s]) > tol * W:
                out.append(f"ideal wheel row {s} accelerates {w[s]}")
        elif kind == UNILATERAL:
            if lam[s] < -tol * F:
                out.append(f"contact {s} pulls {lam[s]}")
            if w[s] < -tol * W:
                out.append(f"contact {s} penetrates {w[s]}")
            if abs(lam[s] * w[s]) > tol * F * W:
                out.append(f"contact {s} not complementary")
        elif kind == BOX:
            u = par[0]
            if abs(lam[s]) > u * (1 + tol) + tol * F:
                out.append(f"wheel {s} force beyond its bound")
            if abs(lam[s]) < u * (1 - 1e-7):
                if abs(w[s]) > tol * W:
                    out.append(f"stuck wheel {s} slides")
            elif lam[s] * w[s] > tol * F * W:
                out.append(f"wheel {s} force does not oppose its sliding")
        else:
            l, ww = lam[s:s + 2], w[s:s + 2]
            if kind == DISC:
                inside = np.hypot(*l) / par[0] if par[0] > 0 else 0.0
                normal = l / par[0] ** 2 if par[0] > 0 else l
            else:
                st = par[0] if l[0] < 0 else par[1]
                inside = np.hypot(l[0] / st, l[1] / par[2])
                normal = np.array([l[0] / st ** 2, l[1] / par[2] ** 2])
            if inside > 1 + tol:
                out.append(f"friction block {s} outside its set ({inside})")
            if inside < 1 - 1e-7:
                if np.hypot(*ww) > tol * W:
                    out.append(f"sticking block {s} slides {ww}")
            else:  # w = -gamma normal, gamma >= 0
                nn = normal / np.hypot(*normal)
                if ww @ nn > tol * W or abs(ww[0] * nn[1] - ww[1] * nn[0]) > tol * W:
                    out.append(f"sliding block {s} not maximally dissipative: w {ww}, n {nn}")
    return out


def enumerate_polyhedral(p, tol=1e-9):
    """The accelerations of every piece of a polyhedral problem (FREE, UNILATERAL, BOX
    blocks) whose KKT conditions hold, by trying every combination of pieces (held, at zero,
    at +-bound) and solving its equations by least squares. Stops at the first; returns its
    accelerations and held rows (None, None when no piece holds)."""
    blocks = p["blocks"]
    G, b = p["G"], p["b"]
    choices = []
    for kind, s, par in blocks:
        if kind == FREE:
            choices.append(("held",))
        elif kind == UNILATERAL:
            choices.append(("held", "zero"))
        elif kind == BOX:
            choices.append(("held", "+", "-") if par[0] > 0 else ("zero",))
        else:
            raise ValueError("not polyhedral")
    m = len(b)
    scale_w = max(1.0, np.abs(b).max(), np.abs(np.diag(G)).max())
    for combo in itertools.product(*choices):
        lam = np.zeros(m)
        held = []
        for (kind, s, par), c in zip(blocks, combo):
            if c == "held":
                held.append(s)
            elif c == "+":
                lam[s] = par[0]
            elif c == "-":
                lam[s] = -par[0]
        if held:
            H = np.array(held)
            rhs = -(b[H] + G[H] @ lam)
            lam[H] = np.linalg.lstsq(G[np.ix_(H, H)], rhs, rcond=1e-12)[0]
        w = G @ lam + b
        F = max(1.0, np.abs(lam).max())
        ok = True
        for (kind, s, par), c in zip(blocks, combo):
            if c == "held":
                ok &= abs(w[s]) <= tol * scale_w * F
                if kind == UNILATERAL:
                    ok &= lam[s] >= -tol * F
                if kind == BOX:
                    ok &= abs(lam[s]) <= par[0] * (1 + tol)
            elif c == "zero":
                ok &= w[s] >= -tol * scale_w * F
            elif c == "+":
                ok &= w[s] <= tol * scale_w * F
            elif c == "-":
                ok &= w[s] >= -tol * scale_w * F
            if not ok:
                break
        if ok:
            return p["a_free"] + p["Minv"] @ p["A"].T @ lam, held
    return None, None


def clarabel_accelerations(p, tol=1e-11):
    """The primal of Gauss's principle with the sets' support functions, in cvxpy (Clarabel):
    min 1/2 |a - a_free|_M^2 + sum_B sigma_K_B(-A_B a)."""
    import cvxpy as cp

    n = len(p["f"])
    a = cp.Variable(n)
    L = np.linalg.cholesky(p["M"])
    cost = 0.5 * cp.sum_squares(L.T @ (a - p["a_free"]))
    cons = []
    A, c = p["A"], p.get("c", np.zeros(len(p["A"])))
    for kind, s, par in p["blocks"]:
        if kind == FREE:
            cons.append(A[s] @ a + c[s] == 0)
        elif kind == UNILATERAL:
            cons.append(A[s] @ a + c[s] >= 0)
        elif kind == BOX:
            cost += par[0] * cp.abs(A[s] @ a + c[s])
        elif kind == DISC:
            cost += par[0] * cp.norm(A[s:s + 2] @ a + c[s:s + 2])
        else:  # split ellipse: y = -(A a + c); sigma = |(p1 y_t+, p0 y_t-, p2 y_n)|
            sp, sm = cp.Variable(nonneg=True), cp.Variable(nonneg=True)
            yt = -(A[s] @ a + c[s])
            cons += [sp >= yt, sm >= -yt]
            cost += cp.norm(cp.hstack([par[1] * sp, par[0] * sm,
                                       par[2] * (-(A[s + 1] @ a + c[s + 1]))]))
    prob = cp.Problem(cp.Minimize(cost), cons)
    prob.solve(solver="CLARABEL", tol_gap_abs=tol, tol_gap_rel=tol, tol_feas=tol,
               max_iter=400)
    return a.value, prob.status


def gauss_objective(p, a):
    """Gauss's principle with the sets' support functions at the accelerations a (the primal
    that clarabel_accelerations minimises): 1/2 |a - a_free|_M^2 + sum_B sigma_K_B(-A_B a)."""
    d = a - p["a_free"]
    v = 0.5 * d @ p["M"] @ d
    A, c = p["A"], p.get("c", np.zeros(len(p["A"])))
    for kind, s, par in p["blocks"]:
        if kind == BOX:
            v += par[0] * abs(A[s] @ a + c[s])
        elif kind in (DISC, SPLIT):
            y = -(A[s:s + 2] @ a + c[s:s + 2])
            if np.any(y != 0):
                v += _support(kind, par, y)[0]
    return v


def agrees_with_clarabel(p, a, tol=1e-6, loose=1e-4):
    """The accelerations a against Clarabel's: within tol of their scale, or, where Clarabel
    stops short on a degenerate problem (its accelerations up to loose away), a gives Gauss's
    objective no higher than Clarabel's (the unique minimiser: Clarabel's point is then the
    less accurate one). Returns the distance (relative)."""
    ref, st = clarabel_accelerations(p)
    assert st in ("optimal", "optimal_inaccurate"), st
    scale = max(1.0, np.abs(ref).max())
    dist = np.abs(a - ref).max() / scale
    if dist > tol:
        assert dist <= loose, dist
        fa, fr = gauss_objective(p, a), gauss_objective(p, ref)
        assert fa <= fr + 1e-12 * abs(fr), (fa, fr)
    return dist


def clarabel_min_norm_forces(p, lam_star):
    """The minimum-norm forces among all optimal ones, in cvxpy (Clarabel): every force inside
    the sets that gives the same generalized constraint force (A^T lam = A^T lam*), the forces
    of a block whose rows accelerate (|w| above 1e-9 of the scale) held at lam*, since
    complementarity and maximum dissipation fix them given the unique accelerations (a
    sliding disc's force opposes its sliding, a contact that opens carries none; a reference
    free to move them trades a feasibility error of 1e-7 for a smaller norm, as a slowly
    sliding disc pins its force only to second order). The statically indeterminate case's
    reference."""
    import cvxpy as cp

    w = p["G"] @ lam_star + p["b"]
    W = max(1.0, np.abs(w).max())
    x = cp.Variable(len(lam_star))
    cons = [p["A"].T @ x == p["A"].T @ lam_star]
    for kind, s, par in p["blocks"]:
        nk = 2 if kind >= DISC else 1
        if np.abs(w[s:s + nk]).max() > 1e-9 * W:
            cons.append(x[s:s + nk] == lam_star[s:s + nk])
        elif kind == UNILATERAL:
            cons.append(x[s] >= 0)
        elif kind == BOX:
            cons.append(cp.abs(x[s]) <= par[0])
        elif kind == DISC:
            cons.append(cp.norm(x[s:s + 2]) <= par[0])
        elif kind == SPLIT:  # semi-axes par[0] backward (x <= 0), par[1] forward, par[2] across
            sp, sm = cp.Variable(nonneg=True), cp.Variable(nonneg=True)
            cons += [x[s] == sp - sm,
                     cp.norm(cp.hstack([sm / par[0], sp / par[1], x[s + 1] / par[2]])) <= 1]
    prob = cp.Problem(cp.Minimize(cp.sum_squares(x)), cons)
    for tol in (1e-12, 1e-10, 1e-9):  # retried looser where Clarabel stops short of 1e-12
        with warnings.catch_warnings():  # "may be inaccurate": the retry's reason
            warnings.simplefilter("ignore", UserWarning)
            prob.solve(solver="CLARABEL", tol_gap_abs=tol, tol_gap_rel=tol, tol_feas=tol,
                       max_iter=500)
        if prob.status == "optimal":
            break
    return x.value, prob.status


def small_scenes(rng, count, models=POLYHEDRAL, *, object_friction=True, need_object=False):
    """``count`` random scenes of 2-3 joints, 1-4 contacts and independent rows, as
    ``(model, q, forward result at zero torque)`` (resampled on overlap); without
    ``object_friction`` no object rubs the ground; ``need_object``: at least one object."""
    import snakecg
    from snakecg.errors import InputError

    out = []
    while len(out) < count:
        robot, ground, objects, pegs, q, _ = random_scene(rng, models,
                                                          n_joints=int(rng.integers(2, 4)))
        if not object_friction and any(o.mu is not None for o in objects):
            continue
        try:
            m0 = snakecg.load(GeneralScene(robot, ground=ground, objects=objects))
            model = snakecg.load(GeneralScene(robot, ground=ground, objects=objects,
                                              obstacles=peg_obstacles(m0, pegs, q)))
            res = model.forward(q, np.zeros(robot.joints))
        except InputError:
            continue
        if (1 <= len(res.contacts) <= 4 and not res.dependent
                and (model.scene.n_objects or not need_object)):
            out.append((model, q, res))
    return out


def _support(kind, par, y):
    """A 2-D set's support function sigma(y) = max_{l in K} l . y, its maximizer l and
    Hessian (the disc's radius, or the split ellipse's semi-axes: p1 along y_t >= 0)."""
    ax = par[0] if kind == DISC else (par[1] if y[0] >= 0 else par[0])
    ay = par[0] if kind == DISC else par[2]
    D = np.array([ax, ay])
    s = np.hypot(*(D * y))
    v = D * y / s
    return s, D * v, (np.diag(D) @ (np.eye(2) - np.outer(v, v)) @ np.diag(D)) / s


def solve_piece(p, pieces, a0=None, tol=1e-9):
    """The accelerations of one assignment of pieces (per block: "held", "zero", "slide",
    "+" / "-" for a bounded wheel at its bound) if it satisfies every KKT condition, else None.
    Solved in the primal, densely: a = Z y on the held rows' null space, Newton on
    1/2 |a - a_free|_M^2 + sum over sliding sets of sigma_K(-A_k a) - lam_fixed . A a; the held
    forces by least squares (minimum norm) and checked against their sets. Newton starts from
    a0 (default a_free) taken onto the held rows' null space."""
    M, A, af = p["M"], p["A"], p["a_free"]
    n, m = len(af), A.shape[0]
    held = [s + i for (kind, s, par), c in zip(p["blocks"], pieces) if c == "held"
            for i in range(2 if kind >= DISC else 1)]
    lam_fix = np.zeros(m)
    slide = []
    for (kind, s, par), c in zip(p["blocks"], pieces):
        if c in "+-":
            lam_fix[s] = par[0] if c == "+" else -par[0]
        elif c == "slide":
            slide.append((kind, s, par))
    if held:
        _, sv, Vt = np.linalg.svd(A[held])
        rank = int(np.sum(sv > 1e-12 * max(sv.max(), 1e-300)))
        Z = Vt[rank:].T
    else:
        Z = np.eye(n)
    if Z.shape[1] == 0:
        a = np.zeros(n)
    else:
        y = np.linalg.solve(Z.T @ M @ Z, Z.T @ M @ (af if a0 is None else a0))

        def parts(y):
            a = Z @ y
            val = 0.5 * (a - af) @ M @ (a - af) - lam_fix @ (A @ a)
            g = M @ (a - af) - A.T @ lam_fix
            H = M.copy()
            for kind, s, par in slide:
                w = A[s:s + 2] @ a
                if not np.hypot(*w) > 0:
                    return None
                sg, lk, Hs = _support(kind, par, -w)
                val += sg
                g -= A[s:s + 2].T @ lk
                H += A[s:s + 2].T @ Hs @ A[s:s + 2]
            return val, Z.T @ g, Z.T @ H @ Z

        for _ in range(200):
            out = parts(y)
            if out is None:
                return None
            val, g, H = out
            if not (np.isfinite(H).all() and np.isfinite(g).all()):
                return None  # a sliding block brought to rest: not this piece
            d = -np.linalg.lstsq(H, g, rcond=1e-15)[0]
            t = 1.0
            while t > 1e-12:  # the value falls, or (rounding hides it) the gradient
                nxt = parts(y + t * d)
                if nxt is not None and (nxt[0] <= val + 1e-4 * t * (g @ d) or np.linalg.norm(
                        nxt[1]) <= (1 - 1e-4 * t) * np.linalg.norm(g)):
                    break
                t *= 0.5
            y = y + t * d
            if np.abs(t * d).max() <= 1e-15 * max(1.0, np.abs(y).max()):
                break
        a = Z @ y
    w = A @ a
    lam = lam_fix.copy()
    for kind, s, par in slide:
        if not np.hypot(*w[s:s + 2]) > tol * max(1.0, np.abs(w).max()):
            return None  # not sliding: held instead
        lam[s:s + 2] = _support(kind, par, -w[s:s + 2])[1]
    rhs = M @ (a - af) - A.T @ lam
    if held:
        lam[held], _, rank, _ = np.linalg.lstsq(A[held].T, rhs, rcond=1e-12)
        if rank < len(held) and not _held_in_sets(p, pieces, lam, tol):
            lam = _held_forces_in_sets(p, pieces, lam, held, rhs)  # dependent rows
            if lam is None:
                return None
    if np.abs(A.T @ lam - M @ (a - af)).max() > 1e-8 * max(1.0, np.abs(M @ (a - af)).max()):
        return None  # the held rows cannot carry the rest
    W = max(1.0, np.abs(p["b"]).max())
    for (kind, s, par), c in zip(p["blocks"], pieces):
        if kind == UNILATERAL and c == "zero" and w[s] < -tol * W:
            return None
        if kind == BOX and c == "+" and w[s] > tol * W:
            return None
        if kind == BOX and c == "-" and w[s] < -tol * W:
            return None
    return a if _held_in_sets(p, pieces, lam, tol) else None


def _held_in_sets(p, pieces, lam, tol):
    """Whether every held block's forces lie in its set (relative tolerance tol)."""
    F = max(1.0, np.abs(lam).max())
    for (kind, s, par), c in zip(p["blocks"], pieces):
        if c != "held":
            continue
        if kind == UNILATERAL and lam[s] < -tol * F:
            return False
        if kind == BOX and abs(lam[s]) > par[0] * (1 + tol) + tol * F:
            return False
        if kind >= DISC:
            l = lam[s:s + 2]
            st = par[0] if kind == DISC or l[0] < 0 else par[1]
            ay = par[0] if kind == DISC else par[2]
            if np.hypot(l[0] / st, l[1] / ay) > 1 + tol:
                return False
    return True


def _held_forces_in_sets(p, pieces, lam, held, rhs):
    """Held forces inside their sets that carry rhs (A_H^T lam_H = rhs), the minimum-norm ones
    (cvxpy, Clarabel): dependent held rows whose least-squares forces leave the sets."""
    import cvxpy as cp

    A = p["A"]
    x = cp.Variable(len(held))
    pos = {r: i for i, r in enumerate(held)}
    cons = [A[held].T @ x == rhs]
    for (kind, s, par), c in zip(p["blocks"], pieces):
        if c != "held" or kind == FREE:
            continue
        if kind == UNILATERAL:
            cons.append(x[pos[s]] >= 0)
        elif kind == BOX:
            cons.append(cp.abs(x[pos[s]]) <= par[0])
        elif kind == DISC:
            cons.append(cp.norm(cp.hstack([x[pos[s]], x[pos[s + 1]]])) <= par[0])
        else:
            sp, sm = cp.Variable(nonneg=True), cp.Variable(nonneg=True)
            cons += [x[pos[s]] == sp - sm, cp.norm(cp.hstack(
                [sm / par[0], sp / par[1], x[pos[s + 1]] / par[2]])) <= 1]
    prob = cp.Problem(cp.Minimize(cp.sum_squares(x)), cons)
    for tol in (1e-12, 1e-9):  # retried looser where Clarabel stops short
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", UserWarning)
                prob.solve(solver="CLARABEL", tol_gap_abs=tol, tol_gap_rel=tol, tol_feas=tol)
        except cp.error.SolverError:
            continue
        if prob.status == "optimal":
            break
    if prob.status != "optimal":
        return None
    out = lam.copy()
    out[held] = x.value
    return out


def approximate_accelerations(p):
    """Clarabel's accelerations to 1e-11, retried to 1e-8 where it stops short; None when it
    fails at both (every block is then ambiguous to enumerate_pieces)."""
    import cvxpy as cp

    for tol in (1e-11, 1e-8):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", UserWarning)
                a, status = clarabel_accelerations(p, tol)
        except cp.error.SolverError:
            continue
        if a is not None and status in ("optimal", "optimal_inaccurate"):
            return a
    return None


def enumerate_pieces(p, a_hint, band=1e-6, limit=4096):
    """The accelerations of the first assignment of pieces (every ground model) whose KKT
    conditions hold, enumerated exactly (solve_piece) over the blocks an approximate solution
    a_hint (Clarabel's) leaves ambiguous, |w| within band of its scale: those try every piece,
    fewest departures from "held" first; a block clearly moving takes the one piece its motion
    allows. The KKT conditions are checked to 1e-12 first, then (none found) to 1e-9. Returns
    (a, held rows) or (None, None)."""
    w = p["A"] @ a_hint if a_hint is not None else np.zeros(len(p["b"]))
    W = max(1.0, np.abs(p["b"]).max(), np.abs(w).max())
    options = []
    for kind, s, par in p["blocks"]:
        ws = w[s:s + (2 if kind >= DISC else 1)]
        zero_set = (kind == BOX and not par[0] > 0) or (kind == DISC and not par[0] > 0) or (
            kind == SPLIT and not (par[2] > 0 and (par[0] > 0 or par[1] > 0)))
        if kind == FREE:
            options.append(["held"])
        elif zero_set:
            options.append(["zero"])
        elif np.abs(ws).max() <= band * W:
            options.append({UNILATERAL: ["held", "zero"], BOX: ["held", "+", "-"]}.get(
                kind, ["held", "slide"]))
        elif kind == UNILATERAL:
            options.append(["zero"] if ws[0] > 0 else ["held"])
        elif kind == BOX:
            options.append(["-" if ws[0] > 0 else "+"])
        else:
            options.append(["slide"])
    amb = [k for k, o in enumerate(options) if len(o) > 1]

    def combos():  # fewest departures first
        for d in range(len(amb) + 1):
            for chosen in itertools.combinations(amb, d):
                for alt in itertools.product(*[range(1, len(options[k])) for k in chosen]):
                    pick = [0] * len(options)
                    for k, i in zip(chosen, alt):
                        pick[k] = i
                    yield pick

    for tol in (1e-12, 1e-9):  # tight first: a wrong piece may pass within 1e-9
        for count, combo in enumerate(combos()):
            if count == limit:
                break
            pieces = [o[i] for o, i in zip(options, combo)]
            a = solve_piece(p, pieces, a_hint, tol)
            if a is not None:
                held = [s + i for (kind, s, par), c in zip(p["blocks"], pieces) if c == "held"
                        for i in range(2 if kind >= DISC else 1)]
                return a, held
    return None, None


#: A small scene file shared by the tests: a 3-joint snake (capsules of radius 0.01) on
#: Coulomb ground (mu 0.3) touching a 100 kg box with link 1, and a peg.
SCENE = """
[robot]
joints = 3
length = 0.15
mass = 1.0
inertia = 0.002
radius = 0.01

[ground]
model = "coulomb"
mu = 0.3

[[object]]
shape = "box"
size = [0.1, 0.1]
mass = 100.0
touching = { link = 1, offset = 0.075, side = "left" }

[[obstacle]]
shape = "peg"
center = [0.3, 0.12]
radius = 0.03
"""


class Balance:
    """The least fraction ``t`` of the friction sets that balances a torque with nothing
    moving: ``min t`` over forces with ``A^T lam + B tau = 0`` (every coordinate, objects
    included), contacts ``lam >= 0``, ideal wheels free, every set scaled by ``t`` (a disc,
    a bounded wheel, a split ellipse). One cvxpy problem per configuration, ``tau`` a
    parameter, solved by Clarabel. ``t <= 1``: ``a = 0`` is the forward solution."""

    def __init__(self, model, q):
        import cvxpy as cp

        res = model.forward(q, np.zeros(model.n_joints))
        p = dense_problem(res, model, np.zeros(model.n_joints))
        A = p["A"]
        n, m = A.shape[1], A.shape[0]
        ns = model.n_coordinates
        B = np.zeros((n, model.n_joints))
        B[3:ns] = np.eye(model.n_joints)
        self.tau = cp.Parameter(model.n_joints)
        lam, t = cp.Variable(m), cp.Variable()
        cons = [A.T @ lam + B @ self.tau == 0]
        for kind, s, par in p["blocks"]:
            if kind == UNILATERAL:
                cons.append(lam[s] >= 0)
            elif kind == BOX:
                cons.append(cp.abs(lam[s]) <= t * par[0])
            elif kind == DISC:
                cons.append(cp.norm(lam[s:s + 2]) <= t * par[0])
            elif kind == SPLIT:
                u = cp.Variable()
                cons += [u >= lam[s] / par[1], u >= -lam[s] / par[0],
                         cp.norm(cp.hstack([u, lam[s + 1] / par[2]])) <= t]
            elif kind != FREE:
                raise AssertionError(kind)
        self.problem = cp.Problem(cp.Minimize(t), cons)
        self.t = t

    def __call__(self, taus):
        out = []
        for tau in np.atleast_2d(taus):
            self.tau.value = tau
            self.problem.solve(solver="CLARABEL", tol_gap_abs=1e-10, tol_gap_rel=1e-10,
                               tol_feas=1e-10)
            out.append(self.t.value if self.problem.status == "optimal" else np.inf)
        return np.array(out)
