"""Drawing a general scene at one configuration, in the style of ``snakecg.plot``: the links
(capsules of the robot's radius), objects, obstacles, every contact's point and normal; with
``tau``, the contact and ground forces and the accelerations of the forward solve at rest,
each group of arrows scaled so that its longest is 0.6 of the mean link length. Artists carry
``gid`` labels (``link1``..., ``object1``..., ``obstacle1``..., ``contact_normals``,
``force_contacts`` (with contact friction: the whole force, normal and friction),
``force_friction`` (the friction part alone, where a contact has one), ``force_ground``,
``acc_links``, ``acc_objects``)."""

from __future__ import annotations

import numpy as np

from ..figures.axes import COLORS, _scale, frame
from .contacts import link_ends
from .geometry import box_corners

__all__ = ["plot_scene"]


def plot_scene(model, q, tau=None, ax=None, *, title: str | None = None):
    """Draw ``q`` of a loaded general scene (``snakecg.load(GeneralScene)``) on ``ax``."""
    from matplotlib.patches import Circle, Polygon

    q = np.asarray(q, dtype=float)
    sc = model.scene
    P = model.link_poses(q)
    ends = link_ends(sc, P)
    op = model.object_poses(q)
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(6.4, 5.2), constrained_layout=True)
    L0 = 0.6 * float(np.mean(sc.robot.length))
    tips = [ends.reshape(-1, 2)]
    for j, o in enumerate(sc.objects):
        if o.shape == "disc":
            patch = Circle(op[j][:2], o.radius)
        else:
            patch = Polygon(box_corners(op[j][:2], o.size, op[j][2]), closed=True)
        patch.set(fc=COLORS["object"], ec="k", lw=1, gid=f"object{j + 1}", zorder=1,
                  label="objects" if j == 0 else None)
        ax.add_patch(patch)
        tips.append(op[j][None, :2])
    for k, o in enumerate(sc.obstacles):
        kw = dict(fc="0.55", ec="k", lw=1, gid=f"obstacle{k + 1}", zorder=1, hatch="//",
                  label="obstacles" if k == 0 else None)
        if o.shape == "peg":
            ax.add_patch(Circle(o.center, o.radius, **kw))
            tips.append(np.asarray(o.center)[None])
        elif o.shape == "box":
            c = box_corners(o.center, o.size, o.angle)
            ax.add_patch(Polygon(c, closed=True, **kw))
            tips.append(c)
        else:
            n = np.asarray(o.normal, float) / np.hypot(*o.normal)
            t = np.array([-n[1], n[0]])
            span = float(np.sum(sc.robot.length))
            p = np.asarray(o.point, float)
            c = np.array([p - span * t, p + span * t, p + span * t - 0.1 * span * n,
                          p - span * t - 0.1 * span * n])
            ax.add_patch(Polygon(c, closed=True, **kw))
    lw = 6 if sc.radius == 0 else max(2.0, 6.0)
    for i in range(model.n_links):
        ax.plot(*ends[i].T, "-", lw=lw, solid_capstyle="round", color=COLORS["snake"],
                gid=f"link{i + 1}", zorder=2, label="snake (link 1 = tail)" if i == 0 else None)
        if sc.radius > 0:
            for e in ends[i]:
                ax.add_patch(Circle(e, sc.radius, fc="none", ec=COLORS["snake"], lw=0.8,
                                    zorder=2))
    ax.plot(ends[:-1, 1, 0], ends[:-1, 1, 1], "o", color="k", ms=4, gid="joints", zorder=3)
    res = model.forward(q, tau if tau is not None else np.zeros(model.n_joints))
    pts = np.array([c["point"] for c in res.contacts]).reshape(-1, 2)
    nrm = np.array([c["normal"] for c in res.contacts]).reshape(-1, 2)
    if len(pts):
        ax.plot(pts[:, 0], pts[:, 1], "*", color=COLORS["normal"], ms=10, gid="contact_points",
                zorder=5)
        ax.quiver(pts[:, 0], pts[:, 1], 0.5 * L0 * nrm[:, 0], 0.5 * L0 * nrm[:, 1],
                  angles="xy", scale_units="xy", scale=1, color=COLORS["normal"],
                  gid="contact_normals", label="contact normals", zorder=6, width=0.006)
        tips.append(pts + 0.5 * L0 * nrm)
    if tau is not None and res.status == 0:
        fc = nrm * np.array([c["force"] for c in res.contacts])[:, None] if len(pts) else pts
        ft = np.array([np.multiply(c.get("tangent", (0.0, 0.0)), c.get("friction", 0.0))
                       for c in res.contacts]).reshape(-1, 2)
        fc = fc + ft  # (on the second body of each contact, as its force)
        gp, gf = [], []
        for g in res.ground:
            if "link" not in g:
                continue
            i = g["link"] - 1
            x, y, phi = P[i]
            t, nl = np.array([np.cos(phi), np.sin(phi)]), np.array([-np.sin(phi), np.cos(phi)])
            f = g["force"]
            vec = (f[0] * nl if g["model"] in ("wheel", "ideal_wheel") else
                   np.asarray(f) if g["model"] == "coulomb" else f[0] * t + f[1] * nl)
            gp.append((x, y))
            gf.append(vec)
        fs, fmax = _scale([*fc, *gf], L0)
        if fmax > 0:
            if len(pts):
                ax.quiver(pts[:, 0], pts[:, 1], fs * fc[:, 0], fs * fc[:, 1], angles="xy",
                          scale_units="xy", scale=1, color=COLORS["force"], zorder=6,
                          width=0.006, gid="force_contacts",
                          label=f"forces ({fmax:.3g} N = {L0:.3g} m)")
                if np.any(ft != 0):
                    ax.quiver(pts[:, 0], pts[:, 1], fs * ft[:, 0], fs * ft[:, 1], angles="xy",
                              scale_units="xy", scale=1, color=COLORS["force"], zorder=6,
                              width=0.004, gid="force_friction", alpha=0.5,
                              label="contact friction")
            if gp:
                gp, gf = np.array(gp), np.array(gf)
                ax.quiver(gp[:, 0], gp[:, 1], fs * gf[:, 0], fs * gf[:, 1], angles="xy",
                          scale_units="xy", scale=1, color=COLORS["force"], zorder=6,
                          width=0.004, gid="force_ground", alpha=0.7)
        J = model.link_jacobians(q)
        acc_l = np.einsum("ikn,n->ik", J[:, :2], res.qdd)
        acc_o = np.asarray(res.a_obj).reshape(-1, 3)[:, :2]
        as_, amax = _scale([*acc_l, *acc_o], L0)
        if amax > 0:
            ax.quiver(P[:, 0], P[:, 1], as_ * acc_l[:, 0], as_ * acc_l[:, 1], angles="xy",
                      scale_units="xy", scale=1, color=COLORS["acc"], zorder=6, width=0.006,
                      gid="acc_links", label=f"accelerations ({amax:.3g} m/s$^2$ = {L0:.3g} m)")
            if len(acc_o):
                ax.quiver(op[:, 0], op[:, 1], as_ * acc_o[:, 0], as_ * acc_o[:, 1],
                          angles="xy", scale_units="xy", scale=1, color=COLORS["acc"],
                          zorder=6, width=0.006, gid="acc_objects", alpha=0.8)
    frame(ax, tips, 0.15)
    if title is None:
        models = sorted({g.model for g in sc.ground})
        title = (f"{model.n_joints} joints, ground {'/'.join(models)}, {sc.n_objects} objects, "
                 f"{len(sc.obstacles)} obstacles, {len(res.contacts)} contacts")
        if tau is not None:
            title += f"\nsr = {float(res.sr):.4g}"
    ax.set_title(title, fontsize=10)
    ax.legend(loc="best", fontsize=8, framealpha=0.85)
    return ax
