"""From the samples of a run to a :class:`~snakecg.simulate.Trajectory`: forces, metrics and
energy at every sample, the displacement-based slippage ratio, the geometry for drawing, and
the JSON-ready summary (schema :data:`~snakecg.simulate.records.SCHEMA`)."""

from __future__ import annotations

import numpy as np

from .records import SCHEMA, Trajectory, jsonable

__all__ = ["assemble", "summary"]


def assemble(sim, samples, events, status) -> Trajectory:
    """The trajectory of the run ``sim`` (a :class:`~snakecg.simulate.simulator.Simulator`)
    from its ``samples`` ``(t, y, mode, tau_fn, impact_loss)``, every quantity evaluated again
    at each sample in the sample's mode."""
    model, dyn = sim.model, sim.dyn
    N = len(samples)
    ns, na, nc, nl, nx = dyn.ns, dyn.na, dyn.nc, dyn.nl, dyn.nx
    t = np.array([s[0] for s in samples])
    Y = np.array([s[1] for s in samples])
    tau = np.zeros((N, na))
    lam = np.zeros((N, nc))
    qdd = np.zeros((N, ns))
    a_obj = np.zeros((N, 3))
    sr = np.zeros(N)
    nao = np.zeros(N)
    nqdd = np.zeros(N)
    gap = np.zeros(N)
    s_ = np.zeros(N)
    AVs = np.zeros((N, nc))
    p_tau = np.zeros(N)
    p_fric = np.zeros(N)
    p_cons = np.zeros(N)
    contact = np.zeros(N, dtype=bool)
    wheel_state = np.empty((N, nl), dtype="<U6")
    impact = np.array([s[4] for s in samples])
    for start, end, mode, tau_fn in _runs(samples):
        done = np.zeros(end - start, dtype=bool)
        if sim.compiled is not None:
            # one compiled call for the run of samples (the torque is constant over it)
            taui = np.asarray(tau_fn(t[start], Y[start], mode), dtype=float)
            r = sim.compiled.samples(Y[start:end], mode, taui)
            dyn.nfev += end - start
            done = r["ok"]
            sl = slice(start, end)
            tau[sl], lam[sl], gap[sl], s_[sl], AVs[sl] = taui, r["lam"], r["gap"], r["s"], r["AV"]
            qdd[sl], a_obj[sl] = r["ydot"][:, nx:nx + ns], r["ydot"][:, nx + ns:2 * nx]
            sr[sl], nao[sl], nqdd[sl] = r["sr"], r["norm_a_obj"], r["norm_qdd"]
            p_tau[sl], p_fric[sl] = r["ydot"][:, 2 * nx], r["ydot"][:, 2 * nx + 1]
        for i in start + np.flatnonzero(~done):
            ydot, li, gi, si, AV, (taui, sri, nai, nqi) = dyn.rates(t[i], Y[i], mode, tau_fn)
            tau[i], lam[i], gap[i], s_[i], AVs[i] = taui, li, gi, si, AV
            qdd[i] = ydot[nx:nx + ns]
            a_obj[i] = ydot[nx + ns:2 * nx]
            sr[i], nao[i], nqdd[i] = sri, nai, nqi
            p_tau[i], p_fric[i] = ydot[2 * nx], ydot[2 * nx + 1]
        # power of the held rows' forces: zero on the constraints (a drift diagnostic; not
        # integrated: off the constraints, at the integrator's stages, it is noise)
        F = mode.free_idx
        if F.size:
            p_cons[start:end] = np.einsum("ij,ij->i", lam[start:end, F], AVs[start:end, F])
        contact[start:end] = mode.contact_held
        wheel_state[start:end] = mode.wheel_names
    q, q_obj = Y[:, :ns], Y[:, ns:nx]
    v, v_obj = Y[:, nx:nx + ns], Y[:, nx + ns:2 * nx]
    W = Y[:, 2 * nx:]
    M = model.mass_matrix(q)
    ke = 0.5 * np.einsum("ni,nij,nj->n", v, M, v) + 0.5 * (v_obj**2 @ dyn.mo)
    com = model.com(q)
    poses = model.link_poses(q)
    # displacement-based slippage ratio (metric of the initial configuration)
    M0 = dyn.mass_matrix(sim.settings.q0)
    dq = q - q[0]
    do = q_obj - q_obj[0]
    num = np.einsum("ni,i,ni->n", do, dyn.mo, do)
    den = num + np.einsum("ni,ij,nj->n", dq, M0, dq)
    with np.errstate(invalid="ignore", divide="ignore"):
        sr_d = np.where(den > 0, num / np.where(den > 0, den, 1.0), np.nan)
    loss = impact  # cumulative kinetic energy removed by impacts / projections
    residual = (ke - sim.ke_initial) - (W[:, 0] + W[:, 1] + W[:, 2] - loss)
    scene = dyn.scene
    geometry = {
        "length": np.asarray(scene.robot.length, float),
        "com": np.asarray(scene.robot.com, float),
        "wheel_offset": dyn.woff.copy(),
        "wheel_links": np.flatnonzero(dyn.present[1:]) + 1,
        "contact_link": dyn.k + 1,
        "side": dyn.sigma,
        "object_distance": float(scene.object_distance),
        "wheel_bounds": dyn.bounds[1:].copy(),
    }
    traj = Trajectory(
        t=t, q=q, v=v, q_obj=q_obj, v_obj=v_obj, rho=dyn.rho.copy(), tau=tau, lam=lam,
        qdd=qdd, a_obj=a_obj, contact=contact, wheel_state=wheel_state, sr=sr,
        norm_a_obj=nao, norm_qdd=nqdd, sr_displacement=sr_d, com=com, link_poses=poses,
        gap=gap, s=s_, row_velocity=AVs, kinetic_energy=ke, power_tau=p_tau,
        power_friction=p_fric, work_tau=W[:, 0].copy(), work_friction=W[:, 1].copy(),
        work_object=W[:, 2].copy(), power_constraint=p_cons, impact_loss=loss,
        energy_residual=residual, events=events, summary={}, geometry=geometry)
    traj.summary = summary(sim, traj, status)
    return traj


def _runs(samples):
    """``(start, end, mode, tau_fn)`` of each run of consecutive samples that share their
    mode and torque function."""
    start = 0
    while start < len(samples):
        mode, tau_fn = samples[start][2], samples[start][3]
        end = start + 1
        while end < len(samples) and samples[end][2] is mode and samples[end][3] is tau_fn:
            end += 1
        yield start, end, mode, tau_fn
        start = end


def summary(sim, tr: Trajectory, status: str) -> dict:
    """The JSON-ready summary of the trajectory ``tr`` of the run ``sim`` (docs/simulate.md)."""
    cfg, dyn = sim.settings, sim.dyn
    sc = dyn.scene
    t = tr.t
    dt = np.diff(t)
    span = max(t[-1] - t[0], 1e-300)
    held = tr.contact
    # time fractions from the piecewise-constant flags of each interval
    held_frac = float(np.sum(dt * held[:-1]) / span) if dt.size else float(held[0])
    sliding = np.isin(tr.wheel_state, ("slide+", "slide-"))
    slide_frac = (np.sum(dt[:, None] * sliding[:-1], axis=0) / span).tolist() \
        if dt.size else sliding[0].astype(float).tolist()
    sr_mean = float(np.sum(0.5 * dt * (tr.sr[1:] + tr.sr[:-1])) / span) if dt.size \
        else float(tr.sr[0])
    first_lost = next((e.t for e in tr.events if e.kind in ("separation", "off_link")),
                      None)
    counts: dict[str, int] = {}
    for e in tr.events:
        counts[e.kind] = counts.get(e.kind, 0) + 1
    held_rows = np.zeros_like(tr.row_velocity, dtype=bool)
    held_rows[:, 0] = held
    held_rows[:, 1:] = tr.wheel_state == "stick"
    gap_res = float(np.abs(tr.gap[held]).max()) if held.any() else 0.0
    gdot_res = float(np.abs(tr.row_velocity[held, 0]).max()) if held.any() else 0.0
    wheel_rows = held_rows[:, 1:]
    u_res = float(np.abs(tr.row_velocity[:, 1:][wheel_rows]).max()) if wheel_rows.any() \
        else 0.0
    do = tr.q_obj[-1] - tr.q_obj[0]
    dc = tr.com[-1] - tr.com[0]
    ke0, ke1 = float(sim.ke_initial), float(tr.kinetic_energy[-1])
    return jsonable({
        "schema": SCHEMA,
        "status": status,
        "joints": sc.robot.joints,
        "scenario": sc.scenario,
        "kappa": sc.kappa,
        "mu": sc.mu,
        "duration": cfg.duration,
        "torque": cfg.kind + ("" if cfg.control_period is None
                              else f" (held over {cfg.control_period:g} s)"),
        "initial_mode": sim.initial_mode,
        "final_mode": sim.final_mode,
        "object_displacement": {"x": do[0], "y": do[1], "psi": do[2],
                                "distance": float(np.hypot(do[0], do[1]))},
        "snake_com_displacement": {"x": dc[0], "y": dc[1],
                                   "distance": float(np.hypot(dc[0], dc[1]))},
        "sr_initial": tr.sr[0],
        "sr_mean": sr_mean,
        "sr_displacement_final": tr.sr_displacement[-1],
        "contact": {"held_fraction": held_frac, "first_lost_at": first_lost,
                    "held_at_end": bool(held[-1])},
        "wheels": {"slide_fraction": slide_frac},
        "event_counts": counts,
        "events": [e.to_dict() for e in tr.events[:200]],
        "energy": {
            "kinetic_initial": ke0, "kinetic_final": ke1,
            "work_tau": tr.work_tau[-1], "work_friction": tr.work_friction[-1],
            "work_object": tr.work_object[-1],
            "impact_loss": tr.impact_loss[-1], "balance_residual": tr.energy_residual[-1],
        },
        "constraint_residual": {"gap": gap_res, "gap_rate": gdot_res,
                                "wheel_lateral_velocity": u_res,
                                "constraint_power": float(np.abs(tr.power_constraint).max()),
                                "velocity_projected_at_events": sim.events.drift_corrected},
        "integrator": {
            "method": cfg.method if cfg.fixed_step is None
            else f"{cfg.method}, fixed step {cfg.fixed_step:g} s",
            "rtol": None if cfg.fixed_step is not None else cfg.rtol,
            "atol": None if cfg.fixed_step is not None else cfg.atol,
            "stabilization": cfg.alpha, "segments": sim.segments,
            "rhs_evaluations": dyn.nfev, "singular_samples": dyn.singular,
            "compiled_segments": sim.compiled is not None,
            "segment_cpu_s": sim.segment_cpu,
            "wall_time_s": sim.wall,
        },
    })
