/* snakecg's engine: one piece of the general-scene solve (scene_solve.c's active set) solved
 * to rounding, the held rows eliminated.
 *
 * On a piece (every block held, zero, or sliding on its set's boundary; scene_solve.c's
 * header), the unknowns are the forces lam_H of the held rows and the angle t_k of every
 * sliding 2-D block's force on its set's boundary (sc_on_boundary); zero rows and saturated
 * boxes have their forces fixed. The equations are the dual's stationarity on the piece:
 * w_H = 0 and T_k . w_k = 0 (no acceleration along the boundary), w = G lam + b. The held
 * equations are linear: with G_HH = P L D L^T P^T by diagonal pivoting (dependent rows,
 * pivots at most DEP_TOL of the first, dropped: the basic solution), factored once,
 *   lam_H = lam_H0 + d0 + X (lam_S - lam_S0),   G_HH d0 = -w_H0,   G_HH X = -G_HS,
 * keeps w_H = 0 for every sliding force lam_S, and the sliding rows then read
 *   w_S = wt + S (lam_S - lam_S0),   S = G_SS + G_SH X (the Schur complement),
 * the gradient of the dual with the held forces eliminated (Hessian S). Newton on the angles
 * alone: Jacobian T^T S T + diag(max(0, -lam_k . w_k)) (the reduced Hessian on the sets'
 * boundaries, dT/dt = -lam), a few unknowns, factored by diagonal pivoting, the step halved
 * until the reduced dual does not rise. Where rows nearly dependent leave a residual that
 * does not fall, they are kept (pivots down to 1e-15) and the piece solved again. */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"

/* held rows dependent where a pivot of their equations falls below this ratio to the first
 * (snakecg.solver.PIVOT_TOL): nearly dependent rows are statically indeterminate to double
 * precision, their forces are taken minimum-norm rather than huge and cancelling */
#define DEP_TOL 1e-10

/* w = G lam + b */
SC_INTERNAL void sc_update_w(sc_problem *p) { sc_matvec_plus(p->m, p->G, p->lam, p->b, p->w); }

/* The reduced dual 1/2 D^T S D + wt^T D at D = lam_S - lam_S0 (ws = wt + S D, computed). */
static double reduced(sc_int n2, const double *S, const double *wt, const double *D,
                      double *restrict ws) {
  sc_int a, c;
  double v = 0.0;
  for (a = 0; a < n2; ++a) ws[a] = wt[a];
  for (c = 0; c < n2; ++c) { /* S symmetric: column c is row c */
    const double *restrict sc = S + c * n2;
    if (D[c] != 0.0)
      for (a = 0; a < n2; ++a) ws[a] += sc[a] * D[c];
  }
  for (a = 0; a < n2; ++a) v += 0.5 * D[a] * (wt[a] + ws[a]);
  return v;
}

/* The piece's equations from the current lam (pivots above rc kept); fn_out: their largest
 * residual after (held rows: |w|, sliding blocks: |T . w| / |T|). Returns the rank defect of
 * the held rows' and the angles' matrices. Scratch: work, iwork (scene_solve_work's). */
static sc_int piece(sc_problem *p, double rc, double *work, sc_int *iwork, double *fn_out) {
  const sc_int m = p->m, nb = p->nb;
  const double *G = p->G;
  sc_int *hr = iwork, *sl = hr + m, *ph = sl + nb, *pj = ph + m;
  sc_int h = 0, ns = 0, n2, k, i, s, t, a, c, it, rank = 0, rj = 0;
  double *X, *S, *J, *d0, *sc, *sc2, *th, *th0, *T, *F, *dx, *l0, *D, *wt, *ws, *W, fn = 0.0,
         v = 0.0;
  for (k = 0; k < nb; ++k) {
    sc_int r = p->start[k], nk = sc_block_size(p->kind[k]);
    if (p->state[k] == S_ZERO)
      for (i = 0; i < nk; ++i) p->lam[r + i] = 0.0;
    else if (p->state[k] == S_SLIDE && p->kind[k] == K_BOX)
      p->lam[r] = p->lam[r] >= 0 ? p->par[3 * k] : -p->par[3 * k];
    else if (p->state[k] == S_SLIDE)
      sl[ns++] = k;
    else
      for (i = 0; i < nk; ++i) hr[h++] = r + i;
  }
  n2 = 2 * ns;
  X = work + h * h; /* (G_HH's factor first) */
  S = X + h * n2;
  J = S + n2 * n2;
  d0 = J + ns * ns;
  sc = d0 + h;
  sc2 = sc + m;
  th = sc2 + m;
  th0 = th + ns;
  F = th0 + ns;
  dx = F + ns;
  T = dx + ns;
  l0 = T + n2;
  D = l0 + n2;
  wt = D + n2;
  ws = wt + n2;
  W = ws + n2; /* h x n2 */
  for (s = 0; s < ns; ++s) {
    double *l = p->lam + p->start[sl[s]];
    th[s] = sc_angle_of(p, sl[s], l);
    sc_on_boundary(p, sl[s], th[s], l, T + 2 * s);
    l0[2 * s] = l[0];
    l0[2 * s + 1] = l[1];
    D[2 * s] = D[2 * s + 1] = 0.0;
  }
  sc_update_w(p);
  if (h > 0) {
    for (i = 0; i < h; ++i) {
      for (t = 0; t <= i; ++t) work[i * h + t] = G[hr[i] * m + hr[t]];
      for (c = 0; c < n2; ++c) X[i * n2 + c] = -G[hr[i] * m + p->start[sl[c / 2]] + c % 2];
      sc[i] = -p->w[hr[i]];
    }
    rank = sc_psd_solve(h, work, h, sc, rc, d0, sc2, ph);
    sc_psd_resolve(h, work, h, rank, ph, n2, X, X, W);
  }
  for (a = 0; a < n2; ++a) { /* S = G_SS + G_SH X, wt = w_S + G_SH d0 */
    const double *ga = G + (p->start[sl[a / 2]] + a % 2) * m;
    double *restrict sa = S + a * n2;
    double wa = p->w[p->start[sl[a / 2]] + a % 2];
    for (c = 0; c < n2; ++c) sa[c] = ga[p->start[sl[c / 2]] + c % 2];
    for (i = 0; i < h; ++i) {
      const double *restrict xi = X + i * n2;
      const double g = ga[hr[i]];
      wa += g * d0[i];
      for (c = 0; c < n2; ++c) sa[c] += g * xi[c];
    }
    wt[a] = wa;
  }
  for (a = 0; a < n2; ++a) /* symmetric to rounding: made exactly so */
    for (c = 0; c < a; ++c) S[a * n2 + c] = S[c * n2 + a] = 0.5 * (S[a * n2 + c] + S[c * n2 + a]);
  for (it = 0; it < 40 && ns > 0; ++it) { /* Newton on the angles */
    double v0 = it ? v : reduced(n2, S, wt, D, ws), tstep = 1.0, step = 0.0;
    sc_int ls;
    fn = 0.0;
    for (s = 0; s < ns; ++s) {
      const double *Ts = T + 2 * s;
      F[s] = Ts[0] * ws[2 * s] + Ts[1] * ws[2 * s + 1];
      fn = sc_max(fn, fabs(F[s]) / (sqrt(Ts[0] * Ts[0] + Ts[1] * Ts[1]) + 1e-300));
    }
    if (it > 0 && fn <= 1e-15 * p->wscale) break; /* (the first step always: its rank) */
    for (s = 0; s < ns; ++s) {
      const double *Ts = T + 2 * s;
      for (t = 0; t <= s; ++t) {
        const double *Tt = T + 2 * t, *r0 = S + 2 * s * n2 + 2 * t, *r1 = r0 + n2;
        J[s * ns + t] = Ts[0] * (r0[0] * Tt[0] + r0[1] * Tt[1]) +
                        Ts[1] * (r1[0] * Tt[0] + r1[1] * Tt[1]);
      }
      { /* the boundary's curvature: -lam . w, at least 0 */
        const double *l = p->lam + p->start[sl[s]];
        J[s * ns + s] += sc_max(0.0, -(l[0] * ws[2 * s] + l[1] * ws[2 * s + 1]));
      }
      F[s] = -F[s];
    }
    rj = sc_psd_solve(ns, J, ns, F, rc, dx, sc2, pj);
    for (s = 0; s < ns; ++s) th0[s] = th[s];
    for (ls = 0; ls < 40; ++ls, tstep *= 0.5) { /* the step, halved while the dual rises */
      for (s = 0; s < ns; ++s) {
        double *l = p->lam + p->start[sl[s]];
        th[s] = th0[s] + tstep * dx[s];
        sc_on_boundary(p, sl[s], th[s], l, T + 2 * s);
        D[2 * s] = l[0] - l0[2 * s];
        D[2 * s + 1] = l[1] - l0[2 * s + 1];
      }
      v = reduced(n2, S, wt, D, ws); /* (ws at the step taken: the next iteration's) */
      if (v <= v0 + 1e-14 * (fabs(v0) + p->fscale * p->wscale)) break;
    }
    for (s = 0; s < ns; ++s) {
      k = sl[s];
      step = sc_max(step, fabs(tstep * dx[s]) *
                            (p->par[3 * k] + (p->kind[k] == K_SPLIT ? p->par[3 * k + 1] : 0.0)));
    }
    if (!(step > 1e-15 * p->fscale)) break;
  }
  for (i = 0; i < h; ++i) { /* the held forces at the sliding ones */
    double v = d0[i];
    for (c = 0; c < n2; ++c) v += X[i * n2 + c] * D[c];
    p->lam[hr[i]] += v;
  }
  sc_update_w(p);
  fn = 0.0;
  for (i = 0; i < h; ++i) fn = sc_max(fn, fabs(p->w[hr[i]]));
  for (s = 0; s < ns; ++s) {
    const double *Ts = T + 2 * s, *w = p->w + p->start[sl[s]];
    fn = sc_max(fn, fabs(Ts[0] * w[0] + Ts[1] * w[1]) /
                      (sqrt(Ts[0] * Ts[0] + Ts[1] * Ts[1]) + 1e-300));
  }
  *fn_out = fn;
  return (h - rank) + (ns - rj);
}

/* piece, solved again from its own result while the residual is above rounding (at most
 * three times): where it does not halve with rows dropped and stays above 1e-12 of the
 * scale, they are kept (pivots to 1e-15). */
static sc_int rounds(sc_problem *p, double *work, sc_int *iwork, double *fn) {
  double rc = DEP_TOL, prev = INFINITY;
  sc_int defect = 0, round;
  for (round = 0; round < 3; ++round) {
    defect = piece(p, rc, work, iwork, fn);
    if (!(*fn > 1e-14 * p->wscale)) break;
    if (defect > 0 && !(*fn < 0.5 * prev) && *fn > 1e-12 * p->wscale) rc = 1e-15;
    prev = *fn;
  }
  return defect;
}

/* The piece's equations solved (returns their rank defect, 0: independent); where that stops
 * short of rounding with a sliding block that does not move (at its set's limit: the angle's
 * equation is degenerate there), that block is held instead and the piece solved again. */
SC_INTERNAL sc_int sc_polish(sc_problem *p, double *work, sc_int *iwork) {
  double fn;
  sc_int k, defect = rounds(p, work, iwork, &fn);
  int again = 0;
  if (!(fn > 1e-14 * p->wscale)) return defect;
  for (k = 0; k < p->nb; ++k)
    if (p->state[k] == S_SLIDE && p->kind[k] >= K_DISC && sc_still(p, k)) {
      p->state[k] = S_HELD;
      again = 1;
    }
  return again ? rounds(p, work, iwork, &fn) : defect;
}
