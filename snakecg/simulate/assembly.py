"""From the samples of a run to a :class:`~snakecg.simulate.Trajectory`: forces, metrics and
energy at every sample, the displacement-based slippage ratio, the geometry for drawing, and
the JSON-ready summary (schema :data:`~snakecg.simulate.records.SCHEMA`)."""

from __future__ import annotations

from functools import partial

import numpy as np

from .. import kernels
from .records import SCHEMA, Deferred, Trajectory, jsonable

__all__ = ["assemble", "summary"]


def assemble(sim, blocks, events, status) -> Trajectory:
    """The trajectory of the run ``sim`` (a :class:`~snakecg.simulate.simulator.Simulator`)
    from its samples in ``blocks`` ``(t (k,), y (k, n_y), mode, tau_fn, impact_loss)``, every
    quantity evaluated again at each sample in the sample's mode (the summary on first
    access)."""
    dyn = sim.dyn
    t = np.concatenate([b[0] for b in blocks])
    N = len(t)
    na, nc, nl, ny = dyn.na, dyn.nc, dyn.nl, dyn.ny
    Y = np.concatenate([b[1] for b in blocks])
    impact = np.repeat([b[4] for b in blocks], [len(b[0]) for b in blocks])
    # per sample, as the compiled samples lay it out: ydot (n_y), lam, A V (n_c), gap, s, sr,
    # norm_a_obj, norm_qdd and the sample's status
    R = np.empty((N, ny + 2 * nc + 6))
    tau = np.empty((N, na))
    p_cons = np.zeros(N)
    contact = np.empty(N, dtype=bool)
    wheel_state = np.empty((N, nl), dtype="<U6")
    for start, end, mode, tau_fn in _runs(blocks):
        sl = slice(start, end)
        if sim.compiled is not None:
            # one compiled call for the run of samples (the torque is constant over it; a
            # sample the C could not evaluate is NaN)
            taui = np.asarray(tau_fn(t[start], Y[start], mode), dtype=float)
            sim.compiled.samples_into(Y[sl], mode, taui, R[sl])
            dyn.nfev += end - start
            tau[sl] = taui
        for i in range(start, end) if sim.compiled is None else ():
            ydot, li, gi, si, AV, (ti, sri, nai, nqi) = dyn.rates(t[i], Y[i], mode, tau_fn)
            R[i, :ny], R[i, ny:ny + nc], R[i, ny + nc:ny + 2 * nc] = ydot, li, AV
            R[i, ny + 2 * nc:] = (gi, si, sri, nai, nqi, 0.0)
            tau[i] = ti
        # power of the held rows' forces: zero on the constraints (a drift diagnostic; not
        # integrated: off the constraints, at the integrator's stages, it is noise)
        F = mode.free_idx
        if F.size:
            p_cons[sl] = (R[sl, ny:ny + nc] * R[sl, ny + nc:ny + 2 * nc]) @ mode.free
        contact[sl] = mode.contact_held
        wheel_state[sl] = mode.wheel_names
    return trajectory(sim, t, Y, impact, R, tau, p_cons, contact, wheel_state, events, status)


def assemble_arrays(sim, t, Y, impact, R, tau, mode_index, modes, events, status):
    """:func:`assemble` of a run done in C (``core_run``): the samples ``t``, ``Y`` with
    their energy removed ``impact``, their quantities ``R`` (rows as the compiled samples'
    with their status: NaN and a non-zero status where the C could not evaluate one), the
    constant torque ``tau`` and each sample's mode (an index into ``modes``). The contact
    flags, wheel states and constraint power come from the modes' table when first read."""
    dyn = sim.dyn
    nc, ny = dyn.nc, dyn.ny
    N = len(t)
    dyn.nfev += N
    idx = mode_index.astype(np.intp)  # (a new array: mode_index is the workspace's)
    lam_av = R[:, ny:ny + nc] * R[:, ny + nc:ny + 2 * nc]

    def of_modes():
        free = np.array([m.free for m in modes])[idx]
        return {"power_constraint": np.einsum("ij,ij->i", lam_av, free),
                "contact": np.array([m.contact_held for m in modes])[idx],
                "wheel_state": np.array([m.wheel_names for m in modes], dtype="<U6")[idx]}

    later = Deferred(of_modes)
    taus = np.empty((N, len(tau)))
    taus[:] = tau
    return trajectory(sim, t, Y, impact, R, taus, later, later, later, events, status)


def trajectory(sim, t, Y, impact, R, tau, p_cons, contact, wheel_state, events, status):
    """The :class:`Trajectory` of the samples ``t``, ``Y`` and their quantities (``p_cons``,
    ``contact`` and ``wheel_state``: arrays, or :class:`Deferred`). What needs the mass
    matrices and link poses of the samples (kinetic energy, COM, poses, the displacement-based
    slippage ratio, the energy balance) and the geometry are computed when first read, from
    copies of the samples."""
    dyn = sim.dyn
    ns, nc, nx, ny = dyn.ns, dyn.nc, dyn.nx, dyn.ny
    e = ny + 2 * nc
    W = Y[:, 2 * nx:]
    kin = Deferred(partial(_kinematic, sim, Y.copy(), impact.copy()))
    return Trajectory(
        t=t, q=Y[:, :ns], v=Y[:, nx:nx + ns], q_obj=Y[:, ns:nx], v_obj=Y[:, nx + ns:2 * nx],
        rho=dyn.rho.copy(), tau=tau, lam=R[:, ny:ny + nc].copy(), qdd=R[:, nx:nx + ns].copy(),
        a_obj=R[:, nx + ns:2 * nx].copy(), contact=contact, wheel_state=wheel_state,
        sr=R[:, e + 2].copy(), norm_a_obj=R[:, e + 3].copy(), norm_qdd=R[:, e + 4].copy(),
        sr_displacement=kin, com=kin, link_poses=kin, gap=R[:, e].copy(),
        s=R[:, e + 1].copy(), row_velocity=R[:, ny + nc:e].copy(), kinetic_energy=kin,
        power_tau=R[:, 2 * nx].copy(), power_friction=R[:, 2 * nx + 1].copy(),
        work_tau=W[:, 0].copy(), work_friction=W[:, 1].copy(), work_object=W[:, 2].copy(),
        power_constraint=p_cons, impact_loss=impact, energy_residual=kin, events=events,
        summary=lambda traj: summary(sim, traj, status),
        geometry=Deferred(partial(_geometry, sim.model, dyn)), violation=sim.check.violation)


def _kinematic(sim, Y, loss) -> dict:
    """The trajectory's fields that need ``M_s`` and the link poses of the samples ``Y``
    (``loss``: the energy removed by impacts and projections up to each), and
    ``sim.ke_initial``."""
    model, dyn, cfg = sim.model, sim.dyn, sim.settings
    N = len(Y)
    ns, nx = dyn.ns, dyn.nx
    q, q_obj = Y[:, :ns], Y[:, ns:nx]
    v, v_obj = Y[:, nx:nx + ns], Y[:, nx + ns:2 * nx]
    W = Y[:, 2 * nx:]
    # M_s and the link poses at the initial configuration and at every sample, in one call
    Q = np.empty((N + 1, ns))
    Q[0], Q[1:] = cfg.q0, q
    kin = sim.compiled.kinematics(Q) if sim.compiled is not None \
        and sim.compiled.has_kinematics else None
    if kin is None:  # SceneModel.mass_matrix, link_poses on the run's own arrays
        kin = (kernels.call(model.backend, "mass_matrix", N + 1, q=Q, K=model.parameters)["M"],
               kernels.call(model.backend, "link_poses", N + 1, q=Q,
                            K=model.parameters)["poses"].transpose(0, 2, 1))
    M0, M = kin[0][0], kin[0][1:]
    poses = np.ascontiguousarray(kin[1][1:])
    mo = dyn.mo
    ke = 0.5 * np.einsum("ni,ni->n", np.einsum("nij,nj->ni", M, v), v) + 0.5 * (
        v_obj**2 @ mo)
    sim.ke_initial = 0.5 * float(cfg.v0 @ M0 @ cfg.v0) + 0.5 * float(
        cfg.v_obj0 @ (mo * cfg.v_obj0))
    m = np.asarray(model.robot.mass, dtype=float)
    com = (m @ poses[..., :2]) / m.sum()  # SceneModel.com
    # displacement-based slippage ratio (metric of the initial configuration)
    dq = q - q[0]
    do = q_obj - q_obj[0]
    num = (do * do) @ mo
    den = num + np.einsum("ni,ij,nj->n", dq, M0, dq)
    sr_d = np.full(N, np.nan)
    np.divide(num, den, out=sr_d, where=den > 0)
    residual = (ke - sim.ke_initial) - (W[:, 0] + W[:, 1] + W[:, 2] - loss)
    return {"kinetic_energy": ke, "com": com, "link_poses": poses, "sr_displacement": sr_d,
            "energy_residual": residual}


def _geometry(model, dyn) -> dict:
    """The trajectory's ``geometry``: constants of the model, for drawing."""
    scene = dyn.scene
    return {"geometry": {
        "length": np.asarray(scene.robot.length, float),
        "com": np.asarray(scene.robot.com, float),
        "wheel_offset": dyn.woff.copy(),
        "wheel_links": np.flatnonzero(dyn.present[1:]) + 1,
        "contact_link": dyn.k + 1,
        "side": dyn.sigma,
        "object_distance": float(scene.object_distance),
        "wheel_bounds": dyn.bounds[1:].copy(),
    }}


def _runs(blocks):
    """``(start, end, mode, tau_fn)`` of each run of consecutive samples (over the blocks)
    that share their mode and torque function."""
    start = end = 0
    key = None
    for b in blocks:
        if key is not None and (b[2] is not key[0] or b[3] is not key[1]):
            yield start, end, key[0], key[1]
            start = end
        key = (b[2], b[3])
        end += len(b[0])
    if key is not None:
        yield start, end, key[0], key[1]


def summary(sim, tr: Trajectory, status: str) -> dict:
    """The JSON-ready summary of the trajectory ``tr`` of the run ``sim``
    (docs/how-to/simulate.md)."""
    cfg, dyn = sim.settings, sim.dyn
    sc = dyn.scene
    t = tr.t
    dt = np.diff(t)
    span = max(t[-1] - t[0], 1e-300)
    held = tr.contact
    # time fractions from the piecewise-constant flags of each interval
    held_frac = float(np.sum(dt * held[:-1]) / span) if dt.size else float(held[0])
    sliding = (tr.wheel_state == "slide+") | (tr.wheel_state == "slide-")
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
    ke1 = float(tr.kinetic_energy[-1])  # (computed first if deferred: sim.ke_initial with it)
    ke0 = float(sim.ke_initial)
    return jsonable({
        "schema": SCHEMA,
        "status": status,
        "violation": None if tr.violation is None else tr.violation.to_dict(),
        "contact_check": sim.check.describe(),
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
