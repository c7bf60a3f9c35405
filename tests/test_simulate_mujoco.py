"""The simulation against MuJoCo on matched scenes (``mujoco_scene.py``: capsule links, a box
or a point object, frictionless contacts, planar joints), and a far object's point crossing
the contact link's line beyond its ends (no event; found while comparing).

What MuJoCo differs in, and so what the margins allow for:

* its contacts are soft: a held contact sits a little inside (about
  ``(1 - d)/d * a_0 * (2 timestep)^2``, ``a_0`` the gap's acceleration without the contact:
  here up to 2e-8..4e-8 m at 1e-4 s), which shifts the object against the snake by that
  much;
* an impact is not an instant: the contact spring-damper (time constant ``2 timestep``)
  stops the closing speed over a few steps and, underdamped or critically damped, gives a
  little back when it lets go (a critically damped contact returns about e^-2 of the
  speed); an overdamped one (``dampratio`` 4) is plastic to 1e-9 m here;
* its integrator (RK4) has an error of order ``timestep^4``, below the softness at the steps
  used.

Each margin is about ten times the agreement measured, and far below what a real error makes:
a mass or inertia wrong by 1 %, a torque on the wrong joint or a lost impact move the object
or the COM by 1e-5..1e-3 m over these runs.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

import snakecg
from snakecg.geometry import contact_tolerance
from snakecg.simulate import serpenoid_controller

W_DEG = [30.0, 40.0, 40.0, 30.0]  # a symmetric W pushing with its middle link
W_TAU = np.array([0.05, 0.02, 0.02, 0.05])


@pytest.fixture(scope="module")
def w_model():
    scene = snakecg.Scene(snakecg.Robot(joints=4), scenario="frictionless", kappa=10.0,
                          contact_link=3)
    return snakecg.load(scene)


def _mujoco(scene, **options):
    pytest.importorskip("mujoco", reason="MuJoCo is a test extra: pip install mujoco")
    from mujoco_scene import matched_scene

    return matched_scene(scene, **options)


def _at(traj, times):
    """The index of the last sample of ``traj`` at each of ``times`` (an event repeats a
    time: the state after it)."""
    idx = np.searchsorted(traj.t, np.asarray(times) + 1e-12, side="right") - 1
    assert np.allclose(traj.t[idx], times, rtol=0, atol=1e-12)
    return idx


def _differences(traj, idx, ref):
    return {"object": np.abs(ref["q_obj"][:, :2] - traj.q_obj[idx, :2]).max(),
            "psi": np.abs(ref["q_obj"][:, 2] - traj.q_obj[idx, 2]).max(),
            "com": np.abs(ref["com"] - traj.com[idx]).max(),
            "base": np.abs(ref["q"][:, :3] - traj.q[idx, :3]).max(),
            "joints": np.abs(ref["q"][:, 3:] - traj.q[idx, 3:]).max()}


def test_push_matches_mujoco(w_model):
    """(a) A 1 s push with constant torques, frictionless ground: the W's middle link pushes
    the plate along its normal (the link keeps its direction against the face, so nothing
    enters the plate: ``completed``), the contact separates at 0.52 s and the object coasts.
    MuJoCo: the plate as a box every link may touch, RK4 at 1e-4 s, critically damped
    contact. Measured: object 8e-9 m (of 32 mm moved), angle 1.5e-8 rad, snake COM 1.8e-8 m,
    link 1 3e-7 (m, rad),
    joints 9e-7 rad; MuJoCo's deepest contact 4e-8 m, below snakecg's tolerance."""
    q0 = np.r_[0.0, 0.0, 0.0, np.deg2rad(W_DEG)]
    traj = w_model.simulate(q0, W_TAU, 1.0, output_dt=0.01)
    assert traj.summary["status"] == "completed"
    assert [e.kind for e in traj.events] == ["separation"]
    t_sep = traj.events[0].t
    assert 0.5 < t_sep < 0.55 and traj.s.min() > 0.0 and traj.s.max() < 0.15

    mj = _mujoco(w_model.scene, timestep=1e-4, integrator="RK4")
    q_obj0, _, _ = w_model.place_object(q0)
    mj.set_state(q0, q_obj=q_obj0)
    times = np.round(np.arange(0.0, 1.0 + 1e-9, 0.01), 12)
    ref = mj.run(W_TAU, 1.0, times)
    d = _differences(traj, _at(traj, times), ref)
    moved = np.hypot(*(traj.q_obj[-1, :2] - traj.q_obj[0, :2]))
    assert moved > 0.03
    assert d["object"] < 1e-7 and d["com"] < 2e-7, d
    assert d["psi"] < 2e-7 and d["base"] < 3e-6 and d["joints"] < 1e-5, d
    assert ref["max_depth"] < contact_tolerance(w_model.robot)
    # after the separation MuJoCo's contact is gone too: the object coasts at the same speed
    assert mj.data.ncon == 0
    assert np.abs(ref["v_obj"][-1] - traj.v_obj[-1]).max() < 1e-7


def test_paper_push_model_matches_mujocos_point_contact():
    """(a, today's model) The paper's push at 3 joints (bent 30, -35, 25 degrees, contact
    link 1, frictionless, kappa = 10, a torque on the input ellipsoid) turns the contact link
    against the plate, which it enters within 2 ms: snakecg's model keeps the contact point
    fixed in the object (``geometry_check="report"`` integrates it on). MuJoCo's
    ``"point"`` object is that model: a point (a 1e-6 m sphere) fixed in the object against
    the contact link's capsule. RK4 at 2e-4 s: measured object 8e-9 m (of 5.7 mm moved),
    COM 2e-8 m, the object's angle 2e-6 rad and link 1's 5e-6 rad (the soft contact's
    7e-8 m depth, 0.05 m from the object's COM), MuJoCo's deepest contact 7e-8 m.
    MuJoCo's box instead, the physical plate, turns on its edge: the object ends 1.2 mm and
    the COM 2.9 mm away from the model's (docs/explanation/simulation-vs-mujoco.md)."""
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="frictionless", kappa=10.0)
    model = snakecg.load(scene)
    q0 = np.r_[0.0, 0.0, 0.0, np.deg2rad([30.0, -35.0, 25.0])]
    direction = np.array([1.0, 0.0, -0.4])
    tau = direction / np.sqrt(direction @ model.maps(q0)["input_metric"] @ direction)
    if not model.forward(q0, tau).contact:
        tau = -tau
    traj = model.simulate(q0, tau, 0.5, output_dt=0.01, geometry_check="report")
    assert traj.violation is not None and traj.violation.t < 2e-3
    assert traj.contact.all() and traj.t[-1] == 0.5
    q_obj0, rho, _ = model.place_object(q0)
    times = np.round(np.arange(0.0, 0.5 + 1e-9, 0.01), 12)
    mj = _mujoco(scene, timestep=2e-4, integrator="RK4", object_geometry="point", rho=rho,
                 link_radius=1e-6)
    mj.set_state(q0, q_obj=q_obj0)
    ref = mj.run(tau, 0.5, times)
    d = _differences(traj, _at(traj, times), ref)
    assert np.hypot(*(traj.q_obj[-1, :2] - q_obj0[:2])) > 5e-3
    assert d["object"] < 1e-7 and d["com"] < 2e-7 and d["psi"] < 2e-5, d
    assert d["base"] < 5e-5 and d["joints"] < 5e-5, d
    assert ref["max_depth"] < contact_tolerance(scene.robot)


def test_serpenoid_matches_mujoco(w_model):
    """(b) A serpenoid gait tracked by the PD law on frictionless ground, the object 2 m
    away (never touched), 1.5 s, the law held over 1 ms in both (zero-order hold: snakecg's
    ``control_period``, MuJoCo's ``qfrc_applied`` set every ten steps). Without ground forces
    the COM keeps its initial velocity (momentum) and the body spins and wriggles about it. MuJoCo:
    RK4 at 1e-4 s, no contact at all, so only its integration error is left: measured 1e-13
    rad on the joints and the base, 7e-12 m on the COM.

    Before the fix this run stopped at 0.67 s ("no progress between events"): the object's
    contact point crossed the contact link's line far beyond the link's end, the event fired
    and, changing nothing, fired again at once."""
    model = w_model
    ctl = serpenoid_controller(model, amplitude=0.6, frequency=1.0, phase_lag=-0.9, kp=2.0,
                               kd=0.2)
    q0 = np.r_[0.0, 0.0, 0.0, ctl.curve.angles(0.0)]
    v0 = np.r_[0.0, 0.0, 0.0, ctl.curve.rates(0.0)]
    far = np.array([0.0, 2.0, 0.0])
    T = 1.5
    traj = model.simulate(q0, ctl, T, v0=v0, q_obj0=far, rho=[0.0, -0.05], output_dt=0.01,
                          control_period=1e-3)
    assert traj.summary["status"] == "completed" and abs(traj.t[-1] - T) < 1e-12
    assert np.abs(traj.q_obj - far).max() == 0.0

    mj = _mujoco(model.scene, timestep=1e-4, integrator="RK4")
    mj.set_state(q0, v0, q_obj=far)
    times = np.round(np.arange(0.0, T + 1e-9, 0.01), 12)
    ref = mj.run(lambda t, q, v: ctl(t, SimpleNamespace(q=q, v=v)), T, times,
                 control_period=1e-3)
    d = _differences(traj, _at(traj, times), ref)
    assert np.ptp(traj.q[:, 3:], axis=0).min() > 1.0  # the joints swing through 1 rad or more
    assert d["joints"] < 1e-9 and d["base"] < 1e-9 and d["com"] < 1e-9, d
    line = traj.com[0] + np.outer(traj.t / T, traj.com[-1] - traj.com[0])
    assert np.abs(traj.com - line).max() < 1e-9  # momentum: the COM moves uniformly
    assert np.abs(ref["q_obj"] - far).max() == 0.0


def test_impact_matches_mujoco(w_model):
    """(c) A plastic impact: the W moves towards the plate at 0.05 m/s from 2 mm away while
    pushing with constant torques; snakecg's ``impact`` event at 35 ms removes the normal
    closing speed (momentum kept, energy lost), then the push goes on and separates at
    0.54 s. MuJoCo: the box's stiff contact, overdamped (``dampratio`` 4: a critically damped
    contact gives back part of the closing speed and leaves the object 1e-5 m ahead), RK4 at
    1e-5 s. Measured: object 8e-9 m (of 43 mm moved), COM 1e-8 m, joints 9e-7 rad, the
    object's final velocity 3e-9 m/s. MuJoCo's contact goes 5.4e-7 m deep while it stops the
    closing speed (of the order of the speed times the time constant): deeper than
    snakecg's tolerance, which MuJoCo meets only with a step ten times shorter."""
    model = w_model
    q0 = np.r_[0.0, 0.0, 0.0, np.deg2rad(W_DEG)]
    q_obj, rho, _ = model.place_object(q0)
    phi = model.link_poses(q0)[2, 2]
    normal = np.array([-np.sin(phi), np.cos(phi)])  # the contact normal, towards the plate
    q_obj0 = q_obj + np.r_[0.002 * normal, 0.0]
    v0 = np.r_[0.05 * normal, 0.0, np.zeros(4)]
    T = 1.0
    traj = model.simulate(q0, W_TAU, T, v0=v0, q_obj0=q_obj0, rho=rho, output_dt=0.01)
    assert traj.summary["status"] == "completed"
    assert [e.kind for e in traj.events] == ["impact", "separation"]
    impact = traj.events[0]
    assert 0.03 < impact.t < 0.04 and impact.data["energy_loss"] > 1e-3

    mj = _mujoco(model.scene, timestep=1e-5, integrator="RK4", dampratio=4.0)
    mj.set_state(q0, v0, q_obj=q_obj0)
    times = np.round(np.arange(0.0, T + 1e-9, 0.01), 12)
    ref = mj.run(W_TAU, T, times)
    d = _differences(traj, _at(traj, times), ref)
    assert np.hypot(*(traj.q_obj[-1, :2] - q_obj0[:2])) > 0.04
    assert d["object"] < 1e-7 and d["com"] < 1e-7, d
    assert d["psi"] < 1e-7 and d["joints"] < 1e-5, d
    assert np.abs(ref["v_obj"][-1] - traj.v_obj[-1]).max() < 5e-8
    assert ref["max_depth"] < 2e-6  # soft: see the docstring


@pytest.mark.parametrize("integrator", ["auto", "scipy"])
def test_far_object_crossing_the_link_line_is_no_event(integrator):
    """A straight snake spinning rigidly about its COM (no torque) with the object 2 m away:
    the contact link's line sweeps over the object's contact point twice a turn, beyond the
    link's end, which is no contact. Reference: the rigid rotation (link 1's COM turns about
    the snake's COM, the joints stay straight). Before the fix the first crossing stopped
    the run ("no progress between events"), in the C run and in Python's loop alike."""
    scene = snakecg.Scene(snakecg.Robot(joints=2), scenario="frictionless", kappa=10.0,
                          contact_link=2)
    model = snakecg.load(scene)
    omega = 2.0 * np.pi  # one turn a second
    r1 = -0.15  # link 1's COM from the snake's COM (links at 0, 0.15, 0.3 along x)
    q0 = np.zeros(5)
    v0 = np.array([0.0, omega * r1, omega, 0.0, 0.0])
    traj = model.simulate(q0, np.zeros(2), 1.2, v0=v0, q_obj0=[0.15, 2.0, 0.0],
                          rho=[0.0, -0.05], integrator=integrator, output_dt=0.01)
    assert traj.summary["status"] == "completed" and traj.t[-1] == 1.2
    a = omega * traj.t
    expected = np.c_[0.15 + r1 * np.cos(a), r1 * np.sin(a), a]
    assert np.abs(traj.q[:, :3] - expected).max() < 1e-8
    assert np.abs(traj.q[:, 3:]).max() < 1e-8
    assert traj.summary["integrator"]["compiled_segments"] == (integrator == "auto")
