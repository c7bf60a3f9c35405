"""Three edges of `optimize_shape` found by attacking it with random queries, each checked
against references apart from its NLP: an orientation test of the links' segments, the exact
per-shape optimum of `extremes` at perturbed shapes, and `optimize` at fixed shapes."""
from __future__ import annotations

import numpy as np

import snakecg


def _segments(robot, q):
    """The links' end points from the planar chain (base pose, then joint angles), written
    apart from snakecg.geometry."""
    L, com = np.asarray(robot.length, float), np.asarray(robot.com, float)
    th = q[2]
    rear = np.asarray(q[:2], float) - com[0] * np.array([np.cos(th), np.sin(th)])
    out = []
    for i in range(len(L)):
        th = th + (q[2 + i] if i > 0 else 0.0)
        front = rear + L[i] * np.array([np.cos(th), np.sin(th)])
        out.append((rear, front))
        rear = front
    return out


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _crossing_pairs(robot, q):
    """Non-adjacent links whose segments cross (strict orientation test)."""
    s = _segments(robot, q)
    out = []
    for i in range(len(s)):
        for j in range(i + 2, len(s)):
            (p1, p2), (p3, p4) = s[i], s[j]
            if (_cross(p3, p4, p1) * _cross(p3, p4, p2) < 0
                    and _cross(p1, p2, p3) * _cross(p1, p2, p4) < 0):
                out.append((i + 1, j + 1))
    return out


def test_a_clearance_of_zero_still_keeps_links_from_crossing():
    """clearance=0 counted crossing links as feasible (they are 0 apart, and the test was
    distance < clearance): max_a_obj with joint limits of +-pi came back `optimal` at a shape
    whose links 1-3, 1-4 and 2-4 cross. Links that meet are now refused at any clearance: the
    answer crosses nowhere, and a crossing shape is infeasible at clearance 0."""
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="frictionless",
                                       contact_link=2))
    res = model.optimize_shape("max_a_obj", clearance=0.0, joint_limits=(-np.pi, np.pi))
    assert res.status == "optimal", res.reason
    assert _crossing_pairs(model.robot, res.q) == []
    crossed = np.r_[0.0, 0.0, 0.0, np.deg2rad([-172.993, -120.03, -120.552])]
    assert _crossing_pairs(model.robot, crossed) != []
    assert not snakecg.geometry.feasibility(model, crossed, clearance=0.0).feasible


def test_the_sliding_wheel_search_runs_to_its_step_or_says_so():
    """The search over sliding wheel states stopped at a cap of 200 rounds with its step at
    0.0125 rad and reported `optimal` at ||a_obj||^2 = 0.17668, where a move of that
    step still did better. It now lengthens a joint's step where its move improves, and
    reaches 1e-7 rad (else the status says it did not). No move of 0.0125 or 1e-3 rad of a
    joint, scored by the exact per-shape extremes and kept apart from the links, beats it."""
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=1.0,
                                       mu=0.02, contact_link=4, side="right"))
    res = model.optimize_shape("max_a_obj", clearance=0.03)
    assert res.value > 0.1778, res.value
    rec = res.certificate["sliding_search"]
    assert res.status == "optimal" and rec["converged"] and rec["step"] <= 1e-7, (res, rec)
    lo, hi = -0.75 * np.pi, 0.75 * np.pi
    for step in (0.0125, 1e-3):
        for j in range(3):
            for sgn in (1.0, -1.0):
                q = res.q.copy()
                q[3 + j] = np.clip(q[3 + j] + sgn * step, lo, hi)
                segs = _segments(model.robot, q)
                if _crossing_pairs(model.robot, q):
                    continue
                d = min(np.min(np.linalg.norm(
                    np.linspace(*segs[a], 200)[:, None] - np.linspace(*segs[b], 200)[None],
                    axis=-1)) for a in range(4) for b in range(a + 2, 4))
                if d < 0.03 + 1e-3:  # (near the clearance: the geometry decides there)
                    continue
                ex = model.extremes(q[None], exact=True)
                if bool(ex.certified[0]):
                    assert ex.max["norm_a_obj"][0] <= res.value * (1 + 1e-9), (step, j, sgn)


def test_max_sr_with_wheels_of_a_heavy_object():
    """At kappa 1e4 (2 joints, wheels) the NLP's regularisation of Xi (1e-9 of the traces)
    biased sr by 6e-6, more than the differences between shapes: the answer failed its
    check, and the coarse grid preferred a folded shape. With 1e-12 the answer is the
    straight shape, `optimal`, and its sr is at least the exact per-configuration optimum
    (`optimize`) at that folded shape and at the straight one."""
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels", kappa=1e4))
    res = model.optimize_shape("max_sr")
    assert res.status == "optimal", res.reason
    assert abs(res.certificate["regularization_gap"]) <= 1e-7
    for angles in ([0.0, 0.0], [-117.8181, -117.8181]):
        q = np.r_[0.0, 0.0, 0.0, np.deg2rad(angles)]
        ref = model.optimize(q, "max_sr")
        assert ref.status == "optimal"
        assert res.value >= float(ref.analysis.sr) - 1e-9, (angles, res.value)
    assert float(model.forward(res.q, res.tau).sr) == res.value


def test_a_push_no_torque_can_make_is_infeasible_for_either_push_objective():
    """Along d = (-0.3, -0.9) no torque of a 1-joint snake pushes its object: least_slip_push
    said `infeasible` and strongest_push `failed` for that one cause. Both say `infeasible`
    now, and the exact torque optimizer at the answer's shape agrees that nothing pushes
    along d there."""
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=1), scenario="frictionless"))
    d = [-0.3, -0.9]
    strong = model.optimize_shape("strongest_push", direction=d)
    least = model.optimize_shape("least_slip_push", direction=d, a_min=1e-3)
    assert (strong.status, least.status) == ("infeasible", "infeasible"), (strong, least)
    assert model.optimize(strong.q, "strongest_push", direction=d).status == "infeasible"


def test_the_answer_lies_within_its_joint_limits():
    """An answer at a joint limit lay 2.8e-12 rad beyond it (IPOPT's rounding at a bound);
    the joint limits always apply, so the answer is now within them exactly."""
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario="ideal_wheels",
                                       kappa=300.0, mu=0.02, contact_link=2, side="right"))
    res = model.optimize_shape("least_slip_push", radius=0.5, feasible=False,
                               direction=[-0.7714077189503415, 0.6363412065423949],
                               a_min=0.0005790880750765692)
    assert res.status == "optimal", res.reason
    lo, hi = np.array(res.limits["joint_limits"]).T
    assert np.all(res.q[3:] >= lo) and np.all(res.q[3:] <= hi), (res.q[3:] - lo, hi - res.q[3:])
    assert float(model.forward(res.q, res.tau).norm_qdd) == res.value
