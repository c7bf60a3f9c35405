"""A simulated run drawn: the summary figures and the animation of a
:class:`~snakecg.simulate.Trajectory` (what ``snakecg simulate`` writes).

* :func:`save_figures`: ``displacement.png``, ``slippage.png``, ``energy.png``, ``forces.png``
  (events marked as dashed lines, intervals with the contact lost shaded, the contact check's
  first violation as a solid red line, and what follows it hatched when the run went on)
  and, by default, the animation;
* :func:`save_animation`: an animated GIF of the robot pushing the object (matplotlib draws
  the frames with blitting, Pillow writes the GIF); from the contact check's first violation
  on, the bodies involved are red and the frame says so.

Every file is written atomically (a unique temporary name in the same folder, then
``os.replace``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError
from ..simulate.inputs import MAX_FRAMES

if TYPE_CHECKING:
    from ..simulate.records import Trajectory

__all__ = ["save_figures", "save_animation"]

_EVENT_COLORS = {"impact": "tab:red", "separation": "tab:purple", "off_link": "tab:purple",
                 "breakaway": "tab:orange", "stick": "tab:green", "reverse": "tab:olive",
                 "projection": "tab:gray"}


def _pyplot():
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg", "pdf", "svg", "ps", "cairo"):
        matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    return plt


def _mark_events(ax, traj: Trajectory, *, label=True):
    seen = set()
    for e in traj.events:
        c = _EVENT_COLORS.get(e.kind, "k")
        lab = e.kind if (label and e.kind not in seen) else None
        seen.add(e.kind)
        ax.axvline(e.t, color=c, lw=0.8, ls="--", alpha=0.8, label=lab)


def _violation_label(v) -> str:
    a, b = v.bodies
    return (f"{v.kind}: link {a} / object" if b == "object"
            else f"{v.kind}: links {a} / {b}") + f" (t = {v.t:.4g} s)"


def _mark_violation(ax, traj: Trajectory, *, label=True):
    """The contact check's first violation: a solid red line, the end of the run (or, when
    the run went on, the start of a hatched span that is not physical)."""
    v = traj.violation
    if v is None:
        return
    ax.axvline(v.t, color="red", lw=1.6, label=_violation_label(v) if label else None)
    if traj.t[-1] > v.t:
        ax.axvspan(v.t, traj.t[-1], fc="none", ec="red", hatch="//", lw=0, alpha=0.25,
                   zorder=0)


def _shade_lost(ax, traj: Trajectory):
    t, held = traj.t, traj.contact
    start = None
    for i in range(len(t)):
        if not held[i] and start is None:
            start = t[i]
        if (held[i] or i == len(t) - 1) and start is not None:
            ax.axvspan(start, t[i], color="0.85", lw=0, zorder=0)
            start = None


def _savefig(fig, path, dpi) -> None:
    from .._files import atomic_path

    with atomic_path(path) as tmp:  # unique temporary name, then os.replace
        fig.savefig(tmp, dpi=dpi, format="png")


def save_figures(traj: Trajectory, folder, *, animation: bool = True, fps: int = 20,
                 frames: int = 100, dpi: int = 110) -> dict[str, str]:
    """Write the summary figures (PNG) and the animation (GIF) of ``traj`` into ``folder``.

    ``displacement.png`` (object and snake COM displacement), ``slippage.png`` (instantaneous
    and displacement-based slippage ratio), ``energy.png`` (power and energy budget),
    ``forces.png`` (constraint forces and active set), ``animation.gif``. Returns the paths.
    """
    from pathlib import Path

    plt = _pyplot()
    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    paths = {}
    t = traj.t
    title = (f"{traj.summary.get('joints')} joints, {traj.summary.get('scenario')}, "
             f"kappa {traj.summary.get('kappa'):g}")

    # displacement -------------------------------------------------------------------------
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.6), sharex=True)
    do = traj.q_obj - traj.q_obj[0]
    dc = traj.com - traj.com[0]
    ax = axes[0]
    ax.plot(t, do[:, 0] * 1e3, label="x")
    ax.plot(t, do[:, 1] * 1e3, label="y")
    ax.plot(t, np.hypot(do[:, 0], do[:, 1]) * 1e3, "k", lw=1.5, label="distance")
    ax.set_ylabel("object COM (mm)")
    ax2 = ax.twinx()
    ax2.plot(t, np.degrees(do[:, 2]), color="tab:gray", lw=0.8, ls=":")
    ax2.set_ylabel("object angle (deg, dotted)", color="tab:gray")
    _shade_lost(ax, traj)
    _mark_events(ax, traj)
    _mark_violation(ax, traj)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("displacement, " + title + " (grey: contact lost)", fontsize=10)
    ax = axes[1]
    ax.plot(t, dc[:, 0] * 1e3, label="x")
    ax.plot(t, dc[:, 1] * 1e3, label="y")
    ax.plot(t, np.hypot(dc[:, 0], dc[:, 1]) * 1e3, "k", lw=1.5, label="distance")
    ax.set_ylabel("snake COM (mm)")
    ax.set_xlabel("t (s)")
    _shade_lost(ax, traj)
    _mark_events(ax, traj, label=False)
    _mark_violation(ax, traj, label=False)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    paths["displacement"] = str(out / "displacement.png")
    _savefig(fig, paths["displacement"], dpi)
    plt.close(fig)

    # slippage ratio -----------------------------------------------------------------------
    fig, ax = plt.subplots(figsize=(7, 3.6))
    ax.plot(t, traj.sr, label="sr (instantaneous, eq. 30)")
    ax.plot(t, traj.sr_displacement, label="sr from displacements since t = 0")
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("slippage ratio")
    _shade_lost(ax, traj)
    _mark_events(ax, traj)
    _mark_violation(ax, traj)
    ax.legend(fontsize=8, loc="best")
    ax.set_title("slippage ratio, " + title, fontsize=10)
    fig.tight_layout()
    paths["slippage"] = str(out / "slippage.png")
    _savefig(fig, paths["slippage"], dpi)
    plt.close(fig)

    # power and energy ---------------------------------------------------------------------
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.6), sharex=True)
    ax = axes[0]
    ax.plot(t, traj.power_tau * 1e3, label="joint torques")
    ax.plot(t, traj.power_friction * 1e3, label="wheel friction")
    ax.set_ylabel("power (mW)")
    _mark_events(ax, traj)
    _mark_violation(ax, traj)
    ax.legend(fontsize=8)
    ax.set_title("power and energy budget, " + title, fontsize=10)
    ax = axes[1]
    ke = traj.kinetic_energy - traj.kinetic_energy[0]
    ax.plot(t, ke * 1e3, "k", lw=2, label="kinetic energy gained")
    ax.plot(t, traj.work_tau * 1e3, label="work of joint torques")
    ax.plot(t, traj.work_friction * 1e3, label="work of wheel friction")
    if np.any(traj.work_object):
        ax.plot(t, traj.work_object * 1e3, label="work of the object wrench")
    ax.plot(t, -traj.impact_loss * 1e3, label="lost in impacts")
    ax.plot(t, traj.energy_residual * 1e3, ":", label="balance residual")
    ax.set_ylabel("energy (mJ)")
    ax.set_xlabel("t (s)")
    _mark_events(ax, traj, label=False)
    _mark_violation(ax, traj, label=False)
    ax.legend(fontsize=8)
    fig.tight_layout()
    paths["energy"] = str(out / "energy.png")
    _savefig(fig, paths["energy"], dpi)
    plt.close(fig)

    # forces and active set -----------------------------------------------------------------
    nl = traj.wheel_state.shape[1]
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.6), sharex=True,
                             gridspec_kw={"height_ratios": [3, 1.3]})
    ax = axes[0]
    ax.plot(t, traj.lam[:, 0], "k", lw=1.5, label="contact")
    wheel_links = list(traj.geometry.get("wheel_links", range(1, nl + 1)))
    for i in wheel_links:
        ax.plot(t, traj.lam[:, i], lw=1, label=f"wheel {i}")
    bounds = traj.geometry.get("wheel_bounds")
    if bounds is not None and np.isfinite(bounds).any():
        for b in np.unique(np.asarray(bounds)[np.isfinite(bounds)]):
            ax.axhline(b, color="0.5", lw=0.6, ls=":")
            ax.axhline(-b, color="0.5", lw=0.6, ls=":")
    ax.set_ylabel("constraint force (N)")
    _mark_events(ax, traj, label=False)
    _mark_violation(ax, traj, label=False)
    ax.legend(fontsize=8, ncol=2)
    ax.set_title("constraint forces and active set (dotted: friction bounds)", fontsize=10)
    ax = axes[1]
    rows = [("contact", np.where(traj.contact, 1, 0))]
    code = {"none": -1, "stick": 1, "slide+": 2, "slide-": 3}
    for i in wheel_links:
        rows.append((f"wheel {i}", np.array([code[s] for s in traj.wheel_state[:, i - 1]])))
    colors = {-1: "white", 0: "0.8", 1: "tab:green", 2: "tab:red", 3: "tab:orange"}
    for r, (name, vals) in enumerate(rows):
        cuts = np.flatnonzero(np.diff(vals)) + 1
        starts = np.concatenate(([0], cuts))
        ends = np.concatenate((cuts, [len(t) - 1]))
        for a, b in zip(starts, ends):
            if t[b] > t[a]:
                ax.broken_barh([(t[a], t[b] - t[a])], (r - 0.4, 0.8),
                               facecolors=colors[int(vals[a])], lw=0)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels([r[0] for r in rows], fontsize=8)
    ax.set_xlabel("t (s)  (green: held/stick, grey: lost, red/orange: slide+/slide-)")
    ax.set_xlim(t[0], t[-1])
    fig.tight_layout()
    paths["forces"] = str(out / "forces.png")
    _savefig(fig, paths["forces"], dpi)
    plt.close(fig)

    if animation:
        paths["animation"] = save_animation(traj, out / "animation.gif", fps=fps, frames=frames)
    return paths


def _frame_indices(t: np.ndarray, frames: int) -> np.ndarray:
    times = np.linspace(t[0], t[-1], max(2, int(frames)))
    idx = np.searchsorted(t, times, side="right") - 1
    return np.clip(idx, 0, len(t) - 1)


def save_animation(traj: Trajectory, path, *, fps: int = 20, frames: int = 100,
                   dpi: int = 80) -> str:
    """An animated GIF of the robot pushing the object: ``frames`` frames evenly spaced in
    time, drawn with matplotlib (links, wheels green when sticking and red when sliding, the
    object as a square of side ``2 object_distance``, the contact point, the paths of the
    object and of the snake's COM; from the contact check's first violation on, the bodies
    involved in red and the frame saying so) and written by Pillow at ``fps`` frames per
    second."""
    from matplotlib.patches import Polygon
    from PIL import Image

    if isinstance(frames, bool) or not isinstance(frames, (int, np.integer)) \
            or not 2 <= frames <= MAX_FRAMES:
        raise InputError(f"frames must be an integer from 2 to {MAX_FRAMES} (the limit: every "
                         f"frame is held in memory until the GIF is written), got {frames!r:.60}")

    plt = _pyplot()
    g = traj.geometry
    length, com = np.asarray(g["length"]), np.asarray(g["com"])
    woff = np.asarray(g["wheel_offset"])
    wheel_links = np.asarray(g["wheel_links"], dtype=int)
    half = float(g["object_distance"])
    P = traj.link_poses  # (N, n_l, 3)
    e = np.stack([np.cos(P[..., 2]), np.sin(P[..., 2])], axis=-1)
    rear = P[..., :2] - com[None, :, None] * e
    front = rear + length[None, :, None] * e
    square = np.array([[-half, -half], [half, -half], [half, half], [-half, half]])

    def object_corners(i):
        c, s = np.cos(traj.q_obj[i, 2]), np.sin(traj.q_obj[i, 2])
        R = np.array([[c, -s], [s, c]])
        return traj.q_obj[i, :2] + square @ R.T

    def contact_point(i):
        c, s = np.cos(traj.q_obj[i, 2]), np.sin(traj.q_obj[i, 2])
        R = np.array([[c, -s], [s, c]])
        return traj.q_obj[i, :2] + R @ traj.rho

    idx = _frame_indices(traj.t, frames)
    violation = traj.violation
    if violation is not None:  # the first violation's sample is a frame (the last, at a stop)
        k = min(int(np.searchsorted(traj.t, violation.t, side="left")), len(traj.t) - 1)
        j = min(int(np.searchsorted(traj.t[idx], traj.t[k], side="left")), len(idx) - 1)
        idx[j] = k
        red = [b - 1 for b in violation.bodies if b != "object"]
    pts = np.concatenate([rear[idx].reshape(-1, 2), front[idx].reshape(-1, 2),
                          np.concatenate([object_corners(i) for i in idx])])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = max(hi - lo) * 0.55 + 0.02
    mid = 0.5 * (lo + hi)
    fig, ax = plt.subplots(figsize=(4.2, 4.2))
    ax.set_xlim(mid[0] - span, mid[0] + span)
    ax.set_ylim(mid[1] - span, mid[1] + span)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    (links_line,) = ax.plot([], [], "-o", color="tab:blue", lw=3, ms=3)
    (wheels_stick,) = ax.plot([], [], "s", color="tab:green", ms=5, label="wheel sticking")
    (wheels_slide,) = ax.plot([], [], "s", color="tab:red", ms=5, label="wheel sliding")
    obj = Polygon(square, closed=True, fc="tan", ec="saddlebrown", alpha=0.8)
    ax.add_patch(obj)
    (cpt,) = ax.plot([], [], "k.", ms=6)
    (bad_links,) = ax.plot([], [], "-", color="red", lw=3)
    (obj_trail,) = ax.plot([], [], color="saddlebrown", lw=0.8)
    (com_trail,) = ax.plot([], [], color="tab:blue", lw=0.8, ls="--", label="snake COM")
    text = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top", fontsize=8)
    ax.legend(loc="lower right", fontsize=7)
    fig.tight_layout()

    def draw(j):
        i = idx[j]
        xs, ys = [], []
        for k in range(length.size):
            xs += [rear[i, k, 0], front[i, k, 0], np.nan]
            ys += [rear[i, k, 1], front[i, k, 1], np.nan]
        links_line.set_data(xs, ys)
        wp = P[i, wheel_links - 1, :2] + woff[wheel_links - 1, None] * e[i, wheel_links - 1]
        sliding = np.char.startswith(traj.wheel_state[i, wheel_links - 1].astype(str), "slide")
        wheels_stick.set_data(wp[~sliding, 0], wp[~sliding, 1])
        wheels_slide.set_data(wp[sliding, 0], wp[sliding, 1])
        obj.set_xy(object_corners(i))
        cp = contact_point(i)
        cpt.set_data([cp[0]], [cp[1]])
        obj_trail.set_data(traj.q_obj[: i + 1, 0], traj.q_obj[: i + 1, 1])
        com_trail.set_data(traj.com[: i + 1, 0], traj.com[: i + 1, 1])
        note = ""
        bx, by = [], []
        if violation is not None and traj.t[i] >= violation.t:
            note = "\n" + _violation_label(violation)
            for k in red:
                bx += [rear[i, k, 0], front[i, k, 0], np.nan]
                by += [rear[i, k, 1], front[i, k, 1], np.nan]
            obj.set_edgecolor("red" if "object" in violation.bodies else "saddlebrown")
        else:
            obj.set_edgecolor("saddlebrown")
        bad_links.set_data(bx, by)
        text.set_text(f"t = {traj.t[i]:.3f} s   contact {'held' if traj.contact[i] else 'lost'}"
                      f"\nsr = {traj.sr[i]:.3f}{note}")
        return (links_line, wheels_stick, wheels_slide, obj, cpt, obj_trail, com_trail,
                bad_links, text)

    # static parts drawn once; each frame restores them and draws only the moving artists
    # (blitting), then Pillow writes the GIF: several times faster than redrawing every
    # tick label per frame
    moving = (links_line, wheels_stick, wheels_slide, obj, cpt, obj_trail, com_trail, bad_links,
              text)
    for a in moving:
        a.set_animated(True)
    canvas = fig.canvas
    fig.set_dpi(dpi)
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)
    images = []
    for j in range(len(idx)):
        canvas.restore_region(background)
        for a in draw(j):
            ax.draw_artist(a)
        rgba = np.asarray(canvas.buffer_rgba())
        images.append(Image.fromarray(rgba[..., :3].copy()).quantize(
            colors=32, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE))
    from .._files import atomic_path

    with atomic_path(path) as tmp:  # unique temporary name, then os.replace
        images[0].save(str(tmp), format="GIF", save_all=True, append_images=images[1:],
                       duration=int(round(1000 / fps)), loop=0, optimize=False)
    plt.close(fig)
    return str(path)
