/* snakecg's engine: the friction and contact sets of the general-scene solve
 * (scene_solve.c); the exact minimiser of a quadratic over each of them is scene_block.c's.
 *
 * A block k of the dual, min 1/2 lam^T G lam + b^T lam over lam in K_1 x ... x K_nb, is one
 * row (FREE: R; UNILATERAL: lam >= 0; BOX: |lam| <= p0) or two (DISC: |lam| <= p0; SPLIT: the
 * split ellipse with semi-axes p0 for lam_t <= 0, p1 for lam_t >= 0, p2 across). On a 2-D
 * set's boundary, lam^T P lam = 1 with P diagonal (block_P). sc_on_boundary parametrizes a
 * 2-D set's boundary by a direction (the sliding pieces' unknowns). Used by scene_solve.c.
 */
#include <math.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"

/* A sliding 2-D block k's force on its set's boundary in the direction u (a unit vector:
 * (cos t, sin t) at the angle t) and the tangent T = dlam/dt there: a disc s u; a split ellipse
 * (st u0, p2 u1), st the semi-axis of the half that u points into. Both have dT/dt = -lam. */
SC_INTERNAL void sc_on_boundary(const sc_problem *p, sc_int k, const double *u, double *l,
                                double *T) {
  const double *q = p->par + 3 * k;
  const double ax = p->kind[k] == K_DISC ? q[0] : (u[0] < 0 ? q[0] : q[1]),
               ay = p->kind[k] == K_DISC ? q[0] : q[2];
  l[0] = ax * u[0];
  l[1] = ay * u[1];
  T[0] = -ax * u[1];
  T[1] = ay * u[0];
}

/* The direction u (unit) of a 2-D block's force in sc_on_boundary's parametrization, radially
 * onto the boundary ((1, 0) for no force). */
SC_INTERNAL void sc_direction_of(const sc_problem *p, sc_int k, const double *l, double *u) {
  const double *q = p->par + 3 * k;
  const double ax = l[0] < 0 ? q[0] : q[1];
  double x = l[0], y = l[1], r;
  if (p->kind[k] != K_DISC) {
    x = ax > 0 ? l[0] / ax : 0.0;
    y = l[1] / q[2];
  }
  r = sqrt(x * x + y * y);
  u[0] = r > 0 ? x / r : 1.0;
  u[1] = r > 0 ? y / r : 0.0;
}

/* 1 if the forces l of block k lie in its set, to the relative tolerance tol; with clip,
 * forces outside by at most that are first moved onto the set. */
SC_INTERNAL int sc_in_set(const sc_problem *p, sc_int k, double *l, double tol, int clip) {
  const double *q = p->par + 3 * k;
  double P[2], phi;
  switch (p->kind[k]) {
    case K_FREE: return 1;
    case K_UNILATERAL:
      if (!(l[0] >= -tol * p->fscale)) return 0;
      if (clip && l[0] < 0) l[0] = 0.0;
      return 1;
    case K_BOX:
      if (!(fabs(l[0]) <= q[0] * (1 + tol))) return 0;
      if (clip) l[0] = fmax(-q[0], fmin(q[0], l[0]));
      return 1;
    default:
      if (!(p->kind[k] == K_DISC ? q[0] > 0 : q[2] > 0 && (q[0] > 0 || q[1] > 0)))
        return l[0] == 0.0 && l[1] == 0.0;
      sc_block_P(p, k, l, P);
      phi = sqrt(P[0] * l[0] * l[0] + P[1] * l[1] * l[1]);
      if (!(phi <= 1 + tol)) return 0;
      if (clip && phi > 1) {
        l[0] /= phi;
        l[1] /= phi;
      }
      return 1;
  }
}

/* An orthonormal basis of the null space of the positive semidefinite n x n A (row-major, its
 * lower triangle read and overwritten): the pivoted L D L^T of sc_psd_solve stopped at pivots
 * of at most NULL_TOL of the first, the null vectors P [-L11^-T L21^T; I] orthonormalized
 * (Gram-Schmidt, twice). Basis vector t at V + t * n (contiguous); returns their number.
 * Work: 2 n doubles, n sc_ints in perm. */
static sc_int null_space(sc_int n, double *A, double *V, double *work, sc_int *perm) {
  double *b = work, *x = work + n;
  sc_int i, j, t, u, rank, nn;
  for (i = 0; i < n; ++i) b[i] = 0.0;
  rank = sc_psd_solve(n, A, n, b, NULL_TOL, x, work + n, perm);
  nn = n - rank;
  for (t = 0; t < nn; ++t) {
    sc_int jj = rank + t;
    double *y = x;
    for (i = 0; i < n; ++i) y[i] = 0.0;
    y[jj] = 1.0;
    for (i = rank - 1; i >= 0; --i) { /* L11^T y1 = -L21^T e_jj */
      double sum = -A[jj * n + i];
      for (j = i + 1; j < rank; ++j) sum -= A[j * n + i] * y[j];
      y[i] = sum;
    }
    for (i = 0; i < n; ++i) V[t * n + perm[i]] = y[i];
  }
  for (t = 0; t < nn; ++t) {
    int pass;
    double nrm;
    for (pass = 0; pass < 2; ++pass)
      for (u = 0; u < t; ++u) {
        double d = 0.0;
        for (i = 0; i < n; ++i) d += V[u * n + i] * V[t * n + i];
        for (i = 0; i < n; ++i) V[t * n + i] -= d * V[u * n + i];
      }
    nrm = 0.0;
    for (i = 0; i < n; ++i) nrm += V[t * n + i] * V[t * n + i];
    nrm = sqrt(nrm);
    for (i = 0; i < n; ++i) V[t * n + i] /= nrm;
  }
  return nn;
}

/* Minimum-norm forces on the face (every block whose rows do not accelerate: the forces of
 * the others are fixed by the unique accelerations): lam_F -= N N^T lam_F, N the null space
 * of G_FF (null_space: pivots at most NULL_TOL of the first). Where that leaves a force's set
 * and the null space is one direction v, the minimum of |lam_F + t v| over the t that keep
 * every held force in its set (an interval holding 0, its ends found by bisection to
 * rounding) is taken instead. Z = L^-1 A^T (n x m, scene_solve.c's) checks that the choice
 * keeps the accelerations. Returns 0 when the face's rows are independent (nothing to
 * choose), 1 when the minimum-norm forces were found, 2 when not (a larger null space whose
 * unconstrained minimum leaves the set: the face's basic solution stays). p->w is read (the
 * face) and left as it was: the caller takes w of the new forces where it reads it. */
SC_INTERNAL int sc_min_norm_face(sc_problem *p, const double *Z, double *work) {
  const sc_int m = p->m;
  sc_int F[512], fk[512], perm[512], nf = 0, i, j, k, t, nnull = 0, tnull = -1;
  double *A, *V, *ev, *l0;
  int inside = 1;
  for (k = 0; k < p->nb; ++k) { /* the face: every block whose rows do not accelerate */
    if (p->state[k] != S_HELD && !sc_still(p, k)) continue;
    for (i = 0; i < sc_block_size(p->kind[k]) && nf < 512; ++i) {
      fk[nf] = k;
      F[nf++] = p->start[k] + i;
    }
  }
  if (nf == 0) return 0;
  A = work;
  V = A + nf * nf;
  ev = V + nf * nf;
  l0 = ev + 2 * nf;
  for (i = 0; i < nf; ++i) /* (the lower triangle: all that null_space reads) */
    for (j = 0; j <= i; ++j) A[i * nf + j] = p->G[F[i] * m + F[j]];
  nnull = null_space(nf, A, V, ev, perm);
  for (i = 0; i < nf; ++i) l0[i] = p->lam[F[i]];
  for (t = 0; t < nnull; ++t) {
    double s;
    tnull = t;
    s = 0.0;
    for (i = 0; i < nf; ++i) s += V[t * nf + i] * l0[i];
    for (i = 0; i < nf; ++i) l0[i] -= s * V[t * nf + i];
  }
  if (nnull == 0) return 0;
  for (i = 0; i < nf; i += sc_block_size(p->kind[fk[i]]))
    if (!sc_in_set(p, fk[i], l0 + i, 1e-13, 1)) inside = 0;
  if (!inside) {
    double tstar = 0.0, lim[2];
    int side;
    if (nnull != 1) return 2;
    for (i = 0; i < nf; ++i) tstar -= V[tnull * nf + i] * p->lam[F[i]];
    for (side = 0; side < 2; ++side) { /* the interval's ends: every block stays in its set */
      double dir = side ? 1.0 : -1.0, lo = 0.0, hi = 1.0, l[2];
      int it, ok = 1;
      for (it = 0; it < 80 && ok; ++it) { /* grow until one block leaves */
        for (i = 0; i < nf && ok; i += sc_block_size(p->kind[fk[i]])) {
          l[0] = p->lam[F[i]] + dir * hi * V[tnull * nf + i];
          if (sc_block_size(p->kind[fk[i]]) == 2)
            l[1] = p->lam[F[i + 1]] + dir * hi * V[tnull * nf + i + 1];
          if (!sc_in_set(p, fk[i], l, 1e-12, 0)) ok = 0;
        }
        if (ok) { lo = hi; hi *= 2.0 * (1.0 + p->fscale); }
      }
      if (ok) { lim[side] = INFINITY; continue; }
      for (it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
        double mid = 0.5 * (lo + hi);
        int in = 1;
        for (i = 0; i < nf && in; i += sc_block_size(p->kind[fk[i]])) {
          l[0] = p->lam[F[i]] + dir * mid * V[tnull * nf + i];
          if (sc_block_size(p->kind[fk[i]]) == 2)
            l[1] = p->lam[F[i + 1]] + dir * mid * V[tnull * nf + i + 1];
          if (!sc_in_set(p, fk[i], l, 1e-12, 0)) in = 0;
        }
        if (in) lo = mid; else hi = mid;
      }
      lim[side] = lo;
    }
    tstar = fmax(-lim[0], fmin(lim[1], tstar));
    for (i = 0; i < nf; ++i) l0[i] = p->lam[F[i]] + tstar * V[tnull * nf + i];
    for (i = 0; i < nf; i += sc_block_size(p->kind[fk[i]])) /* rounding onto the sets */
      sc_in_set(p, fk[i], l0 + i, INFINITY, 1);
  }
  { /* the forces may change only along A^T's null space: the accelerations stay put to
       rounding, |A_F^T dlam|^2_{M^-1} = |Z_F dlam|^2 (else the choice is refused; summed
       as squares, its rounding is that of Z dlam squared: dlam^T G_FF dlam would carry G's
       rounding times |dlam|^2, far above the bound) */
    double quad = 0.0;
    for (t = 0; t < p->n; ++t) {
      double t2 = 0.0;
      for (j = 0; j < nf; ++j) t2 += Z[t * m + F[j]] * (l0[j] - p->lam[F[j]]);
      quad += t2 * t2;
    }
    if (!(quad <= 1e-26 * p->wscale * p->fscale)) return 2;
  }
  for (i = 0; i < nf; ++i) p->lam[F[i]] = l0[i];
  return 1;
}

/* The pieces read from the current lam and w (declared in scene_sets.h). */
SC_INTERNAL void sc_read_states(sc_problem *p, double rel, double rel2) {
  sc_int k;
  for (k = 0; k < p->nb; ++k) {
    sc_int r = p->start[k];
    const double *q = p->par + 3 * k, *l = p->lam + r;
    switch (p->kind[k]) {
      case K_FREE: p->state[k] = S_HELD; break;
      case K_UNILATERAL:
        p->state[k] = l[0] > rel * p->fscale ? S_HELD : (p->w[r] > 0 ? S_ZERO : S_HELD);
        break;
      case K_BOX:
        p->state[k] = !(q[0] > 0) ? S_ZERO : (fabs(l[0]) < q[0] * (1 - rel) ? S_HELD : S_SLIDE);
        break;
      default: {
        double P[2], phi;
        if (!(p->kind[k] == K_DISC ? q[0] > 0 : q[2] > 0 && (q[0] > 0 || q[1] > 0))) {
          p->state[k] = S_ZERO;
          break;
        }
        sc_block_P(p, k, l, P);
        phi = P[0] * l[0] * l[0] + P[1] * l[1] * l[1];
        p->state[k] = phi < (1 - rel2) * (1 - rel2) ? S_HELD : S_SLIDE;
        if (p->state[k] == S_SLIDE) {
          double g = -(p->w[r] * P[0] * l[0] + p->w[r + 1] * P[1] * l[1]) /
                     (P[0] * P[0] * l[0] * l[0] + P[1] * P[1] * l[1] * l[1]);
          p->gamma[k] = g > 0 ? g : 0.0;
        }
      }
    }
  }
}
