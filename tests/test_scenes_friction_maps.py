"""``maps`` of a general scene with Coulomb friction at its contacts: a frictional contact's
piece (open, stick, slip+ or slip-) keeps every output affine in the torques. Held against

* a dense NumPy solve of the same piece's equations in (a, lam) on rows built apart from the
  engine (``test_scenes_contact_friction.reference_problem``: the geometry reference's rows
  and tangent rows; ``piece_solution``: M a - A^T lam = f, w = 0 on the held and sticking
  rows, the forces fixed on the open ones, lam_t = -mu lam_n sign(w_t) on a slipping one), at
  torques inside and outside the piece;
* ``forward`` (the engine's Coulomb solve) at torques inside the piece (where forward reports
  the same states).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import snakecg
from snakecg.errors import InputError
from snakecg.scenes.solve import BOX, FREE, UNILATERAL

from scenes_reference import POLYHEDRAL, small_scenes
from test_scenes_contact_friction import piece_solution, reference_problem


def _match(res, p):
    """The reference's contact for each of forward's contacts (bodies and point)."""
    out = []
    for c in res.contacts:
        found = [j for j, rc in enumerate(p["contacts"])
                 if c["bodies"][0].split(" (")[0] == f"{rc['bodies'][0][0]} "
                 f"{rc['bodies'][0][1] + 1}" and np.allclose(c["point"], rc["point"], atol=1e-9)]
        out.append(found[0] if len(found) == 1 else None)
    return out


def _words(res):
    """Forward's pieces as maps' state words, one per block (contacts, then the ground)."""
    out = []
    for c in res.contacts:
        fs = c.get("friction_state")
        if fs in (None, "none"):
            out.append(c["state"])
        elif fs == "slip":  # w_t > 0 where the friction along the tangent is negative
            out.append("slip+" if c["friction"] < 0 else "slip-")
        else:
            out.append(fs)
    return out + [g["state"] for g in res.ground]


def _reference_combo(p, res, match, words):
    """The same piece in the reference's blocks and words."""
    by_row = {p["contacts"][j]["row"]: i for i, j in enumerate(match)}
    ground = iter(words[len(res.contacts):])
    combo = []
    for b in p["blocks"]:
        if b["kind"] == UNILATERAL:
            combo.append(words[by_row[b["row"]]])
            continue
        g = next(ground)
        if b["kind"] == FREE:
            combo.append("held")
        elif b["kind"] == BOX and b["p"] > 0:
            combo.append({"stick": "stick", "slide+": "+", "slide-": "-"}[g])
        else:
            combo.append("zero")
    return combo


@pytest.fixture(scope="module")
def samples():
    rng = np.random.default_rng(20261206)
    out = []
    for model0, q, _ in small_scenes(rng, 30, POLYHEDRAL, object_friction=False):
        if len(model0.scene.objects) + len(model0.scene.obstacles) == 0:
            continue
        for _ in range(6):
            mu = float(rng.choice([0.1, 0.3, 0.6, 1.0]))
            model = snakecg.load(dataclasses.replace(model0.scene, mu_contact=mu))
            tau = rng.normal(size=model.n_joints) * float(rng.choice([0.3, 1.0, 3.0]))
            out.append((model, q, tau, rng.normal(size=(3, model.n_joints))))
    return out


def test_maps_of_a_frictional_piece_match_the_dense_solve_and_forward(samples):
    checked = {"stick": 0, "slip": 0, "open": 0, "inside": 0, "singular": 0}
    for model, q, tau, others in samples:
        res = model.forward(q, tau)
        if res.status != 0 or res.dependent == 3:  # (1: Coulomb's forces a family)
            continue
        p = reference_problem(model, q, tau)
        match = _match(res, p)
        if None in match:
            continue
        words = _words(res)
        mp = model.maps(q, state=words)
        ns = model.n_coordinates
        combo = _reference_combo(p, res, match, words)

        def from_maps(t):
            qdd = mp["qdd_from_tau"] @ t + mp["qdd_offset"]
            ao = np.einsum("ojk,k->oj", mp["a_obj_from_tau"], t) + mp["a_obj_offset"]
            lam = mp["lam_from_tau"] @ t + mp["lam_offset"]
            return np.r_[qdd, ao.ravel()], lam

        # at the sample (inside the piece: forward's own answer)
        a, lam = from_maps(tau)
        scale = max(1.0, np.abs(res.qdd).max())
        np.testing.assert_allclose(a[:ns], res.qdd, rtol=0, atol=1e-9 * scale)
        np.testing.assert_allclose(a[ns:], np.ravel(res.a_obj), rtol=0, atol=1e-9 * scale)
        assert mp["singular"] == (res.dependent == 1)
        if mp["singular"]:  # the piece's held rows dependent (a contact sticking at its cone's
            # edge, for example): its forces are not unique, forward's (the family's
            # minimum-norm member) are the maps' plus a combination of the piece's null forces
            rows = [k for k in range(len(res.contacts))]
            rows += [int(r) for r in mp["tangent_rows"][:len(res.contacts)] if r >= 0]
            got = [c["force"] for c in res.contacts]
            got += [c["friction"] for k, c in enumerate(res.contacts)
                    if mp["tangent_rows"][k] >= 0]
            d = np.asarray(got) - lam[rows]
            N = np.asarray(mp["lam_null"])[rows]
            z = np.linalg.lstsq(N, d, rcond=None)[0]
            assert np.abs(N @ z - d).max() <= 1e-8 * max(1.0, np.abs(lam).max()), (d, N)
            checked["singular"] += 1
            continue
        for k, c in enumerate(res.contacts):
            F = max(1.0, np.abs(lam).max())
            assert lam[k] == pytest.approx(c["force"], abs=1e-9 * F)
            if mp.get("tangent_rows") is not None and mp["tangent_rows"][k] >= 0:
                assert lam[mp["tangent_rows"][k]] == pytest.approx(c["friction"], abs=1e-9 * F)
            fs = c.get("friction_state")
            if fs in checked:
                checked[fs] += 1
        # the dense solve of the same piece (reference rows) at torques in and out of it
        for t in (tau, *others):
            x = piece_solution(reference_problem(model, q, t), combo)
            assert x is not None
            a_ref, lam_ref = x
            a, lam = from_maps(t)
            sc = max(1.0, np.abs(a_ref).max())
            np.testing.assert_allclose(a, a_ref, rtol=0, atol=1e-9 * sc)
            F = max(1.0, np.abs(lam_ref).max())
            for k, j in enumerate(match):
                rc = p["contacts"][j]
                assert lam[k] == pytest.approx(lam_ref[rc["row"]], abs=1e-9 * F)
                if rc["tangent"] is not None:
                    assert lam[mp["tangent_rows"][k]] == pytest.approx(lam_ref[rc["tangent"]],
                                                                     abs=1e-9 * F)
        # forward at torques near the sample, where it reports the same piece
        for d in others:
            t = tau + 1e-3 * d
            r2 = model.forward(q, t)
            if r2.status != 0 or len(r2.contacts) != len(res.contacts) or _words(r2) != words:
                continue
            a, _ = from_maps(t)
            np.testing.assert_allclose(a[:ns], r2.qdd, rtol=0,
                                       atol=1e-9 * max(1.0, np.abs(r2.qdd).max()))
            checked["inside"] += 1
    print(checked)
    assert checked["stick"] >= 10 and checked["slip"] >= 10 and checked["inside"] >= 20, checked
    assert checked["singular"] >= 1, checked


def test_maps_name_a_frictional_contact_s_states_and_refuse_held():
    robot = snakecg.Robot(joints=1)
    box = snakecg.scenes.SceneObject(shape="box", size=(0.4, 0.1), mass=2.0,
                                     pose=(1.0, -0.45, 0.0))
    wall = snakecg.scenes.Obstacle(shape="wall", point=(0.0, -0.5), normal=(0.0, 1.0))
    model = snakecg.load(snakecg.scenes.GeneralScene(
        robot, ground=snakecg.scenes.Ground(model="frictionless"), objects=(box,),
        obstacles=(wall,), mu_contact=0.5))
    mp = model.maps(np.zeros(4))  # default: every contact sticking
    assert all(name.endswith("(mu 0.5)") for name in mp["blocks"][:2])
    assert list(mp["tangent_rows"][:2]) == [len(mp["lam_offset"]) - 2,
                                           len(mp["lam_offset"]) - 1]
    nb = len(mp["blocks"])
    with pytest.raises(InputError, match=r"state\[0\] \(contact .* \(mu 0\.5\)\) must be one "
                                         r"of open, stick, slip\+, slip-, got 'held'"):
        model.maps(np.zeros(4), state=["held"] + ["stick"] * 1 + ["none"] * (nb - 2))
    # the box pushed along the wall (3 N) and pressed on it (5 N): both corners slip, and the
    # maps of that piece give a_t = -(f_t - mu f_n) / m (Coulomb's closed form)
    res = model.forward(np.zeros(4), np.zeros(1), f_obj=[[-3.0, -5.0, 0.0]])
    words = _words(res)
    assert [w for w in words[:2]] in (["slip+", "slip+"], ["slip-", "slip-"])
    mp = model.maps(np.zeros(4), state=words)
    a = np.einsum("ojk,k->oj", mp["a_obj_from_f_obj"], [-3.0, -5.0, 0.0]) + mp["a_obj_offset"]
    assert mp["state"][0] == mp["state"][1]
    np.testing.assert_allclose(a[0], [-(3.0 - 2.5) / 2.0, 0.0, 0.0], atol=1e-12)


def test_extremes_and_optimize_without_a_frictional_contact_are_the_frictionless_ones():
    """A rough peg that touches nothing: extremes and optimize take the scene and answer as
    the same scene without friction (they used to refuse contact friction)."""
    robot = snakecg.Robot(joints=2)
    box = snakecg.scenes.SceneObject(shape="box", size=(0.08, 0.06), mass=1.5, touching={
        "link": 1, "offset": 0.075, "side": "left"})
    far = snakecg.scenes.Obstacle(shape="peg", center=(0.0, 5.0), radius=0.1)
    rough, smooth = (snakecg.load(snakecg.scenes.GeneralScene(
        robot, objects=(box,), obstacles=(dataclasses.replace(far, mu_contact=mu),)))
        for mu in (0.4, None))
    q = np.zeros(5)
    e1, e0 = rough.extremes(q), smooth.extremes(q)
    assert e1.method == e0.method and e1.certified and e0.certified
    for m in e0.max:
        assert e1.max[m] == pytest.approx(e0.max[m], abs=1e-12)
        assert e1.min[m] == pytest.approx(e0.min[m], abs=1e-12)
        assert e1.solutions["max"][m] == 1
    o1, o0 = rough.optimize(q, "max_sr"), smooth.optimize(q, "max_sr")
    assert o1.status == o0.status == "optimal"
    assert o1.objective_value == pytest.approx(o0.objective_value, abs=1e-12)
    assert o1.uniqueness == "unique" and o0.uniqueness is None
