/* snakecg's engine: one piece of the general-scene solve (scene_solve.c's active set) solved
 * to rounding, the held rows eliminated.
 *
 * On a piece (every block held, zero, or sliding on its set's boundary; scene_solve.c's
 * header), the unknowns are the forces lam_H of the held rows and the angle t_k of every
 * sliding 2-D block's force on its set's boundary (sc_on_boundary, by its direction
 * (cos t_k, sin t_k)); zero rows and saturated boxes have their forces fixed. The equations
 * are the dual's stationarity on the piece: w_H = 0 and T_k . w_k = 0 (no acceleration along
 * the boundary), w = G lam + b. The held equations are linear: with G_HH = P L D L^T P^T by
 * diagonal pivoting (dependent rows, pivots at most DEP_TOL of the first, dropped: the basic
 * solution), factored once,
 *   lam_H = lam_H0 + d0 + X (lam_S - lam_S0),   G_HH d0 = -w_H0,   G_HH X = -G_HS,
 * keeps w_H = 0 for every sliding force lam_S, and the sliding rows then read
 *   w_S = wt + S (lam_S - lam_S0),   S = G_SS + G_SH X = G_SS - Y^T D^-1 Y  (Y = L^-1 P^T G_HS),
 * the gradient of the dual with the held forces eliminated (Hessian S; X itself is never
 * formed). Newton on the angles alone: Jacobian T^T S T + diag(max(0, -lam_k . w_k)) (the
 * reduced Hessian on the sets' boundaries, dT/dt = -lam), a few unknowns, factored as
 * L D L^T (by diagonal pivoting where nearly singular), each direction turned by atan of its
 * step, the step halved until the reduced dual does not rise. Where rows nearly dependent
 * leave a residual that does not fall, they are kept (pivots down to 1e-15) and the piece
 * solved again. An active-set pass may stop the Newton early where a block certainly breaks
 * the KKT conditions (sc_polish). Where the solve keeps them (sc_piece_keep: a
 * contact-friction fixed point's inner solves, on one G), the factor, G_HS, D^-1 Y and S of
 * the last PIECE_KEEP pieces are taken again where the same piece comes back (the held rows'
 * right-hand side then by sc_psd_resolve: sc_psd_solve's operations, the same bits). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"
#include "scene_solve.h"

/* the angles' Newton matrix factored without pivoting where its pivots stay above this ratio to
 * its largest diagonal entry (far from DEP_TOL: the same rank as the pivoted factor's) */
#define ANGLE_TOL 1e-8
/* a pass's Newton stops early where a block breaks the KKT conditions by more than EARLY_TOL
 * (relative) and by EARLY_MARGIN times its change over the last full step, the residual having
 * fallen by EARLY_RATE at least over it (so the rest of the way moves it less) */
#define EARLY_TOL 1e-6
#define EARLY_MARGIN 3.0
#define EARLY_RATE 0.5

/* w = G lam + b */
SC_INTERNAL void sc_update_w(sc_problem *p) { sc_matvec_plus(p->m, p->G, p->lam, p->b, p->w); }

/* A piece's sliding rows come in pairs (n2 = 2 ns is even): the loops over them below go two
 * at a time, as two-lane vectors where the compiler has them (no remainder, no alignment or
 * alias checks: the same operations on the same numbers as one at a time; linalg.h's sc_p2).
 * x[c] += (a0 u0[c] + a1 u1[c]) + (a2 u2[c] + a3 u3[c]) (sg 1) or -= (sg -1), c in [c0, n). */
static inline void pairs4(double *restrict x, const double *restrict u0,
                          const double *restrict u1, const double *restrict u2,
                          const double *restrict u3, double a0, double a1, double a2, double a3,
                          sc_int c0, sc_int n, int sg) {
  sc_int c;
#if defined(__GNUC__)
  if (sg > 0)
    for (c = c0; c < n; c += 2)
      SC_P2(x + c) += (a0 * SC_P2C(u0 + c) + a1 * SC_P2C(u1 + c)) +
                      (a2 * SC_P2C(u2 + c) + a3 * SC_P2C(u3 + c));
  else
    for (c = c0; c < n; c += 2)
      SC_P2(x + c) -= (a0 * SC_P2C(u0 + c) + a1 * SC_P2C(u1 + c)) +
                      (a2 * SC_P2C(u2 + c) + a3 * SC_P2C(u3 + c));
#else
  for (c = c0; c < n; ++c)
    if (sg > 0) x[c] += (a0 * u0[c] + a1 * u1[c]) + (a2 * u2[c] + a3 * u3[c]);
    else x[c] -= (a0 * u0[c] + a1 * u1[c]) + (a2 * u2[c] + a3 * u3[c]);
#endif
}

/* x[c] += a u[c] (sg 1) or -= (sg -1), c in [c0, n), by pairs as pairs4 */
static inline void pairs1(double *restrict x, const double *restrict u, double a, sc_int c0,
                          sc_int n, int sg) {
  sc_int c;
#if defined(__GNUC__)
  if (sg > 0)
    for (c = c0; c < n; c += 2) SC_P2(x + c) += a * SC_P2C(u + c);
  else
    for (c = c0; c < n; c += 2) SC_P2(x + c) -= a * SC_P2C(u + c);
#else
  for (c = c0; c < n; ++c)
    if (sg > 0) x[c] += a * u[c];
    else x[c] -= a * u[c];
#endif
}

/* The reduced dual 1/2 D^T S D + wt^T D at D = lam_S - lam_S0 (ws = wt + S D, computed). */
static double reduced(sc_int n2, const double *S, const double *wt, const double *D,
                      double *restrict ws) {
  sc_int a, c;
  double v = 0.0;
  for (a = 0; a < n2; ++a) ws[a] = wt[a];
  for (c = 0; c + 3 < n2; c += 4) { /* S symmetric: column c is row c (four at a time) */
    const double *restrict s0 = S + c * n2, *restrict s1 = s0 + n2, *restrict s2 = s1 + n2,
                 *restrict s3 = s2 + n2, d0 = D[c], d1 = D[c + 1], d2 = D[c + 2], d3 = D[c + 3];
    pairs4(ws, s0, s1, s2, s3, d0, d1, d2, d3, 0, n2, 1);
  }
  for (; c < n2; ++c) pairs1(ws, S + c * n2, D[c], 0, n2, 1);
  for (a = 0; a < n2; ++a) v += 0.5 * D[a] * (wt[a] + ws[a]);
  return v;
}

/* The held forces at the sliding forces' change D: lam_H += d0 - G_HH^+ G_HS D, that is
 * d0 - P [L^-T z; 0] with z = D^-1 Y D (V = D^-1 Y, L the factor in A; z: rank scratch). */
static void held_forces(sc_int h, sc_int rank, sc_int n2, const double *A, const sc_int *ph,
                        const sc_int *hr, const double *V, const double *d0, const double *D,
                        double *z, double *lam) {
  sc_int i, k, c;
  for (i = 0; i < h; ++i) lam[hr[i]] += d0[i];
  if (n2 == 0) return;
  for (i = 0; i < rank; ++i) { /* (four partial sums; with vectors, (s0, s1) and (s2, s3)) */
    const double *restrict vi = V + i * n2;
#if defined(__GNUC__)
    sc_p2 s01 = {0.0, 0.0}, s23 = {0.0, 0.0};
    double s0;
    for (c = 0; c + 3 < n2; c += 4) {
      s01 += SC_P2C(vi + c) * SC_P2C(D + c);
      s23 += SC_P2C(vi + c + 2) * SC_P2C(D + c + 2);
    }
    for (s0 = s01[0]; c < n2; ++c) s0 += vi[c] * D[c];
    z[i] = (s0 + s01[1]) + (s23[0] + s23[1]);
#else
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (c = 0; c + 3 < n2; c += 4) {
      s0 += vi[c] * D[c], s1 += vi[c + 1] * D[c + 1];
      s2 += vi[c + 2] * D[c + 2], s3 += vi[c + 3] * D[c + 3];
    }
    for (; c < n2; ++c) s0 += vi[c] * D[c];
    z[i] = (s0 + s1) + (s2 + s3);
#endif
  }
  for (k = rank - 1; k > 0; --k) { /* L^T x = z by L's rows (contiguous) */
    const double *restrict ak = A + k * h, zk = z[k];
    for (i = 0; i < k; ++i) z[i] -= ak[i] * zk;
  }
  for (i = 0; i < rank; ++i) lam[hr[ph[i]]] -= z[i];
}

/* How far block k breaks the KKT conditions that scene_solve.c's kkt switches on (relative to
 * its own tolerance's scale; at most 0: not): a held block's forces l outside its set, a
 * sliding 2-D block's acceleration w (2) along its force's outward normal. */
static double breach(const sc_problem *p, sc_int k, const double *l, const double *w) {
  const double *q = p->par + 3 * k;
  double P[2], nx, ny;
  switch (p->kind[k]) {
    case K_UNILATERAL: return p->state[k] == S_HELD ? -l[0] / p->fscale : -1.0;
    case K_BOX: return p->state[k] == S_HELD && q[0] > 0 ? fabs(l[0]) / q[0] - 1.0 : -1.0;
    case K_DISC:
    case K_SPLIT:
      if (sc_zero_set(p, k))
        return -1.0; /* (the set {0}: kkt checks nothing there) */
      sc_block_P(p, k, l, P);
      if (p->state[k] == S_HELD) return sqrt(P[0] * l[0] * l[0] + P[1] * l[1] * l[1]) - 1.0;
      nx = P[0] * l[0];
      ny = P[1] * l[1];
      return (w[0] * nx + w[1] * ny) / (sqrt(nx * nx + ny * ny) * p->wscale);
    default: return -1.0;
  }
}

/* Every block's breach (above) at the iterate lam (m; the held forces taken at the sliding
 * forces' change D from it), ws its sliding rows' w: into bp, after stop is set where one
 * exceeds EARLY_TOL and EARLY_MARGIN times its change from bp's (cmp: bp holds the last
 * iterate's). lam is overwritten (the held forces). Returns stop. */
static int breaches(const sc_problem *p, sc_int h, sc_int rank, sc_int n2, const double *A,
                    const sc_int *ph, const sc_int *hr, const double *V, const double *d0,
                    const double *D, const double *ws, double *z, double *lam, double *bp,
                    int cmp) {
  sc_int k, s = 0;
  int stop = 0;
  if (h > 0) held_forces(h, rank, n2, A, ph, hr, V, d0, D, z, lam);
  for (k = 0; k < p->nb; ++k) {
    double e;
    if (p->state[k] == S_ZERO) continue;
    e = breach(p, k, lam + p->start[k], /* (ws: the sliding 2-D blocks' in sl's order) */
               p->state[k] == S_SLIDE && p->kind[k] >= K_DISC ? ws + 2 * s++ : NULL);
    if (cmp && e > EARLY_TOL && e > EARLY_MARGIN * fabs(e - bp[k])) stop = 1;
    bp[k] = e;
  }
  return stop;
}

/* The last PIECE_KEEP pieces' factors on one G (scene_solve.h): per piece, its key (the held
 * rows hr, h of them, in block order; the sliding 2-D blocks sl, ns; the pivot tolerance rc;
 * h -1: empty) and G_HH's factor (fac, h x h) with its pivots (ph) and rank, G_HS (U, h x
 * 2 ns), D^-1 Y (W, rank x 2 ns) and S (2 ns x 2 ns, mirrored). About half of a fixed
 * point's pieces are the last one's, two thirds one of the last four (10-joint scene). */
#define PIECE_KEEP 4
struct sc_piece_keep {
  sc_int next; /* (the entry replaced next) */
  struct {
    sc_int h, ns, rank, *hr, *sl, *ph;
    double rc, *fac, *U, *W, *S;
  } e[PIECE_KEEP];
};

/* Room for pieces of m rows and nb blocks (h + 2 ns <= m: h x 2 ns <= m^2 / 4), nothing kept;
 * one block (free()). NULL: out of memory. */
SC_INTERNAL sc_piece_keep *sc_piece_keep_new(sc_int m, sc_int nb) {
  const size_t q = (size_t)(m * m / 4 + m), nd = (size_t)(2 * m * m) + 2 * q,
               ni = (size_t)(2 * m + nb);
  sc_piece_keep *pk = (sc_piece_keep *)malloc(sizeof(sc_piece_keep) +
                                              PIECE_KEEP * (nd * sizeof(double) +
                                                            ni * sizeof(sc_int)));
  double *d;
  sc_int *iw, k;
  if (!pk) return NULL;
  d = (double *)(pk + 1);
  iw = (sc_int *)(d + PIECE_KEEP * nd);
  for (k = 0; k < PIECE_KEEP; ++k, d += nd, iw += ni) {
    pk->e[k].fac = d, pk->e[k].S = d + m * m, pk->e[k].U = d + 2 * m * m;
    pk->e[k].W = pk->e[k].U + q;
    pk->e[k].hr = iw, pk->e[k].ph = iw + m, pk->e[k].sl = iw + 2 * m;
  }
  sc_piece_forget(pk);
  return pk;
}

/* Nothing kept (G changed). */
SC_INTERNAL void sc_piece_forget(sc_piece_keep *pk) {
  sc_int k;
  for (k = 0; k < PIECE_KEEP; ++k) pk->e[k].h = -1;
  pk->next = 0;
}

/* The kept entry of the piece (hr, h; sl, ns; rc), -1: none. */
static sc_int piece_kept(const sc_piece_keep *pk, sc_int h, const sc_int *hr, sc_int ns,
                         const sc_int *sl, double rc) {
  sc_int k;
  for (k = 0; k < PIECE_KEEP; ++k)
    if (pk->e[k].h == h && pk->e[k].ns == ns && pk->e[k].rc == rc &&
        !memcmp(pk->e[k].hr, hr, sizeof(sc_int) * (size_t)h) &&
        !memcmp(pk->e[k].sl, sl, sizeof(sc_int) * (size_t)ns))
      return k;
  return -1;
}

/* The angles' Newton matrix J (ns x ns, its lower triangle by rows) = L D L^T without
 * pivoting (linalg.h's sc_ldl_factor: one division per pivot, none in the solve; L in Jc, d and
 * 1/d in dd) where every pivot is above ANGLE_TOL of J's largest diagonal entry: 1, else 0
 * (J's upper triangle filled where it is tried). work: ns doubles. */
static int angles_ldl(sc_int ns, double *J, double *Jc, double *dd, double *work) {
  sc_int s, t;
  double big = 0.0;
  for (s = 0; s < ns; ++s)
    if (J[s * ns + s] > big) big = J[s * ns + s];
  if (!(big > 0.0) || !isfinite(big)) return 0;
  for (s = 0; s < ns; ++s) /* (not tried where it must fail: a pivot is at most its diagonal
    entry, rounding included, while the pivots before it are positive) */
    if (!(J[s * ns + s] > ANGLE_TOL * big)) return 0;
  for (s = 0; s < ns; ++s)
    for (t = 0; t < s; ++t) J[t * ns + s] = J[s * ns + t]; /* (by columns: the upper) */
  sc_ldl_factor(ns, J, ns, NULL, Jc, ns, dd, dd + ns, NULL, 0.0, work);
  for (s = 0; s < ns; ++s)
    if (!(dd[s] > ANGLE_TOL * big)) return 0;
  return 1;
}

/* The piece's held rows hr (h) and sliding rows sr (n2) reduced: G_HH's factor (fac, h x h;
 * pivots ph, those above rc of the first kept: returns their number, the rank) with the held
 * rows' basic solution d0 of G_HH d0 = sc (sc: h, overwritten; sc2: h scratch), G_HS (U, h x n2),
 * D^-1 Y (W, rank x n2; X: Y, the same size) and S (n2 x n2). */
static sc_int reduce(const double *G, sc_int m, sc_int h, const sc_int *hr, sc_int n2,
                     const sc_int *sr, double rc, double *fac, double *sc, double *d0,
                     double *sc2, sc_int *ph, double *U, double *X, double *W, double *S) {
  sc_int i, k, t, a, c, rank = 0;
  if (h > 0) {
    for (i = 0; i < h; ++i)
      for (t = 0; t <= i; ++t) fac[i * h + t] = G[hr[i] * m + hr[t]];
    rank = sc_psd_solve(h, fac, h, sc, rc, d0, sc2, ph);
  }
  /* S = G_SS - G_SH G_HH^+ G_HS = G_SS - Y^T D^-1 Y with Y = L^-1 (P^T G_HS) on the kept rows
   * (G_HH = P L D L^T P^T), its upper triangle then mirrored: exactly symmetric */
  for (i = 0; i < h && n2 > 0; ++i) { /* G_HS gathered once (hr's order; G symmetric) */
    const double *gi = G + hr[i] * m;
    double *restrict ui = U + i * n2;
    for (c = 0; c < n2; c += 2) memcpy(ui + c, gi + sr[c], 2 * sizeof(double)); /* (a pair) */
  }
  for (i = 0; i < rank && n2 > 0; ++i) {
    double *restrict yi = X + i * n2, *restrict vi = W + i * n2;
    memcpy(yi, U + ph[i] * n2, sizeof(double) * (size_t)n2);
    for (k = 0; k + 3 < i; k += 4) { /* (four rows at a time) */
      const double *li = fac + i * h + k, *restrict y0 = X + k * n2, *restrict y1 = y0 + n2,
                   *restrict y2 = y1 + n2, *restrict y3 = y2 + n2;
      pairs4(yi, y0, y1, y2, y3, li[0], li[1], li[2], li[3], 0, n2, -1);
    }
    for (; k < i; ++k) pairs1(yi, X + k * n2, fac[i * h + k], 0, n2, -1);
    { /* (one division) */
      const double r = 1.0 / fac[i * h + i];
#if defined(__GNUC__)
      for (c = 0; c < n2; c += 2) SC_P2(vi + c) = SC_P2C(yi + c) * r;
#else
      for (c = 0; c < n2; ++c) vi[c] = yi[c] * r;
#endif
    }
  }
  for (a = 0; a < n2; ++a) {
    const double *ga = G + sr[a] * m;
    double *restrict sa = S + a * n2;
    for (c = a & ~(sc_int)1; c < n2; c += 2) /* (from a's pair: the lower entry, mirrored
      over below, updated alike) */
      memcpy(sa + c, ga + sr[c], 2 * sizeof(double));
  }
  for (a = 0; a < n2; ++a) {
    double *restrict sa = S + a * n2;
    for (i = 0; i + 3 < rank; i += 4) { /* (four rows of Y at a time) */
      const double *y = X + i * n2 + a, *restrict v0 = W + i * n2, *restrict v1 = v0 + n2,
                   *restrict v2 = v1 + n2, *restrict v3 = v2 + n2;
      const double y0 = y[0], y1 = y[n2], y2 = y[2 * n2], y3 = y[3 * n2];
      pairs4(sa, v0, v1, v2, v3, y0, y1, y2, y3, a & ~(sc_int)1, n2, -1);
    }
    for (; i < rank; ++i) pairs1(sa, W + i * n2, X[i * n2 + a], a & ~(sc_int)1, n2, -1);
  }
  for (a = 0; a < n2; a += 2) { /* (by 2 x 2 blocks) */
    double *restrict r0 = S + a * n2, *restrict r1 = r0 + n2;
    for (c = 0; c < a; c += 2) {
      const double *q0 = S + c * n2 + a, *q1 = q0 + n2;
      r0[c] = q0[0], r0[c + 1] = q1[0], r1[c] = q0[1], r1[c + 1] = q1[1];
    }
    r1[a] = r0[a + 1];
  }
  return rank;
}

/* The piece's equations from the current lam (pivots above rc kept); fn_out: their largest
 * residual after (held rows: |w|, sliding blocks: |T . w| / |T|), fk_out: the same without
 * the held rows dropped as dependent. Returns the rank defect of the held rows' and the
 * angles' matrices. Scratch: work, iwork (scene_solve_work's). */
static sc_int piece(sc_problem *p, double rc, double *work, sc_int *iwork, double *fn_out,
                    double *fk_out, int kept, int *early) {
  const sc_int m = p->m, nb = p->nb;
  const double *G = p->G;
  sc_int *hr = iwork, *sl = hr + m, *ph = sl + nb, *pj = ph + m, *sr = pj + nb;
  sc_int h = 0, ns = 0, n2, k, i, s, t, a, c, it, rank = 0, rj = 0;
  double *X, *S, *J, *d0, *sc, *sc2, *th, *th0, *T, *F, *dx, *l0, *D, *wt, *ws, *W, *Jc, *bp,
         *pl, *pD, *pws, *rad, *U, *fac = work, fn = 0.0, v = 0.0, fprev = INFINITY;
  sc_piece_keep *pk = p->pk;
  sc_int kk = -1;
  int full = 0, known = 0, stop = 0;
  for (k = 0; k < nb; ++k) {
    sc_int r = p->start[k], nk = sc_block_size(p->kind[k]);
    if (p->state[k] == S_ZERO || (p->state[k] == S_SLIDE && p->kind[k] == K_BOX))
      for (i = 0; i < nk; ++i) { /* (fixed forces; w kept along where it was G lam + b) */
        const double l = p->state[k] == S_ZERO ? 0.0 : p->lam[r] >= 0 ? p->par[3 * k] :
                         -p->par[3 * k], d = l - p->lam[r + i];
        const double *restrict col = G + (r + i) * m; /* G symmetric: column r + i */
        double *restrict wv = p->w;
        p->lam[r + i] = l;
        if (kept && d != 0.0)
          for (t = 0; t < m; ++t) wv[t] += col[t] * d;
      }
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
  th0 = th + n2;
  F = th0 + n2;
  dx = F + ns;
  T = dx + ns;
  l0 = T + n2;
  D = l0 + n2;
  wt = D + n2;
  ws = wt + n2;
  W = ws + n2; /* h x n2 */
  Jc = W + h * n2;
  bp = Jc + ns * ns;
  pl = bp + nb; /* the early rule's last iterate: lam, D, ws */
  pD = pl + m;
  pws = pD + n2;
  rad = pws + n2;
  U = rad + ns; /* G_HS, h x n2 */
  for (s = 0; s < ns; ++s) {
    double *l = p->lam + p->start[sl[s]];
    const double e0 = l[0], e1 = l[1];
    sc_direction_of(p, sl[s], l, th + 2 * s);
    sc_on_boundary(p, sl[s], th + 2 * s, l, T + 2 * s); /* (radially onto the boundary) */
    if (kept && (l[0] != e0 || l[1] != e1)) {
      const double d0v = l[0] - e0, d1v = l[1] - e1, *restrict c0 = G + (l - p->lam) * m,
                   *restrict c1 = c0 + m;
      double *restrict wv = p->w;
      for (t = 0; t < m; ++t) wv[t] += c0[t] * d0v + c1[t] * d1v;
    }
    l0[2 * s] = l[0];
    l0[2 * s + 1] = l[1];
    D[2 * s] = D[2 * s + 1] = 0.0;
    k = sl[s]; /* (the set's size: an angle's step in force) */
    rad[s] = p->par[3 * k] + (p->kind[k] == K_SPLIT ? p->par[3 * k + 1] : 0.0);
  }
  for (c = 0; c < n2; ++c) sr[c] = p->start[sl[c / 2]] + c % 2;
  if (!kept) sc_update_w(p);
  for (i = 0; i < h; ++i) sc[i] = -p->w[hr[i]]; /* (the held rows' right-hand side) */
  if (pk && (kk = piece_kept(pk, h, hr, ns, sl, rc)) >= 0) { /* (kept: its factors) */
    fac = pk->e[kk].fac, U = pk->e[kk].U, W = pk->e[kk].W, S = pk->e[kk].S;
    ph = pk->e[kk].ph, rank = pk->e[kk].rank;
    if (h > 0) sc_psd_resolve(h, fac, h, rank, ph, 1, sc, d0, sc2);
  } else {
    if (pk) { /* (built in the entry replaced next, its key set once built) */
      kk = pk->next, pk->next = (pk->next + 1) % PIECE_KEEP, pk->e[kk].h = -1;
      fac = pk->e[kk].fac, U = pk->e[kk].U, W = pk->e[kk].W, S = pk->e[kk].S;
    }
    rank = reduce(G, m, h, hr, n2, sr, rc, fac, sc, d0, sc2, ph, U, X, W, S);
    if (pk) {
      pk->e[kk].h = h, pk->e[kk].ns = ns, pk->e[kk].rank = rank, pk->e[kk].rc = rc;
      memcpy(pk->e[kk].hr, hr, sizeof(sc_int) * (size_t)h);
      memcpy(pk->e[kk].sl, sl, sizeof(sc_int) * (size_t)ns);
      memcpy(pk->e[kk].ph, ph, sizeof(sc_int) * (size_t)h);
    }
  }
  for (a = 0; a < n2; ++a) wt[a] = p->w[sr[a]]; /* wt = w_S + G_SH d0 */
  for (i = 0; i < h && n2 > 0; ++i) /* (each wt[a]'s terms in hr's order, as one sum) */
    pairs1(wt, U + i * n2, d0[i], 0, n2, 1);
  memcpy(ws, wt, sizeof(double) * (size_t)n2); /* (the reduced dual's gradient at D = 0) */
  for (it = 0; it < 40 && ns > 0; ++it) { /* Newton on the angles */
    double v0 = v, tstep = 1.0, step = 0.0; /* (at it 0: D = 0, ws = wt, v = 0) */
    sc_int ls;
    fn = 0.0;
    for (s = 0; s < ns; ++s) {
      const double *Ts = T + 2 * s;
      F[s] = Ts[0] * ws[2 * s] + Ts[1] * ws[2 * s + 1];
      fn = sc_max(fn, fabs(F[s]) / (sqrt(Ts[0] * Ts[0] + Ts[1] * Ts[1]) + 1e-300));
    }
    if (it > 0 && fn <= 1e-15 * p->wscale) break; /* (the first step always: its rank) */
    if (*early && it > 0 && full && fn < EARLY_RATE * fprev) { /* a pass that will switch */
      if (!known) { /* the first iterate of a run kept; its breaches taken only if the next
        iterate is checked too (often it is not) */
        memcpy(pl, p->lam, sizeof(double) * (size_t)m);
        memcpy(pD, D, sizeof(double) * (size_t)n2);
        memcpy(pws, ws, sizeof(double) * (size_t)n2);
        known = 2;
      } else {
        if (known == 2) breaches(p, h, rank, n2, fac, ph, hr, W, d0, pD, pws, sc2, pl, bp, 0);
        memcpy(sc, p->lam, sizeof(double) * (size_t)m);
        stop = breaches(p, h, rank, n2, fac, ph, hr, W, d0, D, ws, sc2, sc, bp, 1);
        known = 1;
      }
      if (stop) break;
    } else
      known = 0;
    fprev = fn;
    for (s = 0; s < ns; ++s) {
      const double *Ts = T + 2 * s;
#if defined(__GNUC__)
      const sc_p2 ts = SC_P2C(Ts);
      for (t = 0; t <= s; ++t) { /* (the same products and sums, by pairs) */
        const double *r0 = S + 2 * s * n2 + 2 * t;
        const sc_p2 tt = SC_P2C(T + 2 * t), e0 = SC_P2C(r0) * tt, e1 = SC_P2C(r0 + n2) * tt,
                    q = (sc_p2){e0[0], e1[0]} + (sc_p2){e0[1], e1[1]}, g = ts * q;
        J[s * ns + t] = g[0] + g[1];
      }
#else
      for (t = 0; t <= s; ++t) {
        const double *Tt = T + 2 * t, *r0 = S + 2 * s * n2 + 2 * t, *r1 = r0 + n2;
        J[s * ns + t] = Ts[0] * (r0[0] * Tt[0] + r0[1] * Tt[1]) +
                        Ts[1] * (r1[0] * Tt[0] + r1[1] * Tt[1]);
      }
#endif
      { /* the boundary's curvature: -lam . w, at least 0 */
        const double *l = p->lam + p->start[sl[s]];
        J[s * ns + s] += sc_max(0.0, -(l[0] * ws[2 * s] + l[1] * ws[2 * s + 1]));
      }
      F[s] = -F[s];
    }
    if (angles_ldl(ns, J, Jc, sc, sc2)) { /* (J well inside the positive definite cone; the
      pivoted LDL^T, which drops dependent angles, elsewhere) */
      for (s = 0; s < ns; ++s) dx[s] = F[s];
      sc_ldl_solve(ns, Jc, ns, sc + ns, dx);
      rj = ns;
    } else
      rj = sc_psd_solve(ns, J, ns, F, rc, dx, sc2, pj);
    { /* (th0: the directions at the iterate; th, every entry written in each trial) */
      double *tw = th0;
      th0 = th;
      th = tw;
    }
    for (ls = 0; ls < 40; ++ls, tstep *= 0.5) { /* the step, halved while the dual rises */
      for (s = 0; s < ns; ++s) {
        double *l = p->lam + p->start[sl[s]];
        const double *u = th0 + 2 * s, e = tstep * dx[s], x = u[0] - e * u[1],
                     y = u[1] + e * u[0], r = 1.0 / sqrt(x * x + y * y);
        th[2 * s] = x * r; /* (turned by atan(e): the angle's Newton step to second order) */
        th[2 * s + 1] = y * r;
        sc_on_boundary(p, sl[s], th + 2 * s, l, T + 2 * s);
        D[2 * s] = l[0] - l0[2 * s];
        D[2 * s + 1] = l[1] - l0[2 * s + 1];
      }
      v = reduced(n2, S, wt, D, ws); /* (ws at the step taken: the next iteration's) */
      if (v <= v0 + 1e-14 * (fabs(v0) + p->fscale * p->wscale)) break;
    }
    full = ls == 0;
    for (s = 0; s < ns; ++s) step = sc_max(step, fabs(tstep * dx[s]) * rad[s]);
    if (!(step > 1e-15 * p->fscale)) break;
  }
  if (stop) /* (the held forces at this iterate: the early rule's, in sc) */
    for (i = 0; i < h; ++i) p->lam[hr[i]] = sc[hr[i]];
  else if (h > 0)
    held_forces(h, rank, n2, fac, ph, hr, W, d0, D, sc2, p->lam);
  sc_update_w(p);
  fn = 0.0;
  for (i = 0; i < rank; ++i) fn = sc_max(fn, fabs(p->w[hr[ph[i]]])); /* (the kept rows) */
  for (s = 0; s < ns; ++s) {
    const double *Ts = T + 2 * s, *w = p->w + p->start[sl[s]];
    fn = sc_max(fn, fabs(Ts[0] * w[0] + Ts[1] * w[1]) /
                      (sqrt(Ts[0] * Ts[0] + Ts[1] * Ts[1]) + 1e-300));
  }
  *fk_out = fn;
  for (i = rank; i < h; ++i) fn = sc_max(fn, fabs(p->w[hr[ph[i]]])); /* (the dropped rows) */
  *fn_out = fn;
  *early = stop;
  return (h - rank) + (ns - rj);
}

/* piece, solved again from its own result while the residual is above rounding (at most
 * three times): where it does not halve with rows dropped and stays above 1e-12 of the
 * scale, they are kept (pivots to 1e-15). Where only the dropped rows are above rounding,
 * solving again from the result cannot lower their residual (they stay dropped): they are
 * kept at once where it is above 1e-12, else the piece stands. early: as sc_polish's. */
static sc_int rounds(sc_problem *p, double *work, sc_int *iwork, double *fn, int kept,
                     int *early) {
  double rc = DEP_TOL, prev = INFINITY, fk;
  sc_int defect = 0, round;
  for (round = 0; round < 3; ++round, kept = 1) {
    defect = piece(p, rc, work, iwork, fn, &fk, kept, early);
    if (*early || !(*fn > 1e-14 * p->wscale)) break;
    if (!(fk > 1e-14 * p->wscale)) { /* (the dropped rows' residual alone: fn above it) */
      if (!(*fn > 1e-12 * p->wscale) || rc < DEP_TOL) break;
      rc = 1e-15;
      continue;
    }
    if (defect > 0 && !(*fn < 0.5 * prev) && *fn > 1e-12 * p->wscale) rc = 1e-15;
    prev = *fn;
  }
  return defect;
}

/* The piece's equations solved (returns their rank defect, 0: independent); where that stops
 * short of rounding with a sliding block that does not move (at its set's limit: the angle's
 * equation is degenerate there), that block is held instead and the piece solved again.
 * early (in): the Newton may stop where a block certainly breaks the KKT conditions (out: it
 * did; lam and w are then the iterate's, for the active set to switch on). kept: w is
 * G lam + b on entry (updated along as the piece fixes forces, not recomputed). */
SC_INTERNAL sc_int sc_polish(sc_problem *p, double *work, sc_int *iwork, int kept, int *early) {
  double fn;
  sc_int k, defect = rounds(p, work, iwork, &fn, kept, early);
  int again = 0;
  if (*early || !(fn > 1e-14 * p->wscale)) return defect;
  for (k = 0; k < p->nb; ++k)
    if (p->state[k] == S_SLIDE && p->kind[k] >= K_DISC && sc_still(p, k)) {
      p->state[k] = S_HELD;
      again = 1;
    }
  return again ? rounds(p, work, iwork, &fn, 1, early) : defect;
}
