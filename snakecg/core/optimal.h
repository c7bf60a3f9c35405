/* snakecg's runtime core: the types of optimal.c's query and the certificate of its answers
 * (included by optimal.c alone).
 *
 * The certificate rebuilds each push problem in the torque itself from the maps and the query
 * (every limit as the optimiser poses it), measures primal feasibility, recomputes the
 * multipliers of the active constraints from the stationarity condition (the normal
 * equations of the active columns) and the duality gap sum_i lam_i slack_i + 1/2 r^T H^-1 r, as
 * snakecg/optimize/certificate.py _push_floats does on floats, operation for operation.
 */
#ifndef SNAKECG_CORE_OPTIMAL_H
#define SNAKECG_CORE_OPTIMAL_H

#include <math.h>
#include <string.h>

#include "dense.h"

/* tolerances of snakecg/optimize (polish.LP_REG, result.HESSIAN_REG, certificate.ACTIVE,
 * certificate.TOLERANCE["stationarity"]) */
#define LP_REG 1e-9
#define HESSIAN_REG 1e-11
#define ACTIVE 1e-7
#define STATIONARITY_TOL 1e-7

enum { OP_MAX_SR = 0, OP_LEAST_SLIP = 1, OP_STRONGEST = 2 };
/* return codes: 0 answered; otherwise the Python path answers */
enum { OP_OK = 0, OP_SIZE = 1, OP_MAPS = 2, OP_STRUCTURE = 3, OP_CLOSED_FORM = 4,
       OP_ACTIVE_SET = 5, OP_CERTIFICATE = 6, OP_NOT_POSITIVE = 7 };
/* binding codes: 0 the task row (no name), 1 the contact, 2 the ellipsoid, 3 + j joint j,
 * 3 + n + w the w-th bounded wheel */
enum { B_TASK = 0, B_CONTACT = 1, B_ELLIPSOID = 2, B_JOINT = 3 };
/* the output vector */
enum { O_STATUS = 0, O_EXPECTED = 1, O_K = 2, O_ADIR = 3, O_STAT = 6, O_PRIMAL = 7, O_COMP = 8,
       O_GAP = 9, O_QUAD = 10, O_TIE = 11, O_NB = 12, O_LAM_LO = 13, O_GAIN = 14, O_FORWARD = 15,
       O_TAU = 16 };

/* One query (mirrored in snakecg/core/optimal.py): the configuration, the model's bounded
 * wheels, the query's limits and task, the outputs. */
typedef struct {
  op_int kind, n, nc, nw;
  const double *scene;     /* the model's scene vector (SCENE_* offsets) */
  const double *q;         /* the configuration */
  double *maps;            /* out: the maps (core_held_maps' layout) */
  const op_int *wheel_row; /* nw rows of L with a friction bound */
  const double *wheel_ub;  /* their bounds, backed off by FRICTION_MARGIN */
  const double *Io;        /* 3: the object's inertia diagonal */
  double pivot_tol;
  double radius;           /* <= 0: no ellipsoid */
  const double *tau_max;   /* n, or null */
  const double *direction; /* 3 (unit), or null */
  double a_min;
  const double *a_obj;     /* 3, or null */
  double *out;
  /* the exact forward solve at the answer (forward.c's core_forward, as SceneModel.forward
   * calls it for one sample at rest): its solver constants, iteration limit, output row */
  const double *constants;
  op_int max_iter;
  double *row;
} op_call;

/* ---------------------------------------------------------------------------------------
 * the query */
typedef struct {
  int n, nc, nw;
  double L[(OP_MAX + 2) * OP_MAX]; /* row-major, leading dimension OP_MAX */
  double Xi[OP_MAX * OP_MAX], Om[OP_MAX * OP_MAX], N[OP_MAX * OP_MAX];
  double a_dir[3], k;
} op_maps;

#define ROW(M, i) ((M) + (i) * OP_MAX)

/* certificate._push_floats: the KKT conditions and the duality gap of a push answer with box
 * limits only; 0 when the multipliers need more than the normal equations */
static int op_push_certificate(const op_call *c, const op_maps *mp, const double *x, int has_lo,
                               double lam_lo, int equal, int lp, double *values) {
  int n = mp->n, R = 0, i, j, w, k = 0, nh = 0;
  double G[OP_ROWS * OP_MAX], lo[OP_ROWS], hi[OP_ROWS];
  double H[OP_MAX * OP_MAX], cvec[OP_MAX], Hx[OP_MAX], grad[OP_MAX], ax[OP_MAX];
  double cols[OP_CONS * OP_MAX], slacks[OP_CONS], his[OP_ROWS * OP_MAX], hisl[OP_ROWS];
  double f, fscale, ref, ng, primal = 0.0, resid, size, comp = 0.0, corr = 0.0, stat;
  double res[OP_MAX], norms[OP_CONS], lam[OP_CONS];
  int freec[OP_CONS];
  const double *ell = ROW(mp->L, 0);
  if (mp->nw + n + 2 > OP_ROWS) return 0;
  for (w = 0; w < mp->nw; ++w) {
    memcpy(G + R * OP_MAX, ROW(mp->L, c->wheel_row[w]), sizeof(double) * n);
    lo[R] = -c->wheel_ub[w];
    hi[R++] = c->wheel_ub[w];
  }
  if (c->tau_max)
    for (j = 0; j < n; ++j) {
      for (i = 0; i < n; ++i) G[R * OP_MAX + i] = (i == j) ? 1.0 : 0.0;
      lo[R] = -c->tau_max[j];
      hi[R++] = c->tau_max[j];
    }
  memcpy(G + R * OP_MAX, ell, sizeof(double) * n);
  lo[R] = 0.0;
  hi[R++] = INFINITY;
  if (has_lo) {
    memcpy(G + R * OP_MAX, ell, sizeof(double) * n);
    lo[R] = lam_lo;
    hi[R++] = equal ? lam_lo : INFINITY;
  }
  if (lp) {
    for (j = 0; j < n; ++j) {
      cvec[j] = -ell[j];
      Hx[j] = 0.0;
    }
  } else {
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) H[i * OP_MAX + j] = 2.0 * ROW(mp->Xi, i)[j];
    for (j = 0; j < n; ++j) cvec[j] = 0.0;
    for (i = 0; i < n; ++i) Hx[i] = op_dot(H + i * OP_MAX, x, n);
  }
  f = 0.5 * op_dot(x, Hx, n) + op_dot(cvec, x, n);
  for (j = 0; j < n; ++j) {
    grad[j] = Hx[j] + cvec[j];
    ax[j] = fabs(x[j]);
  }
  for (i = 0; i < R; ++i) {
    const double *row = G + i * OP_MAX;
    double gx = op_dot(row, x, n), bnd, rs = 0.0, s_lo, s_hi, v;
    int a_lo, a_hi, eq;
    double blo = lo[i] > -INFINITY ? fabs(lo[i]) : 0.0, bhi = hi[i] < INFINITY ? fabs(hi[i]) : 0.0;
    bnd = bhi > blo ? bhi : blo;
    for (j = 0; j < n; ++j) rs += fabs(row[j]) * ax[j];
    rs += bnd;
    rs = rs > 0 ? rs : 1.0;
    s_lo = lo[i] > -INFINITY ? gx - lo[i] : INFINITY;
    s_hi = hi[i] < INFINITY ? hi[i] - gx : INFINITY;
    v = -s_lo;
    if (-s_hi > v) v = -s_hi;
    if (0.0 > v) v = 0.0;
    v = v / rs;
    if (v > primal) primal = v;
    a_lo = s_lo <= ACTIVE * rs;
    a_hi = s_hi <= ACTIVE * rs;
    eq = a_lo && a_hi && lo[i] == hi[i];
    if (a_lo) {
      memcpy(cols + k * OP_MAX, row, sizeof(double) * n);
      slacks[k] = eq ? 0.0 : s_lo;
      freec[k++] = eq;
    }
    if (a_hi && !eq) {
      for (j = 0; j < n; ++j) his[nh * OP_MAX + j] = -row[j];
      hisl[nh++] = s_hi;
    }
  }
  for (i = 0; i < nh; ++i) { /* the upper sides after the lower ones, as kkt orders them */
    memcpy(cols + k * OP_MAX, his + i * OP_MAX, sizeof(double) * n);
    slacks[k] = hisl[i];
    freec[k++] = 0;
  }
  {
    double a = fabs(f), b = fabs(op_dot(grad, x, n));
    fscale = a;
    if (b > fscale) fscale = b;
    if (1e-300 > fscale) fscale = 1e-300;
  }
  ref = (lp ? 0.0 : op_frob(H, OP_MAX, n) * op_norm(x, n)) + op_norm(cvec, n);
  ng = op_norm(grad, n);
  if (k) {
    double Cn[OP_CONS * OP_MAX], Mn[OP_LS * OP_LS], rhs[OP_LS], lam_s[OP_LS], fit[OP_MAX];
    double tol;
    if (k > OP_LS) return 0;
    memset(Mn, 0, sizeof(double) * k * k);
    memset(rhs, 0, sizeof(double) * k);
    for (i = 0; i < k; ++i) {
      double nv = op_norm(cols + i * OP_MAX, n);
      norms[i] = nv != 0.0 ? nv : 1.0;
      for (j = 0; j < n; ++j) Cn[i * OP_MAX + j] = cols[i * OP_MAX + j] / norms[i];
    }
    for (i = 0; i < k; ++i) {
      for (j = 0; j < k; ++j) Mn[i * k + j] = op_dot(Cn + i * OP_MAX, Cn + j * OP_MAX, n);
      rhs[i] = op_dot(Cn + i * OP_MAX, grad, n);
    }
    if (!op_lin_solve(k, Mn, k, rhs, lam_s)) return 0;
    for (i = 0; i < k; ++i)
      if (!freec[i] && lam_s[i] < 0) return 0;
    for (j = 0; j < n; ++j) {
      double s = 0.0;
      for (i = 0; i < k; ++i) s += lam_s[i] * Cn[i * OP_MAX + j];
      fit[j] = s - grad[j];
    }
    tol = ng;
    if (ref > tol) tol = ref;
    if (1e-300 > tol) tol = 1e-300;
    if (!(op_norm(fit, n) <= 0.1 * STATIONARITY_TOL * tol)) return 0;
    size = 0.0;
    for (i = 0; i < k; ++i) {
      lam[i] = lam_s[i] / norms[i];
      size += fabs(lam[i]) * norms[i];
    }
    for (j = 0; j < n; ++j) {
      double s = 0.0;
      for (i = 0; i < k; ++i) s += lam[i] * cols[i * OP_MAX + j];
      res[j] = s - grad[j];
    }
    resid = op_norm(res, n);
    if (ng > size) size = ng;
  } else {
    for (j = 0; j < n; ++j) res[j] = -grad[j];
    resid = ng;
    size = 0.0;
  }
  {
    double d = size;
    if (ref > d) d = ref;
    if (1e-300 > d) d = 1e-300;
    stat = resid > 0 ? resid / d : 0.0;
  }
  for (i = 0; i < k; ++i) comp += fabs(lam[i]) * fabs(slacks[i]);
  if (!lp) {
    double r[OP_MAX], y[OP_MAX];
    int any = 0;
    for (j = 0; j < n; ++j) {
      r[j] = -res[j];
      if (r[j] != 0.0) any = 1;
    }
    if (any) {
      if (!op_chol_solve(n, H, OP_MAX, r, 1e-9, y)) return 0;
      corr = 0.5 * op_dot(r, y, n);
    }
  }
  values[0] = stat;
  values[1] = primal;
  values[2] = k ? comp / fscale : 0.0;
  values[3] = k ? (comp + corr) / fscale : corr / fscale;
  return 1;
}

/* fast.primal_violation (and fast.ellipsoid_violation): the largest relative violation of the
 * all-held limits at tau */
static double op_primal(const op_call *c, const op_maps *mp, const double *tau) {
  int n = mp->n, w, j;
  double worst = 0.0, g, at[OP_MAX];
  const double *ell = ROW(mp->L, 0);
  for (j = 0; j < n; ++j) at[j] = fabs(tau[j]);
  for (w = 0; w < mp->nw; ++w) {
    const double *row = ROW(mp->L, c->wheel_row[w]);
    double ub = c->wheel_ub[w];
    g = fabs(op_dot(row, tau, n));
    if (g > ub) {
      double rs = 0.0, v;
      for (j = 0; j < n; ++j) rs += fabs(row[j]) * at[j];
      rs += ub;
      v = (g - ub) / (rs > 0 ? rs : 1.0);
      if (v > worst) worst = v;
    }
  }
  if (c->tau_max)
    for (j = 0; j < n; ++j) {
      double t = fabs(tau[j]), m = c->tau_max[j];
      if (t > m && (t - m) / (t + m) > worst) worst = (t - m) / (t + m);
    }
  g = op_dot(ell, tau, n);
  if (g < 0) {
    double rs = 0.0, v;
    for (j = 0; j < n; ++j) rs += fabs(ell[j]) * at[j];
    v = -g / (rs > 0 ? rs : 1.0);
    if (v > worst) worst = v;
  }
  if (c->radius > 0) {
    double r2 = c->radius * c->radius, e = op_quad(mp->N, OP_MAX, tau, n);
    if (e > r2) {
      double An[OP_MAX * OP_MAX], qs, v;
      int i;
      for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) An[i * OP_MAX + j] = fabs(ROW(mp->N, i)[j]);
      qs = op_quad(An, OP_MAX, at, n) + fabs(r2);
      v = (e - r2) / (qs > 0 ? qs : 1.0);
      if (v > worst) worst = v;
    }
  }
  return worst;
}

#endif
