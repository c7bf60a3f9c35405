/* snakecg's runtime core: the small dense algebra of optimal.c (included by it alone).
 *
 * Everything here is static and performs the operations of its Python counterpart in the same
 * order (sums left to right, as Python's sum() adds), so that both give the same numbers:
 * Gaussian elimination with partial pivoting (snakecg/optimize/active_set.py _lin_solve), the
 * Cholesky solve (snakecg/optimize/fast.py chol_solve), and the dense dual active-set method of
 * Goldfarb and Idnani (1983) for small strictly convex QPs (active_set.py solve, every
 * variable free): it starts from the unconstrained minimiser with nothing active (or, with a
 * diagonal Hessian, from it clipped to the single-variable rows it violates), adds the most
 * violated row, drops rows whose multiplier would turn negative, and after each addition
 * recomputes the point and the multipliers from the active set, exactly from its rows when
 * they fix the point. Plus the largest eigenvalue of a small symmetric matrix (cyclic Jacobi
 * rotations; LAPACK's eigvalsh on the Python side) and the numerical rank of a small matrix
 * (one-sided Jacobi; numpy.linalg.matrix_rank there).
 */
#ifndef SNAKECG_CORE_DENSE_H
#define SNAKECG_CORE_DENSE_H

#include <math.h>

typedef long long int op_int;

/* largest n_a of a query here; the active set takes DENSE_MAX variables at most (the Python
 * path hands larger problems to qpOASES) */
#define OP_MAX 16
#define DENSE_MAX 4
#define OP_ROWS (2 * OP_MAX + 4)
#define OP_CONS (2 * OP_ROWS)
#define OP_LS (OP_ROWS + 1)

/* relative violation below which a row counts as satisfied (active_set.FEAS_TOL) */
#define FEAS_TOL 1e-12

/* ---------------------------------------------------------------------------------------
 * small dense algebra, summing left to right as Python's sum() does */
static double op_dot(const double *a, const double *b, int n) {
  double s = 0.0;
  int i;
  for (i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}

static double op_norm(const double *a, int n) { return sqrt(op_dot(a, a, n)); }

/* x^T M x with M n x n, row-major, leading dimension ld */
static double op_quad(const double *M, int ld, const double *x, int n) {
  double s = 0.0;
  int i;
  for (i = 0; i < n; ++i) s += x[i] * op_dot(M + i * ld, x, n);
  return s;
}

static double op_frob(const double *M, int ld, int n) {
  double s = 0.0;
  int i;
  for (i = 0; i < n; ++i) s += op_dot(M + i * ld, M + i * ld, n);
  return sqrt(s);
}

/* M^-1 b by Gaussian elimination with partial pivoting (M n x n, row-major, leading dimension
 * ld); 0 when singular or not finite (active_set._lin_solve) */
static int op_lin_solve(int n, const double *M, int ld, const double *b, double *x) {
  double A[OP_LS * (OP_LS + 1)];
  int c, i, j, p, w = n + 1;
  if (n < 1 || n > OP_LS) return 0;
  if (n == 1) {
    double v;
    if (M[0] == 0.0) return 0;
    v = b[0] / M[0];
    if (!isfinite(v)) return 0;
    x[0] = v;
    return 1;
  }
  for (i = 0; i < n; ++i) {
    for (j = 0; j < n; ++j) A[i * w + j] = M[i * ld + j];
    A[i * w + n] = b[i];
  }
  for (c = 0; c < n; ++c) {
    double big = fabs(A[c * w + c]), piv;
    p = c;
    for (i = c + 1; i < n; ++i) {
      double v = fabs(A[i * w + c]);
      if (v > big) {
        p = i;
        big = v;
      }
    }
    if (big == 0.0) return 0;
    if (p != c)
      for (j = 0; j < w; ++j) {
        double t = A[c * w + j];
        A[c * w + j] = A[p * w + j];
        A[p * w + j] = t;
      }
    piv = A[c * w + c];
    for (i = c + 1; i < n; ++i) {
      double f = A[i * w + c] / piv;
      if (f != 0.0)
        for (j = c; j < w; ++j) A[i * w + j] -= f * A[c * w + j];
    }
  }
  for (i = n - 1; i >= 0; --i) {
    double s = 0.0;
    for (j = i + 1; j < n; ++j) s += A[i * w + j] * x[j];
    x[i] = (A[i * w + n] - s) / A[i * w + i];
  }
  for (i = 0; i < n; ++i)
    if (!isfinite(x[i])) return 0;
  return 1;
}

/* M^-1 b for a symmetric positive definite M by Cholesky; 0 when a pivot falls below rel
 * times the largest diagonal (fast.chol_solve) */
static int op_chol_solve(int n, const double *M, int ld, const double *b, double rel, double *x) {
  double Lc[OP_MAX * OP_MAX], y[OP_MAX], big;
  int i, j, k;
  if (n < 1 || n > OP_MAX) return 0;
  big = M[0];
  for (i = 1; i < n; ++i)
    if (M[i * ld + i] > big) big = M[i * ld + i];
  if (!(big > 0)) return 0;
  for (i = 0; i < n; ++i) {
    double d;
    for (j = 0; j < i; ++j)
      Lc[i * OP_MAX + j] = (M[i * ld + j] - op_dot(Lc + i * OP_MAX, Lc + j * OP_MAX, j)) /
                           Lc[j * OP_MAX + j];
    d = M[i * ld + i] - op_dot(Lc + i * OP_MAX, Lc + i * OP_MAX, i);
    if (!(d > rel * big)) return 0;
    Lc[i * OP_MAX + i] = sqrt(d);
  }
  for (i = 0; i < n; ++i) y[i] = (b[i] - op_dot(Lc + i * OP_MAX, y, i)) / Lc[i * OP_MAX + i];
  for (i = n - 1; i >= 0; --i) {
    double s = y[i];
    for (k = i + 1; k < n; ++k) s -= Lc[k * OP_MAX + i] * x[k];
    x[i] = s / Lc[i * OP_MAX + i];
  }
  return 1;
}

/* largest eigenvalue of the symmetric n x n S (row-major, overwritten), cyclic Jacobi */
static double op_top_eigenvalue(int n, double *S) {
  int i, j, l, sweep;
  double top;
  for (sweep = 0; sweep < 60; ++sweep) {
    double off = 0.0, tot = 0.0;
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) {
        double s2 = S[i * n + j] * S[i * n + j];
        tot += s2;
        if (i != j) off += s2;
      }
    if (off <= 1e-32 * tot || off == 0.0) break;
    for (i = 0; i < n - 1; ++i)
      for (j = i + 1; j < n; ++j) {
        double apq = S[i * n + j], theta, t, c, s;
        if (apq == 0.0) continue;
        theta = 0.5 * (S[j * n + j] - S[i * n + i]) / apq;
        t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
        c = 1.0 / sqrt(t * t + 1.0);
        s = t * c;
        for (l = 0; l < n; ++l) {
          double sli = S[l * n + i], slj = S[l * n + j];
          S[l * n + i] = c * sli - s * slj;
          S[l * n + j] = s * sli + c * slj;
        }
        for (l = 0; l < n; ++l) {
          double sil = S[i * n + l], sjl = S[j * n + l];
          S[i * n + l] = c * sil - s * sjl;
          S[j * n + l] = s * sil + c * sjl;
        }
        S[i * n + j] = S[j * n + i] = 0.0;
      }
  }
  top = S[0];
  for (i = 1; i < n; ++i)
    if (S[i * n + i] > top) top = S[i * n + i];
  return top;
}

/* number of singular values of the k x n matrix B (row-major, leading dimension ld) above
 * tol: one-sided Jacobi (Hestenes) rotations of its columns */
static int op_rank(int k, int n, const double *B, int ld, double tol) {
  double U[OP_CONS * DENSE_MAX];
  int i, j, p, q, sweep, rank = 0;
  for (i = 0; i < k; ++i)
    for (j = 0; j < n; ++j) U[i * n + j] = B[i * ld + j];
  for (sweep = 0; sweep < 60; ++sweep) {
    int rotated = 0;
    for (p = 0; p < n - 1; ++p)
      for (q = p + 1; q < n; ++q) {
        double a = 0.0, b = 0.0, g = 0.0, zeta, t, c, s;
        for (i = 0; i < k; ++i) {
          a += U[i * n + p] * U[i * n + p];
          b += U[i * n + q] * U[i * n + q];
          g += U[i * n + p] * U[i * n + q];
        }
        if (g == 0.0 || fabs(g) <= 1e-15 * sqrt(a * b)) continue;
        rotated = 1;
        zeta = (b - a) / (2.0 * g);
        t = (zeta >= 0 ? 1.0 : -1.0) / (fabs(zeta) + sqrt(1.0 + zeta * zeta));
        c = 1.0 / sqrt(1.0 + t * t);
        s = c * t;
        for (i = 0; i < k; ++i) {
          double up = U[i * n + p], uq = U[i * n + q];
          U[i * n + p] = c * up - s * uq;
          U[i * n + q] = s * up + c * uq;
        }
      }
    if (!rotated) break;
  }
  for (j = 0; j < n; ++j) {
    double s = 0.0;
    for (i = 0; i < k; ++i) s += U[i * n + j] * U[i * n + j];
    if (sqrt(s) > tol) ++rank;
  }
  return rank;
}

/* ---------------------------------------------------------------------------------------
 * the dense dual active set (snakecg/optimize/active_set.py solve, every variable free):
 * min 1/2 x^T H x + g^T x s.t. lo <= A x <= hi, H n x n (DENSE_MAX), A R x n (leading
 * dimension DENSE_MAX). Returns 1 with x and the rows' multipliers lam (R), 0 when it gives
 * up (infeasible, or not settled). */
typedef struct {
  int n, m, neq;
  double C[OP_CONS][DENSE_MAX], b[OP_CONS], cn[OP_CONS];
  int origin[OP_CONS];
  double Hinv[DENSE_MAX][DENSE_MAX], x0[DENSE_MAX], g[DENSE_MAX], Hd[DENSE_MAX];
  double h[OP_CONS][DENSE_MAX];
  int have[OP_CONS];
} op_qp;

static const double *op_hv(op_qp *Q, int i) {
  if (!Q->have[i]) {
    int r;
    for (r = 0; r < Q->n; ++r) Q->h[i][r] = op_dot(Q->Hinv[r], Q->C[i], Q->n);
    Q->have[i] = 1;
  }
  return Q->h[i];
}

static int op_inverse(int n, const double *H, double Hi[DENSE_MAX][DENSE_MAX]) {
  int i, j, diag = 1;
  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j)
      if (i != j && H[i * DENSE_MAX + j] != 0.0) diag = 0;
  if (diag) {
    for (i = 0; i < n; ++i)
      if (H[i * DENSE_MAX + i] == 0.0) return 0;
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) Hi[i][j] = (i == j) ? 1.0 / H[i * DENSE_MAX + i] : 0.0;
    return 1;
  }
  if (n == 3) { /* the adjugate */
    double a = H[0], b = H[1], c = H[2], d = H[DENSE_MAX], e = H[DENSE_MAX + 1],
           f = H[DENSE_MAX + 2], g = H[2 * DENSE_MAX], h = H[2 * DENSE_MAX + 1],
           k = H[2 * DENSE_MAX + 2];
    double A = e * k - f * h, B = f * g - d * k, C = d * h - e * g;
    double det = a * A + b * B + c * C;
    if (det > 0 && isfinite(det)) {
      Hi[0][0] = A / det;
      Hi[0][1] = (c * h - b * k) / det;
      Hi[0][2] = (b * f - c * e) / det;
      Hi[1][0] = B / det;
      Hi[1][1] = (a * k - c * g) / det;
      Hi[1][2] = (c * d - a * f) / det;
      Hi[2][0] = C / det;
      Hi[2][1] = (b * g - a * h) / det;
      Hi[2][2] = (a * e - b * d) / det;
      return 1;
    }
  }
  { /* the general inverse, column by column */
    double e[DENSE_MAX], col[DENSE_MAX];
    for (j = 0; j < n; ++j) {
      for (i = 0; i < n; ++i) e[i] = (i == j) ? 1.0 : 0.0;
      if (!op_lin_solve(n, H, DENSE_MAX, e, col)) return 0;
      for (i = 0; i < n; ++i) Hi[i][j] = col[i];
    }
  }
  return 1;
}

/* active_set._bounds_first: with a diagonal H, x0 clipped to the tightest single-variable
 * rows it violates, those rows active (multipliers (H x + g)_j / c_j >= 0); nothing active
 * (x = x0) when that does not hold */
static void op_bounds_first(op_qp *Q, double *x, int *act, double *u, int *na) {
  int n = Q->n, m = Q->m, i, j, k, l;
  int brow[DENSE_MAX];
  double bval[DENSE_MAX];
  for (j = 0; j < n; ++j) {
    brow[j] = -1;
    bval[j] = 0.0;
    x[j] = Q->x0[j];
  }
  *na = 0;
  for (i = 0; i < m; ++i) {
    int nz = 0, lower;
    double c, v;
    j = -1;
    for (k = 0; k < n; ++k)
      if (Q->C[i][k] != 0.0) {
        ++nz;
        j = k;
      }
    if (nz != 1) continue;
    c = Q->C[i][j];
    v = Q->b[i] / c;
    lower = c > 0;
    if ((lower && Q->x0[j] < v) || (!lower && Q->x0[j] > v)) {
      if (brow[j] < 0 || (lower && v > bval[j]) || (!lower && v < bval[j])) {
        brow[j] = i;
        bval[j] = v;
      }
    }
  }
  for (j = 0; j < n; ++j) {
    double lam;
    if (brow[j] < 0) continue;
    i = brow[j];
    x[j] = bval[j];
    lam = (Q->Hd[j] * bval[j] + Q->g[j]) / Q->C[i][j];
    if (!(lam >= 0)) goto none;
    act[*na] = i;
    u[*na] = lam;
    ++*na;
  }
  /* the other single-variable rows must hold, else start from nothing */
  for (j = 0; j < n; ++j) {
    if (brow[j] < 0) continue;
    i = brow[j];
    for (k = 0; k < m; ++k) {
      int single = 1;
      if (k == i || Q->C[k][j] == 0.0) continue;
      for (l = 0; l < n; ++l)
        if (l != j && Q->C[k][l] != 0.0) single = 0;
      if (single && Q->C[k][j] * bval[j] - Q->b[k] < -FEAS_TOL * (1 + fabs(Q->b[k]))) goto none;
    }
  }
  return;
none:
  for (j = 0; j < n; ++j) x[j] = Q->x0[j];
  *na = 0;
}

/* active_set._recompute: the point and multipliers of the active set */
static void op_recompute(op_qp *Q, const int *act, int na, double *x, double *u) {
  int n = Q->n, i, j;
  double M[OP_LS * OP_LS], rhs[OP_CONS], un[OP_CONS], xn[DENSE_MAX];
  const double *hs[OP_CONS];
  if (na > OP_LS) return;
  for (j = 0; j < na; ++j) hs[j] = op_hv(Q, act[j]);
  for (i = 0; i < na; ++i) {
    for (j = 0; j < na; ++j) M[i * na + j] = op_dot(Q->C[act[i]], hs[j], n);
    rhs[i] = Q->b[act[i]] - op_dot(Q->C[act[i]], Q->x0, n);
  }
  if (!op_lin_solve(na, M, na, rhs, un)) return;
  if (na == n) {
    double R[DENSE_MAX * DENSE_MAX], bb[DENSE_MAX];
    for (i = 0; i < n; ++i) {
      for (j = 0; j < n; ++j) R[i * n + j] = Q->C[act[i]][j];
      bb[i] = Q->b[act[i]];
    }
    if (!op_lin_solve(n, R, n, bb, xn)) return;
  } else {
    for (i = 0; i < n; ++i) {
      double s = 0.0;
      for (j = 0; j < na; ++j) s += un[j] * hs[j][i];
      xn[i] = Q->x0[i] + s;
    }
  }
  for (i = 0; i < n; ++i) x[i] = xn[i];
  for (j = 0; j < na; ++j) u[j] = (act[j] < Q->neq || !(0.0 > un[j])) ? un[j] : 0.0;
}

static int op_dense_qp(op_qp *Q, int n, const double *H, const double *g, int R,
                       const double *A, const double *lo, const double *hi, double *xo,
                       double *lam) {
  int r, i, j, it, m = 0, neq = 0, diag = 1, na = 0, iters;
  int act[OP_CONS];
  double x[DENSE_MAX], u[OP_CONS], res[OP_CONS];
  if (n < 1 || n > DENSE_MAX || R > OP_ROWS) return 0;
  Q->n = n;
  for (i = 0; i < n; ++i) {
    Q->g[i] = g[i];
    Q->Hd[i] = H[i * DENSE_MAX + i];
  }
  /* one-sided rows c . x >= b: the equalities first, then the inequalities in row order */
  for (r = 0; r < R; ++r) {
    const double *c = A + r * DENSE_MAX;
    int any = 0;
    for (j = 0; j < n; ++j)
      if (c[j] != 0.0) any = 1;
    if (!any) {
      if (lo[r] > FEAS_TOL * (1 + fabs(lo[r])) || hi[r] < -FEAS_TOL * (1 + fabs(hi[r])))
        return 0;
      continue;
    }
    if (lo[r] == hi[r]) {
      for (j = 0; j < n; ++j) Q->C[m][j] = c[j];
      Q->b[m] = lo[r];
      Q->origin[m++] = r;
    }
  }
  neq = m;
  for (r = 0; r < R; ++r) {
    const double *c = A + r * DENSE_MAX;
    int any = 0;
    for (j = 0; j < n; ++j)
      if (c[j] != 0.0) any = 1;
    if (!any || lo[r] == hi[r]) continue;
    if (lo[r] > -INFINITY) {
      for (j = 0; j < n; ++j) Q->C[m][j] = c[j];
      Q->b[m] = lo[r];
      Q->origin[m++] = r;
    }
    if (hi[r] < INFINITY) {
      for (j = 0; j < n; ++j) Q->C[m][j] = -c[j];
      Q->b[m] = -hi[r];
      Q->origin[m++] = r;
    }
  }
  Q->m = m;
  Q->neq = neq;
  for (i = 0; i < m; ++i) {
    Q->cn[i] = op_norm(Q->C[i], n);
    Q->have[i] = 0;
  }
  if (!op_inverse(n, H, Q->Hinv)) return 0;
  for (i = 0; i < n; ++i) {
    Q->x0[i] = -op_dot(Q->Hinv[i], g, n);
    x[i] = Q->x0[i];
  }
  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j)
      if (i != j && H[i * DENSE_MAX + j] != 0.0) diag = 0;
  if (!neq && diag) op_bounds_first(Q, x, act, u, &na);
  iters = 4 * (m + n) + 10;
  for (it = 0; it < iters; ++it) {
    int p, l;
    const double *npv, *hp;
    double bp, up = 0.0;
    if (it < neq) {
      p = it;
      if (op_dot(Q->C[p], x, n) - Q->b[p] > 0) { /* enter the equality from its violated side */
        for (j = 0; j < n; ++j) Q->C[p][j] = -Q->C[p][j];
        Q->b[p] = -Q->b[p];
        Q->have[p] = 0;
      }
    } else {
      double worst = 0.0;
      p = -1;
      for (i = 0; i < m; ++i) res[i] = op_dot(Q->C[i], x, n) - Q->b[i];
      for (i = neq; i < m; ++i) {
        double s = res[i] / Q->cn[i];
        int in = 0;
        for (j = 0; j < na; ++j)
          if (act[j] == i) in = 1;
        if (s < worst && s < -FEAS_TOL * (1.0 + fabs(Q->b[i]) / Q->cn[i]) && !in) {
          p = i;
          worst = s;
        }
      }
      if (p < 0) {
        for (i = 0; i < m; ++i)
          if (res[i] < -1e-9 * (1.0 + fabs(Q->b[i]))) return 0; /* not settled (rounding) */
        for (i = 0; i < n; ++i) xo[i] = x[i];
        for (r = 0; r < R; ++r) lam[r] = 0.0;
        for (j = 0; j < na; ++j) lam[Q->origin[act[j]]] = fabs(u[j]);
        return 1;
      }
    }
    npv = Q->C[p];
    bp = Q->b[p];
    hp = op_hv(Q, p);
    for (;;) {
      double z[DENSE_MAX], rr[OP_CONS], t1 = INFINITY, t2, t, zn, sp;
      int small;
      if (na > 0) {
        double M[OP_LS * OP_LS], rhs[OP_CONS];
        const double *hs[OP_CONS];
        if (na > OP_LS) return 0;
        for (j = 0; j < na; ++j) hs[j] = op_hv(Q, act[j]);
        for (i = 0; i < na; ++i)
          for (j = 0; j < na; ++j) M[i * na + j] = op_dot(Q->C[act[i]], hs[j], n);
        for (j = 0; j < na; ++j) rhs[j] = op_dot(hs[j], npv, n);
        if (!op_lin_solve(na, M, na, rhs, rr)) return 0;
        for (i = 0; i < n; ++i) {
          double s = 0.0;
          for (j = 0; j < na; ++j) s += rr[j] * hs[j][i];
          z[i] = hp[i] - s;
        }
      } else {
        for (i = 0; i < n; ++i) z[i] = hp[i];
      }
      l = -1;
      for (j = 0; j < na; ++j)
        if (act[j] >= neq && rr[j] > 0 && u[j] / rr[j] < t1) {
          t1 = u[j] / rr[j];
          l = j;
        }
      zn = op_dot(z, npv, n);
      sp = op_dot(npv, x, n) - bp;
      /* z of the size of rounding: p depends on the active rows (no primal step) */
      small = op_norm(z, n) <= 1e-9 * op_norm(hp, n);
      t2 = (!small && zn > 0) ? -sp / zn : INFINITY;
      if (sp >= 0) t2 = 0.0;
      t = (t2 < t1) ? t2 : t1;
      if (!isfinite(t)) return 0; /* infeasible */
      if (t != 0.0) {
        for (i = 0; i < n; ++i) x[i] = x[i] + t * z[i];
        for (j = 0; j < na; ++j) u[j] = u[j] - t * rr[j];
        up += t;
      }
      if (t == t2) {
        if (na >= OP_CONS) return 0;
        act[na] = p;
        u[na] = up;
        ++na;
        op_recompute(Q, act, na, x, u);
        break;
      }
      for (j = l; j < na - 1; ++j) {
        act[j] = act[j + 1];
        u[j] = u[j + 1];
      }
      --na;
    }
  }
  return 0;
}

#endif
