/* snakecg's engine: the general scene's dual on its log-barrier path (an interior point), where
 * scene_solve.c's Gauss-Seidel sweeps read no piece that solves after many sweeps.
 *
 * On a statically indeterminate face (more held rows than the coordinates they hold), the
 * sweeps' forces drift along the face's null space and their reading of the pieces can keep
 * failing for thousands of sweeps. The barrier path has no such drift: for t > 0,
 *   minimise  t (1/2 lam^T G lam + b^T lam) - sum_k log s_k(lam),
 * with s_k = lam (a contact), p^2 - lam^2 (a box), 1 - lam^T P lam (a disc or split ellipse,
 * sc_block_P), has one minimiser, strictly inside the sets, whose gap to the dual's optimum is
 * at most nu / t (nu: the barrier terms; Boyd & Vandenberghe, "Convex Optimization", 11.2-11.3).
 * Each t's minimiser is followed by damped Newton steps (the Hessian t G + the barrier's, of
 * m rows, solved through an n x n system: newton_step), the step halved until it stays inside
 * the sets and the objective falls (Armijo); t grows by MU once the Newton decrement is below
 * CENTRED, until nu / t is below GAP of the scales. The blocks whose set is {0} keep zero
 * forces. The point is no answer: scene_solve.c reads its pieces and solves them exactly (its
 * passes and certificate). */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"
#include "scene_barrier.h"

#define MU 50.0         /* t's growth between centrings */
#define CENTRED 1e-2    /* a centring's Newton decrement (squared) */
#define CENTRED_END 1e-6 /* the last centring's, or where it no longer halves (rounding) */
#define GAP 1e-11       /* nu / t at the end, of the scales' product */
#define NEWTON_MAX 400  /* Newton steps at most */
#define FREE_DAMP 1e-8  /* a free row's damping, of t G_ii */

/* The barrier's value at lam (INFINITY outside the sets); with g (m) and Dh (3 per block: its
 * Hessian's h00, h10, h11) where given: its gradient added and its blocks' Hessians set. */
static double barrier(const sc_problem *p, const double *lam, double *g, double *Dh) {
  double v = 0.0;
  sc_int k;
  for (k = 0; k < p->nb; ++k) {
    const sc_int r = p->start[k];
    const double *q = p->par + 3 * k, *l = lam + r;
    double s, P[2], u0, u1, *d = Dh ? Dh + 3 * k : NULL;
    if (sc_zero_set(p, k) || p->kind[k] == K_FREE) continue;
    switch (p->kind[k]) {
      case K_UNILATERAL:
        if (!(l[0] > 0)) return INFINITY;
        v -= log(l[0]);
        if (g) g[r] -= 1.0 / l[0], d[0] = 1.0 / (l[0] * l[0]);
        break;
      case K_BOX:
        s = q[0] * q[0] - l[0] * l[0];
        if (!(s > 0)) return INFINITY;
        v -= log(s);
        if (g) g[r] += 2.0 * l[0] / s, d[0] = 2.0 / s + 4.0 * l[0] * l[0] / (s * s);
        break;
      default: /* a disc or split ellipse */
        sc_block_P(p, k, l, P);
        u0 = P[0] * l[0];
        u1 = P[1] * l[1];
        s = 1.0 - (u0 * l[0] + u1 * l[1]);
        if (!(s > 0)) return INFINITY;
        v -= log(s);
        if (g) {
          g[r] += 2.0 * u0 / s;
          g[r + 1] += 2.0 * u1 / s;
          d[0] = 2.0 * P[0] / s + 4.0 * u0 * u0 / (s * s);
          d[1] = 4.0 * u0 * u1 / (s * s);
          d[2] = 2.0 * P[1] / s + 4.0 * u1 * u1 / (s * s);
        }
    }
  }
  return v;
}

/* The Newton step dx = -(t G + D)^-1 g with G = Z^T Z (Z: n x m) by Woodbury's identity:
 * (t Z^T Z + D)^-1 = D^-1 - D^-1 Z^T (I / t + Z D^-1 Z^T)^-1 Z D^-1, an n x n system for the
 * m x m one (D: the barrier's blocks; a free row's D a damping of FREE_DAMP t G_ii, which
 * leaves Newton's fixed point where it was; a set {0}'s rows fixed). Work: n^2 + nm + 3n + m
 * + 3 nb doubles after Dh, iwork n. */
static void newton_step(const sc_problem *p, const double *Z, double t, const double *g,
                        double *Dh, double *dx, double *work, sc_int *iwork) {
  const sc_int n = p->n, m = p->m;
  double *K = work, *y = K + n * n, *v = y + n, *u = v + n, *Di = u + m, *W = Di + 3 * p->nb;
  sc_int i, j, k, c;
  for (k = 0; k < p->nb; ++k) { /* D^-1 by blocks; u = D^-1 g */
    const sc_int r = p->start[k];
    double *d = Dh + 3 * k, *e = Di + 3 * k;
    if (sc_zero_set(p, k)) {
      for (c = 0; c < sc_block_size(p->kind[k]); ++c) u[r + c] = 0.0;
      e[0] = e[1] = e[2] = 0.0;
      continue;
    }
    if (p->kind[k] == K_FREE) d[0] = FREE_DAMP * t * (p->G[r * m + r] > 0 ? p->G[r * m + r] : 1.0);
    if (sc_block_size(p->kind[k]) == 1) {
      e[0] = 1.0 / d[0];
      u[r] = e[0] * g[r];
    } else {
      const double det = d[0] * d[2] - d[1] * d[1];
      e[0] = d[2] / det, e[1] = -d[1] / det, e[2] = d[0] / det;
      u[r] = e[0] * g[r] + e[1] * g[r + 1];
      u[r + 1] = e[1] * g[r] + e[2] * g[r + 1];
    }
  }
  for (i = 0; i < n; ++i) { /* W = Z D^-1 (by blocks), y = Z u */
    const double *zi = Z + i * m;
    double *wi = W + i * m, s = 0.0;
    for (c = 0; c < m; ++c) s += zi[c] * u[c];
    y[i] = s;
    for (k = 0; k < p->nb; ++k) {
      const sc_int r = p->start[k];
      const double *e = Di + 3 * k;
      if (sc_block_size(p->kind[k]) == 1) {
        wi[r] = e[0] * zi[r];
      } else {
        wi[r] = e[0] * zi[r] + e[1] * zi[r + 1];
        wi[r + 1] = e[1] * zi[r] + e[2] * zi[r + 1];
      }
    }
  }
  for (i = 0; i < n; ++i) /* K = I / t + W Z^T (its lower triangle, rows by rows) */
    for (j = 0; j <= i; ++j) {
      const double *wi = W + i * m, *zj = Z + j * m;
      double s0 = 0.0, s1 = 0.0;
#if defined(__GNUC__) /* (two lanes, two vectors: linalg.h's sc_p2) */
      sc_p2 a = {0.0, 0.0}, b = {0.0, 0.0};
      for (c = 0; c + 3 < m; c += 4)
        a += SC_P2C(wi + c) * SC_P2C(zj + c), b += SC_P2C(wi + c + 2) * SC_P2C(zj + c + 2);
      a += b;
      s0 = a[0], s1 = a[1];
#else
      c = 0;
#endif
      for (; c + 1 < m; c += 2) s0 += wi[c] * zj[c], s1 += wi[c + 1] * zj[c + 1];
      if (c < m) s0 += wi[c] * zj[c];
      K[i * n + j] = (s0 + s1) + (i == j ? 1.0 / t : 0.0);
    }
  sc_psd_solve(n, K, n, y, 1e-15, v, W + n * m, iwork);
  for (c = 0; c < m; ++c) { /* dx = -u + D^-1 Z^T v */
    double s = 0.0;
    for (i = 0; i < n; ++i) s += Z[i * m + c] * v[i];
    dx[c] = s;
  }
  for (k = 0; k < p->nb; ++k) {
    const sc_int r = p->start[k];
    const double *e = Di + 3 * k;
    if (sc_zero_set(p, k)) {
      for (c = 0; c < sc_block_size(p->kind[k]); ++c) dx[r + c] = 0.0;
    } else if (sc_block_size(p->kind[k]) == 1) {
      dx[r] = e[0] * dx[r] - u[r];
    } else {
      const double s0 = dx[r], s1 = dx[r + 1];
      dx[r] = e[0] * s0 + e[1] * s1 - u[r];
      dx[r + 1] = e[1] * s0 + e[2] * s1 - u[r + 1];
    }
  }
}

/* The path followed from t = 1 / (the scales' product) and lam = 0 (contacts at 1e-2 of the
 * force scale: strictly inside), t times MU per centring (scene_barrier.h). */
SC_INTERNAL sc_int sc_barrier(sc_problem *p, const double *Z, double *work, sc_int *iwork) {
  const sc_int n = p->n, m = p->m;
  const double scale = p->fscale * p->wscale;
  double *g = work, *gq = g + m, *dx = gq + m, *tr = dx + m, *Dh = tr + m,
         *rest = Dh + 3 * p->nb;
  double *lam = p->lam, t = 1.0 / scale, nu = 0.0;
  sc_int i, j, k, newton = 0;
  for (i = 0; i < m; ++i) lam[i] = 0.0;
  for (k = 0; k < p->nb; ++k) /* (a strictly feasible start: contacts pressed a little) */
    if (!sc_zero_set(p, k) && p->kind[k] != K_FREE) {
      nu += 1.0;
      if (p->kind[k] == K_UNILATERAL) lam[p->start[k]] = 1e-2 * p->fscale;
    }
  for (;;) { /* (the last centring: its decrement to CENTRED_END, or while it halves) */
    const int last = nu / t <= GAP * scale;
    double dprev = INFINITY;
    for (;;) { /* centring: damped Newton */
      double b0, dec = 0.0, slope = 0.0, quad = 0.0, step = 1.0;
      if (++newton > NEWTON_MAX) return last ? newton : 0;
      sc_matvec_plus(m, p->G, lam, p->b, gq); /* gq = t (G lam + b); g = gq + the barrier's */
      for (i = 0; i < m; ++i) g[i] = gq[i] *= t;
      b0 = barrier(p, lam, g, Dh);
      newton_step(p, Z, t, g, Dh, dx, rest, iwork);
      for (i = 0; i < m; ++i) dec -= g[i] * dx[i], slope += gq[i] * dx[i];
      if (!(dec >= 0) || !isfinite(dec)) return 0;
      if (dec <= (last ? CENTRED_END : CENTRED) || (last && dec > 0.5 * dprev)) break;
      dprev = dec;
      for (i = 0; i < n; ++i) { /* t dx^T G dx / 2 = t |Z dx|^2 / 2 */
        double s = 0.0;
        for (j = 0; j < m; ++j) s += Z[i * m + j] * dx[j];
        quad += s * s;
      }
      quad *= 0.5 * t;
      for (;; step *= 0.5) { /* (the objective's change: the quadratic's exact, the barrier's) */
        double v;
        if (step < 1e-12) return last ? newton : 0;
        for (i = 0; i < m; ++i) tr[i] = lam[i] + step * dx[i];
        v = barrier(p, tr, NULL, NULL);
        if (isfinite(v) && step * slope + step * step * quad + (v - b0) <= -0.25 * step * dec)
          break;
      }
      memcpy(lam, tr, sizeof(double) * (size_t)m);
    }
    if (last) return newton;
    t *= MU;
  }
}

/* The barrier's point put onto the pieces read from it (p->state): a sliding 2-D block's force
 * radially onto its set's boundary (sc_direction_of, sc_on_boundary: as a piece starts), a box
 * at its bound, an open contact's force zero (a near miss for scene_solve.c to keep where no
 * piece solves: its KKT residuals are the point's distance from the path's end, about the
 * gap). */
SC_INTERNAL void sc_barrier_onto(sc_problem *p) {
  sc_int k;
  for (k = 0; k < p->nb; ++k) {
    double *l = p->lam + p->start[k], u[2], T[2];
    if (p->state[k] == S_ZERO) {
      l[0] = 0.0;
      if (sc_block_size(p->kind[k]) == 2) l[1] = 0.0;
    } else if (p->state[k] == S_SLIDE && p->kind[k] == K_BOX) {
      l[0] = l[0] >= 0 ? p->par[3 * k] : -p->par[3 * k];
    } else if (p->state[k] == S_SLIDE && !sc_zero_set(p, k)) { /* (radially, as a piece) */
      sc_direction_of(p, k, l, u);
      sc_on_boundary(p, k, u, l, T);
    }
  }
}
