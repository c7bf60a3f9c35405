/* snakecg's engine: the exact minimiser of a quadratic over one block's set, and the block
 * Gauss-Seidel sweeps of the general solve's dual built on it (scene_solve.c's start; the sets
 * in scene_sets.c).
 *
 * block_min minimises 1/2 l^T G_kk l + c^T l over K_k exactly: a clamp, or a 2-D trust-region
 * problem in closed form on the eigenvectors (its secular equation solved to rounding:
 * scene_block.h); the split ellipse as the backward half, the forward half, or the segment
 * lam_t = 0 (the minimiser over the convex set lies in the half whose own full-ellipse
 * minimiser falls inside it, else on the dividing segment). The scaled H of a 2-D block
 * depends on the sample alone: the sweeps take its part of the minimiser (block_prep) once
 * and reuse it at every sweep, bit for bit what taking it again gives.
 */
#include <math.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_block.h"

/* H = G_kk of a 2-D block scaled to the unit disc: a disc by its radius s, the split
 * ellipse's half by its semi-axes (st along, p2 across). */
static inline void scaled_h(const double *H, double sx, double sy, double *Hs) {
  Hs[0] = H[0] * sx * sx; Hs[1] = H[1] * sx * sy;
  Hs[2] = H[2] * sx * sy; Hs[3] = H[3] * sy * sy;
}

SC_INTERNAL void sc_block_prep(const sc_problem *p, sc_int k, sc_tr2d *pr) {
  const sc_int r = p->start[k], m = p->m;
  const double *q = p->par + 3 * k, *G = p->G;
  double H[4] = {G[r * m + r], G[r * m + r + 1], G[(r + 1) * m + r], G[(r + 1) * m + r + 1]}, Hs[4];
  int half;
  if (p->kind[k] == K_DISC) {
    if (q[0] > 0) {
      scaled_h(H, q[0], q[0], Hs);
      sc_tr2d_prep(Hs, pr);
    }
    return;
  }
  for (half = 0; half < 2; ++half)
    if (q[half] > 0) {
      scaled_h(H, q[half], q[2], Hs);
      sc_tr2d_prep(Hs, pr + half);
    }
}

/* The exact minimiser over block k's set of 1/2 l^T H l + c^T l (H = G_kk). */
SC_INTERNAL void sc_block_min(const sc_problem *p, sc_int k, const double *c, double *l,
                              const sc_tr2d *pr) {
  const sc_int r = p->start[k], m = p->m;
  const double *q = p->par + 3 * k, *G = p->G;
  sc_tr2d own[2];
  if (p->kind[k] < K_DISC) {
    double h = G[r * m + r], x = h > 0 ? -c[0] / h : 0.0;
    if (p->kind[k] == K_UNILATERAL && x < 0) x = 0;
    if (p->kind[k] == K_BOX) x = x > q[0] ? q[0] : (x < -q[0] ? -q[0] : x);
    if (!(h > 0)) x = 0.0;
    l[0] = x;
    return;
  }
  if (p->kind[k] == K_DISC) {
    double gs[2], x[2], s = q[0];
    if (!(s > 0)) { l[0] = l[1] = 0.0; return; }
    if (!pr) {
      sc_block_prep(p, k, own);
      pr = own;
    }
    gs[0] = c[0] * s;
    gs[1] = c[1] * s;
    sc_tr2d_min(pr, gs, x);
    l[0] = s * x[0];
    l[1] = s * x[1];
  } else { /* split ellipse: the backward half, the forward half, or the segment t = 0 */
    const double h3 = G[(r + 1) * m + r + 1];
    int half;
    if (!(q[2] > 0) || !(q[0] > 0 || q[1] > 0)) {
      l[0] = 0.0;
      l[1] = q[2] > 0 ? fmax(-q[2], fmin(q[2], h3 > 0 ? -c[1] / h3 : 0.0)) : 0.0;
      if (!(q[0] > 0 || q[1] > 0)) return;
    }
    if (!pr) {
      sc_block_prep(p, k, own);
      pr = own;
    }
    for (half = 0; half < 2; ++half) {
      double st = q[half], gs[2], x[2];
      if (!(st > 0)) continue;
      gs[0] = c[0] * st;
      gs[1] = c[1] * q[2];
      sc_tr2d_min(pr + half, gs, x);
      if ((half == 0 && x[0] <= 0) || (half == 1 && x[0] >= 0)) {
        l[0] = st * x[0];
        l[1] = q[2] * x[1];
        return;
      }
    }
    l[0] = 0.0;
    l[1] = h3 > 0 ? -c[1] / h3 : 0.0;
    l[1] = fmax(-q[2], fmin(q[2], l[1]));
  }
}

/* The sweeps (declared in scene_block.h). */
SC_INTERNAL sc_int sc_block_sweeps(sc_problem *p, sc_int max_sweeps, double rel, int zero,
                                   sc_tr2d *pr) {
  const sc_int m = p->m;
  sc_int s, k, i, j;
  if (zero) {
    for (j = 0; j < m; ++j) p->w[j] = p->b[j] + 0.0;
    for (k = 0; k < p->nb && k < PREP_BLOCKS; ++k)
      if (p->kind[k] >= K_DISC) sc_block_prep(p, k, pr + 2 * k);
  } else
    sc_update_w(p);
  for (s = 0; s < max_sweeps; ++s) {
    double change = 0.0, size = 0.0;
    for (k = 0; k < p->nb; ++k) {
      sc_int r = p->start[k], nk = sc_block_size(p->kind[k]);
      double c[2], l[2], d[2];
      for (i = 0; i < nk; ++i) {
        c[i] = p->w[r + i];
        for (j = 0; j < nk; ++j) c[i] -= p->G[(r + i) * m + r + j] * p->lam[r + j];
      }
      sc_block_min(p, k, c, l, k < PREP_BLOCKS ? pr + 2 * k : NULL);
      for (i = 0; i < nk; ++i) {
        d[i] = l[i] - p->lam[r + i];
        if (fabs(d[i]) > change) change = fabs(d[i]);
        if (fabs(l[i]) > size) size = fabs(l[i]);
        p->lam[r + i] = l[i];
      }
      { /* w along: G symmetric, its columns r.. are its rows */
        double *restrict wv = p->w;
        const double *restrict c0 = p->G + r * m, *restrict c1 = c0 + m;
        if (nk == 2 && d[0] != 0.0 && d[1] != 0.0)
          for (j = 0; j < m; ++j) wv[j] += c0[j] * d[0] + c1[j] * d[1];
        else
          for (i = 0; i < nk; ++i)
            if (d[i] != 0.0)
              for (j = 0; j < m; ++j) wv[j] += c0[i * m + j] * d[i];
      }
    }
    if (!(change > rel * (size > p->fscale ? size : p->fscale))) break;
  }
  sc_update_w(p);
  return s < max_sweeps ? s + 1 : max_sweeps;
}
