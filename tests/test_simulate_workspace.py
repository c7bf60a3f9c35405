"""The lean parts of a whole compiled run: the start's contact check and settle inside the
same C call (``core_run``), the model's workspaces (lent to one run at a time, also from
threads) and the trajectory's deferred fields (computed when first read), against
independent references:

* the deferred fields (kinetic energy, COM, link poses, displacement-based slippage ratio,
  energy balance) against the dense numpy model of ``tests/reference.py``, the mode fields
  (contact, wheel states, constraint power) against the Python loop's eager ones; read after
  the samples were changed in place, after later runs reused the workspace, and after a copy
  or a pickle;
* the start in C against the start in Python (the same C settle called from Python, and the
  Python reference path of ``Events.settle``), on starts with impacts and projections, and a
  start impact against ``solve_ivp`` at a tight tolerance;
* runs from several threads at once against the same runs one after the other.
"""

from __future__ import annotations

import copy
import pickle
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest
from reference import Reference

import snakecg
from snakecg.simulate import compiled as compiled_module
from snakecg.simulate import workspace
from snakecg.simulate.events import Events
from snakecg.simulate.simulator import Simulator

Q3 = np.array([0.0, 0.0, 0.0, 0.5, -0.6, 0.4])
DEFERRED = ("kinetic_energy", "com", "link_poses", "sr_displacement", "energy_residual",
            "contact", "wheel_state", "power_constraint", "geometry")


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(scenario):
        if scenario not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=10.0)
            cache[scenario] = (snakecg.load(scene), Reference(scene))
        return cache[scenario]

    return get


def _push(sm, radius):
    """A push on the input ellipsoid at Q3 that keeps the contact at t = 0."""
    direction = np.array([1.0, 0.0, -0.4])
    N = sm.maps(Q3)["input_metric"]
    tau = radius * direction / np.sqrt(direction @ N @ direction)
    return tau if sm.forward(Q3, tau).contact else -tau


def _same(a, b, tol=1e-12):
    """The same samples (to ``tol``), events and arrays."""
    assert [(e.kind, e.row, e.before, e.after) for e in a.events] == \
        [(e.kind, e.row, e.before, e.after) for e in b.events]
    for x, z in zip(a.events, b.events):
        assert abs(x.t - z.t) <= max(tol, 1e-15)
        assert x.data.keys() == z.data.keys()
        for k in x.data:
            assert np.allclose(x.data[k], z.data[k], rtol=tol, atol=1e-15), k
    assert a.t.shape == b.t.shape
    for name, x in a.arrays().items():
        z = getattr(b, name)
        if x.dtype.kind == "f":
            assert np.allclose(x, z, rtol=tol, atol=tol, equal_nan=True), name
        else:
            assert (x == z).all(), name


@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
def test_deferred_fields_against_dense_reference(models, scenario, monkeypatch):
    """The fields computed when first read, from the run's own copy of the samples: the
    kinetic energy ``1/2 V^T I V``, the link poses and the COM, the displacement-based
    slippage ratio in the metric of ``M_s(q0)`` and the energy balance by the dense model;
    the contact flags, wheel states and constraint power as the Python loop gives them."""
    sm, ref = models(scenario)
    rng = np.random.default_rng(4)
    v0 = 0.2 * rng.normal(size=6)
    traj = sm.simulate(Q3, _push(sm, 4.0), 0.3, v0=v0, output_dt=0.02,
                       geometry_check="report")
    assert set(DEFERRED) <= set(traj.__dict__["_deferred"])
    q, v = traj.q.copy(), traj.v.copy()
    q_obj, v_obj = traj.q_obj.copy(), traj.v_obj.copy()
    work = traj.work_tau + traj.work_friction + traj.work_object
    loss = traj.impact_loss.copy()
    traj.q[:] = np.nan  # the deferred fields do not read the returned arrays
    traj.v[:] = np.nan
    traj.impact_loss[:] = np.nan
    mo = np.array([ref.m_obj, ref.m_obj, ref.I_obj_rot])
    ke = np.array([0.5 * vi @ ref.mass_matrix(qi) @ vi + 0.5 * (mo * vo) @ vo
                   for qi, vi, vo in zip(q, v, v_obj)])
    assert np.allclose(traj.kinetic_energy, ke, rtol=1e-12, atol=1e-15)
    poses = np.array([ref.link_poses(qi) for qi in q])
    assert np.abs(traj.link_poses - poses).max() <= 1e-12
    com = np.einsum("nik,i->nk", poses[:, :, :2], ref.mass) / ref.mass.sum()
    assert np.abs(traj.com - com).max() <= 1e-12
    M0 = ref.mass_matrix(Q3)
    dq, do = q - q[0], q_obj - q_obj[0]
    num = np.array([d @ (mo * d) for d in do])
    den = num + np.array([d @ M0 @ d for d in dq])
    assert np.isnan(traj.sr_displacement[0]) and den[0] == 0
    assert np.allclose(traj.sr_displacement[1:], num[1:] / den[1:], rtol=1e-10, atol=1e-15)
    ke0 = 0.5 * v0 @ M0 @ v0
    residual = (ke - ke0) - (work - loss)
    assert np.allclose(traj.energy_residual, residual, rtol=0, atol=1e-12 * max(1.0, ke.max()))
    assert traj.summary["energy"]["kinetic_initial"] == pytest.approx(ke0, rel=1e-12)
    # the mode fields against the Python loop's (eager) ones
    with monkeypatch.context() as m:
        m.setattr(Simulator, "_run_compiled", lambda self, *args: None)
        loop = sm.simulate(Q3, _push(sm, 4.0), 0.3, v0=v0, output_dt=0.02,
                           geometry_check="report")
    assert "_deferred" not in loop.__dict__ or "contact" not in loop.__dict__["_deferred"]
    assert (traj.contact == loop.contact).all()
    assert (traj.wheel_state == loop.wheel_state).all()
    assert np.allclose(traj.power_constraint, loop.power_constraint, rtol=1e-12, atol=1e-15)
    assert traj.geometry["contact_link"] == sm.scene.contact_link
    assert "_deferred" not in traj.__dict__  # all computed by now
    assert len(traj.events) >= 1


def test_deferred_fields_after_other_runs_copies_and_pickles(models):
    """A trajectory read after later runs of the model reused its workspace, a copy and an
    unpickled clone of it: the same fields as a run read at once."""
    sm, _ = models("wheels")
    tau = _push(sm, 4.0)
    a = sm.simulate(Q3, tau, 0.3, output_dt=0.05)
    for r in (1.0, -2.0, 8.0):  # reuse the workspace (and its buffers) in between
        sm.simulate(Q3, _push(sm, r), 0.3, output_dt=0.01)
    clone = pickle.loads(pickle.dumps(a))  # computes the deferred fields first
    assert "_deferred" not in a.__dict__ and "_deferred" not in clone.__dict__
    b = sm.simulate(Q3, tau, 0.3, output_dt=0.05)
    for x in (a, clone, copy.deepcopy(b)):
        for name in DEFERRED[:-1]:
            u, w = getattr(x, name), getattr(b, name)
            assert np.array_equal(u, w, equal_nan=u.dtype.kind == "f"), name
        assert x.geometry.keys() == b.geometry.keys()
        assert all(np.array_equal(x.geometry[k], b.geometry[k]) for k in b.geometry)
        assert x.summary == b.summary or _summary_equal(x.summary, b.summary)


def _summary_equal(s, t):
    drop = ("segment_cpu_s", "wall_time_s")
    s, t = copy.deepcopy(s), copy.deepcopy(t)
    for d in (s, t):
        for k in drop:
            d["integrator"].pop(k)
    return s == t


def test_runs_from_threads_match_sequential_runs(models):
    """Runs of one model from four threads at once (each takes its own workspace from the
    model's pool, more than the pool keeps): the same trajectories as one after the other."""
    sm, _ = models("ideal_wheels")
    rng = np.random.default_rng(8)
    jobs = [(_push(sm, r), 0.1 * rng.normal(size=6)) for r in (1.0, 2.0, 4.0, 8.0) * 3]

    def run(job):
        tr = sm.simulate(Q3, job[0], 0.2, v0=job[1], output_dt=0.02)
        tr.kinetic_energy  # noqa: B018 - deferred fields read in the thread too
        return tr

    sequential = [run(j) for j in jobs]
    with ThreadPoolExecutor(max_workers=6) as pool:
        threaded = list(pool.map(run, jobs))
    for a, b in zip(threaded, sequential):
        _same(a, b, tol=0.0)
    assert len(sm.data().simulation_pool) <= workspace.POOL_SIZE


_SETTLE = Events.settle


def _python_settle(self, *args, **kwargs):
    """``Events.settle`` in Python (the engine of ``backend="casadi"``), not the C's."""
    kernel, self.kernel = self.kernel, None
    try:
        return _SETTLE(self, *args, **kwargs)
    finally:
        self.kernel = kernel


@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
def test_start_in_c_matches_python_start(models, scenario, monkeypatch):
    """The start done inside core_run against the start in Python before a C run (the same
    C settle called from Python) and against the Python loop with the Python reference
    settle (``Events.settle`` without the compiled kernel): the same start records
    (impacts, projections of initial velocities), events and samples (bit for bit, and
    within 1e-10 of the reference settle, whose linear solves round differently)."""
    sm, _ = models(scenario)
    rng = np.random.default_rng(12)
    cases = [(_push(sm, 4.0), {})]
    for _ in range(5):
        cases.append((_push(sm, 2.0), {"v0": 0.3 * rng.normal(size=6),
                                       "v_obj0": 0.3 * rng.normal(size=3)}))
    run_all = compiled_module.CompiledSegments.run_all

    def no_start(self, y, mode, *args):  # core_run with the start: handed back at once
        if mode is None:
            self.started = False
            return None
        return run_all(self, y, mode, *args)

    starts = set()
    for tau, kw in cases:
        a = sm.simulate(Q3, tau, 0.2, output_dt=0.02, **kw)
        with monkeypatch.context() as m:
            m.setattr(compiled_module.CompiledSegments, "run_all", no_start)
            b = sm.simulate(Q3, tau, 0.2, output_dt=0.02, **kw)
        with monkeypatch.context() as m:
            m.setattr(Simulator, "_run_compiled", lambda self, *args: None)
            m.setattr(Events, "settle", _python_settle)
            c = sm.simulate(Q3, tau, 0.2, output_dt=0.02, **kw)
        _same(a, b, tol=0.0)
        _same(a, c, tol=1e-10)  # numpy's LU solves in the Python settle, C's in core_settle
        assert a.summary["initial_mode"] == c.summary["initial_mode"]
        starts |= {e.kind for e in a.events if e.before == "start"}
    assert "impact" in starts
    if scenario == "ideal_wheels":
        assert "projection" in starts


def test_start_impact_against_solve_ivp(models):
    """A run that starts with the object closing on the contact (a plastic impact at t = 0,
    done in C) against solve_ivp at a tight tolerance with the Python event handling: the
    same impact and positions within 1e-9 m at the end."""
    sm, _ = models("ideal_wheels")
    tau = _push(sm, 1.0)
    kw = {"v_obj0": np.array([0.0, -0.2, 0.0]), "output_dt": 0.05}
    a = sm.simulate(Q3, tau, 0.1, rtol=1e-12, atol=1e-14, **kw)
    b = sm.simulate(Q3, tau, 0.1, rtol=1e-12, atol=1e-14, integrator="scipy", **kw)
    assert a.events[0].kind == b.events[0].kind == "impact" and a.events[0].t == 0.0
    assert a.events[0].data["energy_loss"] == pytest.approx(b.events[0].data["energy_loss"],
                                                            rel=1e-12)
    assert np.abs(a.q[-1] - b.q[-1]).max() <= 1e-9
    assert np.abs(a.q_obj[-1] - b.q_obj[-1]).max() <= 1e-9


def test_workspace_pool(models):
    """Two runs alive at once hold two workspaces; a finished run gives its workspace back
    (the pool keeps at most POOL_SIZE, without an output buffer above KEEP_BYTES); the pool
    does not keep the model alive."""
    import gc
    import weakref

    scene = snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels", kappa=10.0)
    sm = snakecg.load(scene)
    q0 = np.array([0.0, 0.0, 0.0, 0.4, -0.3])
    tau = np.array([0.01, -0.005])
    sm.simulate(q0, tau, 0.05)
    pool = sm.data().simulation_pool
    assert len(pool) == 1
    held = [workspace.take(sm) for _ in range(3)]
    assert len(pool) == 0 and len({id(w) for w in held}) == 3
    for w in held * 2:
        workspace.give(sm, w)
    assert len(pool) == workspace.POOL_SIZE
    # a run with many output samples does not leave its large buffer in the pool
    pool.clear()
    sm.simulate(q0, tau, 0.05, output_dt=0.05 / 20000)
    assert len(pool) == 1 and pool[0]._out[0].nbytes <= workspace.KEEP_BYTES
    ref = weakref.ref(sm)
    del sm, pool, held, w
    gc.collect()
    assert ref() is None
