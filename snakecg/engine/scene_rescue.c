/* snakecg's engine: pieces with nearly dependent held rows solved from Z itself (scene_solve.c's
 * last resort, every RESCUE_SWEEPS of its Gauss-Seidel sweeps without a solved piece).
 *
 * The dual's piece (scene_piece.c) eliminates the held rows through G_HH = Z_H^T Z_H. Where
 * Z_H's columns are delta from dependent, G_HH holds delta^2: for delta below about 1e-7
 * that is below G's rounding, and rows that are only nearly dependent are taken as dependent
 * (dropped); their accelerations then stay at about delta of their scale, beyond the
 * acceptance, whatever piece the sweeps read, while the sweeps' forces drift along the nearly
 * singular direction. Z_H resolves them: its pivoted QR keeps a row down to RESCUE_DEP of the
 * first pivot, far below delta and far above the exactly dependent rows' rounding (1e-16).
 *
 * A piece is solved in the primal, as scene_primal.c's (y = L^T a, g = L^-1 f, Z = L^-1 A^T,
 * w = Z^T y + c):
 *   minimise 1/2 |y - g_F|^2 + sum_{sliding disc i} s_i |w_i|   subject to w_B = 0,
 * B the held rows that Z_H's pivoted QR keeps (the basic ones; the others are combinations
 * of them to rounding, their forces zero: the face's basic solution), g_F the free motion
 * with the saturated boxes' forces. Newton with the equalities: H = I + sum_i (s_i / |w_i|)
 * v_i v_i^T = R R^T (v_i = Z_i u_i^perp), e = R^T dy, Y = R^-1 Z_B = Q_1 R_1 (Householder),
 *   e = -(I - Q_1 Q_1^T) q + Q_1 R_1^-T r_B,   q = R^-1 grad,   r_B = -(Z_B^T y + c_B),
 * the projection and the equalities' correction by orthogonal factors (no product Y^T Y, no
 * squared condition); the first step whole (onto the equalities), the later ones halved while
 * the objective rises. A sliding disc keeps its last direction u_i while its |w_i| is below
 * SLIDE_FLOOR of the scale (at first its force's). Then the forces: the sliding discs'
 * -s_i u_i, the basic rows' Z_B lam_B = y - g_F - Z_S lam_S by Z_B's QR, every row's w from
 * g + Z lam. A sliding split ellipse (anisotropic ground) on its force's side is such a
 * disc, of radius 1 on its rows scaled by that side's semi-axes (its support function |D w|,
 * its force -D u); a box at its bound is a fixed force.
 *
 * The active set (sc_rescue) starts from the sweeps' reading and switches one block a pass,
 * the one that breaks its piece the most: switching every violated block at once, as
 * scene_solve.c's passes do, wanders on these pieces. Where the held rows are dependent, the
 * face's forces are first moved into their sets along Z_F's null space (scene_sets.c's
 * minimum-norm choice with that basis). Every answer is the caller's to certify (its KKT
 * check, on w from Z): the rescue finds pieces, it does not relax the acceptance. */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"
#include "scene_rescue.h"

#define RESCUE_DEP 1e-12 /* Z_H's pivots at most this of the first: dependent rows */
#define RESCUE_STEPS 40  /* Newton steps at most */
#define RESCUE_PASSES 10 /* active-set passes at most (one switch each) */
#define SLIDE_FLOOR 1e-10 /* a sliding disc's |w| (of the scale) below which its direction stays */

/* Every row's w = Z^T (g + Z lam) + c, from Z (y: n scratch, left g + Z lam). */
SC_INTERNAL void sc_rescue_w(sc_problem *p, const double *Z, const double *g, const double *c,
                             double *y) {
  const sc_int n = p->n, m = p->m;
  sc_int i, j;
  for (i = 0; i < n; ++i) {
    double t = g[i];
    for (j = 0; j < m; ++j) t += Z[i * m + j] * p->lam[j];
    y[i] = t;
  }
  for (j = 0; j < m; ++j) {
    double u = c ? c[j] : 0.0;
    for (i = 0; i < n; ++i) u += Z[i * m + j] * y[i];
    p->w[j] = u;
  }
}

/* the objective 1/2 |y - g_F|^2 + sum s_i |w_i| at y (sl, rad, sd: the sliding discs' first
 * rows, radii and rows' scales; ws, nws: their scaled w, |w|) */
static double objective(sc_int n, const sc_problem *p, const double *Z, const double *c,
                        const sc_int *sl, const double *rad, const double *sd, sc_int ns,
                        const double *gF, const double *y, double *ws, double *nws) {
  sc_int i, j, e;
  double v = 0.0;
  for (i = 0; i < n; ++i) v += 0.5 * (y[i] - gF[i]) * (y[i] - gF[i]);
  for (j = 0; j < ns; ++j) {
    for (e = 0; e < 2; ++e) {
      double u = c ? c[sl[j] + e] : 0.0;
      for (i = 0; i < n; ++i) u += Z[i * p->m + sl[j] + e] * y[i];
      ws[2 * j + e] = sd[2 * j + e] * u;
    }
    nws[j] = sqrt(ws[2 * j] * ws[2 * j] + ws[2 * j + 1] * ws[2 * j + 1]);
    v += rad[j] * nws[j];
  }
  return v;
}

/* The piece of p->state solved from Z (the header's); its forces' start in p->lam (the sliding
 * discs' directions, the start y = g_F + Z lam). p->lam and p->w (every row's, from g + Z lam)
 * filled; returns 1 (def: the held rows' rank defect by Z_H's QR, their basic forces), or 0
 * where it does not treat the piece (p->lam, p->w then undefined). A sliding split ellipse is
 * a disc of radius 1 on its rows scaled by its semi-axes (sd, scene_sets.h's sc_piece_parts),
 * on its force's side. Work: n^2 + 2 n m + 6 n + 11 m doubles, 4 m sc_ints. The QR factors
 * are linalg.h's. */
static int rescue_piece(sc_problem *p, const double *Z, const double *g, const double *c,
                        double *work, sc_int *iwork, sc_int *def) {
  const sc_int n = p->n, m = p->m;
  double *R = work, *X = R + n * n, *Y = X + n * m, *gF = Y + n * m, *y = gF + n, *grad = y + n,
         *q = grad + n, *dy = q + n, *yt = dy + n, *ws = yt + n, *nws = ws + m, *beta = nws + m,
         *rd = beta + m, *rb = rd + m, *ud = rb + m, *xb = ud + m, *qw = xb + m, *rad = qw + m,
         *sd = rad + m;
  sc_int *hr = iwork, *sl = hr + m, *perm = sl + m, *hp = perm + m, h = 0, ns = 0, rank, i, j,
         k, it;
  double phi, ysc = sqrt(p->fscale * p->wscale);
  if (!sc_piece_parts(p, n, Z, g, gF, hr, &h, sl, rad, &ns, sd))
    return 0; /* (the piece: held rows, fixed forces, sliding discs; scene_sets.h) */
  for (j = 0; j < ns; ++j) /* (each disc's sliding direction u_j from its force, until its w
    gives one) */
    ud[2 * j] = -p->lam[sl[j]] / (rad[j] * sd[2 * j]),
    ud[2 * j + 1] = -p->lam[sl[j] + 1] / (rad[j] * sd[2 * j + 1]);
  /* Z_H's pivoted QR (n x h, row-major): its rank, the basic rows first in hr */
  for (i = 0; i < n; ++i) {
    dy[i] = 0.0;
    for (j = 0; j < h; ++j) X[i * h + j] = Z[i * m + hr[j]];
  }
  rank = h > 0 ? sc_qr_least_squares(n, h, X, h, dy, RESCUE_DEP, xb, qw, perm) : 0;
  for (j = 0; j < h; ++j) hp[j] = hr[perm[j]];
  memcpy(hr, hp, sizeof(sc_int) * (size_t)h);
  *def = h - rank;
  /* the start y = g_F + Z lam over the sliding discs and held rows (dropped rows: lam 0) */
  for (j = rank; j < h; ++j) p->lam[hr[j]] = 0.0;
  for (i = 0; i < n; ++i) {
    double t = gF[i];
    for (j = 0; j < ns; ++j)
      t += Z[i * m + sl[j]] * p->lam[sl[j]] + Z[i * m + sl[j] + 1] * p->lam[sl[j] + 1];
    for (j = 0; j < rank; ++j) t += Z[i * m + hr[j]] * p->lam[hr[j]];
    y[i] = t;
  }
  phi = objective(n, p, Z, c, sl, rad, sd, ns, gF, y, ws, nws);
  for (it = 0; it < RESCUE_STEPS; ++it) {
    double step = 0.0, tstep = 1.0, ymax = ysc;
    for (j = 0; j < ns; ++j)
      if (nws[j] > SLIDE_FLOOR * p->wscale) /* (else the last direction: a disc at rest) */
        ud[2 * j] = ws[2 * j] / nws[j], ud[2 * j + 1] = ws[2 * j + 1] / nws[j];
    /* the gradient y - g_F + sum s_j Z_j u_j, the Hessian I + sum (s_j / |w_j|) v_j v_j^T */
    for (i = 0; i < n; ++i) grad[i] = y[i] - gF[i];
    for (i = 0; i < n * n; ++i) R[i] = 0.0;
    for (i = 0; i < n; ++i) R[i * n + i] = 1.0;
    for (j = 0; j < ns; ++j) {
      const double s = rad[j], u0 = ud[2 * j], u1 = ud[2 * j + 1],
                   f = s / fmax(nws[j], SLIDE_FLOOR * p->wscale);
      double *v = yt;
      for (i = 0; i < n; ++i) {
        const double z0 = sd[2 * j] * Z[i * m + sl[j]], z1 = sd[2 * j + 1] * Z[i * m + sl[j] + 1];
        grad[i] += s * (z0 * u0 + z1 * u1);
        v[i] = -z0 * u1 + z1 * u0;
      }
      for (i = 0; i < n; ++i)
        for (k = 0; k <= i; ++k) R[i * n + k] += f * v[i] * v[k];
    }
    if (!sc_cholesky(n, R, n, 0.0)) return 0;
    /* q = R^-1 grad, Y = R^-1 Z_B (column j at Y + j n) = Q_1 R_1, r_B = -(Z_B^T y + c_B) */
    memcpy(q, grad, sizeof(double) * (size_t)n);
    sc_lower_solve(n, R, q);
    for (j = 0; j < rank; ++j) {
      double *yj = Y + j * n, u = c ? c[hr[j]] : 0.0;
      for (i = 0; i < n; ++i) u += Z[i * m + hr[j]] * y[i], yj[i] = Z[i * m + hr[j]];
      rb[j] = -u;
      sc_lower_solve(n, R, yj);
    }
    sc_qr_factor(n, rank, Y, n, rd, beta);
    /* e = -(I - Q_1 Q_1^T) q + Q_1 R_1^-T r_B, in dy: Q^T q with its first rank entries
     * replaced by R_1^-T r_B, the rest negated, then Q; dy = R^-T e */
    memcpy(dy, q, sizeof(double) * (size_t)n);
    sc_qr_apply(n, rank, Y, n, beta, dy, 1);
    for (j = 0; j < rank; ++j) {
      double s = rb[j];
      if (!(rd[j] != 0.0)) return 0;
      for (k = 0; k < j; ++k) s -= Y[k + j * n] * dy[k];
      dy[j] = s / rd[j];
    }
    for (i = rank; i < n; ++i) dy[i] = -dy[i];
    sc_qr_apply(n, rank, Y, n, beta, dy, 0);
    sc_lower_t_solve(n, R, dy);
    for (i = 0; i < n; ++i) step = fmax(step, fabs(dy[i])), ymax = fmax(ymax, fabs(y[i]));
    for (;;) { /* the first step whole (onto the equalities); later ones halved while phi rises */
      double pt;
      for (i = 0; i < n; ++i) yt[i] = y[i] + tstep * dy[i];
      pt = objective(n, p, Z, c, sl, rad, sd, ns, gF, yt, ws, nws);
      if (it == 0 || pt <= phi || tstep < 1e-10) {
        phi = pt;
        break;
      }
      tstep *= 0.5;
    }
    memcpy(y, yt, sizeof(double) * (size_t)n);
    if (step * tstep <= 1e-15 * ymax) break;
  }
  /* the forces: sliding discs -s_j u_j; basic rows Z_B lam_B = y - g_F - Z_S lam_S (least
   * squares by Z_B's QR), dropped rows 0 */
  for (j = 0; j < ns; ++j) {
    const double s = rad[j];
    if (nws[j] > SLIDE_FLOOR * p->wscale)
      ud[2 * j] = ws[2 * j] / nws[j], ud[2 * j + 1] = ws[2 * j + 1] / nws[j];
    p->lam[sl[j]] = -s * sd[2 * j] * ud[2 * j];
    p->lam[sl[j] + 1] = -s * sd[2 * j + 1] * ud[2 * j + 1];
  }
  for (i = 0; i < n; ++i) {
    double t = y[i] - gF[i];
    for (j = 0; j < ns; ++j)
      t -= Z[i * m + sl[j]] * p->lam[sl[j]] + Z[i * m + sl[j] + 1] * p->lam[sl[j] + 1];
    dy[i] = t;
    for (j = 0; j < rank; ++j) X[i * rank + j] = Z[i * m + hr[j]];
  }
  if (rank > 0 && sc_qr_least_squares(n, rank, X, rank, dy, 0.0, xb, qw, perm) < rank) return 0;
  for (j = 0; j < rank; ++j) p->lam[hr[j]] = xb[j];
  sc_rescue_w(p, Z, g, c, y);
  return 1;
}

/* Where the held rows are dependent (the piece's rank defect), the forces on the face (every
 * block held or without acceleration) moved inside their sets, minimum-norm, along Z_F's null
 * space (scene_sets.c's sc_min_norm_basis; the accelerations may move by eps of their scale):
 * Z_F^T's pivoted Householder QR (pivots down to RESCUE_DEP of the first, as the piece's)
 * picks the coordinates that span its columns, and Q's last nf - rank columns from their
 * unpivoted QR are the null space, orthonormal. Then every row's w from g + Z lam. Returns
 * sc_min_norm_basis's answer (0: nothing to choose). */
static int rescue_face(sc_problem *p, const double *Z, const double *g, const double *c,
                       double *work, double eps) {
  const sc_int n = p->n, m = p->m;
  sc_int F[512], fk[512], perm[512], nf, rank, i, j, k, t;
  double *V, *X, *C, *rd, *beta, *zr, *xs, *qw, *rest;
  int ans;
  if (n > 512 || (nf = sc_face_rows(p, F, fk)) == 0) return 0;
  V = work, X = V + nf * nf, C = X + nf * n, rd = C + nf * n, beta = rd + n, zr = beta + n,
  xs = zr + nf, qw = xs + n, rest = qw + n;
  for (j = 0; j < nf; ++j) { /* Z_F^T (nf x n, row-major): its rank, the coordinates that
    span its columns first in perm */
    zr[j] = 0.0;
    for (i = 0; i < n; ++i) X[j * n + i] = Z[i * m + F[j]];
  }
  rank = sc_qr_least_squares(nf, n, X, n, zr, RESCUE_DEP, xs, qw, perm);
  if (rank >= nf) return 0;
  for (k = 0; k < rank; ++k) /* those columns (column k at C + k nf), their unpivoted QR */
    for (j = 0; j < nf; ++j) C[k * nf + j] = Z[perm[k] * m + F[j]];
  sc_qr_factor(nf, rank, C, nf, rd, beta);
  for (t = 0; t < nf - rank; ++t) { /* the null space: Q's last nf - rank columns */
    double *v = V + t * nf;
    for (j = 0; j < nf; ++j) v[j] = j == rank + t ? 1.0 : 0.0;
    sc_qr_apply(nf, rank, C, nf, beta, v, 0);
  }
  ans = sc_min_norm_basis(p, Z, nf, F, fk, V, nf - rank, rest, eps, 0.0, NULL, NULL);
  sc_rescue_w(p, Z, g, c, rest);
  return ans;
}

/* The rescue's active-set switch (the caller's KKT check switched p->state from was): only the
 * block that breaks its piece the most keeps its switch (a contact's pull or acceleration into
 * its obstacle, a box's or disc's force beyond its set, a sliding block's acceleration along
 * its force; relative), the others are switched back. Many switches at once wander here,
 * where the rows are nearly dependent. */
static void one_switch(sc_problem *p, const sc_int *was) {
  sc_int k, worst = -1;
  double big = -1.0;
  for (k = 0; k < p->nb; ++k) {
    const sc_int r = p->start[k];
    const double *l = p->lam + r, *w = p->w + r;
    double v;
    if (p->state[k] == was[k]) continue;
    if (p->kind[k] == K_UNILATERAL) v = was[k] == S_HELD ? -l[0] / p->fscale : -w[0] / p->wscale;
    else if (p->kind[k] == K_BOX)
      v = was[k] == S_HELD ? (fabs(l[0]) - p->par[3 * k]) / p->fscale : fabs(w[0]) / p->wscale;
    else if (was[k] == S_HELD) v = (hypot(l[0], l[1]) - p->par[3 * k]) / p->fscale;
    else v = hypot(w[0], w[1]) / p->wscale;
    if (v > big) big = v, worst = k;
  }
  for (k = 0; k < p->nb; ++k)
    if (k != worst) p->state[k] = was[k];
}

/* Sliding discs that do not move (|w| within the acceptance: at their set's limit) held, as
 * sc_polish holds them; returns 1 if any. */
static int hold_still(sc_problem *p) {
  sc_int k;
  int any = 0;
  for (k = 0; k < p->nb; ++k)
    if (p->state[k] == S_SLIDE && p->kind[k] == K_DISC && sc_still(p, k))
      p->state[k] = S_HELD, any = 1;
  return any;
}

/* Active-set passes on pieces solved from Z from the states in p (its forces: the start), one
 * switch a pass (kkt: scene_solve.c's check, which switches with its last argument 1, and
 * returns 1 where it did), the face's forces moved into their sets where the held rows are
 * dependent; w from Z throughout. Returns 1 when a piece's solution satisfies the KKT
 * conditions (res: its residuals), else 0 (p->lam, p->w, p->state then the last pass's).
 * Work: as sc_rescue's caller gives (rest_size doubles, 3 (m + nb) sc_ints), was: nb. */
SC_INTERNAL int sc_rescue(sc_problem *p, const double *Z, const double *g, const double *c,
                          double *work, sc_int *iwork, sc_int *was, sc_int *passes,
                          sc_int *defect, double *res, int (*kkt)(sc_problem *, double *, int)) {
  sc_int pass;
  for (pass = 0; pass < RESCUE_PASSES; ++pass) {
    ++*passes;
    if (!rescue_piece(p, Z, g, c, work, iwork, defect)) return 0;
    if (*defect > 0 && (kkt(p, res, 0), res[0] > TOL_ACCEPT) && res[1] <= TOL_ACCEPT &&
        res[2] <= TOL_ACCEPT) /* (dependent rows: the face's forces into their sets) */
      rescue_face(p, Z, g, c, work, 1e-10);
    memcpy(was, p->state, sizeof(sc_int) * (size_t)p->nb);
    if (kkt(p, res, 1)) one_switch(p, was);
    else if (res[0] <= TOL_ACCEPT && res[1] <= TOL_ACCEPT && res[2] <= TOL_ACCEPT) return 1;
    else if (!hold_still(p)) return 0;
  }
  return 0;
}
