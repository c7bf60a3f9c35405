/* snakecg's engine: dense convex QPs, the ellipsoid constraint through its multiplier,
 * (prototypes and method notes in engine.h; NNLS and the KKT certificate in certificate.c).
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
  double *D = sc_qp_gi_d(w), *J, *R, *d, *z, *r, *u, *x, *hp, *xs, *ls, *bnd, *cn, *K, *rhs;
  sc_int *I = sc_qp_gi_i(w), *row, *sgn, *piv, *act, *rows_act;
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
  double *D = sc_qp_qc_d(w), *Hm, *xp, *xn, *nx, *dx, *bact, *lamp, *lamd, *kr, *K, *x_in, *lam_in;
  double phi = rho2, psi = 0.0, mu, lo = 0.0, hi = INFINITY, inv_rho = 1.0 / sqrt(rho2);
  double mu_in = 0.0;
  sc_int *I = sc_qp_qc_i(w), *act, *piv, *act_in, q = 0, q_in = -1, i, j, k, solves = 0, newton = 0;
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
