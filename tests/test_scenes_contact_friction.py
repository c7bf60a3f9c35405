"""Coulomb friction at a general scene's contacts (``mu_contact``), held against references
written apart from the engine (``snakecg/engine/scene_friction.c``):

* a dense NumPy enumeration of every contact's Coulomb state (open, stick, slip either way)
  and every other block's piece, each piece's linear equations in (a, lam) solved and kept
  where all of Coulomb's conditions hold, on random small scenes (pegs and objects touching
  links, polyhedral ground); the rows come from the geometry reference
  (tests/scenes_rows_reference.py), the tangent rows from its contact points here;
* closed forms: a box pushed against a wall;
* the frictionless answer where no contact has friction, bit for bit.
"""

from __future__ import annotations

import dataclasses
import itertools
import json

import numpy as np
import pytest

import snakecg
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject
from snakecg.scenes.description import pair_mu
from snakecg.scenes.toml_reading import scene_from_data

from scenes_reference import POLYHEDRAL, inertia_and_force, small_scenes
from scenes_rows_reference import _point_jacobian, rows_of
from snakecg.scenes.solve import BOX, FREE, UNILATERAL


# ---- the reference ------------------------------------------------------------------------
def _body_mu(scene, body):
    kind, i = body
    if kind == "link":
        return None
    return (scene.objects if kind == "object" else scene.obstacles)[i].mu_contact


def reference_problem(model, q, tau, f_obj=None):
    """M, f, the rows A (normal rows, the ground's, then one tangent row per frictional
    contact), the blocks and the contacts, built from the geometry reference."""
    scene = model.scene
    P, J = model.link_poses(q), model.link_jacobians(q)
    rows, obj_poses = rows_of(scene, model.masses, P, J)
    ns = model.n_coordinates
    M, f = inertia_and_force(model, q, tau, f_obj)
    n = len(f)
    A = [r for r in rows.A]
    blocks = []
    for kind, start, par, label in zip(rows.kind, rows.start, rows.par, rows.labels):
        blocks.append({"kind": kind, "row": start, "p": par[0], "tangent": None, "mu": 0.0})
    contacts = []
    for c_i, c in enumerate(rows.contacts):
        mu = pair_mu(scene.mu_contact, _body_mu(scene, c.a), _body_mu(scene, c.b))
        contacts.append({"bodies": (c.a, c.b), "point": (c.point_a + c.point_b) / 2,
                         "normal": c.normal, "row": c.row, "tangent": None, "mu": mu})
        if mu > 0:
            t = np.array([-c.normal[1], c.normal[0]])
            Ja = _point_jacobian(c.a, c.point_a, J, P, obj_poses, ns, n)
            Jb = _point_jacobian(c.b, c.point_b, J, P, obj_poses, ns, n)
            A.append(t @ (Jb - Ja))
            blk = next(b for b in blocks if b["row"] == c.row and b["kind"] == UNILATERAL)
            blk["tangent"], blk["mu"] = len(A) - 1, mu
            contacts[-1]["tangent"] = len(A) - 1
    return {"M": M, "f": f, "A": np.array(A).reshape(len(A), n), "blocks": blocks,
            "contacts": contacts}


def piece_solution(p, combo):
    """One piece's linear equations solved densely in (a, lam): M a - A^T lam = f and, per
    block (``combo``: its state, as :func:`coulomb_solutions` names them), w = 0 on a held
    row or a sticking contact's two rows, the force fixed on an open row (0) or a sliding
    wheel (+-p), a slipping contact's friction lam_t = -mu lam_n sign(w_t). None where the
    equations are singular."""
    M, f, A = p["M"], p["f"], p["A"]
    m, n = A.shape
    K = np.zeros((n + m, n + m))
    rhs = np.zeros(n + m)
    K[:n, :n], K[:n, n:], rhs[:n] = M, -A.T, f

    def w_zero(r):
        K[n + r, :n] = A[r]

    def force(r, value=0.0, other=None, coef=0.0):
        K[n + r, n + r] = 1.0
        if other is not None:
            K[n + r, n + other] = coef
        rhs[n + r] = value

    for b, s in zip(p["blocks"], combo):
        r, t = b["row"], b["tangent"]
        if s in ("held", "stick"):
            w_zero(r)
        elif s in ("open", "zero"):
            force(r)
        elif s in ("+", "-"):
            force(r, b["p"] if s == "+" else -b["p"])
        else:  # slip: normal held
            w_zero(r)
        if t is None:
            continue
        if s == "open":
            force(t)
        elif s == "stick":
            w_zero(t)
        else:  # lam_t = -mu lam_n sign(w_t)
            force(t, 0.0, r, b["mu"] if s == "slip+" else -b["mu"])
    if np.linalg.matrix_rank(K, tol=1e-10 * np.abs(K).max()) < n + m:
        return None
    x = np.linalg.solve(K, rhs)
    return x[:n], x[n:]


def coulomb_solutions(p, tol=1e-9):
    """Every solution of Coulomb's conditions by enumeration of the pieces: each contact
    (open, stick, slip with w_t > 0, slip with w_t < 0; frictionless: held, open), bounded
    wheel (stick, force +p, force -p), ideal wheel (held). Each piece: M a - A^T lam = f and
    one equation per row, solved densely in (a, lam); kept where every inequality holds
    within tol of the scales. Returns (solutions [(a, lam)], singular pieces met)."""
    M, f, A = p["M"], p["f"], p["A"]
    m, n = A.shape
    a_free = np.linalg.solve(M, f)
    W = max(1e-12, np.abs(A @ a_free).max() if m else 0.0)
    options = []
    for b in p["blocks"]:
        if b["kind"] == FREE:
            options.append(["held"])
        elif b["kind"] == UNILATERAL:
            options.append(["open", "stick", "slip+", "slip-"] if b["tangent"] is not None
                           else ["held", "open"])
        elif b["kind"] == BOX:
            options.append(["stick", "+", "-"] if b["p"] > 0 else ["zero"])
        else:
            raise ValueError("polyhedral blocks only")
    sols, singular = [], 0
    for combo in itertools.product(*options):
        x = piece_solution(p, combo)
        if x is None:
            singular += 1
            continue
        a, lam = x
        w = A @ a
        F = max(1e-12, np.abs(lam).max())
        ok = True
        for b, s in zip(p["blocks"], combo):
            r, t = b["row"], b["tangent"]
            if b["kind"] == UNILATERAL:
                ok &= lam[r] >= -tol * F and w[r] >= -tol * W
                if t is not None and s == "stick":
                    ok &= abs(lam[t]) <= b["mu"] * lam[r] + tol * F
                if t is not None and s == "slip+":
                    ok &= w[t] >= -tol * W
                if t is not None and s == "slip-":
                    ok &= w[t] <= tol * W
            elif b["kind"] == BOX and s == "stick":
                ok &= abs(lam[r]) <= b["p"] * (1 + tol) + tol * F
            elif s == "+":
                ok &= w[r] <= tol * W
            elif s == "-":
                ok &= w[r] >= -tol * W
        if ok and not any(np.abs(a - a2).max() <= 1e-7 * max(1.0, np.abs(a).max())
                          for a2, _ in sols):
            sols.append((a, lam))
    return sols, singular


def coulomb_violations(p, a, lam, tol=1e-9):
    """Every condition of Coulomb's law and of the ground's sets that (a, lam) violates,
    checked densely: M a = f + A^T lam; normal forces >= 0, complementary to their rows'
    accelerations >= 0; friction within mu lam_n, a sticking contact without tangential
    acceleration, a slipping one's force at -mu lam_n sign(w_t); a bounded wheel within its
    bound, sticking or sliding against its force; an ideal wheel still."""
    M, f, A = p["M"], p["f"], p["A"]
    out = []
    w = A @ a
    F = max(1e-12, np.abs(lam).max())
    W = max(1e-12, np.abs(A @ np.linalg.solve(M, f)).max())
    if np.abs(M @ a - f - A.T @ lam).max() > tol * max(1.0, np.abs(f).max(), F):
        out.append("M a != f + A^T lam")
    for b in p["blocks"]:
        r, t = b["row"], b["tangent"]
        if b["kind"] == FREE and abs(w[r]) > tol * W:
            out.append(f"ideal wheel {r} moves")
        elif b["kind"] == BOX:
            if abs(lam[r]) > b["p"] + tol * F:
                out.append(f"wheel {r} beyond its bound")
            elif abs(lam[r]) < b["p"] - tol * F and abs(w[r]) > tol * W:
                out.append(f"wheel {r} slides inside its bound")
            elif lam[r] * w[r] > tol * F * W:
                out.append(f"wheel {r} helps its sliding")
        elif b["kind"] == UNILATERAL:
            if lam[r] < -tol * F or w[r] < -tol * W or abs(lam[r] * w[r]) > tol * F * W:
                out.append(f"contact {r}: lam {lam[r]}, w {w[r]}")
            if t is None:
                continue
            if abs(lam[t]) > b["mu"] * lam[r] + tol * F:
                out.append(f"contact {r}: friction outside the cone")
            if abs(w[t]) > tol * W and abs(lam[t] + b["mu"] * lam[r] * np.sign(w[t])) > tol * F:
                out.append(f"contact {r}: slips without friction -mu lam_n sign(w_t)")
    return out


def engine_forces(res, p):
    """The engine's contact forces as the reference's lam (matched by bodies and point)."""
    lam = np.full(p["A"].shape[0], np.nan)
    for c in res.contacts:
        for rc in p["contacts"]:
            same = (c["bodies"][0].split(" (")[0] == f"{rc['bodies'][0][0]} "
                    f"{rc['bodies'][0][1] + 1}" and np.allclose(c["point"], rc["point"],
                                                               atol=1e-9))
            if same:
                lam[rc["row"]] = c["force"]
                if rc["tangent"] is not None:
                    lam[rc["tangent"]] = c["friction"]
    return lam


# ---- random small scenes against the enumeration -------------------------------------------
def frictional_cases(seed: int, count: int) -> list:
    """``(model, q, tau)``: ``count`` random small scenes with a peg or an object (polyhedral
    ground, no object rubbing it), each with 8 contact coefficients and torques."""
    rng = np.random.default_rng(seed)
    out = []
    for model0, q, _ in small_scenes(rng, count, POLYHEDRAL, object_friction=False):
        if len(model0.scene.objects) + len(model0.scene.obstacles) == 0:
            continue
        for _ in range(8):
            mu = float(rng.choice([0.1, 0.3, 0.6, 1.0, 2.0]))
            scene = dataclasses.replace(model0.scene, mu_contact=mu)
            model = snakecg.load(scene)
            tau = rng.normal(size=model.n_joints) * float(rng.choice([0.1, 1.0, 5.0]))
            out.append((model, q, tau))
    return out


@pytest.fixture(scope="module")
def frictional_samples():
    return frictional_cases(20261205, 45)


def test_random_scenes_match_the_enumeration(frictional_samples):
    stats = {"unique": 0, "several": 0, "not_certified": 0, "checked": 0}
    for model, q, tau in frictional_samples:  # (the stats: printed with -s)
        res = model.forward(q, tau)
        p = reference_problem(model, q, tau)
        sols, singular = coulomb_solutions(p)
        if res.status != 0:  # not settled: only where no single solution is known
            assert res.status == 7 and not (len(sols) == 1 and singular == 0), \
                (res.reason, len(sols), singular)
            continue
        stats["checked"] += 1
        stats[res.uniqueness] += 1
        a = np.r_[res.qdd, np.ravel(res.a_obj)]
        scale = max(1.0, np.abs(a).max())
        match = [s for s in sols if np.abs(s[0] - a).max() <= 1e-9 * scale]
        lam = engine_forces(res, p)
        lam[[b["row"] for b in p["blocks"] if b["kind"] != UNILATERAL]] = [
            g["force"][0] for g in res.ground]
        if not match:  # a solution on a singular piece: Coulomb's conditions densely
            assert singular > 0 and coulomb_violations(p, a, lam) == [], (a, sols)
            stats["singular"] = stats.get("singular", 0) + 1
            continue
        d = a - np.linalg.solve(p["M"], p["f"])  # ||lambda||^2 counts the friction forces
        np.testing.assert_allclose(res.norm_lambda, d @ p["M"] @ d, rtol=1e-9, atol=1e-12)
        F = max(1.0, np.abs(match[0][1]).max())
        known = ~np.isnan(lam)
        if not res.dependent:
            np.testing.assert_allclose(lam[known], match[0][1][known], atol=1e-9 * F, rtol=0)
        if len(sols) >= 2:
            assert res.uniqueness != "unique"
            assert abs(res.solutions) >= 2
        if res.uniqueness == "unique" and singular == 0:
            assert len(sols) == 1
    print(stats)
    assert stats["checked"] >= 300, stats
    assert stats["unique"] > 0


# ---- closed forms ------------------------------------------------------------------------
def _box_on_wall(mu, *, own=None):
    robot = snakecg.Robot(joints=1)
    # (wide and low: pushed at its COM it slides without tipping while mu < 0.2 / 0.05)
    box = SceneObject(shape="box", size=(0.4, 0.1), mass=2.0, pose=(1.0, -0.45, 0.0),
                      mu_contact=own)
    wall = Obstacle(shape="wall", point=(0.0, -0.5), normal=(0.0, 1.0))
    return snakecg.load(GeneralScene(robot, ground=Ground(model="frictionless"),
                                     objects=(box,), obstacles=(wall,), mu_contact=mu))


@pytest.mark.parametrize("mu", [0.2, 0.5, 1.3])
def test_box_pushed_against_a_wall_sticks_or_slides_as_coulomb_says(mu):
    """A box of mass m pressed on a wall by f_n with a tangential push f_t sticks iff |f_t|
    <= mu f_n, else slides with a_t = sign(f_t) (|f_t| - mu f_n) / m."""
    model = _box_on_wall(mu)
    m, fn = 2.0, 5.0
    for ft in np.linspace(-3 * mu * fn, 3 * mu * fn, 13):
        res = model.forward(np.zeros(4), np.zeros(1), f_obj=[[ft, -fn, 0.0]])
        assert res.status == 0 and res.uniqueness == "unique"
        at = 0.0 if abs(ft) <= mu * fn else np.sign(ft) * (abs(ft) - mu * fn) / m
        np.testing.assert_allclose(res.a_obj[0], [at, 0.0, 0.0], atol=1e-12)
        # the box is the first body: the friction on it is minus the second's
        fric = -sum(c["friction"] * c["tangent"][0] for c in res.contacts)
        np.testing.assert_allclose(fric, -ft if abs(ft) <= mu * fn else -np.sign(ft) * mu * fn,
                                   atol=1e-12)
        states = {c["friction_state"] for c in res.contacts}
        assert states == ({"stick"} if abs(ft) < mu * fn else {"slip"}) or abs(
            abs(ft) - mu * fn) < 1e-9


@pytest.mark.parametrize("mu", [0.05, 0.3])
def test_a_disc_pressed_on_a_peg_rolls_or_slips_as_coulomb_says(mu):
    """A disc (m, r, I = m r^2 / 2) pressed on a peg by f_n with a push f_t at its centre:
    sticking, it rolls about the peg, a = f_t / (1.5 m), alpha = -a / r, the friction
    -f_t / 3, which holds iff |f_t| / 3 <= mu f_n; else it slips: a = (f_t - mu f_n s) / m,
    alpha = -2 mu f_n s / (m r), s = sign(f_t)."""
    m, r, fn = 2.0, 0.05, 5.0
    disc = SceneObject(shape="disc", radius=r, mass=m, pose=(1.0, 0.0, 0.0))
    peg = Obstacle(shape="peg", center=(1.0, -0.08), radius=0.03)
    model = snakecg.load(GeneralScene(snakecg.Robot(joints=1), ground=Ground(),
                                      objects=(disc,), obstacles=(peg,), mu_contact=mu))
    for ft in (-2.0, -0.5, 0.2, 1.0, 4.0):
        res = model.forward(np.zeros(4), np.zeros(1), f_obj=[[ft, -fn, 0.0]])
        assert res.status == 0 and res.uniqueness == "unique"
        if abs(ft) / 3 <= mu * fn:
            a = ft / (1.5 * m)
            want, state = [a, 0.0, -a / r], "stick"
        else:
            s = np.sign(ft)
            want, state = [(ft - mu * fn * s) / m, 0.0, -2 * mu * fn * s / (m * r)], "slip"
        np.testing.assert_allclose(res.a_obj[0], want, atol=1e-10)
        assert res.contacts[0]["friction_state"] == state


def test_a_body_s_own_coefficient_overrides_the_scene_s():
    """The pair's coefficient is the larger of the bodies' own where one is given."""
    assert pair_mu(0.2, None, None) == 0.2
    assert pair_mu(0.2, 0.0, None) == 0.0
    assert pair_mu(0.0, 0.4, 0.7) == 0.7
    model = _box_on_wall(0.0, own=0.5)
    res = model.forward(np.zeros(4), np.zeros(1), f_obj=[[-3.0, -5.0, 0.0]])
    np.testing.assert_allclose(res.a_obj[0][0], -(3.0 - 2.5) / 2.0, atol=1e-12)
    assert {c["mu"] for c in res.contacts} == {0.5}


def test_without_frictional_contacts_the_answer_is_the_frictionless_one_bit_for_bit():
    """A scene whose only frictional body touches nothing at this sample answers as the same
    scene without friction, bit for bit."""
    rng = np.random.default_rng(7)
    for model0, q, _ in small_scenes(rng, 6, POLYHEDRAL, object_friction=False):
        far = Obstacle(shape="peg", center=(50.0, 50.0), radius=0.1, mu_contact=0.8)
        fric = snakecg.load(dataclasses.replace(
            model0.scene, obstacles=model0.scene.obstacles + (far,)))
        base = snakecg.load(dataclasses.replace(
            model0.scene, obstacles=model0.scene.obstacles + (dataclasses.replace(
                far, mu_contact=None),)))
        assert fric.packed.friction and not base.packed.friction
        tau = rng.normal(size=model0.n_joints)
        r1, r0 = fric.forward(q, tau), base.forward(q, tau)
        assert np.array_equal(r1.qdd, r0.qdd) and np.array_equal(r1.a_obj, r0.a_obj)
        assert [c["force"] for c in r1.contacts] == [c["force"] for c in r0.contacts]
        assert r1.norm_lambda == r0.norm_lambda and r1.uniqueness == "unique"


def test_json_has_the_friction_fields():
    res = _box_on_wall(0.5).forward(np.zeros(4), np.zeros(1), f_obj=[[-3.0, -5.0, 0.0]])
    d = json.loads(json.dumps(res.to_dict(), allow_nan=False))
    assert d["uniqueness"] == "unique" and d["solutions"] == 1
    c = d["contacts"][0]
    assert c["friction_state"] == "slip" and c["mu"] == 0.5 and len(c["tangent"]) == 2


# ---- input --------------------------------------------------------------------------------
def _table(**contacts):
    return {"robot": {"joints": 1}, "contacts": contacts,
            "obstacle": [{"shape": "peg", "center": [0.0, 1.0], "radius": 0.1,
                          "mu_contact": 0.4}]}


def test_toml_reads_the_contact_coefficients():
    scene = scene_from_data(_table(mu=0.25))
    assert scene.mu_contact == 0.25 and scene.obstacles[0].mu_contact == 0.4
    assert scene_from_data({"robot": {"joints": 1}}).mu_contact == 0.0


@pytest.mark.parametrize("bad, match", [
    (_table(mu=-0.1), r"\[contacts\] mu must be a finite number >= 0"),
    (_table(mu="high"), r"\[contacts\] mu must be a finite number >= 0"),
    ({**_table(), "obstacle": [{"shape": "peg", "center": [0, 1], "radius": 0.1,
                                "mu_contact": -1}]}, r"obstacle\[1\]\.mu_contact must be"),
])
def test_toml_refuses_bad_coefficients_naming_the_key(bad, match):
    with pytest.raises(InputError, match=match):
        scene_from_data(bad)


def test_python_refuses_a_bad_scene_coefficient():
    with pytest.raises(InputError, match="mu_contact must be a finite number >= 0"):
        GeneralScene(snakecg.Robot(joints=1), mu_contact=float("nan"))
    with pytest.raises(InputError, match=r"object\[1\]\.mu_contact"):
        GeneralScene(snakecg.Robot(joints=1), objects=(SceneObject(
            shape="disc", radius=0.1, pose=(0, 1, 0), mu_contact=-2.0),))


# ---- simulation ---------------------------------------------------------------------------
def test_a_box_sliding_along_a_wall_decelerates_at_mu_fn_over_m():
    """Pressed on the wall by f_n and launched along it at v0, the box's velocity falls as
    v0 - mu f_n t / m until it stops (Coulomb's kinetic friction, constant), then it stays;
    the run's energy: the kinetic energy falls by what friction dissipates (the step's own
    dissipation, m (dv)^2 / 2 per step, beside it), impulses >= 0, nothing penetrates."""
    mu, m, fn, v0, dt = 0.3, 2.0, 5.0, 2.0, 1e-3
    model = _box_on_wall(mu)
    run = model.simulate(np.zeros(4), 3.0, v_obj0=[[v0, 0.0, 0.0]], f_obj=[[0.0, -fn, 0.0]],
                         dt=dt)
    assert run.status == "completed"
    t = np.asarray(run.t)
    v = np.asarray(run.v_obj)[:, 0]
    a = mu * fn / m
    np.testing.assert_allclose(v[:, 0], np.maximum(v0 - a * t, 0.0), atol=1e-9)
    np.testing.assert_allclose(v[:, 1:], 0.0, atol=1e-12)
    ke = np.asarray(run.kinetic_energy)
    fr = np.asarray(run.friction_dissipation)
    assert np.all(np.diff(fr) >= -1e-15) and np.all(np.asarray(run.contact_impulse) >= 0)
    assert np.all(ke <= ke[0] + np.asarray(run.work_tau) + 1e-12)
    scheme = np.sum(m * np.diff(v[:, 0]) ** 2 / 2)  # the implicit step's own loss
    np.testing.assert_allclose(ke[0] - ke[-1], fr[-1] + scheme, rtol=1e-12)
    assert min(run.min_gap) >= -run.tolerance


def _mujoco_box(mu, m, f, timestep, solref):
    mujoco = pytest.importorskip("mujoco")
    inertia = m * (0.4 ** 2 + 0.1 ** 2) / 12
    soft = f'condim="3" friction="{mu} 0 0" solref="{solref} 1" solimp="0.99 0.9999 1e-6"'
    xml = f"""<mujoco><option timestep="{timestep}" gravity="0 0 0" cone="elliptic"
      noslip_iterations="20" integrator="implicitfast"/><worldbody>
      <geom type="plane" size="10 10 0.1" pos="0 -0.5 0" zaxis="0 1 0" {soft}/>
      <body pos="1 -0.45 0"><joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 1 0"/>
      <joint type="hinge" axis="0 0 1"/><geom type="box" size="0.2 0.05 0.05" {soft}/>
      <inertial pos="0 0 0" mass="{m}" diaginertia="1 1 {inertia}"/></body>
      </worldbody></mujoco>"""
    M = mujoco.MjModel.from_xml_string(xml)
    D = mujoco.MjData(M)
    D.xfrc_applied[1, :3] = f
    return mujoco, M, D


@pytest.mark.parametrize("ft", [1.0, 2.5])
def test_a_box_pushed_along_a_wall_follows_mujoco(ft):
    """The box pressed on the wall (f_n = 5 N, mu 0.3) and pushed along it from rest: held
    (f_t = 1 < mu f_n) or sliding at (f_t - mu f_n) / m (f_t = 2.5). MuJoCo (condim 3,
    elliptic cones, 20 noslip iterations, solref 2 ms at a 0.1 ms step) on the same box and
    wall agrees within 1 mm and 1.5 cm/s over 2 s (measured: 0.5 mm, 8 mm/s): its soft
    contact lets the box hop off the wall by up to 0.2 mm, which snakecg's hard contact
    does not. (A stiffer solref, 0.2 ms, makes MuJoCo chatter off the wall by millimetres.)"""
    mu, m, fn, T, h = 0.3, 2.0, 5.0, 2.0, 1e-4
    mujoco, M, D = _mujoco_box(mu, m, [ft, -fn, 0.0], h, 0.002)
    ts, xs, vs = [], [], []
    for k in range(1, int(round(T / h)) + 1):
        mujoco.mj_step(M, D)
        if k % 100 == 0:
            ts.append(k * h)
            xs.append(1.0 + D.qpos[0])
            vs.append(D.qvel[0])
    run = _box_on_wall(mu).simulate(np.zeros(4), T, f_obj=[[ft, -fn, 0.0]], dt=1e-3)
    t = np.asarray(run.t)
    x = np.interp(ts, t, np.asarray(run.q_obj)[:, 0, 0])
    v = np.interp(ts, t, np.asarray(run.v_obj)[:, 0, 0])
    a = max(0.0, ft - mu * fn) / m
    np.testing.assert_allclose(v, a * np.asarray(ts), atol=1e-9)  # the closed form
    assert np.abs(x - xs).max() <= 1e-3
    assert np.abs(v - vs).max() <= 1.5e-2


@pytest.mark.parametrize("radius", [0.0, 0.01])
def test_a_peg_at_a_joint_shares_its_normal_force_between_the_links(radius):
    """A peg touching both links at their joint: the two contacts' normal rows are one, their
    normal forces split arbitrarily (statically indeterminate), so together they allow a
    friction of mu times the summed normal force. The accelerations are among the
    enumeration's solutions; the reported split meets each contact's own cone."""
    robot = snakecg.Robot(joints=1)
    base = GeneralScene(robot, radius=radius, ground=Ground(model="wheels", mu=0.3))
    P = snakecg.load(base).link_poses(np.zeros(4))
    joint = P[0][:2] + np.array([robot.length[0] - robot.com[0], 0.0])
    peg = Obstacle(shape="peg", center=(joint[0], joint[1] + 0.03 + radius), radius=0.03)
    rng = np.random.default_rng(3)
    for mu in (0.2, 0.8):
        model = snakecg.load(dataclasses.replace(base, obstacles=(peg,), mu_contact=mu))
        for tau in rng.normal(size=(12, 1)) * 2.0:
            res = model.forward(np.zeros(4), tau)
            assert res.status == 0 and len(res.contacts) == 2
            p = reference_problem(model, np.zeros(4), tau)
            sols, _ = coulomb_solutions(p)
            a = np.r_[res.qdd, np.ravel(res.a_obj)]
            lam = engine_forces(res, p)
            lam[[b["row"] for b in p["blocks"] if b["kind"] != UNILATERAL]] = [
                g["force"][0] for g in res.ground]
            assert coulomb_violations(p, a, lam) == []
            if len(sols) >= 2:  # (the pieces with both normals held are singular: unseen)
                assert res.uniqueness != "unique"
