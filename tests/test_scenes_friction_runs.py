"""Contact friction over whole runs: the obstacle-aided locomotion example with rough pegs,
and frictional impacts against their closed form.

References: the capsule-peg and link-link distances of ``capsule_reference`` (NumPy, apart
from the engine's geometry) for penetration; the run's energy balance (the kinetic energy
gained never exceeds the torques' work less friction and impact losses plus the gap
stabilisation's work); for an impact, the impulse law of a rigid disc worked out by hand
below (Coulomb's law on the impulses of an inelastic impact); and, at the recorded steps and
impacts where the bounds' fixed point does not settle, NumPy enumerations of the contacts'
pieces (``_coulomb_pieces``, ``_impact_solutions``)."""

from __future__ import annotations

import dataclasses
import itertools
import json
from pathlib import Path

import numpy as np
import pytest

import snakecg
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject, load_scene
from snakecg.scenes.toml_reading import read_scene
from snakecg.scenes.stepping import contact_tolerance
from snakecg.simulate import serpenoid_controller

from run_laws import assert_run_laws


def _rough_pegs_row(mu):
    if mu == 1.0:  # the example with rough pegs: pegs_row.toml's with mu_contact 1 at each
        scene = read_scene("examples/scenes/pegs_row_rough.toml")
        plain = read_scene("examples/scenes/pegs_row.toml")
        assert [o.mu_contact for o in scene.obstacles] == [1.0] * len(plain.obstacles)
        assert scene.robot == plain.robot and scene.ground == plain.ground
        assert [o.center for o in scene.obstacles] == [o.center for o in plain.obstacles]
        return load_scene(scene)
    scene = read_scene("examples/scenes/pegs_row.toml")
    pegs = tuple(dataclasses.replace(o, mu_contact=mu) for o in scene.obstacles)
    return load_scene(dataclasses.replace(scene, obstacles=pegs))


# The state where the bounds' fixed point cycled (the example at mu_contact 1 after 17 ms, with
# frictionless impacts): a peg by a joint touching both links with nearly one normal row.
CYCLING_Q = [0.00024075863369241277, 0.0006482743580151433, -0.02198509319228567,
    0.024703593861360937, 0.4852191210355022, 0.27991984675148035, -0.3023569116841101,
    -0.4691562056253228, 0.007128875143526904, 0.48330527410925067, 0.28158294926374766,
    -0.3066199964564431, -0.4516865756670861]
CYCLING_V = [0.007904031420365512, 0.10359926923212215, -1.3777558303464417, 0.9338668093909724,
    1.5557170203856756, -1.839568840574544, 0.6881348953992854, 0.07809958606848802,
    -0.38019887186852946, 1.5109991678349624, -2.0506571557867592, 0.45222943139559674,
    0.8134877247426411]
CYCLING_TAU = [0.9458322562057886, -0.23191876161662583, -0.5764248437315753, -1.2371840782740673,
    0.4915261428264129, 1.5157991477619772, -0.1993649365888968, -0.529729374290587,
    -1.123781591349633, 0.09621340164180228]


def test_the_step_where_the_fixed_point_cycled_is_solved():
    """One 1 ms step from the state where the passes cycled between pieces (the normal split
    between the two nearly parallel rows swinging with the bounds): the semismooth Newton on
    the bounds settles it, with Coulomb's residuals within 1e-9."""
    model = _rough_pegs_row(1.0)
    run = model.simulate(np.array(CYCLING_Q), 1e-3, v0=np.array(CYCLING_V),
                         tau=np.array(CYCLING_TAU), dt=1e-3)
    assert run.status == "completed", run.message
    assert max(run.n_contacts) >= 2
    assert max(run.certificate.values()) <= 1e-9


# A state where Newton's steps from the first start stall (the example at mu_contact 1.5 with
# the gait at 0.4 rad and 1.5 Hz, after 1.33 s): settled after the first start.
STALLING_Q = [-0.04292616886978592, 0.01211051092846942, -0.09127980823052863, -0.04258009575786208,
    0.4793164494059722, 0.4487468212046312, -0.12485121539651826, -0.47077393497635867,
    -0.17025984629462432, 0.2932534135479661, 0.26205496189980104, -0.14649249686116417,
    -0.37558486439040784]
STALLING_V = [0.049974358745125375, 0.37265174686401525, -4.386752839147681, 3.44796081102902,
    2.3655519621930337, -1.162890901351929, -3.4864571052982547, -0.4164892117176863,
    3.979836650705033, 3.121672703392473, -1.5846032029446422, -2.0607164522945594,
    0.34151349546574883]
STALLING_TAU = [0.25085267996145677, -1.3693046369046147, -2.4433816884572694, -0.7913730434077632,
    1.2303237775532916, 1.3680874334262743, 0.2644894993156143, -0.44994940493115215,
    -1.0026824246624122, 0.05103225953875251]


def test_the_step_where_newton_stalls_is_solved_from_a_restart():
    """One 1 ms step from a state where the iterations from the frictionless start stall
    (between a contact's sticking and slipping pieces): the candidate states or the restarts
    from large bounds settle it, Coulomb's residuals within 1e-9."""
    model = _rough_pegs_row(1.5)
    run = model.simulate(np.array(STALLING_Q), 1e-3, v0=np.array(STALLING_V),
                         tau=np.array(STALLING_TAU), dt=1e-3)
    assert run.status == "completed", run.message
    assert max(run.certificate.values()) <= 1e-9


@pytest.mark.parametrize("mu", [1.0, 1.5])
def test_the_pegs_row_with_rough_pegs_runs_and_keeps_coulomb_s_law(mu):
    """mu_contact = 1 or 1.5 on every peg: a peg a hair's breadth off a joint touches both
    links' ends with nearly one normal row, where the bounds' plain fixed point cycles (at 1.5
    the run stopped after 46 ms). Now it runs; nothing penetrates beyond the tolerance (NumPy
    distances), the energy stays within the torques' work, every step's Coulomb residuals
    (the cone, stick, slip against the sliding, the normal complementarity) within 1e-9."""
    model = _rough_pegs_row(mu)
    q0 = np.zeros(13)
    q0[3:] = 0.5 * np.sin(np.arange(10) * 2 * np.pi / 5)
    gait = serpenoid_controller(model, amplitude=0.5, frequency=1.0, phase_lag=2 * np.pi / 5,
                                kp=10.0, kd=0.3, tau_max=None)
    run = model.simulate(q0, 0.3, tau=gait, dt=1e-3)
    assert run.status == "completed", run.message
    assert run.t[-1] == pytest.approx(0.3)
    assert max(run.n_contacts) >= 2
    assert_run_laws(model.scene, run)


def _disc_at_wall(mu, inertia, m=2.0, r=0.1):
    disc = SceneObject(shape="disc", radius=r, mass=m, inertia=inertia,
                       pose=(1.0, -0.5 + r + 0.0005, 0.0))
    wall = Obstacle(shape="wall", point=(0.0, -0.5), normal=(0.0, 1.0))
    return snakecg.load(GeneralScene(snakecg.Robot(joints=1), ground=Ground(model="frictionless"),
                                     objects=(disc,), obstacles=(wall,), mu_contact=mu))


def disc_impact(m, r, inertia, mu, vt, vn, omega):
    """A disc (mass m, radius r, inertia I about its centre) hits a wall y = 0 below it with
    velocity (vt, -vn), vn > 0, and spin omega (counter-clockwise); the impact is inelastic
    (restitution 0). The contact point is at (0, -r) from the centre: its sliding velocity is
    u = vt + r omega, and a tangential impulse p_t (along +x, on the disc) changes vt by
    p_t / m and omega by r p_t / I (the moment of (p_t, 0) at (0, -r)), so u by p_t k with
    k = 1 / m + r^2 / I. The normal impulse stops the normal velocity: p_n = m vn. Coulomb:
    stick (u after = 0) needs p_t = -u / k within mu p_n; else slip, p_t = -mu p_n sign(u).
    So p_t = -sign(u) min(|u| / k, mu m vn). A uniform disc (I = m r^2 / 2, k = 3 / m) from
    no spin rolls after when |vt| <= 3 mu vn, keeping 2/3 of vt (it loses 1/3); without the
    rotation's coupling (I -> infinity) vt after is sign(vt) max(0, |vt| - mu vn)."""
    u = vt + r * omega
    k = 1.0 / m + r * r / inertia
    pt = -np.sign(u) * min(abs(u) / k, mu * m * vn)
    return vt + pt / m, omega + r * pt / inertia, pt, m * vn


@pytest.mark.parametrize("mu", [0.1, 0.5, 2.0])
@pytest.mark.parametrize("shape", ["uniform", "ring"])
@pytest.mark.parametrize("vt", [1.0, -0.7])
def test_a_disc_hitting_a_wall_obliquely_follows_the_impulse_law(mu, shape, vt):
    """The velocities just after the impact equal the closed form (disc_impact) to 1e-9:
    rolling after (stick) where mu vn is large enough, else sliding on with its tangential
    velocity cut by mu vn; the kinetic energy never rises, the normal impulse is >= 0, and
    the friction impulse opposes the contact's sliding."""
    m, r, vn = 2.0, 0.1, 0.8
    inertia = m * r * r * (0.5 if shape == "uniform" else 1.0)
    model = _disc_at_wall(mu, inertia)
    run = model.simulate(np.zeros(4), 0.003, v_obj0=[[vt, -vn, 0.0]], dt=1e-3)
    assert run.status == "completed" and len(run.events) == 1
    i = int(np.searchsorted(run.t, run.events[0].t))
    assert run.t[i] == run.events[0].t
    v = np.asarray(run.v_obj)[i, 0]
    vt1, om1, pt, pn = disc_impact(m, r, inertia, mu, vt, vn, 0.0)
    np.testing.assert_allclose(v, [vt1, 0.0, om1], atol=1e-9)
    np.testing.assert_allclose(run.events[0].impulses, [pn], rtol=1e-9)
    assert min(run.events[0].impulses) >= 0
    # the event's friction impulse (along its tangent, on the second body) is the closed
    # form's p_t on the disc, its state stick where |u| / k is within mu p_n
    ev = run.summary["events"][0]
    disc_second = ev["bodies"][0] == ["obstacle 1", "object 1"]
    assert disc_second or ev["bodies"][0] == ["object 1", "obstacle 1"]
    on_disc = (1.0 if disc_second else -1.0) * ev["friction_impulses"][0] * \
        np.asarray(ev["tangents"][0])
    np.testing.assert_allclose(on_disc, [pt, 0.0], atol=1e-9 * pn)
    k = 1.0 / m + r * r / inertia
    assert ev["friction_states"] == ["stick" if abs(vt) / k < mu * pn else "slip"]
    u0, u1 = vt, v[0] + r * v[2]  # the contact point's sliding before and after
    assert m * (v[0] - vt) * u0 < 0  # the friction impulse against the sliding
    assert u1 * u0 >= -1e-12  # it never reverses the sliding
    ke0, ke1 = 0.5 * m * (vt ** 2 + vn ** 2), 0.5 * (m * v[0] ** 2 + inertia * v[2] ** 2)
    assert ke1 <= ke0
    np.testing.assert_allclose(run.impact_loss[i], ke0 - ke1, rtol=1e-9)
    if shape == "uniform" and abs(vt) <= 3 * mu * vn:  # rolling: 2/3 of vt kept
        assert v[0] == pytest.approx(2 * vt / 3, abs=1e-12)
        assert abs(u1) <= 1e-12


def test_a_frictionless_impact_keeps_the_tangential_velocity():
    """mu = 0: the impact's impulse is normal; the tangential velocity and spin are kept."""
    model = _disc_at_wall(0.0, 0.01)
    run = model.simulate(np.zeros(4), 0.003, v_obj0=[[1.0, -0.8, 0.0]], dt=1e-3)
    i = int(np.searchsorted(run.t, run.events[0].t))
    np.testing.assert_allclose(np.asarray(run.v_obj)[i, 0], [1.0, 0.0, 0.0], atol=1e-12)
    # a scene without contact friction: the event's fields as before, none added
    assert set(run.summary["events"][0]) == {"t", "kind", "bodies", "impulses", "loss",
                                             "certificate"}
    assert run.events[0].friction_impulses is None


# A step the fixed point does not settle (the sweep's gait at 0.3 rad and 0.5 Hz, mu_contact 3,
# after 12.7 ms): a peg at a joint touching both links' ends, their normal rows nearly one.
UNSETTLED_Q = [-0.00044519038603647144, -0.00031368327766602666, -0.009177788961733959,
    0.017832611205317154, 0.46736833806964895, 0.28943116140828634, -0.29199059179641845,
    -0.47292600532147394, 0.0031981181929010417, 0.4740930371507265, 0.28452549992791826,
    -0.2934033686599191, -0.44310798675509355]
UNSETTLED_V = [0.00017049914485880947, -0.00908007033264329, 0.1211048950687929,
    -0.13385338534158903, 0.34722814755492215, -0.43081068485146023, -0.38328087708513714,
    0.4196097947086437, 0.6242169784273578, -0.27864824145070144, -1.333136994796072,
    0.5288070649493117, 3.4647053354765682]
UNSETTLED_TAU = [0.26433391359641806, -1.8133396698031317, -1.3354031467235588,
    0.9539597503215012, 1.8876261184595569, 0.18325773458989472, -1.69282374391222,
    -1.0156486389364914, 0.6944611363461758, 0.675917270565374]


def _coulomb_pieces(st, model, h, tau):
    """The solutions of one step's Coulomb problem at the rows of ``st`` (a :class:`_Stepper`
    at the step's start) with every ground disc sliding: the frictional contacts' pieces
    enumerated (open, stick, slip + or -: w_t > 0 or < 0), each piece's smooth equations
    solved by SciPy's hybrid Newton (M V = f + A^T lam; open: lam = 0; stick: w_n = w_t = 0;
    slip: w_n = 0, lam_t = -+mu lam_n; a sliding disc's force -R w / |w|) and kept where
    Coulomb's inequalities hold: ``[(pieces, V, lam)]``. NumPy apart from the engine's solve
    (the rows, inertia and gaps are the engine's)."""
    import itertools

    from scipy.optimize import root

    from snakecg.scenes.stepping import GAP_BAND

    n, M, out = st.n, st.M.copy(), st.out
    nc, m, nb = int(out[1]), int(out[2]), int(out[3])
    A, start = st.A[:m + nc].copy(), st.start[:nb].copy()
    rec = out[10 + 3 * st.no:10 + 3 * st.no + 16 * nc].reshape(nc, 16)
    mu = rec[:, 13]
    f = M @ st.V
    f[:st.ns] += h * (np.r_[0, 0, 0, tau] - model.bias_forces(st.x[:st.ns], st.V[:st.ns]))
    off = np.zeros(m + nc)
    for k in range(nc):
        g = rec[k, 10]
        off[start[k]] = g / h if abs(g) > GAP_BAND * st.engine.tol else 0.0
    discs = [(start[b], st.par[b, 0] * h) for b in range(nc, nb)]
    assert list(st.kind[:nc]) == [1] * nc and list(st.kind[nc:nb]) == [3] * (nb - nc)

    def residual(z, piece):
        V, lam = z[:n], z[n:]
        w = A @ V + off
        r = [M @ V - f - A.T @ lam]
        for k, p in enumerate(piece):
            rn, rt = start[k], m + k
            r.append([lam[rn], lam[rt]] if p == "open" else [w[rn], w[rt]] if p == "stick"
                     else [w[rn], lam[rt] + (1 if p == "+" else -1) * mu[k] * lam[rn]])
        r += [lam[s:s + 2] + R * w[s:s + 2] / np.linalg.norm(w[s:s + 2]) for s, R in discs]
        return np.concatenate(r)

    V0, lam0 = st.V.copy(), np.zeros(m + nc)
    for s, R in discs:
        lam0[s:s + 2] = -R * A[s:s + 2] @ V0 / np.linalg.norm(A[s:s + 2] @ V0)
    found = []
    for p in itertools.product(("open", "stick", "+", "-"), repeat=nc):
        z = root(residual, np.r_[V0, lam0], args=(p,), method="hybr", tol=1e-14).x
        V, lam = z[:n], z[n:]
        w = A @ V + off
        F, W = np.abs(lam).max(), np.abs(w).max()
        ok = np.abs(residual(z, p)).max() <= 1e-12 * max(1.0, np.abs(f).max())
        for k, x in enumerate(p):
            rn, rt = start[k], m + k
            if x == "open":
                ok &= w[rn] >= -1e-9 * W
            else:
                ok &= lam[rn] >= -1e-9 * F
                ok &= abs(lam[rt]) <= mu[k] * lam[rn] + 1e-9 * F if x == "stick" else \
                    (1 if x == "+" else -1) * w[rt] >= -1e-9 * W
        ok &= min(np.linalg.norm(w[s:s + 2]) for s, _ in discs) > 1e-9 * W
        if ok:
            found.append((p, V, lam))
    return found


def _recorded_steps():
    """Steps where the bounds' fixed point and Newton steps did not settle from any of their
    four starts, recorded from the sweep of benchmarks/bench_friction_sweep.py (15 gaits x
    mu_contact 0.3-3 on the pegs row): the pegs' coefficient, the gait, the time, and the
    state and torques at the step's start. The one at mu_contact 3 after 12.7 ms (UNSETTLED_*)
    is a peg at a joint touching both links' ends, their normal rows 3e-4 apart."""
    rows = json.loads((Path(__file__).parent / "data" / "friction_unsettled_steps.json")
                      .read_text(encoding="utf-8"))
    rows.append({"mu_contact": 3.0, "amplitude": 0.3, "frequency": 0.5, "t": 0.0127,
                 "q": UNSETTLED_Q, "v": UNSETTLED_V, "tau": UNSETTLED_TAU})
    return rows


@pytest.mark.parametrize("step", _recorded_steps(),
                         ids=lambda r: f"mu{r['mu_contact']:g}-{r['amplitude']:g}rad-"
                                       f"{r['frequency']:g}Hz-t{r['t']:.4f}")
def test_a_step_the_fixed_point_does_not_settle_is_coulomb_s_one_solution(step):
    """Steps (1 to 3 pegs touching, no impact) where the fixed point on the bounds does not
    settle (its passes swing between a contact's stick and slip pieces, or between two nearly
    parallel contacts' loads): the enumeration of the contacts' pieces (NumPy, SciPy's Newton
    on each piece, every ground disc sliding) finds exactly one Coulomb solution, and the
    engine's step (its candidate states solved exactly) is that one: its velocities within
    1e-7 (measured: 2e-9 at the ill-conditioned pair 3e-4 apart, else 2e-11), Coulomb's
    residuals within 1e-9. A step that fails them is never accepted."""
    from snakecg.scenes.stepping import _Stepper

    model = _rough_pegs_row(step["mu_contact"])
    q, v, tau = (np.array(step[k]) for k in ("q", "v", "tau"))
    run = model.simulate(q, 1e-3, v0=v, tau=tau, dt=1e-3)
    st = _Stepper(model, run.tolerance, np.zeros(0))
    st.begin(q, np.zeros(0), v, None)
    assert 1 <= int(st.out[1]) <= 3
    found = _coulomb_pieces(st, model, 1e-3, tau)
    assert len(found) == 1, [p for p, _, _ in found]
    assert run.status == "completed", run.message
    assert len(run.events) == 0 and len(run.t) == 2
    np.testing.assert_allclose(run.v[-1], found[0][1][:13], rtol=0, atol=1e-7)
    assert max(run.certificate.values()) <= 1e-9


def _impact_solutions(M, A, m, nc, start, mu, V0, tol=1e-9):
    """Every solution of an inelastic impact's Coulomb law at the rows of a step's end (NumPy,
    apart from the engine): M V = M V0 + A_c^T p over the contacts' normal rows (start[k])
    and the frictional ones' tangent rows (m + k), the ground giving no impulse; each contact's
    pieces enumerated (frictionless: held, open; frictional: open, stick, slip + or -), each
    piece's linear equations solved and kept where its inequalities hold: p_n >= 0,
    w_n = A_n V >= 0, |p_t| <= mu p_n sticking, +-w_t >= 0 slipping with p_t = -+mu p_n.
    Returns [(pieces, V, p)]."""
    n = len(V0)
    fric = [k for k in range(nc) if mu[k] > 0]
    tan = {k: nc + j for j, k in enumerate(fric)}
    C = A[[start[k] for k in range(nc)] + [m + k for k in fric]]
    r = len(C)
    W = max(1e-12, np.abs(C @ V0).max())
    found = []
    options = [("open", "stick", "+", "-") if mu[k] > 0 else ("held", "open") for k in range(nc)]
    for piece in itertools.product(*options):
        K, rhs = np.zeros((n + r, n + r)), np.zeros(n + r)
        K[:n, :n], K[:n, n:], rhs[:n] = M, -C.T, M @ V0
        for k, s in enumerate(piece):
            t = tan.get(k)
            if s == "open":
                K[n + k, n + k] = 1.0
                if t is not None:
                    K[n + t, n + t] = 1.0
                continue
            K[n + k, :n] = C[k]
            if t is not None and s == "stick":
                K[n + t, :n] = C[t]
            elif t is not None:
                K[n + t, n + t], K[n + t, n + k] = 1.0, mu[k] if s == "+" else -mu[k]
        if np.linalg.matrix_rank(K) < n + r:
            continue
        x = np.linalg.solve(K, rhs)
        V, p = x[:n], x[n:]
        w, F = C @ V, max(1e-12, np.abs(p).max())
        ok = all(p[k] >= -tol * F and w[k] >= -tol * W for k in range(nc))
        for k, s in enumerate(piece):
            t = tan.get(k)
            if s == "stick" and t is not None:
                ok &= abs(p[t]) <= mu[k] * p[k] + tol * F
            elif s in ("+", "-"):
                ok &= (w[t] if s == "+" else -w[t]) >= -tol * W
        if ok:
            found.append((piece, V, p))
    return found


@pytest.mark.parametrize("step", json.loads(
    (Path(__file__).parent / "data" / "friction_unsettled_impacts.json").read_text(
        encoding="utf-8")), ids=lambda r: f"mu{r['mu_contact']:g}-{r['amplitude']:g}rad-"
                                          f"{r['frequency']:g}Hz-t{r['t']:.4f}")
def test_an_impact_the_fixed_point_does_not_settle_is_coulomb_s_one_solution(step):
    """Steps of the same sweep that stopped in the impact after them (a contact new at the
    step's end closing fast; 2 to 7 contacts): the enumeration of the impact's pieces
    (_impact_solutions, NumPy) finds exactly one solution at the rows of the step's end and
    the velocity before the impact, and the engine's velocities after it are that one's
    (within 1e-9; measured 1e-11); the run from that state completes."""
    from snakecg.scenes.stepping import _Stepper

    model = _rough_pegs_row(step["mu_contact"])
    q, v, tau = (np.array(step[k]) for k in ("q", "v", "tau"))
    st = _Stepper(model, contact_tolerance(model.scene, None), np.zeros(0))
    st.begin(q, np.zeros(0), v, None)
    st.tau[:model.n_joints] = tau
    assert st.call(1e-3) == 0  # the step and its impact accepted
    out = st.out
    nc, m = int(out[1]), int(out[2])
    rec = out[10 + 3 * st.no:10 + 3 * st.no + 16 * nc].reshape(nc, 16)
    found = _impact_solutions(st.M, st.A, m, nc, st.start, rec[:, 13], st.Vp.copy())
    assert len(found) == 1, [p for p, _, _ in found]
    assert np.abs(st.V - st.Vp).max() > 1e-3  # (an impact changed the velocities)
    np.testing.assert_allclose(st.V, found[0][1], rtol=0,
                               atol=1e-9 * max(1.0, np.abs(st.Vp).max()))
    run = model.simulate(q, 1e-3, v0=v, tau=tau, dt=1e-3)
    assert run.status == "completed" and len(run.events) == 1, run.message
    assert max(run.certificate.values()) <= 1e-9
