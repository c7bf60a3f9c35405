"""General scenes over time (snakecg.scenes.stepping), against independent references:
closed-form inelastic impacts of discs, the velocity-level step written independently as a
conic QP for cvxpy + Clarabel, NumPy distances of capsules and pegs on every sample, and the
physical laws (energy, impulses >= 0, kinetic friction against sliding) over every run."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import snakecg
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject, load_scene
from snakecg.scenes.toml_reading import read_scene
from snakecg.simulate import serpenoid_controller

from capsule_reference import deepest_overlap, link_segments, segment_segment

ROOT = Path(__file__).resolve().parents[1]
PEGS_ROW = ROOT / "examples" / "scenes" / "pegs_row.toml"


def _laws(run):
    """Energy: kinetic energy gained <= the torques' work - friction dissipated - impact loss
    + the contacts' work (to 1e-9 J; the contacts' work is the gap stabilisation's, which
    pushes a contact within the tolerance back to zero gap: at most 2 % of the torques'
    work); friction dissipates, impacts lose energy, impulses >= 0; the sliding blocks'
    impulses oppose the sliding velocity."""
    ke = run.kinetic_energy
    gain = ke - ke[0]
    budget = run.work_tau - run.friction_dissipation - run.impact_loss + run.contact_work
    assert np.all(np.abs(run.contact_work) <= 0.02 * np.abs(run.work_tau) + 1e-12)
    assert np.all(gain <= budget + 1e-9 + 1e-9 * np.abs(budget)), float(np.max(gain - budget))
    assert np.all(np.diff(run.friction_dissipation) >= -1e-12)
    assert np.all(np.diff(run.impact_loss) >= -1e-12)
    assert np.all(run.contact_impulse >= -1e-12)
    for e in run.events:
        assert all(p >= 0 for p in e.impulses)
        assert max(e.certificate.values()) <= 1e-8
    if run.min_sliding_cosine >= 0:
        assert run.min_sliding_cosine >= 1 - 1e-9


# closed-form impacts ------------------------------------------------------------------------
def _far_robot():
    return snakecg.Robot(joints=1)


def test_disc_hits_a_wall_inelastically_at_the_time_of_contact():
    """A disc (no friction) sliding at u toward a wall from gap d0: contact at t = d0 / u, the
    normal velocity removed, the tangential kept (the closed-form plastic impact), no
    penetration beyond the tolerance on any sample."""
    u, d0, vt, rad = 0.5, 0.1, 0.2, 0.05
    wall = Obstacle(shape="wall", point=(1.0, 0.0), normal=(-1.0, 0.0))
    disc = SceneObject(shape="disc", radius=rad, mass=2.0, pose=(1.0 - rad - d0, 0.0, 0.0))
    scene = GeneralScene(_far_robot(), ground=Ground(model="frictionless"), objects=(disc,),
                         obstacles=(wall,))
    model = load_scene(scene)
    q0 = np.array([-1.0, 0.0, 0.0, 0.0])
    run = model.simulate(q0, 0.5, v_obj0=[[u, vt, 0.0]], dt=1e-2, tolerance=1e-6)
    assert run.status == "completed", run.message
    assert len(run.events) == 1
    e = run.events[0]
    assert abs(e.t - d0 / u) <= 1e-6 / u + 1e-12
    # plastic impact: the impulse m u, the kinetic energy 1/2 m u^2 lost
    assert e.impulses[0] == pytest.approx(2.0 * u, rel=1e-9)
    assert e.loss == pytest.approx(0.5 * 2.0 * u * u, rel=1e-9)
    after = run.t > e.t + 1e-12
    np.testing.assert_allclose(run.v_obj[after, 0, 0], 0.0, atol=1e-12)
    np.testing.assert_allclose(run.v_obj[after, 0, 1], vt, rtol=1e-12)
    x_face = run.q_obj[:, 0, 0] + rad
    assert np.all(x_face <= 1.0 + 1e-6)
    _laws(run)


def test_two_discs_collide_centrally_with_momentum_kept():
    """Two discs on a line, 1 kg at 1 m/s onto 3 kg at rest: after the plastic impact both move
    at (m1 v1) / (m1 + m2) = 0.25 m/s; the loss is 1/2 m1 m2 / (m1 + m2) v1^2."""
    d1 = SceneObject(shape="disc", radius=0.05, mass=1.0, pose=(0.0, 0.0, 0.0))
    d2 = SceneObject(shape="disc", radius=0.05, mass=3.0, pose=(0.2, 0.0, 0.0))
    scene = GeneralScene(_far_robot(), ground=Ground(model="frictionless"), objects=(d1, d2))
    model = load_scene(scene)
    run = model.simulate(np.array([-2.0, 0.0, 0.0, 0.0]), 0.3, v_obj0=[[1.0, 0, 0], [0, 0, 0]],
                         dt=1e-2, tolerance=1e-6)
    assert run.status == "completed", run.message
    assert len(run.events) == 1
    assert run.events[0].t == pytest.approx(0.1, abs=1e-6)
    np.testing.assert_allclose(run.v_obj[-1, :, 0], [0.25, 0.25], rtol=1e-10)
    assert run.events[0].loss == pytest.approx(0.5 * 1 * 3 / 4 * 1.0, rel=1e-9)
    _laws(run)


def test_a_disc_under_coulomb_friction_stops_at_the_closed_form_distance():
    """A disc with ground friction mu sliding at u stops after u^2 / (2 mu g) (semi-implicit
    Euler: within u h of it) and sticks afterwards, kinetic friction against sliding."""
    u, mu, g = 0.6, 0.3, 9.81
    disc = SceneObject(shape="disc", radius=0.05, mass=1.5, pose=(0.0, 0.0, 0.0), mu=mu)
    scene = GeneralScene(_far_robot(), ground=Ground(model="frictionless"), objects=(disc,))
    run = load_scene(scene).simulate(np.array([-2.0, 0.0, 0.0, 0.0]), 0.5,
                                     v_obj0=[[u, 0, 0]], dt=1e-3)
    assert run.status == "completed"
    assert run.q_obj[-1, 0, 0] == pytest.approx(u * u / (2 * mu * g), abs=u * 1e-3)
    assert np.all(run.v_obj[run.t > u / (mu * g) + 2e-3, 0, 0] == 0.0)
    # the friction's work lam . v+ per step: the kinetic energy lost less the scheme's own
    # dissipation 1/2 m |dv|^2 per step (dv = mu g h), 1/2 m mu g h u in all
    h = 1e-3
    assert run.friction_dissipation[-1] == pytest.approx(
        0.5 * 1.5 * u * u - 0.5 * 1.5 * mu * g * h * u, abs=1.5 * (mu * g * h) ** 2)
    _laws(run)


# the velocity-level step against an independent conic QP -----------------------------------
def test_one_step_against_cvxpy_clarabel(rng):
    """One step of the engine (core_scene_step) with a peg contact, Coulomb, bounded and ideal
    wheels, a disc object with ground friction, both contacts' gaps inside the tolerance on
    either side (the rows' offsets g / h): V+ equals the minimiser of the same conic QP
    written apart with the reference's rows (tests/scenes_rows_reference.py), the generated
    mass matrix and bias forces, solved by Clarabel."""
    cp = pytest.importorskip("cvxpy")
    pytest.importorskip("clarabel")
    from scenes_rows_reference import place_objects, rows_of

    from snakecg.scenes.contacts import link_ends
    from snakecg.scenes.stepping import STEP_NOT_CONVERGED, _Stepper

    robot = snakecg.Robot(joints=3)
    ground = (Ground(model="coulomb", mu=0.3), Ground(model="wheels", mu=0.2),
              Ground(model="ideal_wheels"), Ground(model="coulomb", mu=0.5))
    base = GeneralScene(robot, radius=0.02, ground=ground)
    q = np.array([0.0, 0.0, 0.1, 0.4, -0.3, 0.5])
    P = load_scene(base).link_poses(q)
    ends = link_ends(base, P)
    mid = 0.5 * (ends[1, 0] + ends[1, 1])
    t = (ends[1, 1] - ends[1, 0]) / 0.15
    peg = Obstacle(shape="peg", center=tuple(mid + (0.05 + 3e-7) * np.array([-t[1], t[0]])),
                   radius=0.03)  # 3e-7 m off link 2
    disc = SceneObject(shape="disc", radius=0.04, mass=0.7, mu=0.4,
                       touching={"link": 4, "offset": 0.07, "side": "right"})
    scene = GeneralScene(robot, radius=0.02, ground=ground, objects=(disc,), obstacles=(peg,))
    model = load_scene(scene)
    tol = 1e-6
    J = model.link_jacobians(q)
    qo = place_objects(scene, P)
    placed, _ = rows_of(scene, model.masses, P, J, obj_poses=qo, tol=tol)
    qo[0, :2] -= 2e-7 * placed.contacts[1].normal  # the disc 2e-7 m into link 4
    rows, _ = rows_of(scene, model.masses, P, J, obj_poses=qo, tol=tol)
    assert [c.b for c in rows.contacts] == [("obstacle", 0), ("object", 0)]
    assert [c.gap for c in rows.contacts] == pytest.approx([3e-7, -2e-7], abs=1e-12)
    h = 1e-3
    V = np.r_[rng.normal(size=6) * 0.3, rng.normal(size=3) * 0.2]
    tau = rng.normal(size=3)
    st = _Stepper(model, tol, np.zeros(3))
    st.x[:] = np.r_[q, qo.ravel()]
    st.V[:] = V
    assert st.call(0.0) == 0 and len(st.rows().contacts) == 2
    st.tau[:] = tau
    assert st.call(h) != STEP_NOT_CONVERGED
    Mf = np.zeros((9, 9))
    Mf[:6, :6] = model.mass_matrix(q)
    Mf[6:, 6:] = np.diag([0.7, 0.7, disc.plate_inertia])
    fgen = np.zeros(9)
    fgen[3:6] = tau
    fgen[:6] -= model.bias_forces(q, V[:6])
    # the same problem, independently: min 1/2 |x - v*|_M^2 + h sum r_k |A_k x| s.t. ...
    vstar = V + h * np.linalg.solve(Mf, fgen)
    x = cp.Variable(9)
    Lc = np.linalg.cholesky(Mf)
    cost = 0.5 * cp.sum_squares(Lc.T @ (x - vstar))
    cons = []
    g = scene.gravity
    for i, gr in enumerate(ground):
        xi, yi, phi = model.link_poses(q)[i]
        Ji = model.link_jacobians(q)[i]
        Jl = np.zeros((3, 9))
        Jl[:, :6] = Ji
        if gr.model == "coulomb":
            cost += h * gr.mu * robot.mass[i] * g * cp.norm(Jl[:2] @ x, 2)
        elif gr.model in ("wheels", "ideal_wheels"):
            lat = np.array([-np.sin(phi), np.cos(phi), 0.0]) @ Jl
            if gr.model == "wheels":
                cost += h * gr.mu * robot.mass[i] * g * cp.abs(lat @ x)
            else:
                cons.append(lat @ x == 0)
    Jo = np.zeros((2, 9))
    Jo[:, 6:8] = np.eye(2)
    cost += h * 0.4 * 0.7 * g * cp.norm(Jo @ x, 2)
    for c in rows.contacts:  # (no offset within a thousandth of the tolerance: none here)
        assert abs(c.gap) > 1e-3 * tol
        cons.append(rows.A[c.row] @ x + c.gap / h >= 0)
    cp.Problem(cp.Minimize(cost), cons).solve(solver=cp.CLARABEL, tol_gap_abs=1e-12,
                                              tol_gap_rel=1e-12, tol_feas=1e-12)
    np.testing.assert_allclose(st.Vp, x.value, atol=2e-6 * np.abs(x.value).max())


# obstacle-aided locomotion ------------------------------------------------------------------
def _pegs_row_runs(duration):
    scene = read_scene(PEGS_ROW)
    free = GeneralScene(scene.robot, radius=scene.radius, ground=scene.ground)
    q0 = np.zeros(13)
    q0[3:] = 0.5 * np.sin(np.arange(10) * 2 * np.pi / 5)
    runs = {}
    for name, sc in (("pegs", scene), ("free", free)):
        model = load_scene(sc)
        gait = serpenoid_controller(model, amplitude=0.5, frequency=1.0,
                                    phase_lag=2 * np.pi / 5, kp=10.0, kd=0.3, tau_max=None)
        run = model.simulate(q0, duration, tau=gait, dt=1e-3)
        runs[name] = (sc, model, run)
    return runs


def test_pegs_row_obstacle_aided_locomotion():
    """Among the pegs the snake moves forward along the row; on the same ground without them it
    barely moves (isotropic Coulomb friction gives lateral undulation no grip). Nothing
    penetrates beyond the tolerance on any sample (NumPy distances of capsules and pegs)."""
    runs = _pegs_row_runs(1.5)
    progress = {}
    for name, (sc, model, run) in runs.items():
        assert run.status == "completed", run.message
        assert deepest_overlap(sc, run.q) <= run.tolerance * (1 + 1e-6)
        assert np.min(run.min_gap) >= -run.tolerance
        _laws(run)
        com = model.com(run.q)
        progress[name] = float(np.hypot(*(com[-1] - com[0])))
    assert runs["pegs"][2].events  # it pushes against the pegs: impacts happen
    assert progress["pegs"] > 0.1
    assert progress["free"] < 0.02
    assert progress["pegs"] > 8 * progress["free"]


def test_self_contact_is_a_row_and_nothing_crosses():
    """A 4-joint snake folded by large torques onto itself on a frictionless ground: its
    links touch (self-contact rows) and never cross (NumPy segment distances)."""
    robot = snakecg.Robot(joints=4)
    scene = GeneralScene(robot, radius=0.02, ground=Ground(model="coulomb", mu=0.05))
    model = load_scene(scene)
    q0 = np.array([0.0, 0.0, 0.0, 1.2, 1.2, 1.2, 0.0])
    run = model.simulate(q0, 0.6, tau=np.array([0.6, 0.6, 0.6, 0.3]), dt=1e-3)
    assert run.status == "completed", run.message
    assert run.n_contacts.max() >= 1
    assert deepest_overlap(scene, run.q) <= run.tolerance * (1 + 1e-6)
    _laws(run)


def test_simulate_refuses_bad_arguments_before_any_work():
    scene = GeneralScene(snakecg.Robot(joints=2), ground=Ground(model="coulomb", mu=0.1))
    model = load_scene(scene)
    with pytest.raises(InputError, match=r"q0 must be 5 finite numbers.*dt must be"):
        model.simulate([0, 0, 0], 1.0, dt=-1)
    with pytest.raises(InputError, match="tolerance must be"):
        model.simulate(np.zeros(5), 1.0, tolerance=1.0)
    assert math.isfinite(model.simulate(np.zeros(5), 0.01).kinetic_energy[-1])


def test_a_start_that_overlaps_is_refused_naming_the_bodies_and_the_depth(tmp_path, capsys):
    """A disc placed 4 mm into a wall (closed form: its centre 4 mm nearer than its radius):
    one run is refused before any step, as the paper's scene refuses it, naming the two bodies
    and the depth; the CLI in one line with exit status 2; a batch marks that run alone."""
    from snakecg.cli import main
    from snakecg.scenes import simulate_scene_batch

    rad, depth = 0.05, 0.004
    wall = Obstacle(shape="wall", point=(1.0, 0.0), normal=(-1.0, 0.0))
    disc = SceneObject(shape="disc", radius=rad, mass=2.0, pose=(1.0 - rad + depth, 0.0, 0.0))
    scene = GeneralScene(_far_robot(), ground=Ground(model="frictionless"), objects=(disc,),
                         obstacles=(wall,))
    model = load_scene(scene)
    with pytest.raises(InputError, match=r"initial state is not physical: object 1 and "
                       r"obstacle 1 overlap by 0.004 m"):
        model.simulate(np.zeros(4), 0.01)
    apart = [[[1.0 - rad - 0.01, 0.0, 0.0]]]
    batch = simulate_scene_batch(model, np.zeros((2, 4)), 0.01,
                                 q_obj0=np.array([[[1.0 - rad + depth, 0.0, 0.0]], *apart]))
    assert list(batch.status) == ["penetration", "completed"]
    assert "overlap by 0.004 m" in batch.message[0]
    toml = tmp_path / "disc.toml"
    toml.write_text("[robot]\njoints = 1\n[ground]\nmodel = \"frictionless\"\n"
                    f"[[object]]\nshape = \"disc\"\nradius = {rad}\nmass = 2.0\n"
                    f"pose = [{1.0 - rad + depth}, 0.0, 0.0]\n"
                    "[[obstacle]]\nshape = \"wall\"\npoint = [1.0, 0.0]\nnormal = [-1.0, 0.0]\n")
    rc = main(["simulate", "--scene", str(toml), "--q", "0,0,0,0", "--tau", "0",
               "--duration", "0.01", "--out", str(tmp_path / "out"), "--quiet"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and "overlap by 0.004 m" in err[0]
    assert not (tmp_path / "out").exists()


def test_a_constant_wrench_works_f_obj_times_the_displacement():
    """A box on Coulomb ground pushed and turned by a constant wrench, 0.2 s: the kinetic
    energy gained is the wrench's work f_obj . (q_obj - q_obj[0]) less the friction dissipated
    and the scheme's own loss, 1/2 |V+ - V|_M^2 summed over the steps (semi-implicit Euler),
    to 1e-9: the balance the how-to states for runs with f_obj."""
    box = SceneObject(shape="box", size=(0.1, 0.1), mass=2.0, mu=0.2, pose=(2.0, 0.0, 0.3))
    model = load_scene(GeneralScene(_far_robot(), ground=Ground(model="coulomb", mu=0.3),
                                    objects=(box,)))
    f = np.array([[30.0, -10.0, 2.0]])
    run = model.simulate(np.zeros(4), 0.2, f_obj=f)
    assert run.status == "completed" and run.friction_dissipation[-1] > 0.5
    work = float(np.sum(f * (run.q_obj[-1] - run.q_obj[0])))
    gain = run.kinetic_energy[-1] - run.kinetic_energy[0]
    dv = np.diff(run.v_obj[:, 0, :], axis=0)
    scheme = 0.5 * float(np.sum(dv ** 2 @ np.array([2.0, 2.0, 2.0 * 0.02 / 12])))
    assert gain == pytest.approx(work - run.friction_dissipation[-1] - scheme, abs=1e-9)


def _deepest_overlap_of_bodies(scene, run) -> float:
    """The deepest overlap (m) over a run's samples of every pair that can touch (links that
    are not neighbours, links with objects, objects with objects), by the tests' closest
    points (scenes_geometry_reference: separating axes), no pegs or walls."""
    from scenes_geometry_reference import Shape, closest

    worst, scale = 0.0, max(scene.robot.length)
    for q, qo in zip(run.q, run.q_obj):
        links = [Shape("segment", np.array([a, b]), scene.radius)
                 for a, b in link_segments(scene.robot, q)]
        objs = [Shape("point", qo[j, :2], o.radius) if o.shape == "disc"
                else Shape("polygon", _box_corners(qo[j], o.size))
                for j, o in enumerate(scene.objects)]
        pairs = [(A, B) for A in links for B in objs]
        pairs += [(links[i], links[j]) for i in range(len(links))
                  for j in range(i + 2, len(links))]
        pairs += [(objs[i], objs[k]) for i in range(len(objs)) for k in range(i + 1, len(objs))]
        for A, B in pairs:
            if A.kind == "polygon":
                A, B = B, A
            worst = max(worst, -closest(A, B, scale)[0])
    return worst


def test_a_step_whose_solve_does_not_converge_is_taken_again_halved():
    """A random scene of the simulation campaign (3 joints on four ground models, a box and
    two discs pressed by a constant torque): at t = 0.162 s its step's solve did not converge
    at the full step (nearly dependent rows) and the run ended not_converged. Halved, the
    step converges: the run completes, no pair overlaps beyond the tolerance on any sample
    (the tests' closest points of segments, discs and boxes), and the energy laws hold."""
    robot = snakecg.Robot(joints=3, mass=(1.3763742690256087, 1.0523463212462962,
                                          0.8564950651940352, 0.9824298190412027),
                          length=(0.16427904671798899, 0.12499006334975063,
                                  0.14614422842851688, 0.15188033467861559),
                          inertia=(0.001335435930036699, 0.0017656626358713754,
                                   0.0038897617723326504, 0.0020588058834374113))
    ground = (Ground(model="frictionless"), Ground(model="frictionless"),
              Ground(model="anisotropic", mu_forward=0.47005364733140964,
                     mu_backward=0.06469822860109727, mu_lateral=0.5828333077883276),
              Ground(model="wheels", mu=0.3096223938243699,
                     wheel_offset=-0.0005478129134649616))
    objects = (SceneObject(shape="box", size=(0.049525677632571014, 0.0507562563213656),
                           mass=36.24691552869378,
                           touching={"link": 3, "offset": 0.12777215951637694, "side": "right"}),
               SceneObject(shape="disc", radius=0.021928072957702858, mass=20.288872133216937,
                           touching={"link": 1, "offset": 0.13843683685644345, "side": "right"}),
               SceneObject(shape="disc", radius=0.026058493095400932, mass=9.140886622385944,
                           touching={"link": 4, "offset": 0.1205645819311787, "side": "right"},
                           mu=0.1413569515710373))
    scene = GeneralScene(robot, ground=ground, objects=objects)
    q0 = np.array([-1.6984455905603177, -0.02586513996954804, 1.0388964250809964,
                   -0.07179653637338368, -0.9865157461624381, 1.1632220732231648])
    tau = np.array([-0.36974076258660016, -1.8998593477112768, 3.4233542802322505])
    run = load_scene(scene).simulate(q0, 0.25, tau=tau, dt=1e-3)
    assert run.status == "completed", (run.status, run.message)
    assert run.t[-1] == pytest.approx(0.25, abs=1e-12)
    assert _deepest_overlap_of_bodies(scene, run) <= run.tolerance * (1 + 1e-6)
    _laws(run)


# MuJoCo on the matched pegs scene ------------------------------------------------------------
def test_pegs_row_against_mujoco():
    """The pegs-row run for 1 s against MuJoCo on the matched scene (capsules and cylinders,
    COM spheres on a Coulomb floor with condim 3 and noslip, stiff solref; tests/
    mujoco_pegs.py) at 2e-4 s, where its capsule-peg overlaps stay within snakecg's tolerance:
    the COM paths agree to a quarter of the distance travelled and the end points to 15 %.
    (They are not the same model: MuJoCo's contacts are soft, its friction regularised, and
    snakecg steps at 1e-3 s; see the obstacle-aided locomotion page.)"""
    pytest.importorskip("mujoco")
    from mujoco_pegs import MatchedPegs

    from snakecg.scenes.stepping import SceneState

    scene = read_scene(PEGS_ROW)
    model = load_scene(scene)
    q0 = np.zeros(13)
    q0[3:] = 0.5 * np.sin(np.arange(10) * 2 * np.pi / 5)
    gait = serpenoid_controller(model, amplitude=0.5, frequency=1.0, phase_lag=2 * np.pi / 5,
                                kp=10.0, kd=0.3, tau_max=None)
    run = model.simulate(q0, 1.0, tau=gait, dt=1e-3)
    assert run.status == "completed"
    com = model.com(run.q)
    ts = 2e-4
    mj = MatchedPegs(scene, timestep=ts)
    mj.set_state(q0)
    hold = 5  # the torque held over snakecg's step
    coms, depth = [], 0.0
    for k in range(5000):
        if k % hold == 0:
            q, v = mj.state()
            tau = gait(k * ts, SceneState(k * ts, q, v, np.zeros((0, 3)), np.zeros((0, 3))))
        mj.step(tau)
        depth = max(depth, mj.peg_depth())
        if (k + 1) % hold == 0:
            coms.append(model.com(mj.state()[0]))
    coms = np.array(coms)
    travelled = float(np.hypot(*(com[-1] - com[0])))
    assert travelled > 0.05
    assert depth <= run.tolerance
    assert np.hypot(*(coms[-1] - com[-1])) <= 0.15 * travelled
    assert np.abs(coms - com[1:1 + len(coms)]).max() <= 0.25 * travelled


def test_cli_simulate_scene_json_and_refusals(tmp_path, capsys):
    """``snakecg simulate --scene``: strict JSON with the run's status and energy; options of
    the paper's scene refused in one line with exit 2."""
    import json

    from snakecg.cli import main

    q = "0,0,0,0,0.4755,0.2939,-0.2939,-0.4755,0,0.4755,0.2939,-0.2939,-0.4755"
    rc = main(["simulate", "--scene", str(PEGS_ROW), f"--q={q}", "--tau",
               "0.2,0,0,0,0,0,0,0,0,0", "--duration", "0.02", "--json", "--out",
               str(tmp_path / "out")])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and out["status"] == "completed"
    # 20 steps of 1 ms, and one more where a step was shortened to a contact's onset
    assert out["duration"] == pytest.approx(0.02, abs=1e-12)
    assert out["steps"] == 20 + sum(e["kind"] == "impact" for e in out["events"])
    assert out["energy"]["work_tau"] > 0
    assert (tmp_path / "out" / "trajectory.npz").is_file()
    rc = main(["simulate", "--scene", str(PEGS_ROW), f"--q={q}", "--tau",
               "0,0,0,0,0,0,0,0,0,0", "--a-min", "1"])
    assert rc == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--a-min applies to the paper's scene only" in err[0]


def _box_corners(pose, size):
    c, s = np.cos(pose[2]), np.sin(pose[2])
    a, b = size[0] / 2, size[1] / 2
    loc = np.array([[-a, -b], [a, -b], [a, b], [-a, b]])
    return pose[:2] + loc @ np.array([[c, s], [-s, c]])


def _segment_box_distance(a0, a1, corners):
    """0 if the segment meets the box (an end inside, or crossing an edge), else the least
    distance between the segment and the box's edges."""
    def inside(p):
        def cross(u, w):
            return u[0] * w[1] - u[1] * w[0]

        return all(cross(corners[(k + 1) % 4] - corners[k], p - corners[k]) >= 0
                   for k in range(4))

    if inside(a0) or inside(a1):
        return 0.0
    return min(segment_segment(a0, a1, corners[k], corners[(k + 1) % 4]) for k in range(4))


@pytest.mark.parametrize("ground", [Ground(model="anisotropic", mu_forward=0.05,
                                           mu_backward=0.3, mu_lateral=0.5),
                                    Ground(model="wheels", mu=0.3, wheel_offset=0.02)],
                         ids=["anisotropic", "wheels"])
def test_pushing_a_box_on_every_ground_stays_outside_it(ground):
    """A 3-joint snake drives a box touching its middle link: the box turns on the link, its
    corner or face the contact as the geometry says; the links never enter the box (NumPy
    segment-box distance on every sample) and the laws hold."""
    robot = snakecg.Robot(joints=3)
    box = SceneObject(shape="box", size=(0.1, 0.06), mass=0.5, mu=0.2,
                      touching={"link": 2, "offset": 0.09, "side": "left"})
    scene = GeneralScene(robot, radius=0.01, ground=ground, objects=(box,))
    model = load_scene(scene)
    q0 = np.array([0.0, 0.0, 0.0, -0.2, -0.1, 0.3])
    gait = serpenoid_controller(model, amplitude=0.4, frequency=1.5, phase_lag=1.0, kp=3.0,
                                kd=0.1, tau_max=None)
    run = model.simulate(q0, 0.8, tau=gait, dt=1e-3)
    assert run.status == "completed", run.message
    moved = np.hypot(*(run.q_obj[-1, 0, :2] - run.q_obj[0, 0, :2]))
    assert moved > 1e-3
    worst = 0.0
    for q, qo in zip(run.q, run.q_obj):
        corners = _box_corners(qo[0], box.size)
        for a, b in link_segments(robot, q):
            worst = max(worst, scene.radius - _segment_box_distance(a, b, corners))
    assert worst <= run.tolerance * (1 + 1e-6)
    _laws(run)


def test_the_records_figures_against_numpy_and_the_reference_rows():
    """Every sample of two runs (a box pushed on Coulomb ground; the pegs row, with impacts):
    the engine's step (scene_step.c) keeps the figures, here recomputed apart: the kinetic
    energy 1/2 V^T M V with the generated mass matrix and the objects' inertia, the torques'
    work h tau . v+ per step (steps without an impact), the contacts' count and smallest gap
    as the reference rows (tests/scenes_rows_reference.py) find them at the sample's state
    with the run's tolerance."""
    from scenes_rows_reference import rows_of

    robot = snakecg.Robot(joints=3)
    box = SceneObject(shape="box", size=(0.1, 0.06), mass=0.5, mu=0.2,
                      touching={"link": 2, "offset": 0.09, "side": "left"})
    pushing = GeneralScene(robot, radius=0.01, ground=Ground(model="coulomb", mu=0.3),
                           objects=(box,))
    q_pegs = np.zeros(13)
    q_pegs[3:] = 0.5 * np.sin(np.arange(10) * 2 * np.pi / 5)
    touching = impacts = 0
    for scene, q0 in ((pushing, np.array([0.0, 0.0, 0.0, -0.2, -0.1, 0.3])),
                      (read_scene(PEGS_ROW), q_pegs)):
        model = load_scene(scene)
        gait = serpenoid_controller(model, amplitude=0.4, frequency=1.5, phase_lag=1.0,
                                    kp=3.0, kd=0.1, tau_max=None)
        run = model.simulate(q0, 0.3, tau=gait, dt=1e-3)
        assert run.status == "completed", run.message
        impacts += len(run.events)
        for k in range(len(run.t)):
            q, v, qo, vo = run.q[k], run.v[k], run.q_obj[k], run.v_obj[k]
            ke = 0.5 * v @ model.mass_matrix(q) @ v + 0.5 * sum(
                w @ np.diag([o.mass, o.mass, o.plate_inertia]) @ w
                for w, o in zip(vo, scene.objects))
            assert run.kinetic_energy[k] == pytest.approx(ke, rel=1e-12, abs=1e-15)
            rows, _ = rows_of(scene, model.masses, model.link_poses(q),
                              model.link_jacobians(q), obj_poses=qo, tol=run.tolerance)
            assert run.n_contacts[k] == len(rows.contacts)
            want = min((c.gap for c in rows.contacts), default=np.inf)
            assert run.min_gap[k] == pytest.approx(want, abs=1e-15)
            touching += len(rows.contacts) > 0
            if k and run.impact_loss[k] == run.impact_loss[k - 1]:
                work = (run.t[k] - run.t[k - 1]) * run.tau[k] @ v[3:]
                assert run.work_tau[k] - run.work_tau[k - 1] == pytest.approx(
                    work, rel=1e-9, abs=1e-15)
    assert touching >= 100 and impacts >= 1


def test_a_fast_spin_gains_beyond_the_budget_by_the_schemes_error_only():
    """A 1-joint snake spun up by a large torque (80 J in 0.25 s): the step takes the inertia
    and the bias forces at its start, so the kinetic energy gained may exceed the torques'
    work less the dissipation; the excess is the scheme's error, which shrinks at least by
    half with every halved step (the energy balance, a physical law, in the limit)."""
    robot = snakecg.Robot(joints=1, mass=(0.517, 1.235), length=(0.146, 0.133),
                          inertia=(0.00135, 0.00209))
    scene = GeneralScene(robot, radius=0.015, ground=(
        Ground(model="anisotropic", mu_forward=0.39, mu_backward=0.05, mu_lateral=0.3),
        Ground(model="coulomb", mu=0.5)))
    model = load_scene(scene)
    q0 = np.array([0.371, 1.034, 0.651, -0.578])
    excess = []
    for dt in (1e-3, 5e-4, 2.5e-4):
        run = model.simulate(q0, 0.25, tau=np.array([-3.06]), dt=dt)
        assert run.status == "completed", run.message
        gain = run.kinetic_energy - run.kinetic_energy[0]
        budget = run.work_tau - run.friction_dissipation - run.impact_loss + run.contact_work
        excess.append(float(np.max(gain - budget)))
        assert excess[-1] <= 0.01 * run.work_tau[-1]
    assert excess[0] > 1e-3  # the effect is there at 1 ms
    assert excess[1] <= 0.5 * excess[0] and excess[2] <= 0.5 * excess[1]


def test_a_long_run_reports_progress(monkeypatch):
    import snakecg.scenes.stepping as stepping

    monkeypatch.setattr(stepping, "PROGRESS_EVERY", 0.0)
    monkeypatch.setattr(stepping, "PAUSE_STEPS", 1)  # the engine's loop returns every step
    model = load_scene(GeneralScene(snakecg.Robot(joints=2), ground=Ground(model="coulomb")))
    lines = []
    run = model.simulate(np.zeros(5), 0.01, tau=np.array([0.1, 0.0]), progress=lines.append)
    assert run.status == "completed" and len(lines) == 9  # at the pauses before steps 2..10
    assert lines[-1] == "simulate: t = 0.009 s of 0.01 s, 9 steps, 0 impacts"
