/* snakecg's engine: dense convex QPs, the ellipsoid constraint through its multiplier,
 * non-negative least squares and the KKT certificate (prototypes and method notes in engine.h).
 *
 * This file is part of the runtime (not generated); it knows nothing of the model and is
 * compiled into every model's library beside the other core files.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
/* ---------------------------------------------------------------------------------------
 * workspace */
/* doubles and sc_ints of each region, as carved by the function that uses it */
#define GI_D(n, m) (6 * (n) * (n) + 10 * (n) + 2 + 2 * (2 * (m) + 2))
#define GI_I(n, m) (2 * (2 * (m) + 2) + 2 * (n) + 2 * (n) + 2)
#define QC_D(n, m) (5 * (n) * (n) + 12 * (n))
#define QC_I(n, m) (2 * (n) + 2 * (n))
#define CE_K(n, m) (2 * (m) + 2)
#define CE_D(n, m)                                                                  \
  (7 * (n) * CE_K(n, m) + 14 * CE_K(n, m) + CE_K(n, m) * CE_K(n, m) + 2 * (n) * (n) + \
   12 * (n) + 4 * (m))
#define CE_I(n, m) (9 * CE_K(n, m))

void sc_qp_work_init(sc_qp_work *w, sc_int n_max, sc_int m_max, double *d, sc_int *i) {
  w->n_max = n_max;
  w->m_max = m_max;
  w->d = d;
  w->i = i;
}

int sc_qp_work_alloc(sc_qp_work *w, sc_int n_max, sc_int m_max) {
  w->n_max = n_max;
  w->m_max = m_max;
  w->d = (double *)malloc(sizeof(double) * (size_t)SC_QP_WORK_DOUBLES(n_max, m_max));
  w->i = (sc_int *)malloc(sizeof(sc_int) * (size_t)SC_QP_WORK_INTS(n_max, m_max));
  if (!w->d || !w->i) {
    sc_qp_work_free(w);
    return -1;
  }
  return 0;
}

void sc_qp_work_free(sc_qp_work *w) {
  free(w->d);
  free(w->i);
  w->d = 0;
  w->i = 0;
}

/* the three regions of the workspace: the active-set solver, the secular equation, the
 * certificate (each may call the one before it) */
static double *gi_d(sc_qp_work *w) { return w->d; }
static sc_int *gi_i(sc_qp_work *w) { return w->i; }
static double *qc_d(sc_qp_work *w) { return w->d + GI_D(w->n_max, w->m_max); }
static sc_int *qc_i(sc_qp_work *w) { return w->i + GI_I(w->n_max, w->m_max); }
static double *ce_d(sc_qp_work *w) {
  return w->d + GI_D(w->n_max, w->m_max) + QC_D(w->n_max, w->m_max);
}
static sc_int *ce_i(sc_qp_work *w) {
  return w->i + GI_I(w->n_max, w->m_max) + QC_I(w->n_max, w->m_max);
}

/* ---------------------------------------------------------------------------------------
 * The optimum of an active set: min 1/2 x^T H x + g^T x s.t. a_r . x = b_r for the k rows
 * `rows` (at their bound `b`), one KKT system
 *     [ H   -A^T ] [ x   ]   [ -g ]
 *     [ A    0   ] [ lam ] = [  b ]
 * solved by LU with partial pivoting. Returns 1 with x and the rows' multipliers, 0 when the
 * system is singular. K and rhs hold (n + k)^2 and n + k doubles, piv n + k. */
static int active_set_optimum(sc_int n, const double *H, const double *g, const double *A,
                              sc_int k, const sc_int *rows, const double *b, double *x,
                              double *lam, double *K, double *rhs, sc_int *piv) {
  sc_int s = n + k, i, j;
  for (i = 0; i < s * s; ++i) K[i] = 0.0;
  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j) K[i * s + j] = H[i * n + j];
  for (j = 0; j < k; ++j)
    for (i = 0; i < n; ++i) {
      K[i * s + n + j] = -A[rows[j] * n + i];
      K[(n + j) * s + i] = A[rows[j] * n + i];
    }
  for (i = 0; i < n; ++i) rhs[i] = -g[i];
  for (j = 0; j < k; ++j) rhs[n + j] = b[j];
  if (!sc_lu_factor(s, K, s, piv)) return 0;
  sc_lu_solve(s, K, s, piv, rhs);
  for (i = 0; i < s; ++i)
    if (!isfinite(rhs[i])) return 0;
  for (i = 0; i < n; ++i) x[i] = rhs[i];
  for (j = 0; j < k; ++j) lam[j] = rhs[n + j];
  return 1;
}

static double objective(sc_int n, const double *H, const double *g, const double *x) {
  return 0.5 * sc_quad(n, H, n, x) + sc_dot(g, x, n);
}

/* every row within its bounds, to `rel` relative (the active-set optimum's acceptance test) */
static int rows_hold(sc_int n, sc_int m, const double *A, const double *lo, const double *hi,
                     const double *x, double rel) {
  sc_int r;
  for (r = 0; r < m; ++r) {
    double ax = sc_dot(A + r * n, x, n), tol = rel * (1.0 + fabs(ax));
    if (ax < lo[r] - tol || ax > hi[r] + tol) return 0;
  }
  return 1;
}

/* ---------------------------------------------------------------------------------------
 * Goldfarb & Idnani's dual active-set method ("A numerically stable dual method for solving
 * strictly convex quadratic programs", Math. Programming 27, 1983), in the factored form of
 * their section 4: H = L L^T, J = L^-T Q and an upper triangular R with J^T N_A = [R; 0] for
 * the active normals N_A, both updated by Givens rotations. It starts from the unconstrained
 * minimiser -H^-1 g with nothing active (a dual feasible pair, every time: no state between
 * calls), adds the most violated constraint (equalities first), and takes the full step that
 * makes it active or the partial step that drops an active constraint whose multiplier would
 * turn negative. Each row lo <= a . x <= hi is one or two one-sided constraints s a . x >= s b. */
int sc_qp_solve(const sc_qp *qp, sc_qp_work *w, sc_qp_solution *sol) {
  const sc_int n = qp->n, m = qp->m;
  const double *A = qp->A;
  double *D = gi_d(w), *J, *R, *d, *z, *r, *u, *x, *hp, *xs, *ls, *bnd, *cn, *K, *rhs;
  sc_int *I = gi_i(w), *row, *sgn, *piv, *act, *rows_act;
  sc_int mo = 0, neq = 0, next_eq = 0, q = 0, it, i, j, k, iters;
  int status = SC_QP_ITERATIONS;
  if (n > w->n_max || m > w->m_max || n < 1) return SC_QP_SIZE;
  J = D;
  R = J + n * n;
  d = R + n * n;
  z = d + n;
  r = z + n;
  x = r + n;
  hp = x + n;
  xs = hp + n;
  u = xs + n;  /* n + 1 */
  ls = u + n + 1; /* n + 1 */
  rhs = ls + n + 1; /* 2 n */
  bnd = rhs + 2 * n;
  cn = bnd + 2 * m + 2;
  K = cn + 2 * m + 2; /* (2 n)^2 */
  row = I;
  sgn = row + 2 * m + 2;
  piv = sgn + 2 * m + 2; /* 2 n */
  act = piv + 2 * n;     /* n + 1 */
  rows_act = act + n + 1;
  sol->n_active = 0;
  sol->iterations = 0;
  sol->newton = 0;
  sol->mu = 0.0;
  /* the one-sided constraints: equalities first, then both sides of the other rows */
  for (k = 0; k < 2; ++k)
    for (i = 0; i < m; ++i) {
      const double *a = A + i * n;
      double an = sc_norm(a, n);
      int eq = qp->lo[i] == qp->hi[i] && isfinite(qp->lo[i]);
      if (an == 0.0) { /* a row without variables must hold as it is */
        if (k == 0 && (qp->lo[i] > SC_QP_FEAS_TOL * (1 + fabs(qp->lo[i])) ||
                       qp->hi[i] < -SC_QP_FEAS_TOL * (1 + fabs(qp->hi[i]))))
          return SC_QP_INFEASIBLE;
        continue;
      }
      if (k == 0 && eq) {
        row[mo] = i, sgn[mo] = 1, bnd[mo] = qp->lo[i], cn[mo++] = an;
      } else if (k == 1 && !eq) {
        if (qp->lo[i] > -INFINITY) row[mo] = i, sgn[mo] = 1, bnd[mo] = qp->lo[i], cn[mo++] = an;
        if (qp->hi[i] < INFINITY) row[mo] = i, sgn[mo] = -1, bnd[mo] = -qp->hi[i], cn[mo++] = an;
      }
      if (k == 0) neq = mo;
    }
  /* H = L L^T (L in R's space for now), then J = L^-T (upper triangular), row by row from the
   * bottom: (L^T J)_ij = delta_ij */
  for (i = 0; i < n * n; ++i) R[i] = qp->H[i];
  if (!sc_cholesky(n, R, n, 1e-14)) return SC_QP_NOT_CONVEX;
  for (j = 0; j < n; ++j)
    for (i = n - 1; i >= 0; --i) {
      double s = (i == j) ? 1.0 : 0.0;
      for (k = i + 1; k < n; ++k) s -= R[k * n + i] * J[k * n + j];
      J[i * n + j] = s / R[i * n + i];
    }
  for (i = 0; i < n * n; ++i) R[i] = 0.0;
  /* the unconstrained minimiser x = -H^-1 g = -J J^T g */
  for (k = 0; k < n; ++k) {
    double s = 0.0;
    for (i = 0; i < n; ++i) s += J[i * n + k] * qp->g[i];
    d[k] = s;
  }
  for (i = 0; i < n; ++i) x[i] = -sc_dot(J + i * n, d, n);
  iters = 10 * (mo + n) + 50;
  for (it = 0; it < iters; ++it) {
    sc_int p = -1;
    double sp, u_plus = 0.0, sigma;
    const double *a;
    /* step 1: the constraint to add, the equalities first (from their violated side), then
     * the most violated inequality (relative to its normal's length) */
    if (next_eq < neq) {
      p = next_eq++;
      if (sc_dot(A + row[p] * n, x, n) - bnd[p] > 0) {
        sgn[p] = -1;
        bnd[p] = -bnd[p];
      }
    } else {
      double worst = 0.0;
      for (k = neq; k < mo; ++k) {
        double s;
        int in = 0;
        for (j = 0; j < q; ++j)
          if (act[j] == k) in = 1;
        if (in) continue;
        s = (sgn[k] * sc_dot(A + row[k] * n, x, n) - bnd[k]) / cn[k];
        if (s < worst && s < -SC_QP_FEAS_TOL * (1.0 + fabs(bnd[k]) / cn[k])) {
          worst = s;
          p = k;
        }
      }
      if (p < 0) { /* every constraint holds: optimal */
        status = SC_QP_OPTIMAL;
        break;
      }
    }
    a = A + row[p] * n;
    sigma = (double)sgn[p];
    for (;;) { /* step 2: the primal and dual directions and the step length */
      double t1 = INFINITY, t2 = INFINITY, t, zn = 0.0, dn = 0.0;
      sc_int dropped = -1;
      for (k = 0; k < n; ++k) { /* d = J^T n_p */
        double s = 0.0;
        for (i = 0; i < n; ++i) s += J[i * n + k] * a[i];
        d[k] = sigma * s;
        dn += d[k] * d[k];
        if (k >= q) zn += d[k] * d[k]; /* n_p . z = |d_2|^2 */
      }
      for (i = 0; i < n; ++i) { /* z = J_2 d_2 */
        double s = 0.0;
        for (k = q; k < n; ++k) s += J[i * n + k] * d[k];
        z[i] = s;
      }
      for (j = q - 1; j >= 0; --j) { /* r = R^-1 d_1 */
        double s = d[j];
        for (k = j + 1; k < q; ++k) s -= R[j * n + k] * r[k];
        r[j] = s / R[j * n + j];
      }
      for (j = 0; j < q; ++j) /* partial step: an active inequality's multiplier reaches 0 */
        if (act[j] >= neq && r[j] > 0 && u[j] / r[j] < t1) {
          t1 = u[j] / r[j];
          dropped = j;
        }
      sp = sigma * sc_dot(a, x, n) - bnd[p];
      /* d_2 of the size of rounding: n_p depends on the active normals (no primal step; the
       * test in J's coordinates, where H's conditioning has been taken out) */
      if (zn > 1e-20 * dn) t2 = sp >= 0 ? 0.0 : -sp / zn;
      t = t2 < t1 ? t2 : t1;
      if (!isfinite(t)) {
        if (p < neq && fabs(sp) <= SC_QP_FEAS_TOL * (cn[p] + fabs(bnd[p]))) break; /* a
          dependent equality that holds already: nothing to add */
        status = SC_QP_INFEASIBLE;
        goto done;
      }
      if (t < t2) { /* the partial step: drop the blocking constraint */
        sc_int l = dropped;
        for (j = 0; j < q; ++j) u[j] -= t * r[j];
        u_plus += t;
        if (t2 < INFINITY)
          for (i = 0; i < n; ++i) x[i] += t * z[i];
        /* remove column l of R; rotations of rows (k, k+1) restore the triangle, and the
         * same rotations of J's columns (k, k+1) keep J^T N_A = [R; 0] */
        for (j = l; j < q - 1; ++j) {
          act[j] = act[j + 1];
          u[j] = u[j + 1];
          for (i = 0; i <= j + 1; ++i) R[i * n + j] = R[i * n + j + 1];
        }
        for (k = l; k < q - 1; ++k) {
          double aa = R[k * n + k], bb = R[(k + 1) * n + k], h = hypot(aa, bb), c, s;
          if (bb == 0.0) continue;
          c = aa / h;
          s = bb / h;
          for (j = k; j < q - 1; ++j) {
            double r1 = R[k * n + j], r2 = R[(k + 1) * n + j];
            R[k * n + j] = c * r1 + s * r2;
            R[(k + 1) * n + j] = -s * r1 + c * r2;
          }
          for (i = 0; i < n; ++i) {
            double j1 = J[i * n + k], j2 = J[i * n + k + 1];
            J[i * n + k] = c * j1 + s * j2;
            J[i * n + k + 1] = -s * j1 + c * j2;
          }
        }
        --q;
        ++sol->iterations;
        continue;
      }
      /* the full step: p becomes active; rotations of J's columns (k-1, k) from the bottom
       * bring d_2 into its first entry, which completes R's new column */
      for (i = 0; i < n; ++i) x[i] += t * z[i];
      for (j = 0; j < q; ++j) u[j] -= t * r[j];
      u_plus += t;
      for (k = n - 1; k > q; --k) {
        double aa = d[k - 1], bb = d[k], h, c, s;
        if (bb == 0.0) continue;
        h = hypot(aa, bb);
        c = aa / h;
        s = bb / h;
        d[k - 1] = h;
        d[k] = 0.0;
        for (i = 0; i < n; ++i) {
          double j1 = J[i * n + k - 1], j2 = J[i * n + k];
          J[i * n + k - 1] = c * j1 + s * j2;
          J[i * n + k] = -s * j1 + c * j2;
        }
      }
      for (i = 0; i <= q; ++i) R[i * n + q] = d[i];
      act[q] = p;
      u[q] = u_plus;
      ++q;
      ++sol->iterations;
      /* the point and the multipliers of the new active set, solved directly: long steps
       * (an LP's tiny curvature puts the unconstrained minimiser far away) would otherwise
       * leave their rounding in x */
      for (j = 0; j < q; ++j) {
        rows_act[j] = row[act[j]];
        hp[j] = sgn[act[j]] > 0 ? bnd[act[j]] : -bnd[act[j]];
      }
      if (active_set_optimum(n, qp->H, qp->g, A, q, rows_act, hp, xs, ls, K, rhs, piv)) {
        for (i = 0; i < n; ++i) x[i] = xs[i];
        for (j = 0; j < q; ++j) {
          u[j] = sgn[act[j]] * ls[j];
          if (act[j] >= neq && u[j] < 0) u[j] = 0.0;
        }
      }
      break;
    }
  }
done:
  if (status != SC_QP_OPTIMAL) return status;
  /* the active set's optimum, solved directly: kept when it holds every row and is no worse
   * (the answer is then a function of the active set alone, exact to rounding) */
  for (j = 0; j < q; ++j) {
    rows_act[j] = row[act[j]];
    hp[j] = sgn[act[j]] > 0 ? bnd[act[j]] : -bnd[act[j]];
  }
  for (i = 0; i < m; ++i) sol->lam[i] = 0.0;
  if (active_set_optimum(n, qp->H, qp->g, A, q, rows_act, hp, xs, ls, K, rhs, piv) &&
      rows_hold(n, m, A, qp->lo, qp->hi, xs, SC_QP_FEAS_TOL)) {
    /* taken when its multipliers have their signs (it is then the optimum: the KKT
     * conditions hold) or it is no worse than the iteration's point */
    double f0 = objective(n, qp->H, qp->g, x), f1 = objective(n, qp->H, qp->g, xs), big = 0.0;
    int signs = 1;
    for (j = 0; j < q; ++j)
      if (fabs(ls[j]) > big) big = fabs(ls[j]);
    for (j = 0; j < q; ++j)
      if (act[j] >= neq && sgn[act[j]] * ls[j] < -1e-12 * big) signs = 0;
    if (signs || f1 <= f0 + 1e-12 * fabs(f0)) {
      for (i = 0; i < n; ++i) x[i] = xs[i];
      for (j = 0; j < q; ++j) u[j] = sgn[act[j]] * ls[j]; /* back to one-sided below */
    }
  }
  for (j = 0; j < q; ++j) sol->lam[rows_act[j]] = sgn[act[j]] * u[j];
  for (i = 0; i < n; ++i) sol->x[i] = x[i];
  for (j = 0; j < q; ++j) sol->active[j] = rows_act[j];
  sol->n_active = q;
  return SC_QP_OPTIMAL;
}

/* ---------------------------------------------------------------------------------------
 * The ellipsoid's multiplier. The caller has solved the problem without the ellipsoid and
 * found its optimum outside: the ellipsoid is then active at the optimum, whose multiplier
 * mu > 0 solves phi(mu) = rho2 with x(mu) the QP optimum of H + mu N over the linear rows
 * (the Lagrangian 1/2 x^T H x + g^T x + mu/2 (x^T N x - rho2)). phi decreases with mu
 * (Moré & Sorensen's argument for the trust region, row by row of the active set); the root
 * exists iff the least-N-norm point of the rows, phi(infinity), lies inside. On a piece of
 * constant active set x(mu) solves the KKT system K(mu) [x; lam] = [-g; b], and
 * d x / d mu = -K(mu)^-1 [N x; 0], so Newton's method on psi(mu) = 1/sqrt(phi) - 1/sqrt(rho2)
 * (nearly linear in mu) stays on the piece while its multipliers keep their signs and the
 * inactive rows hold; otherwise the QP at the new mu gives the next piece. A bracket
 * [lo, hi] of the root keeps the steps safe (bisection when Newton leaves it). Converged when
 * |phi / rho2 - 1| <= 4e-15 or the bracket is as narrow as mu's rounding. mu0 > 0 is the first
 * guess (its natural size). */
static int piece_valid(const sc_qp *qp, const double *x, const double *lam, const sc_int *act,
                       sc_int q) {
  sc_int j;
  for (j = 0; j < q; ++j) { /* an inequality's multiplier keeps the sign of its side */
    sc_int i = act[j];
    double ax = sc_dot(qp->A + i * qp->n, x, qp->n);
    if (qp->lo[i] == qp->hi[i]) continue;
    if (fabs(ax - qp->lo[i]) <= fabs(ax - qp->hi[i]) ? lam[j] < 0 : lam[j] > 0) return 0;
  }
  return rows_hold(qp->n, qp->m, qp->A, qp->lo, qp->hi, x, SC_QP_FEAS_TOL);
}

/* the bounds at which the active rows are held at x (the side nearer to a_r . x) */
static void active_bounds(const sc_qp *qp, const sc_int *act, sc_int q, const double *x,
                          double *b) {
  sc_int j;
  for (j = 0; j < q; ++j) {
    sc_int r = act[j];
    double ax = sc_dot(qp->A + r * qp->n, x, qp->n);
    b[j] = (qp->lo[r] == qp->hi[r] || fabs(ax - qp->lo[r]) <= fabs(ax - qp->hi[r])) ? qp->lo[r]
                                                                                     : qp->hi[r];
  }
}

/* a point of a piece with its active set and their multipliers, copied */
static void copy_piece(sc_int n, sc_int q, const double *x, const sc_int *act, const double *lam,
                       double *x_to, sc_int *act_to, double *lam_to) {
  sc_int i;
  for (i = 0; i < n; ++i) x_to[i] = x[i];
  for (i = 0; i < q; ++i) {
    act_to[i] = act[i];
    lam_to[i] = lam[i];
  }
}

int sc_qcqp_ellipsoid(const sc_qp *qp, const double *N, double rho2, double mu0, sc_qp_work *w,
                      sc_qp_solution *sol) {
  const sc_int n = qp->n, m = qp->m;
  double *D = qc_d(w), *Hm, *xp, *xn, *nx, *dx, *bact, *lamp, *lamd, *kr, *K, *x_in, *lam_in;
  double phi = rho2, psi = 0.0, mu, lo = 0.0, hi = INFINITY, inv_rho = 1.0 / sqrt(rho2);
  double mu_in = 0.0;
  sc_int *I = qc_i(w), *act, *piv, *act_in, q = 0, q_in = -1, i, j, k, solves = 0, newton = 0;
  int st;
  sc_qp sub = *qp;
  if (n > w->n_max || m > w->m_max) return SC_QP_SIZE;
  Hm = D;
  xp = Hm + n * n;
  xn = xp + n;
  nx = xn + n;
  dx = nx + n;
  bact = dx + n;
  lamp = bact + n;
  lamd = lamp + n;
  kr = lamd + n; /* 2 n */
  K = kr + 2 * n; /* (2 n)^2 */
  x_in = K + 4 * n * n;
  lam_in = x_in + n;
  act = I;
  piv = act + n; /* 2 n */
  act_in = piv + 2 * n;
  sub.H = Hm;
  /* phi(infinity): the least-N-norm point of the rows; outside the ellipsoid, no root */
  for (i = 0; i < n; ++i) nx[i] = 0.0;
  for (i = 0; i < n * n; ++i) Hm[i] = N[i];
  sub.g = nx;
  st = sc_qp_solve(&sub, w, sol);
  ++solves;
  if (st != SC_QP_OPTIMAL) return st;
  if (sc_quad(n, N, n, sol->x) > rho2 * (1.0 + 1e-12)) {
    sol->iterations = solves;
    return SC_QP_EMPTY;
  }
  sub.g = qp->g;
  mu0 = mu0 > 0 && isfinite(mu0) ? mu0 : 1.0;
  mu = mu0;
  for (k = 0; k < 200; ++k) {
    /* the QP at mu: its active set is the piece */
    for (i = 0; i < n * n; ++i) Hm[i] = qp->H[i] + mu * N[i];
    st = sc_qp_solve(&sub, w, sol);
    ++solves;
    if (st != SC_QP_OPTIMAL) return st;
    q = sol->n_active;
    for (j = 0; j < q; ++j) {
      act[j] = sol->active[j];
      lamp[j] = sol->lam[act[j]];
    }
    for (i = 0; i < n; ++i) xp[i] = sol->x[i];
    for (;;) { /* Newton's method on this piece */
      double dphi = 0.0, dpsi, mu_new;
      sc_matvec(n, n, N, n, xp, nx);
      phi = sc_dot(xp, nx, n);
      psi = 1.0 / sqrt(phi) - inv_rho;
      if (psi < 0) {
        lo = mu;
      } else { /* the latest point inside: the answer should the root fall between pieces */
        hi = mu;
        copy_piece(n, q, xp, act, lamp, x_in, act_in, lam_in);
        q_in = q;
        mu_in = mu;
      }
      if (fabs(phi / rho2 - 1.0) <= 4e-15 || (isfinite(hi) && hi - lo <= 4e-16 * hi))
        goto converged;
      /* inside for every mu down to rounding of its natural size: the root is mu = 0 (a
       * linear objective whose optimal face reaches into the ellipsoid) */
      if (psi >= 0 && mu <= 1e-14 * mu0) goto converged;
      /* d x / d mu = -K(mu)^-1 [N x; 0]: the active-set optimum with g := N x, b := 0 */
      for (j = 0; j < q; ++j) bact[j] = 0.0;
      if (active_set_optimum(n, Hm, nx, qp->A, q, act, bact, dx, lamd, K, kr, piv)) {
        dphi = 2.0 * sc_dot(nx, dx, n);
        dpsi = -0.5 * dphi / (phi * sqrt(phi));
        mu_new = (dpsi > 0 && isfinite(dpsi)) ? mu - psi / dpsi : NAN;
      } else {
        mu_new = NAN;
      }
      if (!(mu_new > lo && mu_new < hi)) mu_new = isfinite(hi) ? 0.5 * (lo + hi) : 10.0 * mu;
      ++newton;
      if (fabs(mu_new - mu) <= 4e-16 * mu) goto converged;
      mu = mu_new;
      /* the same piece at the new mu, unless its active set no longer holds */
      for (i = 0; i < n * n; ++i) Hm[i] = qp->H[i] + mu * N[i];
      active_bounds(qp, act, q, xp, bact);
      if (!active_set_optimum(n, Hm, qp->g, qp->A, q, act, bact, xn, lamd, K, kr, piv) ||
          !piece_valid(qp, xn, lamd, act, q))
        break;
      for (i = 0; i < n; ++i) xp[i] = xn[i];
      for (j = 0; j < q; ++j) lamp[j] = lamd[j];
    }
  }
  sol->iterations = solves;
  sol->newton = newton;
  return SC_QP_ITERATIONS;
converged:
  if (psi < 0 && fabs(phi / rho2 - 1.0) > 4e-15 && q_in >= 0) {
    /* the bracket closed on a point outside by more than rounding (phi jumps between two
     * pieces there): the inside end of the bracket, as close to the root as mu's rounding */
    copy_piece(n, q_in, x_in, act_in, lam_in, xp, act, lamp);
    q = q_in;
    mu = mu_in;
  }
  for (i = 0; i < n; ++i) sol->x[i] = xp[i];
  for (i = 0; i < m; ++i) sol->lam[i] = 0.0;
  for (j = 0; j < q; ++j) {
    sol->active[j] = act[j];
    sol->lam[act[j]] = lamp[j];
  }
  sol->n_active = q;
  sol->mu = mu;
  sol->iterations = solves;
  sol->newton = newton;
  return SC_QP_OPTIMAL;
}

/* ---------------------------------------------------------------------------------------
 * Non-negative least squares, min ||C y - d|| s.t. y >= 0 (C n x k row-major), by the active
 * set method of Lawson & Hanson ("Solving Least Squares Problems", 1974, ch. 23): the passive
 * set grows by the variable of largest positive dual w = C^T (d - C y); each unconstrained
 * least-squares solve on the passive set (Householder QR) that leaves the positive orthant is
 * cut back by interpolation. work: 4 k + n k + 2 n doubles; iwork: 3 k. Returns the number of
 * iterations, or -1 when not converged. */
int sc_nnls(sc_int n, sc_int k, const double *C, const double *d, double *y, double *work,
            sc_int *iwork) {
  double *wd = work, *s = wd + k, *qx = s + k, *qn = qx + k, *Ap = qn + k, *bp = Ap + n * k,
         *res = bp + n;
  sc_int *passive = iwork, *col = passive + k, *perm = col + k, it, i, j, np, maxit = 3 * k + 10;
  double cmax = 0.0, tol;
  for (j = 0; j < k; ++j) {
    y[j] = 0.0;
    passive[j] = 0;
  }
  for (i = 0; i < n * k; ++i)
    if (fabs(C[i]) > cmax) cmax = fabs(C[i]);
  tol = 10.0 * 2.220446049250313e-16 * cmax * (sc_norm(d, n) + 1e-300) * (double)(n > k ? n : k);
  for (it = 0; it < maxit; ++it) {
    sc_int jmax = -1;
    double wmax = tol;
    for (i = 0; i < n; ++i) { /* the dual w = C^T (d - C y) */
      double t = d[i];
      for (j = 0; j < k; ++j) t -= C[i * k + j] * y[j];
      res[i] = t;
    }
    for (j = 0; j < k; ++j) {
      double t = 0.0;
      for (i = 0; i < n; ++i) t += C[i * k + j] * res[i];
      wd[j] = t;
      if (!passive[j] && t > wmax) {
        wmax = t;
        jmax = j;
      }
    }
    if (jmax < 0) return (int)it;
    passive[jmax] = 1;
    for (;;) {
      double alpha = INFINITY;
      np = 0;
      for (j = 0; j < k; ++j)
        if (passive[j]) col[np++] = j;
      for (i = 0; i < n; ++i) {
        for (j = 0; j < np; ++j) Ap[i * np + j] = C[i * k + col[j]];
        bp[i] = d[i];
      }
      for (j = 0; j < k; ++j) s[j] = 0.0;
      sc_qr_least_squares(n, np, Ap, np, bp, 1e-13, qx, qn, perm);
      for (j = 0; j < np; ++j) s[col[j]] = qx[j];
      for (j = 0; j < np; ++j) {
        sc_int c = col[j];
        if (s[c] <= 0.0) {
          double a = y[c] / (y[c] - s[c]);
          if (a < alpha) alpha = a;
        }
      }
      if (alpha == INFINITY) { /* the passive solution is positive: take it */
        for (j = 0; j < k; ++j) y[j] = s[j];
        break;
      }
      for (j = 0; j < k; ++j) {
        y[j] += alpha * (s[j] - y[j]);
        if (passive[j] && y[j] <= 0.0) {
          passive[j] = 0;
          y[j] = 0.0;
        }
      }
    }
  }
  return -1;
}

/* ---------------------------------------------------------------------------------------
 * The KKT certificate (engine.h). Constraint "sizes" follow the row: |G| |x| + |bound| for a row,
 * |x| |Q| |x| + |r2| for the quadric; the gradient's size is ||H|| ||x|| + ||c||. The
 * duality gap of a convex problem at multipliers lam: with L(y) = f(y) - sum_i lam_i s_i(y)
 * (the quadric's slack r2 - y^T Q y among the s_i), L is quadratic with Hessian
 * K = H + 2 mu Q, so the dual function is d(lam) = L(x) - 1/2 r^T K^+ r with r = grad L(x),
 * and the gap f(x) - d(lam) is sum_i lam_i s_i(x) + 1/2 r^T K^+ r: every term small at a KKT
 * point (evaluating L at a computed minimiser instead would lose the gap to K's
 * conditioning). */
void sc_kkt_certificate(sc_int n, const double *x, const double *H, const double *c, sc_int m,
                        const double *G, const double *lo, const double *hi, const double *Q,
                        double r2, int convex, double active, double stationarity_tol,
                        double *values, double *lam_rows, double *mu_out, sc_qp_work *w) {
  const sc_int kmax = CE_K(w->n_max, w->m_max);
  double *D = ce_d(w), *Hx = D, *grad = Hx + n, *res = grad + n, *qx = res + n, *yv = qx + n,
         *ew = yv + n, *slo = ew + n, *shi = slo + m, *rs = shi + m, *gx = rs + m,
         *cols = gx + m, *Cn = cols + n * kmax, *big = Cn + n * kmax, *slack = big + 2 * n * kmax,
         *norms = slack + kmax, *lam = norms + kmax, *lsq = lam + kmax, *M = lsq + 2 * kmax,
         *E = M + kmax * kmax, *V = E + n * n, *nw = V + n * n; /* nnls: 8 kmax + 2 n kmax + 2 n */
  sc_int *I = ce_i(w), *freec = I, *origin = freec + kmax, *piv = origin + kmax,
         *iw = piv + kmax; /* nnls: 6 kmax */
  sc_int i, j, k = 0, qcol = -1;
  double f, fscale, ref, primal = 0.0, resid, size, comp = 0.0, stat, gnorm, mu = 0.0;
  for (i = 0; i < n; ++i) Hx[i] = H ? sc_dot(H + i * n, x, n) : 0.0;
  f = 0.5 * sc_dot(x, Hx, n) + sc_dot(c, x, n);
  for (i = 0; i < n; ++i) grad[i] = Hx[i] + c[i];
  /* primal feasibility and the active rows: lower sides first, then upper, then Q */
  for (i = 0; i < m; ++i) {
    const double *g = G + i * n;
    double b = 0.0, v;
    gx[i] = sc_dot(g, x, n);
    if (isfinite(lo[i]) && fabs(lo[i]) > b) b = fabs(lo[i]);
    if (isfinite(hi[i]) && fabs(hi[i]) > b) b = fabs(hi[i]);
    rs[i] = b;
    for (j = 0; j < n; ++j) rs[i] += fabs(g[j]) * fabs(x[j]);
    if (!(rs[i] > 0)) rs[i] = 1.0;
    slo[i] = isfinite(lo[i]) ? gx[i] - lo[i] : INFINITY;
    shi[i] = isfinite(hi[i]) ? hi[i] - gx[i] : INFINITY;
    v = -slo[i] > -shi[i] ? -slo[i] : -shi[i];
    if (v / rs[i] > primal) primal = v / rs[i];
  }
  for (i = 0; i < m; ++i) /* the lower sides (an equality: one free column) */
    if (slo[i] <= active * rs[i]) {
      int eq = shi[i] <= active * rs[i] && lo[i] == hi[i];
      for (j = 0; j < n; ++j) cols[j * kmax + k] = G[i * n + j];
      slack[k] = eq ? 0.0 : slo[i];
      freec[k] = eq;
      origin[k++] = i;
    }
  for (i = 0; i < m; ++i)
    if (shi[i] <= active * rs[i] && !(slo[i] <= active * rs[i] && lo[i] == hi[i])) {
      for (j = 0; j < n; ++j) cols[j * kmax + k] = -G[i * n + j];
      slack[k] = shi[i];
      freec[k] = 0;
      origin[k++] = -2 - i; /* the upper side of row i */
    }
  if (Q) {
    double qs = r2 >= 0 ? r2 : -r2, qv;
    for (i = 0; i < n; ++i) {
      qx[i] = sc_dot(Q + i * n, x, n);
      for (j = 0; j < n; ++j) qs += fabs(x[i]) * fabs(Q[i * n + j]) * fabs(x[j]);
    }
    if (!(qs > 0)) qs = 1.0;
    qv = sc_dot(x, qx, n) - r2;
    if ((qv > 0 ? qv : 0.0) / qs > primal) primal = qv / qs;
    if (-qv <= active * qs) {
      qcol = k;
      for (j = 0; j < n; ++j) cols[j * kmax + k] = -2.0 * qx[j];
      slack[k] = -qv;
      freec[k] = 0;
      origin[k++] = -1;
    }
  }
  {
    double a = fabs(f), b = fabs(sc_dot(grad, x, n));
    fscale = a > b ? a : b;
    if (!(fscale > 1e-300)) fscale = 1e-300;
  }
  ref = (H ? sc_frobenius(n, n, H, n) * sc_norm(x, n) : 0.0) + sc_norm(c, n);
  gnorm = sc_norm(grad, n);
  if (k) {
    int ok = 1;
    double fit = 0.0, tol = gnorm > ref ? gnorm : ref;
    if (!(tol > 1e-300)) tol = 1e-300;
    for (j = 0; j < k; ++j) { /* unit columns */
      double s = 0.0;
      for (i = 0; i < n; ++i) s += cols[i * kmax + j] * cols[i * kmax + j];
      norms[j] = s > 0 ? sqrt(s) : 1.0;
      for (i = 0; i < n; ++i) Cn[i * kmax + j] = cols[i * kmax + j] / norms[j];
    }
    /* the normal equations (a handful of unit columns) */
    for (i = 0; i < k; ++i) {
      for (j = 0; j < k; ++j) {
        double s = 0.0;
        sc_int l;
        for (l = 0; l < n; ++l) s += Cn[l * kmax + i] * Cn[l * kmax + j];
        M[i * k + j] = s;
      }
      {
        double s = 0.0;
        sc_int l;
        for (l = 0; l < n; ++l) s += Cn[l * kmax + i] * grad[l];
        lam[i] = s;
      }
    }
    if (!sc_lu_factor(k, M, k, piv)) ok = 0;
    if (ok) {
      sc_lu_solve(k, M, k, piv, lam);
      for (j = 0; j < k; ++j)
        if (!isfinite(lam[j]) || (!freec[j] && lam[j] < 0)) ok = 0;
    }
    if (ok) {
      for (i = 0; i < n; ++i) {
        double s = -grad[i];
        for (j = 0; j < k; ++j) s += Cn[i * kmax + j] * lam[j];
        fit += s * s;
      }
      ok = sqrt(fit) <= 0.1 * stationarity_tol * tol;
    }
    if (!ok) { /* signs bind or the columns are dependent: non-negative least squares, a free
                * multiplier as the difference of two */
      sc_int kk = k, l;
      for (j = 0; j < k; ++j)
        if (freec[j]) ++kk;
      for (i = 0; i < n; ++i) {
        l = k;
        for (j = 0; j < k; ++j) {
          big[i * kk + j] = Cn[i * kmax + j];
          if (freec[j]) big[i * kk + l++] = -Cn[i * kmax + j];
        }
      }
      sc_nnls(n, kk, big, grad, lsq, nw, iw);
      l = k;
      for (j = 0; j < k; ++j) {
        lam[j] = lsq[j];
        if (freec[j]) lam[j] -= lsq[l++];
      }
    }
    size = gnorm;
    {
      double s = 0.0;
      for (j = 0; j < k; ++j) {
        lam[j] /= norms[j];
        s += fabs(lam[j]) * norms[j];
      }
      if (s > size) size = s;
    }
    for (i = 0; i < n; ++i) {
      double s = -grad[i];
      for (j = 0; j < k; ++j) s += cols[i * kmax + j] * lam[j];
      res[i] = s;
    }
    resid = sc_norm(res, n);
  } else {
    for (i = 0; i < n; ++i) res[i] = -grad[i];
    resid = gnorm;
    size = 0.0;
  }
  {
    double dd = size > ref ? size : ref;
    if (!(dd > 1e-300)) dd = 1e-300;
    stat = resid > 0 ? resid / dd : 0.0;
  }
  for (j = 0; j < k; ++j) comp += fabs(lam[j]) * fabs(slack[j]);
  if (qcol >= 0) mu = lam[qcol];
  values[0] = stat;
  values[1] = primal;
  values[2] = k ? comp / fscale : 0.0;
  values[3] = NAN;
  if (convex) { /* 1/2 r^T K^+ r, r = grad - C lam, K = H + 2 mu Q, K^+ from its eigenvalues */
    double corr = 0.0, top = 0.0;
    int any = 0;
    for (i = 0; i < n; ++i) {
      yv[i] = -res[i];
      if (yv[i] != 0.0) any = 1;
      for (j = 0; j < n; ++j)
        E[i * n + j] = (H ? H[i * n + j] : 0.0) + (Q ? 2.0 * mu * Q[i * n + j] : 0.0);
    }
    if (any) {
      int nonzero = 0;
      for (i = 0; i < n * n; ++i)
        if (E[i] != 0.0) nonzero = 1;
      if (nonzero) {
        sc_eigen_symmetric(n, E, n, ew, V, n);
        for (i = 0; i < n; ++i)
          if (fabs(ew[i]) > top) top = fabs(ew[i]);
        for (j = 0; j < n; ++j)
          if (fabs(ew[j]) > 1e-12 * top) {
            double s = 0.0;
            for (i = 0; i < n; ++i) s += V[i * n + j] * yv[i];
            corr += 0.5 * s * s / ew[j];
          }
      }
    }
    values[3] = (k ? comp + corr : corr) / fscale;
  }
  if (lam_rows) {
    for (i = 0; i < m; ++i) lam_rows[i] = 0.0;
    for (j = 0; j < k; ++j) {
      if (origin[j] >= 0) lam_rows[origin[j]] += lam[j];
      else if (origin[j] <= -2) lam_rows[-2 - origin[j]] -= lam[j];
    }
  }
  if (mu_out) *mu_out = mu;
}
