/* snakecg's engine: the general scene's exact solve (scene_solve.c) compiled for tiny problems.
 *
 * A problem whose blocks are all one row (FREE, UNILATERAL, BOX: contacts and wheels, no
 * Coulomb discs or split ellipses), with at most SC_TINY_M rows and no more rows than
 * coordinates (the paper's scene: a contact and three wheels' lateral rows on 9 coordinates)
 * is solved here by the general path's own steps in their order:
 *   the set-up (scene_tiny_setup.c: the inertia's factor by L D L^T with sc_inertia_factor's
 *   pivot rule, its pivots' reciprocals instead of square roots, compiled with every loop over
 *   the coordinates unrolled for the snake with 0-2 objects; then Z = L^-1 [A^T f], whose last
 *   column is g = L^-1 f, and its Gram matrix weighted by D^-1, G = Z^T D^-1 Z and
 *   b = Z^T D^-1 g + c, in one sweep over the coordinates compiled once per row count; the
 *   same quantities as the general path's Cholesky, other rounding), the scales,
 *   the start from the caller's pieces (FROM_PASSES active-set passes), then from the held
 *   guess (GUESS_PASSES), each pass the piece's equations solved to rounding (scene_piece.c:
 *   the held rows' forces from G_HH d = -w_H, at most three rounds while max |w_H| is above
 *   1e-14 of the scale) and the KKT conditions checked and switched (scene_solve.c's kkt: the
 *   same rules; its residuals read once no piece switches), then the certificate, the pieces
 *   reported and a = L^-T D^-1 (g + Z lam). The passes are compiled once per row count
 *   (1..SC_TINY_M), all of it twice: plain and with AVX2 and FMA (chosen where the processor
 *   has both; within rounding of each other). The forward (scene_rows.c) calls it first and
 *   gets the inertia's factor back for its metrics (sc_tiny_forward).
 * What differs is G_HH's factor: the general path's diagonal pivoting (sc_psd_solve: a pivot
 * search and swaps on the gathered rows, rows dropped at pivots of DEP_TOL = 1e-10 of the
 * first) becomes the same L D L^T in the rows' order, the other rows the identity (no
 * gather, no search), factored once per pass (its rounds reuse it); with four rows, G_HH's
 * inverse from its cofactors instead (piece4: no chain of divisions; the definiteness from its
 * leading minors, the factor's pivots' products). It is used only where the
 * pivoted factor would keep every held row: each pivoted pivot is at most G_HH's largest
 * diagonal entry (the first pivot), so at least det G_HH over that entry to the h - 1, and at
 * least G_HH's least eigenvalue, itself at least 1 / trace(G_HH^-1); where neither bound is
 * DEF_TOL (1e-3) of the largest diagonal entry, the general path solves the problem.
 * So the pieces, their passes and the answer are the general path's, to rounding.
 * Whatever else the general path does goes to it as well, the problem solved there from the
 * start: a singular inertia, no piece answered within the passes (the sweeps), a degenerate
 * answer (a non-held block whose rows do not accelerate: the minimum-norm face). Every answer
 * given here has dependent = 0, no rank defect and no sweeps. */
#include <math.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"
#include "scene_tiny.h"
#include "scene_tiny_setup.h"

#if defined(__GNUC__)
#define TINY_FLAT static inline __attribute__((always_inline))
#else
#define TINY_FLAT static inline
#endif

/* G_HH's factor in the rows' order used where its pivots certainly stay above this of the
 * first (G_HH's condition about 1e3 at most: beyond, the unpivoted order's rounding showed,
 * 1.1e-10 of |a| against the pivoted factor's 1.7e-11 at a condition of 1,950) */
#define DEF_TOL 1e-3

/* core_scene_tiny's switch and counts (tries, and those left to the general path: one atomic
 * add per answered problem; measurement only) */
static int tiny_on = 1; /* (2: on, the copy without FMA) */
static long tiny_counts[2];
#if defined(__GNUC__)
#define TINY_ADD(k, v) __atomic_fetch_add(&tiny_counts[k], (v), __ATOMIC_RELAXED)
#define TINY_TAKE(k) __atomic_exchange_n(&tiny_counts[k], 0L, __ATOMIC_RELAXED)
#else
#define TINY_ADD(k, v) (tiny_counts[k] += (v))
static long tiny_take(int k) {
  long v = tiny_counts[k];
  tiny_counts[k] = 0;
  return v;
}
#define TINY_TAKE(k) tiny_take(k)
#endif

typedef struct {
  const sc_int *kind;
  const double *par; /* 3 per row */
  double G[SC_TINY_M * SC_TINY_M], b[SC_TINY_M], lam[SC_TINY_M], w[SC_TINY_M], F, W;
  sc_int state[SC_TINY_M];
} tiny;

/* w = G lam + b (each row's products summed in order, lam read once); with SSE2 two rows at a
 * time from G's columns (G is symmetric: gram writes both triangles), each lane the same sum
 * in the same order as a row's own (the same bits, half the operations) */
TINY_FLAT void wvec(const sc_int m, tiny *p) {
  double l[SC_TINY_M];
  sc_int i, j;
  for (j = 0; j < m; ++j) l[j] = p->lam[j];
#if defined(__SSE2__)
  for (i = 0; i + 1 < m; i += 2) {
    __m128d s = _mm_setzero_pd();
    for (j = 0; j < m; ++j)
      s = _mm_add_pd(s, _mm_mul_pd(_mm_loadu_pd(p->G + j * m + i), _mm_set1_pd(l[j])));
    _mm_storeu_pd(p->w + i, _mm_add_pd(_mm_loadu_pd(p->b + i), s));
  }
  if (m & 1) {
    const double *g = p->G + (m - 1) * m;
    double s = 0.0;
    for (j = 0; j < m; ++j) s += g[j] * l[j];
    p->w[m - 1] = p->b[m - 1] + s;
  }
#else
  for (i = 0; i < m; ++i) {
    const double *g = p->G + i * m;
    double s = 0.0;
    for (j = 0; j < m; ++j) s += g[j] * l[j];
    p->w[i] = p->b[i] + s;
  }
#endif
}

/* piece for four rows (the paper's scene: a contact and three wheels), G_HH's factor replaced
 * by its inverse from cofactors (the other rows and columns the identity): the 2 x 2 minors of
 * rows 0-1 (s) and rows 2-3 (c), the determinant and the adjugate X from them, all independent
 * products where the factor has a chain of four divisions; each round's d = X r / det (r the
 * negated held residuals), a product of independent terms where the factor has two
 * substitutions. The same rules: definite where the leading minors (the factor's pivots'
 * products) are positive and det finite; then det G_HH >= DEF_TOL big^h, or else the least
 * eigenvalue's bound, trace(G_HH^-1) = sum_H X_kk / det, with DEF_TOL big trace < 1 (both
 * multiplied through by big^h and det: no division). The inverse is accurate to about its
 * condition, at least big trace, times the rounding, the factor to the rounding: a round's
 * residual comes out up to that much larger, so where big trace is above 8 a second round is
 * made whatever the first's residual (the paper's scene: below 8 throughout). */
TINY_FLAT int piece4(tiny *p) {
  double a[16], X[16], r[4], big = 0.0, bigh = 1.0, s0, s1, s2, s3, s4, s5, c0, c1, c2, c3, c4,
                            c5, det, rdet, tr = 0.0;
  int held[4], h = 0, round;
  sc_int i, j, k;
  for (k = 0; k < 4; ++k) {
    held[k] = p->state[k] == S_HELD;
    if (held[k]) {
      ++h;
      if (p->G[k * 4 + k] > big) big = p->G[k * 4 + k];
    } else {
      const double q = p->par[3 * k];
      p->lam[k] = p->state[k] == S_ZERO ? 0.0 : p->lam[k] >= 0 ? q : -q;
    }
  }
  wvec(4, p);
  if (h == 0) return 1;
  for (i = 0; i < 4; ++i)
    for (j = 0; j < 4; ++j) a[i * 4 + j] = held[i] && held[j] ? p->G[i * 4 + j] : i == j;
#define A_(i, j) a[(i) * 4 + (j)]
  s0 = A_(0, 0) * A_(1, 1) - A_(1, 0) * A_(0, 1);
  s1 = A_(0, 0) * A_(1, 2) - A_(1, 0) * A_(0, 2);
  s2 = A_(0, 0) * A_(1, 3) - A_(1, 0) * A_(0, 3);
  s3 = A_(0, 1) * A_(1, 2) - A_(1, 1) * A_(0, 2);
  s4 = A_(0, 1) * A_(1, 3) - A_(1, 1) * A_(0, 3);
  s5 = A_(0, 2) * A_(1, 3) - A_(1, 2) * A_(0, 3);
  c5 = A_(2, 2) * A_(3, 3) - A_(3, 2) * A_(2, 3);
  c4 = A_(2, 1) * A_(3, 3) - A_(3, 1) * A_(2, 3);
  c3 = A_(2, 1) * A_(3, 2) - A_(3, 1) * A_(2, 2);
  c2 = A_(2, 0) * A_(3, 3) - A_(3, 0) * A_(2, 3);
  c1 = A_(2, 0) * A_(3, 2) - A_(3, 0) * A_(2, 2);
  c0 = A_(2, 0) * A_(3, 1) - A_(3, 0) * A_(2, 1);
  det = (s0 * c5 - s1 * c4) + (s2 * c3 + s3 * c2) + (s5 * c0 - s4 * c1);
  X[0] = A_(1, 1) * c5 - A_(1, 2) * c4 + A_(1, 3) * c3;
  X[1] = -A_(0, 1) * c5 + A_(0, 2) * c4 - A_(0, 3) * c3;
  X[2] = A_(3, 1) * s5 - A_(3, 2) * s4 + A_(3, 3) * s3;
  X[3] = -A_(2, 1) * s5 + A_(2, 2) * s4 - A_(2, 3) * s3;
  X[5] = A_(0, 0) * c5 - A_(0, 2) * c2 + A_(0, 3) * c1;
  X[6] = -A_(3, 0) * s5 + A_(3, 2) * s2 - A_(3, 3) * s1;
  X[7] = A_(2, 0) * s5 - A_(2, 2) * s2 + A_(2, 3) * s1;
  X[10] = A_(3, 0) * s4 - A_(3, 1) * s2 + A_(3, 3) * s0;
  X[11] = -A_(2, 0) * s4 + A_(2, 1) * s2 - A_(2, 3) * s0;
  X[15] = A_(2, 0) * s3 - A_(2, 1) * s1 + A_(2, 2) * s0; /* (the leading 3 x 3 minor) */
#undef A_
  X[4] = X[1], X[8] = X[2], X[12] = X[3], X[9] = X[6], X[13] = X[7], X[14] = X[11];
  if (!(a[0] > 0.0) || !(s0 > 0.0) || !(X[15] > 0.0) || !(det > 0.0) || !(det < INFINITY))
    return 0;
  rdet = 1.0 / det;
  for (k = 0; k < 4; ++k) {
    bigh *= held[k] ? big : 1.0;
    tr += held[k] ? X[k * 5] : 0.0;
  }
  if (!(det > DEF_TOL * bigh) && !(tr * big * DEF_TOL < det)) return 0;
  for (round = 0; round < 3; ++round) {
    double fn = 0.0;
    for (i = 0; i < 4; ++i) r[i] = held[i] ? -p->w[i] : 0.0;
    for (i = 0; i < 4; ++i) /* (the other rows' d: +0, X's rows there the identity's times det) */
      p->lam[i] += ((X[i * 4] * r[0] + X[i * 4 + 1] * r[1]) +
                    (X[i * 4 + 2] * r[2] + X[i * 4 + 3] * r[3])) * rdet;
    wvec(4, p);
    for (i = 0; i < 4; ++i)
      if (held[i]) fn = sc_max(fn, fabs(p->w[i]));
    if (!(fn > 1e-14 * p->W) && (round || !(tr * big > 8.0 * det))) break;
  }
  return 1;
}

/* The piece's equations solved (scene_piece.c's piece and rounds for one-row blocks): the fixed
 * forces set, w = G lam + b, then lam_H += d with G_HH d = -w_H while max |w_H| > 1e-14 W, at
 * most three times. Returns 0 where G_HH is not certainly definite (nothing answered). */
TINY_FLAT int piece(const sc_int m, tiny *p) {
  double C[SC_TINY_M * SC_TINY_M], y[SC_TINY_M], rd[SC_TINY_M], big = 0.0, det = 1.0, rb;
  int held[SC_TINY_M], h = 0, round;
  sc_int i, j, k;
  if (m == 4) return piece4(p);
  for (k = 0; k < m; ++k) {
    held[k] = p->state[k] == S_HELD;
    if (held[k]) {
      ++h;
      if (p->G[k * m + k] > big) big = p->G[k * m + k];
    } else {
      const double q = p->par[3 * k];
      p->lam[k] = p->state[k] == S_ZERO ? 0.0 : p->lam[k] >= 0 ? q : -q;
    }
  }
  wvec(m, p);
  if (h == 0) return 1;
  for (i = 0; i < m; ++i) /* G_HH in place, the other rows and columns the identity */
    for (j = 0; j <= i; ++j) C[i * m + j] = held[i] && held[j] ? p->G[i * m + j] : i == j;
  rb = 1.0 / big;
  for (k = 0; k < m; ++k) { /* G_HH = L D L^T in the rows' order (sc_psd_solve's, but one
    division a pivot: its reciprocal rd, the column's entries products with it) */
    const double d = C[k * m + k];
    if (!(d > 0.0) || !(d < INFINITY)) return 0;
    rd[k] = 1.0 / d;
    if (held[k]) det *= d * rb;
    for (i = k + 1; i < m; ++i) y[i] = C[i * m + k];
    for (i = k + 1; i < m; ++i) {
      const double l = y[i] * rd[k];
      for (j = k + 1; j <= i; ++j) C[i * m + j] -= l * y[j];
      C[i * m + k] = l;
    }
  }
  if (!(det > DEF_TOL)) { /* the least eigenvalue: at least 1 / trace(G_HH^-1) */
    double X[SC_TINY_M], tr = 0.0;
    for (k = 0; k < m; ++k) { /* row k of L^-1, its squares over D_k */
      double sq = 0.0;
      if (!held[k]) continue;
      for (i = k; i >= 0; --i) {
        double t = i == k ? 1.0 : 0.0;
        for (j = i + 1; j <= k; ++j) t -= X[j] * C[j * m + i];
        X[i] = t;
        if (held[i]) sq += t * t;
      }
      tr += sq * rd[k];
    }
    if (!(tr * big * DEF_TOL < 1.0)) return 0;
  }
  for (round = 0; round < 3; ++round) {
    double fn = 0.0;
    for (i = 0; i < m; ++i) { /* L y = -w_H, D z = y, L^T d = z */
      double t = held[i] ? -p->w[i] : 0.0;
      for (k = 0; k < i; ++k) t -= C[i * m + k] * y[k];
      y[i] = t;
    }
    for (i = 0; i < m; ++i) y[i] *= rd[i];
    for (i = m - 1; i >= 0; --i)
      for (k = i + 1; k < m; ++k) y[i] -= C[k * m + i] * y[k];
    for (i = 0; i < m; ++i) p->lam[i] += y[i]; /* (the other rows' y: +0, the identity's) */
    wvec(m, p);
    for (i = 0; i < m; ++i)
      if (held[i]) fn = sc_max(fn, fabs(p->w[i]));
    if (!(fn > 1e-14 * p->W)) break;
  }
  return 1;
}

/* scene_solve.c's kkt for one-row blocks: the residuals (primal, dual, complementarity,
 * relative). Each is the largest of its rows' terms over one scale (F, W or F W); the
 * division rounds monotonically, so the largest numerator divided once is the largest of the
 * quotients, bit for bit, with three divisions instead of three a row. */
TINY_FLAT void kkt(const sc_int m, const tiny *p, double *res) {
  double pr = 0.0, du = 0.0, co = 0.0, e;
  sc_int k;
  for (k = 0; k < m; ++k) {
    const double q = p->par[3 * k], l = p->lam[k], w = p->w[k];
    switch (p->kind[k]) {
      case K_FREE:
        du = sc_max(du, fabs(w));
        break;
      case K_UNILATERAL:
        pr = sc_max(pr, sc_max(0.0, -l));
        du = sc_max(du, sc_max(0.0, -w));
        co = sc_max(co, fabs(l * w));
        break;
      default: { /* K_BOX */
        const double x = q - fabs(l);
        pr = sc_max(pr, sc_max(0.0, fabs(l) - q));
        if (!(q > 0)) break; /* the set {0}: its normal cone is every w */
        if (fabs(l) < q) e = fabs(w);
        else e = l > 0 ? sc_max(0.0, w) : sc_max(0.0, -w);
        du = sc_max(du, e);
        co = sc_max(co, fabs((x < 0.0 ? x : 0.0) * w)); /* (fmin(x, 0.0)'s) */
      }
    }
  }
  res[0] = pr / p->F;
  res[1] = du / p->W;
  res[2] = co / (p->F * p->W);
}

/* scene_solve.c's kkt's switches for one-row blocks: the violated pieces switched (its rules
 * on the same values; returns 1 if any). */
TINY_FLAT int kkt_switch(const sc_int m, tiny *p) {
  const double F = p->F, W = p->W;
  int moved = 0;
  sc_int k;
  for (k = 0; k < m; ++k) {
    const double q = p->par[3 * k], l = p->lam[k], w = p->w[k];
    if (p->kind[k] == K_UNILATERAL) {
      if (p->state[k] == S_HELD && l < -TOL_ACCEPT * F) p->state[k] = S_ZERO, moved = 1;
      else if (p->state[k] == S_ZERO && w < -TOL_ACCEPT * W) p->state[k] = S_HELD, moved = 1;
    } else if (p->kind[k] == K_BOX && q > 0) { /* (the set {0}: its normal cone is every w) */
      if (p->state[k] == S_HELD && fabs(l) > q * (1 + TOL_ACCEPT)) {
        p->state[k] = S_SLIDE, moved = 1;
      } else if (p->state[k] == S_SLIDE) {
        const double e = fabs(l) < q ? fabs(w) : l > 0 ? sc_max(0.0, w) : sc_max(0.0, -w);
        if (e > TOL_ACCEPT * W) p->state[k] = S_HELD, moved = 1;
      }
    }
  }
  return moved;
}

/* scene_solve.c's active_set: 1 answered (res its residuals), 0 not within max_pass, -1 a piece
 * left to the general path. The residuals are read where no piece switched (they do not
 * depend on the pieces' states). */
TINY_FLAT int passes(const sc_int m, tiny *p, int max_pass, sc_int *count, double *res) {
  int pass;
  for (pass = 0; pass < max_pass; ++pass) {
    ++*count;
    if (!piece(m, p)) return -1;
    if (!kkt_switch(m, p)) {
      kkt(m, p, res);
      return res[0] <= TOL_ACCEPT && res[1] <= TOL_ACCEPT && res[2] <= TOL_ACCEPT;
    }
  }
  return 0;
}

/* the passes and the residuals compiled once per row count (and called, not inlined, by
 * solve), a second time with AVX2 and FMA, chosen where the processor has both and the switch
 * is 1 (the set-up's parts likewise: scene_tiny_setup.c); within rounding of the plain copy,
 * not bit for bit. Every problem of a process goes through the one copy its processor chooses. */
#if defined(__GNUC__)
#define TINY_CALLED static __attribute__((noinline))
#else
#define TINY_CALLED static
#endif
#define TINY_BY_M(r, x, attr) \
  attr int passes##x##_##r(tiny *p, int max_pass, sc_int *count, double *res) { \
    return passes(r, p, max_pass, count, res); \
  } \
  attr void final##x##_##r(tiny *p, double *res) { \
    wvec(r, p); \
    kkt(r, p, res); \
  }
TINY_BY_M(1, , TINY_CALLED) TINY_BY_M(2, , TINY_CALLED) TINY_BY_M(3, , TINY_CALLED)
TINY_BY_M(4, , TINY_CALLED) TINY_BY_M(5, , TINY_CALLED) TINY_BY_M(6, , TINY_CALLED)
#if defined(__x86_64__) && !defined(__clang__) && __GNUC__ >= 6 && !defined(SC_NO_AVX)
#define TINY_FMA 1
#define TINY_FUSED static __attribute__((noinline, target("avx2,fma")))
TINY_BY_M(1, _fma, TINY_FUSED) TINY_BY_M(2, _fma, TINY_FUSED) TINY_BY_M(3, _fma, TINY_FUSED)
TINY_BY_M(4, _fma, TINY_FUSED) TINY_BY_M(5, _fma, TINY_FUSED) TINY_BY_M(6, _fma, TINY_FUSED)
/* a call of the copy chosen (fused: a constant in each copy of solve) */
#define TINY_CHOSEN(fused, m, plain, fma) \
  do { \
    if (fused) { TINY_SWITCH_M(m, fma) } else { TINY_SWITCH_M(m, plain) } \
  } while (0)
#else
#define TINY_CHOSEN(fused, m, plain, fma) \
  do { \
    (void)(fused); \
    TINY_SWITCH_M(m, plain) \
  } while (0)
#endif
#undef TINY_BY_M
#define TINY_SWITCH_M(m, call) \
  switch (m) { \
    case 1: call(1); break; case 2: call(2); break; case 3: call(3); break; \
    case 4: call(4); break; case 5: call(5); break; default: call(6); \
  }

/* scene_solve.c's tight_scales: where the sets are far larger than every force the sample
 * asks and holds (scene_sets.h's sc_tight_scales), the answer checked again at the forces'
 * scales (p's scales replaced, res its residuals there); 0 where it breaks them. A force below
 * 1e-3 of the first scale first (most samples: no division). */
static int tight_holds(sc_int m, tiny *p, double *res) {
  double fs, ws;
  sc_int i;
  for (i = 0; i < m; ++i)
    if (!(fabs(p->lam[i]) < 1e-3 * p->F)) return 1;
  if (!sc_tight_scales(m, p->G, m + 1, p->b, p->lam, p->F, &fs, &ws)) return 1;
  p->F = fs;
  p->W = ws > 0 ? ws : p->W;
  kkt(m, p, res);
  return res[0] <= TOL_ACCEPT && res[1] <= TOL_ACCEPT && res[2] <= TOL_ACCEPT;
}

/* The solve (m rows); shape as factored's; L (n x n) and rc (n): the inertia's factor, *t its
 * dense block's size (-1: not factored, the factor's pivot rule failed); fused: the FMA copy's
 * parts (a constant in each copy). */
TINY_FLAT int solve_body(const int fused, sc_int m, sc_int n, int shape, const double *M,
                         const double *f, const double *A, const double *c, const sc_int *kind,
                         const double *par, const double *from, double *L, double *rc,
                         sc_int *t, double *lam_out, double *a, double *w_out,
                         double *state_out, double *info) {
  double Z[SC_TINY_N * (SC_TINY_M + 1)], res[3], fs = 0.0, ws = 0.0;
  sc_int i, k, tt, count = 0;
  int ok = 0, moved = 0;
  tiny p;
  p.kind = kind;
  p.par = par;
  *t = -1;
  if (!sc_tiny_factored(fused, n, shape, M, f, L, rc, &tt)) return 0; /* (sc_tiny_inertia's) */
  sc_tiny_gram(fused, m, n, tt, L, rc, A, f, c, Z, p.G, p.b);
  *t = tt;
  for (i = 0; i < m; ++i) { /* scene_solve.c's scales */
    const double d = p.G[i * m + i], bi = fabs(p.b[i]);
    if (d > 0 && bi / d > fs) fs = bi / d;
    if (bi > ws) ws = bi;
  }
  for (k = 0; k < 3 * m; ++k)
    if (fabs(par[k]) > fs && fabs(par[k]) < INFINITY) fs = fabs(par[k]); /* (finite ones) */
  for (i = 0; i < m; ++i)
    if (p.G[i * m + i] * fs > ws) ws = p.G[i * m + i] * fs;
  p.F = fs > 0 ? fs : 1.0;
  p.W = ws > 0 ? ws : 1.0;
  if (from) { /* the caller's pieces (scene_solve.c's start_from) */
    for (k = 0; k < m; ++k) {
      const double q = par[3 * k], *s = from + 3 * k;
      const sc_int code = (sc_int)s[0];
      const int zero_set = kind[k] == K_BOX && !(q > 0);
      p.lam[k] = 0.0;
      p.state[k] = zero_set || (code == S_ZERO && kind[k] != K_FREE) ? S_ZERO : S_HELD;
      if (p.state[k] == S_ZERO) continue;
      p.lam[k] = s[1];
      if (code >= S_SLIDE && kind[k] == K_BOX) {
        p.lam[k] = code == 4 ? -q : q;
        p.state[k] = S_SLIDE;
      }
    }
#define TINY_FROM(r) ok = passes_##r(&p, FROM_PASSES, &count, res)
#define TINY_FROM_F(r) ok = passes_fma_##r(&p, FROM_PASSES, &count, res)
    TINY_CHOSEN(fused, m, TINY_FROM, TINY_FROM_F);
#undef TINY_FROM
#undef TINY_FROM_F
    if (ok < 0) return 0;
  }
  if (!ok) { /* the held guess: every block held (or its set zero) */
    for (k = 0; k < m; ++k) {
      p.lam[k] = 0.0;
      p.state[k] = kind[k] == K_BOX && !(par[3 * k] > 0) ? S_ZERO : S_HELD;
    }
#define TINY_GUESS(r) ok = passes_##r(&p, GUESS_PASSES, &count, res)
#define TINY_GUESS_F(r) ok = passes_fma_##r(&p, GUESS_PASSES, &count, res)
    TINY_CHOSEN(fused, m, TINY_GUESS, TINY_GUESS_F);
#undef TINY_GUESS
#undef TINY_GUESS_F
    if (ok <= 0) return 0;
  }
  if (!tight_holds(m, &p, res)) return 0; /* (the general path switches and solves it) */
  for (k = 0; k < m; ++k) /* a degenerate answer (sc_still): the minimum-norm face's */
    if (p.state[k] != S_HELD && !(fabs(p.w[k]) > TOL_ACCEPT * p.W)) return 0;
  for (k = 0; k < m; ++k) /* a contact's force below zero by rounding: zero */
    if (kind[k] == K_UNILATERAL && p.lam[k] < 0) {
      p.lam[k] = 0.0;
      moved = 1;
    }
  if (moved) {
#define TINY_FINAL(r) final_##r(&p, res)
#define TINY_FINAL_F(r) final_fma_##r(&p, res)
    TINY_CHOSEN(fused, m, TINY_FINAL, TINY_FINAL_F);
#undef TINY_FINAL
#undef TINY_FINAL_F
  }
  memset(info, 0, sizeof(double) * INFO_WIDTH);
  info[INFO_PRIMAL] = res[0];
  info[INFO_DUAL] = res[1];
  info[INFO_COMPL] = res[2];
  info[INFO_PASSES] = (double)count;
  for (k = 0; k < m; ++k) { /* on the set's boundary without sliding: stick at the limit */
    if (p.state[k] == S_SLIDE && fabs(p.w[k]) <= TOL_ACCEPT * p.W) p.state[k] = S_HELD;
    state_out[k] = p.state[k] == S_SLIDE ? (p.lam[k] > 0 ? 3.0 : 4.0) : (double)p.state[k];
    lam_out[k] = p.lam[k];
    w_out[k] = p.w[k];
  }
  sc_tiny_accel(fused, m, n, shape, tt, L, Z, p.lam, a); /* a = L^-T D^-1 (g + Z lam) */
  return 1;
}

static int solve(sc_int m, sc_int n, int shape, const double *M, const double *f,
                 const double *A, const double *c, const sc_int *kind, const double *par,
                 const double *from, double *L, double *rc, sc_int *t, double *lam_out,
                 double *a, double *w_out, double *state_out, double *info) {
  return solve_body(0, m, n, shape, M, f, A, c, kind, par, from, L, rc, t, lam_out, a, w_out,
                    state_out, info);
}
#ifdef TINY_FMA
TINY_FUSED int solve_fma(sc_int m, sc_int n, int shape, const double *M, const double *f,
                         const double *A, const double *c, const sc_int *kind,
                         const double *par, const double *from, double *L, double *rc,
                         sc_int *t, double *lam_out, double *a, double *w_out,
                         double *state_out, double *info) {
  return solve_body(1, m, n, shape, M, f, A, c, kind, par, from, L, rc, t, lam_out, a, w_out,
                    state_out, info);
}
#endif

/* the copy a problem goes through: 1 the FMA copy (where the switch is 1 and the processor has
 * AVX2 and FMA), 0 the plain one */
static int fused_copy(void) {
#ifdef TINY_FMA
  return tiny_on == 1 && sc_tiny_fma();
#else
  return 0;
#endif
}
#ifdef TINY_FMA
#define TINY_SOLVE(...) (fused_copy() ? solve_fma(__VA_ARGS__) : solve(__VA_ARGS__))
#else
#define TINY_SOLVE(...) solve(__VA_ARGS__)
#endif

/* The problem's shape for setup (the objects' count, or -1), or -2 where it is not tiny;
 * diag: the caller's M has its rows from n_s on diagonal (else they are checked). */
static int tiny_shape(sc_int n, sc_int m, sc_int nb, const double *M, const sc_int *kind,
                      const sc_int *start, int diag) {
  sc_int i, j, k;
  int shape = (int)((n - SNAKECG_NS) / 3);
  if (!tiny_on || m < 1 || m > SC_TINY_M || nb != m || m > n || n > SC_TINY_N) return -2;
  for (k = 0; k < m; ++k)
    if (kind[k] < K_FREE || kind[k] > K_BOX || start[k] != k) return -2;
  if (n < SNAKECG_NS || n > SNAKECG_NS + 6 || (n - SNAKECG_NS) % 3 != 0) return -1;
  for (i = SNAKECG_NS; i < n && !diag; ++i) /* the objects' rows: their diagonal */
    for (j = 0; j < i; ++j)
      if (M[i * n + j] != 0.0) return -1;
  return shape;
}

SC_INTERNAL int sc_tiny_solve(sc_int n, sc_int m, sc_int nb, const double *M, const double *f,
                              const double *A, const double *c, const sc_int *kind,
                              const sc_int *start, const double *par, const double *from,
                              double *lam, double *a, double *w, double *state_out,
                              double *info) {
  double L[SC_TINY_N * SC_TINY_N], r[SC_TINY_N];
  sc_int t;
  int ok, shape = tiny_shape(n, m, nb, M, kind, start, 0);
  if (shape < -1) return 0;
  ok = TINY_SOLVE(m, n, shape, M, f, A, c, kind, par, from, L, r, &t, lam, a, w, state_out,
                  info);
  TINY_ADD(0, 1L);
  if (!ok) TINY_ADD(1, 1L);
  return ok;
}

SC_INTERNAL int sc_tiny_forward(sc_int n, sc_int m, sc_int nb, const double *M, const double *f,
                                const double *A, const sc_int *kind, const sc_int *start,
                                const double *par, const double *from, double *lam, double *a,
                                double *w, double *state_out, double *info, double *L,
                                double *r, sc_int *t) {
  int ok, shape = tiny_shape(n, m, nb, M, kind, start, 1);
  *t = -1;
  if (shape < -1) return 0;
  ok = TINY_SOLVE(m, n, shape, M, f, A, 0, kind, par, from, L, r, t, lam, a, w, state_out,
                  info);
  TINY_ADD(0, 1L);
  if (!ok) TINY_ADD(1, 1L);
  return ok;
}

SC_INTERNAL int sc_tiny_inertia(sc_int n, const double *M, const double *f, double *L,
                                double *r, sc_int *t) {
  int shape = (int)((n - SNAKECG_NS) / 3);
  if (n < SNAKECG_NS || n > SNAKECG_NS + 6 || (n - SNAKECG_NS) % 3 != 0) shape = -1;
  if (sc_tiny_factored(fused_copy(), n, shape, M, f, L, r, t)) return 1;
  *t = -1;
  return 0;
}

/* The tiny path switched on (mode 1: its FMA copy where the processor has AVX2 and FMA; 2: its
 * copy without FMA) or off (0: every problem to the general path), or left (-1); counts (2
 * doubles, or NULL): the problems tried and answered since the last read, then reset. Returns
 * the previous mode. */
int SNAKECG_EXPORT(core_scene_tiny)(sc_int mode, double *counts) {
  int prev = tiny_on;
  if (mode >= 0 && mode <= 2) tiny_on = (int)mode;
  if (counts) {
    long t = TINY_TAKE(0);
    long left = TINY_TAKE(1);
    counts[0] = (double)t, counts[1] = (double)(t - left);
  }
  return prev;
}
