/* snakecg's engine: the general solve's 2-D block minimiser (scene_block.c's block_min, the
 * sweeps' exact step: min 1/2 x^T H x + g^T x over the unit disc, H 2 x 2 positive
 * semidefinite), in two halves: what depends on H alone (sc_tr2d_prep: its eigen-
 * decomposition, the interior test's determinant), which the sweeps take once a sample per
 * block (H is a block of G scaled by its set), and what depends on g (sc_tr2d_min). The
 * halves' operations are those of the one function they were, in its order: bit for bit.
 * Included after math.h; the blocks' functions (the last two) where engine.h was. */
#ifndef SNAKECG_ENGINE_SCENE_BLOCK_H
#define SNAKECG_ENGINE_SCENE_BLOCK_H

typedef struct { /* H's part: its entries, 1/det, h0 <= h1 with eigenvector v0 (v1 = v0 turned) */
  double a, c, bb, id, h0, h1, v00, v01, v10, v11;
  int definite; /* (h0/h1 above about 1e-3: the interior minimiser by Cramer's rule first) */
} sc_tr2d;

static inline void sc_tr2d_prep(const double *H, sc_tr2d *t) {
  double a = H[0], c = H[3], bb = 0.5 * (H[1] + H[2]);
  double tr = 0.5 * (a + c), d = sqrt(0.25 * (a - c) * (a - c) + bb * bb);
  double h0 = tr - d, h1 = tr + d, det = a * c - bb * bb;
  t->a = a, t->c = c, t->bb = bb, t->id = 1.0 / det;
  t->definite = det > 4e-3 * tr * tr;
  if (fabs(bb) > 1e-300) {
    /* eigenvector of h0: (bb, h0 - a) or (h0 - c, bb) */
    double e0 = bb, e1 = h0 - a, nn;
    if (fabs(h0 - c) > fabs(h0 - a)) e0 = h0 - c, e1 = bb;
    nn = sqrt(e0 * e0 + e1 * e1);
    t->v00 = e0 / nn, t->v01 = e1 / nn;
  } else if (a <= c) {
    h0 = a; h1 = c;
    t->v00 = 1.0; t->v01 = 0.0;
  } else {
    h0 = c; h1 = a;
    t->v00 = 0.0; t->v01 = 1.0;
  }
  t->v10 = -t->v01, t->v11 = t->v00;
  t->h0 = h0 < 0 ? 0 : h0; /* rounding of a semidefinite H */
  t->h1 = h1;
}

/* The minimiser x for g on H's eigenvectors (t), the secular equation
 * sum g_i^2 / (h_i + s)^2 = 1 by safeguarded Halley steps to rounding. */
static inline void sc_tr2d_min(const sc_tr2d *t, const double *g, double *x) {
  const double h[2] = {t->h0, t->h1}, v[2][2] = {{t->v00, t->v01}, {t->v10, t->v11}};
  double gp[2];
  int it, i;
  if (t->definite) { /* the interior minimiser -H^-1 g first, by Cramer */
    double y0 = (t->bb * g[1] - t->c * g[0]) * t->id, y1 = (t->bb * g[0] - t->a * g[1]) * t->id;
    if (y0 * y0 + y1 * y1 <= 1.0) { x[0] = y0; x[1] = y1; return; }
  }
  for (i = 0; i < 2; ++i) gp[i] = v[i][0] * g[0] + v[i][1] * g[1];
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
  { /* |g|/(h1 + s) <= |y(s)| <= |g|/(h0 + s) and |g_i|/(h_i + s) <= |y(s)|: a bracket */
    const double a0 = gp[0] * gp[0], a1 = gp[1] * gp[1], gn = sqrt(a0 + a1);
    double lo = fmax(0.0, gn - h[1]), hi = gn - h[0], s, r0, r1, y0, y1, n2, nn;
    s = fmax(gn - (h[0] * a0 + h[1] * a1) / (a0 + a1), fmax(sqrt(a0) - h[0], sqrt(a1) - h[1]));
    for (it = 0;; ++it) { /* phi = 1/|y| - 1 (increasing, concave): Halley, else Newton */
      if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
      r0 = 1.0 / (h[0] + s), r1 = 1.0 / (h[1] + s); /* independent: a short chain */
      y0 = gp[0] * r0, y1 = gp[1] * r1;
      n2 = y0 * y0 + y1 * y1;
      nn = sqrt(n2);
      if (nn > 1.0) lo = s; else hi = s;
      if (fabs(nn - 1.0) <= 4e-16 * nn || hi - lo <= 4e-16 * hi || it == 199) break;
      { /* phi/phi' = n2 (1 - |y|)/s1, phi''/phi' = 3 (s1^2/n2 - s2)/s1 (s1^2 <= n2 s2) */
        double p0 = y0 * y0 * r0, p1 = y1 * y1 * r1, s1 = p0 + p1, s2 = p0 * r0 + p1 * r1;
        double den = s1 * s1 + 1.5 * (nn - 1.0) * (s1 * s1 - n2 * s2);
        s += den > 0.25 * s1 * s1 ? n2 * (nn - 1.0) * s1 / den : n2 * (nn - 1.0) / s1;
      }
    }
    nn = -1.0 / nn; /* x = -y/|y|: on the circle exactly */
    x[0] = nn * (y0 * v[0][0] + y1 * v[1][0]);
    x[1] = nn * (y0 * v[0][1] + y1 * v[1][1]);
  }
}

/* min 1/2 x^T H x + g^T x over |x| <= 1 (both halves at once). */
static inline void sc_trust_region_2d(const double *H, const double *g, double *x) {
  sc_tr2d t;
  sc_tr2d_prep(H, &t);
  sc_tr2d_min(&t, g, x);
}

#ifdef SNAKECG_ENGINE_H
/* Block k's H's prepared (2 halves: a disc's in pr[0]; a split ellipse's backward and forward
 * halves), for sc_block_min. */
SC_INTERNAL void sc_block_prep(const sc_problem *p, sc_int k, sc_tr2d *pr);
/* The exact minimiser over block k's set of 1/2 l^T G_kk l + c^T l; pr: block k's
 * sc_block_prep, or NULL (taken here). */
SC_INTERNAL void sc_block_min(const sc_problem *p, sc_int k, const double *c, double *l,
                              const sc_tr2d *pr);
/* Block Gauss-Seidel sweeps of the dual (scene_solve.c's start) until the largest change is
 * below rel * scale; returns the sweeps. w = G lam + b is kept along (one column of G per
 * changed row), and recomputed after; on entry from zero forces (zero: the sample's first
 * sweeps) it is b + 0 (what the product gives: sums of zeros, +0), and the first PREP_BLOCKS
 * blocks' H's part of their minimiser is taken into pr (2 per block) for every later sweep of
 * the sample. */
#define PREP_BLOCKS 64 /* blocks whose minimiser's H part the sweeps keep (the others: each time) */
SC_INTERNAL sc_int sc_block_sweeps(sc_problem *p, sc_int max_sweeps, double rel, int zero,
                                   sc_tr2d *pr);
#endif
#endif
