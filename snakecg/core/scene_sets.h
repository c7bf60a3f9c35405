/* snakecg's runtime core: the friction and contact sets of the general-scene solve
 * (scene_solve.c) and the exact minimiser of a quadratic over each of them.
 *
 * A block k of the dual, min 1/2 lam^T G lam + b^T lam over lam in K_1 x ... x K_nb, is one
 * row (FREE: R; UNILATERAL: lam >= 0; BOX: |lam| <= p0) or two (DISC: |lam| <= p0; SPLIT: the
 * split ellipse with semi-axes p0 for lam_t <= 0, p1 for lam_t >= 0, p2 across). On a 2-D
 * set's boundary, lam^T P lam = 1 with P diagonal (block_P). block_min minimises
 * 1/2 l^T G_kk l + c^T l over K_k exactly: a clamp, or a 2-D trust-region problem in closed
 * form on the eigenvectors (its secular equation solved to rounding); the split ellipse as
 * the backward half, the forward half, or the segment lam_t = 0 (the minimiser over the
 * convex set lies in the half whose own full-ellipse minimiser falls inside it, else on the
 * dividing segment). Included by scene_solve.c alone (everything static).
 */
#ifndef SNAKECG_CORE_SCENE_SETS_H
#define SNAKECG_CORE_SCENE_SETS_H

#include <math.h>

#include "linalg.h"

enum { K_FREE = 0, K_UNILATERAL = 1, K_BOX = 2, K_DISC = 3, K_SPLIT = 4 };

typedef struct {
  sc_int n, m, nb;
  const sc_int *kind, *start;
  const double *par; /* nb x 3 */
  double *G, *b, *lam, *w, *gamma;
  sc_int *state;
  double fscale, wscale;
} problem;

static sc_int block_size(sc_int kind) { return kind >= K_DISC ? 2 : 1; }

/* P of a 2-D block at lam (diag, 2 entries): the set is lam^T P lam <= 1 */
static void block_P(const problem *p, sc_int k, const double *l, double *P) {
  const double *q = p->par + 3 * k;
  if (p->kind[k] == K_DISC) {
    P[0] = P[1] = 1.0 / (q[0] * q[0]);
  } else {
    double st = l[0] < 0 ? q[0] : q[1];
    P[0] = 1.0 / (st * st);
    P[1] = 1.0 / (q[2] * q[2]);
  }
}

/* min 1/2 x^T H x + g^T x over |x| <= 1 (H 2x2 symmetric positive semidefinite): the
 * trust-region problem in closed form on H's eigenvectors, its secular equation
 * sum g_i^2 / (h_i + s)^2 = 1 solved by safeguarded Newton on 1/|x(s)| to rounding. */
static void trust_region_2d(const double *H, const double *g, double *x) {
  double a = H[0], c = H[3], bb = 0.5 * (H[1] + H[2]);
  double tr = 0.5 * (a + c), d = sqrt(0.25 * (a - c) * (a - c) + bb * bb);
  double h[2] = {tr - d, tr + d}, v[2][2], gp[2], lo, hi, s, nx;
  int it, i;
  if (fabs(bb) > 1e-300) {
    /* eigenvector of h0: (bb, h0 - a) or (h0 - c, bb) */
    double e0 = bb, e1 = h[0] - a, nn;
    if (fabs(h[0] - c) > fabs(h[0] - a)) {
      e0 = h[0] - c;
      e1 = bb;
    }
    nn = sqrt(e0 * e0 + e1 * e1);
    v[0][0] = e0 / nn;
    v[0][1] = e1 / nn;
  } else if (a <= c) {
    h[0] = a; h[1] = c;
    v[0][0] = 1.0; v[0][1] = 0.0;
  } else {
    h[0] = c; h[1] = a;
    v[0][0] = 0.0; v[0][1] = 1.0;
  }
  v[1][0] = -v[0][1];
  v[1][1] = v[0][0];
  for (i = 0; i < 2; ++i) gp[i] = v[i][0] * g[0] + v[i][1] * g[1];
  if (h[0] < 0) h[0] = 0; /* rounding of a semidefinite H */
  /* interior: x = -H^+ g (min-norm on a null direction) */
  {
    double y0 = 0.0, y1 = 0.0, tiny = 1e-14 * (h[1] > 0 ? h[1] : 1.0);
    int interior = 1;
    if (h[0] > tiny) y0 = -gp[0] / h[0];
    else if (fabs(gp[0]) > 0) interior = 0;
    if (h[1] > tiny) y1 = -gp[1] / h[1];
    else if (fabs(gp[1]) > 0) interior = 0;
    if (interior && y0 * y0 + y1 * y1 <= 1.0) {
      x[0] = y0 * v[0][0] + y1 * v[1][0];
      x[1] = y0 * v[0][1] + y1 * v[1][1];
      return;
    }
  }
  lo = 0.0;
  hi = sqrt(gp[0] * gp[0] + gp[1] * gp[1]); /* |x(hi)| <= |g| / hi <= 1 */
  s = lo;
  for (it = 0; it < 200; ++it) {
    double y0, y1, dn, phi, dphi;
    if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
    y0 = gp[0] / (h[0] + s);
    y1 = gp[1] / (h[1] + s);
    nx = sqrt(y0 * y0 + y1 * y1);
    phi = 1.0 / nx - 1.0; /* increasing in s */
    if (phi < 0) lo = s; else hi = s;
    if (phi == 0.0 || hi - lo <= 4e-16 * hi) break;
    dn = (y0 * y0 / (h[0] + s) + y1 * y1 / (h[1] + s)) / nx; /* -d|x|/ds */
    dphi = dn / (nx * nx);
    s = s - phi / dphi;
  }
  {
    double y0 = -gp[0] / (h[0] + s), y1 = -gp[1] / (h[1] + s), nn = sqrt(y0 * y0 + y1 * y1);
    if (nn > 0) { y0 /= nn; y1 /= nn; } /* on the circle exactly */
    x[0] = y0 * v[0][0] + y1 * v[1][0];
    x[1] = y0 * v[0][1] + y1 * v[1][1];
  }
}

/* The exact minimiser over block k's set of 1/2 l^T H l + c^T l (H = G_kk). */
static void block_min(const problem *p, sc_int k, const double *c, double *l) {
  const sc_int r = p->start[k], m = p->m;
  const double *q = p->par + 3 * k, *G = p->G;
  if (p->kind[k] < K_DISC) {
    double h = G[r * m + r], x = h > 0 ? -c[0] / h : 0.0;
    if (p->kind[k] == K_UNILATERAL && x < 0) x = 0;
    if (p->kind[k] == K_BOX) x = x > q[0] ? q[0] : (x < -q[0] ? -q[0] : x);
    if (!(h > 0)) x = p->kind[k] == K_UNILATERAL ? 0.0 : 0.0;
    l[0] = x;
    return;
  }
  {
    double H[4] = {G[r * m + r], G[r * m + r + 1], G[(r + 1) * m + r], G[(r + 1) * m + r + 1]};
    if (p->kind[k] == K_DISC) {
      double Hs[4], gs[2], x[2], s = q[0];
      if (!(s > 0)) { l[0] = l[1] = 0.0; return; }
      for (int i = 0; i < 4; ++i) Hs[i] = H[i] * s * s;
      gs[0] = c[0] * s;
      gs[1] = c[1] * s;
      trust_region_2d(Hs, gs, x);
      l[0] = s * x[0];
      l[1] = s * x[1];
    } else { /* split ellipse: the backward half, the forward half, or the segment t = 0 */
      int half;
      if (!(q[2] > 0) || !(q[0] > 0 || q[1] > 0)) {
        l[0] = 0.0;
        l[1] = q[2] > 0 ? fmax(-q[2], fmin(q[2], H[3] > 0 ? -c[1] / H[3] : 0.0)) : 0.0;
        if (!(q[0] > 0 || q[1] > 0)) return;
      }
      for (half = 0; half < 2; ++half) {
        double st = q[half], Hs[4], gs[2], x[2];
        if (!(st > 0)) continue;
        Hs[0] = H[0] * st * st; Hs[1] = H[1] * st * q[2];
        Hs[2] = H[2] * st * q[2]; Hs[3] = H[3] * q[2] * q[2];
        gs[0] = c[0] * st;
        gs[1] = c[1] * q[2];
        trust_region_2d(Hs, gs, x);
        if ((half == 0 && x[0] <= 0) || (half == 1 && x[0] >= 0)) {
          l[0] = st * x[0];
          l[1] = q[2] * x[1];
          return;
        }
      }
      l[0] = 0.0;
      l[1] = H[3] > 0 ? -c[1] / H[3] : 0.0;
      l[1] = fmax(-q[2], fmin(q[2], l[1]));
    }
  }
}

#endif
