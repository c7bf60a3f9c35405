/* snakecg's runtime core: dense convex QPs, the ellipsoid constraint, non-negative least squares
 * and the KKT certificate (qp.c). Building blocks that know nothing of snakes: problems of a
 * few dozen variables and rows, solved exactly on their active set.
 *
 *   sc_qp_solve          min 1/2 x^T H x + g^T x  s.t.  lo <= A x <= hi, H positive definite:
 *                        the dual active-set method of Goldfarb & Idnani (1983), then the
 *                        optimum of its final active set solved directly (one KKT system), so
 *                        that the answer is a function of the active set alone
 *   sc_qcqp_ellipsoid    the same problem plus the ellipsoid x^T N x <= rho2 (N positive
 *                        definite, H positive semidefinite), through the ellipsoid's
 *                        multiplier mu: x(mu) minimises 1/2 x^T (H + mu N) x + g^T x over the
 *                        linear rows, phi(mu) = x(mu)^T N x(mu) decreases with mu, and the
 *                        secular equation 1/sqrt(phi(mu)) = 1/sqrt(rho2) is solved by Newton's
 *                        method on each piece of constant active set (safeguarded by a
 *                        bracket), to machine precision
 *   sc_nnls              min ||C y - d|| s.t. y >= 0 (Lawson & Hanson 1974, ch. 23)
 *   sc_kkt_certificate   the KKT residuals of a point of a QP or QCQP (primal feasibility,
 *                        stationarity with multipliers recomputed by least squares, dual signs,
 *                        complementarity, and for a convex problem the duality gap)
 *
 * Why the multiplier for the ellipsoid rather than an interior-point method: the linear rows are
 * handled by the same exact active-set solver as every QP here, infeasibility is decided
 * exactly (the least-N-norm point of the rows, one more QP), the answer comes with its active
 * set and multipliers, and on each piece of constant active set the solution is a rational
 * function of mu, so Newton's method converges quadratically to the root; an interior point
 * method stops near its barrier parameter's tolerance and needs an exact active-set solve
 * after it anyway.
 *
 * Matrices are row-major (element (i, j) of an m x n matrix at [i * n + j]). Nothing is
 * allocated but the workspace of sc_qp_work_alloc, which serves every problem up to its sizes.
 */
#ifndef SNAKECG_CORE_QP_H
#define SNAKECG_CORE_QP_H

#include "linalg.h"

#if defined(__GNUC__)
/* the library exports the model's prefixed entry points only; the core's own functions
 * across its files stay inside it */
#define SC_INTERNAL __attribute__((visibility("hidden")))
#else
#define SC_INTERNAL
#endif

/* A dense QP: min 1/2 x^T H x + g^T x s.t. lo_r <= a_r . x <= hi_r for r < m (a_r the rows of
 * A; -INFINITY / INFINITY for a missing side; lo_r == hi_r an equality). */
typedef struct {
  sc_int n, m;
  const double *H; /* n x n, symmetric */
  const double *g; /* n */
  const double *A; /* m x n */
  const double *lo, *hi;
} sc_qp;

/* A solution: x, the rows' signed multipliers (H x + g = sum_r lam_r a_r, lam_r >= 0 on an
 * active lower side, <= 0 on an active upper side, 0 on an inactive row), the active rows,
 * the counts of work done. */
typedef struct {
  double *x;      /* n */
  double *lam;    /* m */
  sc_int *active; /* n_active rows (at most n), in the order they entered */
  sc_int n_active;
  sc_int iterations; /* active-set changes (sc_qp_solve); QP solves (sc_qcqp_ellipsoid) */
  sc_int newton;     /* sc_qcqp_ellipsoid: Newton steps on the secular equation */
  double mu;         /* sc_qcqp_ellipsoid: the ellipsoid's multiplier (0: not active) */
} sc_qp_solution;

/* a problem's and a solution's fields at once */
static inline void sc_qp_define(sc_qp *qp, sc_int n, sc_int m, const double *H, const double *g,
                                const double *A, const double *lo, const double *hi) {
  qp->n = n;
  qp->m = m;
  qp->H = H;
  qp->g = g;
  qp->A = A;
  qp->lo = lo;
  qp->hi = hi;
}

static inline void sc_qp_solution_define(sc_qp_solution *s, double *x, double *lam,
                                         sc_int *active) {
  s->x = x;
  s->lam = lam;
  s->active = active;
  s->n_active = s->iterations = s->newton = 0;
  s->mu = 0.0;
}

enum {
  SC_QP_OPTIMAL = 0,
  SC_QP_INFEASIBLE = 1,  /* the linear rows have no common point */
  SC_QP_NOT_CONVEX = 2,  /* H is not numerically positive definite */
  SC_QP_ITERATIONS = 3,  /* no convergence within the iteration limit */
  SC_QP_EMPTY = 4,       /* sc_qcqp_ellipsoid: no point of the rows inside the ellipsoid */
  SC_QP_SIZE = 5         /* larger than the workspace */
};

/* Scratch space for problems of up to n_max variables and m_max rows: allocated
 * (sc_qp_work_alloc), or the caller's arrays of SC_QP_WORK_DOUBLES and SC_QP_WORK_INTS
 * entries (sc_qp_work_init; a model's fixed sizes on the stack: no allocation per call). */
typedef struct {
  sc_int n_max, m_max;
  double *d;
  sc_int *i;
} sc_qp_work;

#define SC_QP_WORK_DOUBLES(n, m)                                                         \
  (6 * (n) * (n) + 10 * (n) + 4 * (m) + 6 + 5 * (n) * (n) + 12 * (n) +                  \
   7 * (n) * (2 * (m) + 2) + 14 * (2 * (m) + 2) + (2 * (m) + 2) * (2 * (m) + 2) +       \
   2 * (n) * (n) + 12 * (n) + 4 * (m) + 64)
#define SC_QP_WORK_INTS(n, m) (4 * (m) + 4 + 4 * (n) + 2 + 4 * (n) + 9 * (2 * (m) + 2) + 64)

/* Relative violation below which a row counts as satisfied (sc_qp_solve). */
#define SC_QP_FEAS_TOL 1e-12

SC_INTERNAL int sc_qp_work_alloc(sc_qp_work *w, sc_int n_max, sc_int m_max);
SC_INTERNAL void sc_qp_work_init(sc_qp_work *w, sc_int n_max, sc_int m_max, double *d,
                                 sc_int *i);
SC_INTERNAL void sc_qp_work_free(sc_qp_work *w);
SC_INTERNAL int sc_qp_solve(const sc_qp *qp, sc_qp_work *w, sc_qp_solution *sol);
SC_INTERNAL int sc_qcqp_ellipsoid(const sc_qp *qp, const double *N, double rho2, double mu0,
                                  sc_qp_work *w, sc_qp_solution *sol);
SC_INTERNAL int sc_nnls(sc_int n, sc_int k, const double *C, const double *d, double *y,
                        double *work, sc_int *iwork);

/* The certificate of a point x of min 1/2 x^T H x + c^T x (H null: linear) s.t.
 * lo <= G x <= hi (m rows) and, when Q is not null, x^T Q x <= r2. The constraints whose
 * relative slack is at most `active` are taken as active, their multipliers recomputed from the
 * stationarity condition (the normal equations of the unit-scaled active columns, or
 * non-negative least squares when their signs bind or they are dependent); `values` receives
 * stationarity, primal feasibility, complementarity and (convex only, else NaN) the duality
 * gap f(x) - d(lam), each relative (docs/how-to/optimize.md), and the multipliers of the rows
 * (lam, m: signed as in sc_qp_solution) and of Q (*mu), when those pointers are not null. */
SC_INTERNAL void sc_kkt_certificate(sc_int n, const double *x, const double *H, const double *c,
                                    sc_int m, const double *G, const double *lo,
                                    const double *hi, const double *Q, double r2, int convex,
                                    double active, double stationarity_tol, double *values,
                                    double *lam, double *mu, sc_qp_work *w);

#endif
