/* snakecg's engine: small dense linear algebra (the one home of LU, Cholesky, the symmetric
 * eigensolver and Householder QR for the core's optimisation code). All `static inline`,
 * row-major with a leading dimension `ld` (A_ij at A[i * ld + j]), sizes as sc_int, no
 * allocation (scratch from the caller); for a few dozen unknowns, so the plain textbook
 * methods (Golub & Van Loan, "Matrix Computations", 4th ed.):
 *
 *   sc_lu_factor / sc_lu_solve          Gaussian elimination with partial pivoting (alg. 3.4.1)
 *   sc_cholesky / sc_cholesky_solve     A = L L^T, with a relative pivot threshold (alg. 4.2.2);
 *                                       sc_lower_solve / sc_lower_t_solve by its factor alone
 *   sc_ldl_factor / sc_ldl_solve        A = L D L^T without pivoting, rows that may drop out
 *   sc_eigen_symmetric                  cyclic Jacobi rotations, eigenvectors optional (8.5.3)
 *   sc_qr_least_squares                 Householder QR with column pivoting (alg. 5.4.1), the
 *                                       basic solution of a least-squares problem of any rank
 *   sc_qr_factor / sc_qr_apply          Householder QR without pivoting (alg. 5.2.1)
 *   sc_svd_jacobi / sc_svd_least_norm   one-sided Jacobi SVD (8.6.3), least-norm solutions
 *   sc_psd_solve / sc_psd_resolve       semidefinite P L D L^T P^T (diagonal pivoting) */
#ifndef SNAKECG_ENGINE_LINALG_H
#define SNAKECG_ENGINE_LINALG_H

#include <math.h>

/* included by engine.h, after its integer type sc_int */

/* Two doubles as one two-lane vector where the compiler has them (GCC's vector extension:
 * SSE2 on x86-64), for loops that give each entry the same operations in the same order as
 * one at a time (so the same bits); plain loops for other compilers. */
#if defined(__GNUC__)
typedef double __attribute__((vector_size(16), aligned(8), may_alias)) sc_p2;
#define SC_P2(x) (*(sc_p2 *)(x))
#define SC_P2C(x) (*(const sc_p2 *)(x))
#endif

static inline double sc_dot(const double *a, const double *b, sc_int n) {
  double s = 0.0;
  sc_int i;
  for (i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}

static inline double sc_norm(const double *a, sc_int n) { return sqrt(sc_dot(a, a, n)); }

static inline double sc_max_abs(const double *a, sc_int n) {
  double m = 0.0;
  sc_int i;
  for (i = 0; i < n; ++i)
    if (fabs(a[i]) > m) m = fabs(a[i]);
  return m;
}

/* y = A x, A m x n */
static inline void sc_matvec(sc_int m, sc_int n, const double *A, sc_int ld, const double *x,
                             double *y) {
  sc_int i;
  for (i = 0; i < m; ++i) y[i] = sc_dot(A + i * ld, x, n);
}

/* x^T A x, A n x n */
static inline double sc_quad(sc_int n, const double *A, sc_int ld, const double *x) {
  double s = 0.0;
  sc_int i;
  for (i = 0; i < n; ++i) s += x[i] * sc_dot(A + i * ld, x, n);
  return s;
}

/* Frobenius norm of the m x n matrix A */
static inline double sc_frobenius(sc_int m, sc_int n, const double *A, sc_int ld) {
  double s = 0.0;
  sc_int i;
  for (i = 0; i < m; ++i) s += sc_dot(A + i * ld, A + i * ld, n);
  return sqrt(s);
}

/* LU with partial pivoting: P A = L U in place of A (L unit lower, U upper), piv[k] the row
 * swapped with k at step k. Returns 1, or 0 when a pivot is zero or a factor not finite. */
static inline int sc_lu_factor(sc_int n, double *A, sc_int ld, sc_int *piv) {
  sc_int i, j, k;
  for (k = 0; k < n; ++k) {
    sc_int p = k;
    double big = fabs(A[k * ld + k]), inv;
    for (i = k + 1; i < n; ++i)
      if (fabs(A[i * ld + k]) > big) {
        big = fabs(A[i * ld + k]);
        p = i;
      }
    piv[k] = p;
    if (!(big > 0.0) || !isfinite(big)) return 0;
    if (p != k)
      for (j = 0; j < n; ++j) {
        double t = A[k * ld + j];
        A[k * ld + j] = A[p * ld + j];
        A[p * ld + j] = t;
      }
    inv = 1.0 / A[k * ld + k];
    for (i = k + 1; i < n; ++i) {
      double f = A[i * ld + k] * inv;
      A[i * ld + k] = f;
      if (f != 0.0)
        for (j = k + 1; j < n; ++j) A[i * ld + j] -= f * A[k * ld + j];
    }
  }
  return 1;
}

/* b := A^-1 b with sc_lu_factor's factors (the swaps first: its L belongs to P A) */
static inline void sc_lu_solve(sc_int n, const double *A, sc_int ld, const sc_int *piv,
                               double *b) {
  sc_int i, k;
  for (k = 0; k < n; ++k)
    if (piv[k] != k) {
      double t = b[k];
      b[k] = b[piv[k]];
      b[piv[k]] = t;
    }
  for (i = 1; i < n; ++i) {
    double s = b[i];
    for (k = 0; k < i; ++k) s -= A[i * ld + k] * b[k];
    b[i] = s;
  }
  for (i = n - 1; i >= 0; --i) {
    double s = b[i];
    for (k = i + 1; k < n; ++k) s -= A[i * ld + k] * b[k];
    b[i] = s / A[i * ld + i];
  }
}

/* Cholesky A = L L^T, L in place of A's lower triangle (the upper one left alone). Returns 1,
 * or 0 when a pivot (before its square root) is not above rel * max_i A_ii. */
static inline int sc_cholesky(sc_int n, double *A, sc_int ld, double rel) {
  sc_int i, j, k;
  double big = 0.0;
  for (i = 0; i < n; ++i)
    if (A[i * ld + i] > big) big = A[i * ld + i];
  if (!(big > 0.0) || !isfinite(big)) return 0;
  for (j = 0; j < n; ++j) {
    double d = A[j * ld + j];
    for (k = 0; k < j; ++k) d -= A[j * ld + k] * A[j * ld + k];
    if (!(d > rel * big)) return 0;
    d = sqrt(d);
    A[j * ld + j] = d;
    for (i = j + 1; i < n; ++i) {
      double t = A[i * ld + j];
      for (k = 0; k < j; ++k) t -= A[i * ld + k] * A[j * ld + k];
      A[i * ld + j] = t / d;
    }
  }
  return 1;
}

/* b := (L L^T)^-1 b with the factor of sc_cholesky */
static inline void sc_cholesky_solve(sc_int n, const double *L, sc_int ld, double *b) {
  sc_int i, k;
  for (i = 0; i < n; ++i) {
    double s = b[i];
    for (k = 0; k < i; ++k) s -= L[i * ld + k] * b[k];
    b[i] = s / L[i * ld + i];
  }
  for (i = n - 1; i >= 0; --i) {
    double s = b[i];
    for (k = i + 1; k < n; ++k) s -= L[k * ld + i] * b[k];
    b[i] = s / L[i * ld + i];
  }
}

/* A = L D L^T without pivoting (alg. 4.1.2) of rows and columns idx[0..n) of A (column-major,
 * A_ij at A[i + j lda], lower triangle read; idx null: the first n); unit lower L at
 * L[i + j ldl] (below the diagonal), d, dinv = 1 / d; work: n doubles. drop (may be null): on
 * entry drop[j] != 0 lets row j drop when |d_j / A_jj| <= drop_tol (then d_j = dinv_j = 0, L's
 * column j zero); on exit, whether it did. Returns the smallest d_j / A_jj kept, at most 1. */
static inline double sc_ldl_factor(sc_int n, const double *A, sc_int lda, const int *idx,
                                   double *L, sc_int ldl, double *d, double *dinv, int *drop,
                                   double drop_tol, double *work) {
  double ratio = 1.0, *ld = work; /* row j of L D */
  sc_int i, j, k;
#define SC_A(i, j) (idx ? A[idx[i] + lda * idx[j]] : A[(i) + lda * (j)])
  SC_UNROLL
  for (j = 0; j < n; ++j) {
    double s = SC_A(j, j), r;
    for (k = 0; k < j; ++k) {
      ld[k] = L[j + ldl * k] * d[k];
      s -= L[j + ldl * k] * ld[k];
    }
    r = s / SC_A(j, j);
    if (drop) drop[j] = drop[j] && fabs(r) <= drop_tol;
    if (drop && drop[j]) { /* dependent: out of the factorization */
      d[j] = dinv[j] = 0.0;
      for (i = j + 1; i < n; ++i) L[i + ldl * j] = 0.0;
      continue;
    }
    d[j] = s;
    dinv[j] = 1.0 / s; /* one division per pivot */
    if (!(r >= ratio)) ratio = r;
    for (i = j + 1; i + 1 < n; i += 2) { /* rows i and i + 1 side by side (adjacent in L) */
#if defined(__GNUC__)
      sc_p2 t = {SC_A(i, j), SC_A(i + 1, j)};
      for (k = 0; k < j; ++k) t -= SC_P2C(L + i + ldl * k) * ld[k];
      SC_P2(L + i + ldl * j) = t * dinv[j];
#else
      double t0 = SC_A(i, j), t1 = SC_A(i + 1, j);
      for (k = 0; k < j; ++k) t0 -= L[i + ldl * k] * ld[k], t1 -= L[i + 1 + ldl * k] * ld[k];
      L[i + ldl * j] = t0 * dinv[j], L[i + 1 + ldl * j] = t1 * dinv[j];
#endif
    }
    if (i < n) { /* the last row alone (a loop here: GCC's aggressive-loop warning at -O2) */
      double t = SC_A(i, j);
      for (k = 0; k < j; ++k) t -= L[i + ldl * k] * ld[k];
      L[i + ldl * j] = t * dinv[j];
    }
  }
#undef SC_A
  return ratio;
}

/* y := (L D L^T)^-1 y with sc_ldl_factor's factors (a dropped row: dinv 0, a zero column) */
#if defined(__GNUC__) /* inlined (an out-of-line copy: GCC's -Wmaybe-uninitialized on L, dinv) */
__attribute__((always_inline))
#endif
static inline void sc_ldl_solve(sc_int n, const double *L, sc_int ldl, const double *dinv,
                                double *y) {
  sc_int i, k;
  i = 0; /* forward (rows i and i + 1 side by side, then i + 1's last term), diagonal, back */
#if defined(__GNUC__)
  for (; i + 1 < n; i += 2) {
    sc_p2 t = {y[i], y[i + 1]};
    for (k = 0; k < i; ++k) t -= SC_P2C(L + i + ldl * k) * y[k];
    y[i] = t[0];
    y[i + 1] = t[1] - L[i + 1 + ldl * i] * y[i];
  }
#endif
  for (; i < n; ++i)
    for (k = 0; k < i; ++k) y[i] -= L[i + ldl * k] * y[k];
  for (i = n - 1; i >= 0; --i) {
    y[i] *= dinv[i];
    for (k = i + 1; k < n; ++k) y[i] -= L[k + ldl * i] * y[k];
  }
}

/* Eigenvalues (w, ascending) and, V not null, orthonormal eigenvectors (V's columns) of the
 * symmetric A by cyclic Jacobi rotations (A overwritten). Returns the sweeps (at most 60),
 * until the off-diagonal part is below 1e-32 of the squared Frobenius norm (rounding). */
static inline int sc_eigen_symmetric(sc_int n, double *A, sc_int ld, double *w, double *V,
                                     sc_int ldv) {
  sc_int i, j, l;
  int sweep;
  if (V)
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) V[i * ldv + j] = (i == j) ? 1.0 : 0.0;
  for (sweep = 0; sweep < 60; ++sweep) {
    double off = 0.0, tot = 0.0;
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) {
        double s2 = A[i * ld + j] * A[i * ld + j];
        tot += s2;
        if (i != j) off += s2;
      }
    if (off == 0.0 || off <= 1e-32 * tot) break;
    for (i = 0; i < n - 1; ++i)
      for (j = i + 1; j < n; ++j) {
        double apq = A[i * ld + j], theta, t, c, s;
        if (apq == 0.0) continue;
        theta = 0.5 * (A[j * ld + j] - A[i * ld + i]) / apq;
        t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
        c = 1.0 / sqrt(t * t + 1.0);
        s = t * c;
        for (l = 0; l < n; ++l) { /* A := A G (columns i, j) */
          double ali = A[l * ld + i], alj = A[l * ld + j];
          A[l * ld + i] = c * ali - s * alj;
          A[l * ld + j] = s * ali + c * alj;
        }
        for (l = 0; l < n; ++l) { /* A := G^T A (rows i, j) */
          double ail = A[i * ld + l], ajl = A[j * ld + l];
          A[i * ld + l] = c * ail - s * ajl;
          A[j * ld + l] = s * ail + c * ajl;
        }
        A[i * ld + j] = A[j * ld + i] = 0.0;
        if (V)
          for (l = 0; l < n; ++l) {
            double vli = V[l * ldv + i], vlj = V[l * ldv + j];
            V[l * ldv + i] = c * vli - s * vlj;
            V[l * ldv + j] = s * vli + c * vlj;
          }
      }
  }
  for (i = 0; i < n; ++i) w[i] = A[i * ld + i];
  for (i = 1; i < n; ++i) /* insertion sort, columns of V along */
    for (j = i; j > 0 && w[j - 1] > w[j]; --j) {
      double t = w[j];
      w[j] = w[j - 1];
      w[j - 1] = t;
      if (V)
        for (l = 0; l < n; ++l) {
          t = V[l * ldv + j];
          V[l * ldv + j] = V[l * ldv + j - 1];
          V[l * ldv + j - 1] = t;
        }
    }
  return sweep;
}

/* The basic solution of min ||A x - b|| (A m x n, any shape and rank) by Householder QR with
 * column pivoting: A P = Q R, rank r = the |R_kk| above rcond |R_00|, x = P [R_11^-1 (Q^T b)_1;
 * 0]. A, b overwritten; work: n doubles, perm n sc_ints. Returns r (0 when A is zero). */
static inline sc_int sc_qr_least_squares(sc_int m, sc_int n, double *A, sc_int ld, double *b,
                                         double rcond, double *x, double *work, sc_int *perm) {
  sc_int i, j, k, rank = 0, steps = m < n ? m : n;
  double *cn = work, r00 = 0.0;
  for (j = 0; j < n; ++j) {
    double s = 0.0;
    for (i = 0; i < m; ++i) s += A[i * ld + j] * A[i * ld + j];
    cn[j] = s;
    perm[j] = j;
  }
  for (k = 0; k < steps; ++k) {
    sc_int p = k;
    double alpha, vnorm2, beta;
    for (j = k + 1; j < n; ++j) /* the column of largest remaining norm */
      if (cn[j] > cn[p]) p = j;
    if (p != k) {
      double t;
      sc_int ti;
      for (i = 0; i < m; ++i) {
        t = A[i * ld + k];
        A[i * ld + k] = A[i * ld + p];
        A[i * ld + p] = t;
      }
      t = cn[k];
      cn[k] = cn[p];
      cn[p] = t;
      ti = perm[k];
      perm[k] = perm[p];
      perm[p] = ti;
    }
    /* the Householder reflector of column k below the diagonal: v = x - alpha e_1 */
    vnorm2 = 0.0;
    for (i = k; i < m; ++i) vnorm2 += A[i * ld + k] * A[i * ld + k];
    alpha = sqrt(vnorm2);
    if (A[k * ld + k] > 0) alpha = -alpha;
    if (k == 0) r00 = fabs(alpha);
    if (!(fabs(alpha) > rcond * r00) || alpha == 0.0) break;
    A[k * ld + k] -= alpha; /* v in place, v_k = x_k - alpha */
    beta = 0.0;
    for (i = k; i < m; ++i) beta += A[i * ld + k] * A[i * ld + k];
    for (j = k + 1; j < n; ++j) { /* columns j > k: a -= 2 v (v . a) / (v . v) */
      double s = 0.0;
      for (i = k; i < m; ++i) s += A[i * ld + k] * A[i * ld + j];
      s = 2.0 * s / beta;
      for (i = k; i < m; ++i) A[i * ld + j] -= s * A[i * ld + k];
      cn[j] = 0.0; /* the squared norm of what is left below row k (recomputed: exact) */
      for (i = k + 1; i < m; ++i) cn[j] += A[i * ld + j] * A[i * ld + j];
    }
    { /* b := H b */
      double s = 0.0;
      for (i = k; i < m; ++i) s += A[i * ld + k] * b[i];
      s = 2.0 * s / beta;
      for (i = k; i < m; ++i) b[i] -= s * A[i * ld + k];
    }
    A[k * ld + k] = alpha; /* R_kk (the reflector's vector is no longer needed) */
    ++rank;
  }
  for (j = 0; j < n; ++j) x[j] = 0.0;
  for (k = rank - 1; k >= 0; --k) { /* R_11 y = (Q^T b)_1, x = P y */
    double s = b[k];
    for (j = k + 1; j < rank; ++j) s -= A[k * ld + j] * x[perm[j]];
    x[perm[k]] = s / A[k * ld + k];
  }
  return rank;
}

/* Householder QR of the m columns of A (n >= m rows; column j at A + j ld): A = Q R (5.2.1).
 * In place: R above the diagonal (R_kj at A[k + j ld]), its diagonal in rd, the reflectors v_k
 * on and below it (H_k = 1 - 2 v_k v_k^T / beta_k, beta_k = v_k . v_k; 0: H_k = 1). */
static inline void sc_qr_factor(sc_int n, sc_int m, double *A, sc_int ld, double *rd,
                                double *beta) {
  sc_int i, j, k;
  for (k = 0; k < m; ++k) {
    double *v = A + k * ld, nrm = 0.0, alpha, bk;
    for (i = k; i < n; ++i) nrm += v[i] * v[i];
    nrm = sqrt(nrm);
    alpha = v[k] > 0 ? -nrm : nrm;
    if (nrm == 0.0) {
      rd[k] = 0.0;
      beta[k] = 0.0;
      continue;
    }
    v[k] -= alpha;
    bk = 0.0;
    for (i = k; i < n; ++i) bk += v[i] * v[i];
    beta[k] = bk;
    rd[k] = alpha;
    for (j = k + 1; j < m; ++j) { /* a_j -= v (v . a_j) 2 / beta */
      double *aj = A + j * ld, s = 0.0;
      for (i = k; i < n; ++i) s += v[i] * aj[i];
      s = 2.0 * s / bk;
      for (i = k; i < n; ++i) aj[i] -= s * v[i];
    }
  }
}

/* x := Q^T x (transpose 1) or Q x (transpose 0), n entries, with sc_qr_factor's reflectors */
static inline void sc_qr_apply(sc_int n, sc_int m, const double *A, sc_int ld,
                               const double *beta, double *x, int transpose) {
  sc_int i, k, step;
  for (step = 0; step < m; ++step) {
    const double *v;
    double s = 0.0;
    k = transpose ? step : m - 1 - step;
    if (beta[k] == 0.0) continue;
    v = A + k * ld;
    for (i = k; i < n; ++i) s += v[i] * x[i];
    s = 2.0 * s / beta[k];
    for (i = k; i < n; ++i) x[i] -= s * v[i];
  }
}

/* The singular values of the n x m U (column j at U + j ld) by one-sided Jacobi (8.6.3):
 * U := U V with orthogonal columns, V (m x m, column j at V + j m) the right singular vectors,
 * s_j = |U_j|; until every pair of columns is orthogonal to rounding (at most 60 sweeps). */
static inline void sc_svd_jacobi(sc_int n, sc_int m, double *U, sc_int ld, double *V,
                                 double *s) {
  sc_int i, p, q;
  int sweep, rotated = 1;
  for (p = 0; p < m; ++p)
    for (q = 0; q < m; ++q) V[p + q * m] = p == q ? 1.0 : 0.0;
  for (sweep = 0; sweep < 60 && rotated; ++sweep) {
    rotated = 0;
    for (p = 0; p < m - 1; ++p)
      for (q = p + 1; q < m; ++q) {
        double *up = U + p * ld, *uq = U + q * ld, al = 0.0, be = 0.0, ga = 0.0, ze, t, c, sn;
        for (i = 0; i < n; ++i) {
          al += up[i] * up[i];
          be += uq[i] * uq[i];
          ga += up[i] * uq[i];
        }
        if (!(fabs(ga) > 1e-16 * sqrt(al * be))) continue;
        rotated = 1;
        ze = (be - al) / (2.0 * ga);
        t = (ze >= 0 ? 1.0 : -1.0) / (fabs(ze) + sqrt(1.0 + ze * ze));
        c = 1.0 / sqrt(1.0 + t * t);
        sn = c * t;
        for (i = 0; i < n; ++i) {
          double a = up[i], b = uq[i];
          up[i] = c * a - sn * b;
          uq[i] = sn * a + c * b;
        }
        for (i = 0; i < m; ++i) {
          double a = V[i + p * m], b = V[i + q * m];
          V[i + p * m] = c * a - sn * b;
          V[i + q * m] = sn * a + c * b;
        }
      }
  }
  for (p = 0; p < m; ++p) s[p] = sc_norm(U + p * ld, n);
}

/* The least-norm solution x (m) by sc_svd_jacobi's factors (singular values <= rcond times the
 * largest dropped, as numpy's lstsq) of U x = b (b: n; gram 0) or U^T U x = b (m; gram 1). */
static inline void sc_svd_least_norm(sc_int n, sc_int m, const double *U, sc_int ld,
                                     const double *V, const double *s, const double *b,
                                     double rcond, int gram, double *x) {
  sc_int i, j;
  double smax = 0.0;
  for (j = 0; j < m; ++j)
    if (s[j] > smax) smax = s[j];
  for (i = 0; i < m; ++i) x[i] = 0.0;
  for (j = 0; j < m; ++j) {
    double c;
    if (gram ? !(s[j] * s[j] > rcond * smax * smax) : !(s[j] > rcond * smax)) continue;
    c = gram ? sc_dot(V + j * m, b, m) : sc_dot(U + j * ld, b, n);
    c /= s[j] * s[j];
    for (i = 0; i < m; ++i) x[i] += V[i + j * m] * c;
  }
}

/* A symmetric positive semidefinite A (its lower triangle read and overwritten) = P L D L^T
 * P^T by diagonal pivoting (the largest pivot first, as LAPACK's dpstrf); rank r = the pivots
 * above rcond times the first. x = the basic solution of A x = b: P [(L D L^T)_11^-1
 * (P^T b)_1; 0] (b overwritten). work holds n doubles, perm n sc_ints. Returns r. */
#if defined(__GNUC__) /* inlined everywhere: scene_primal.c's FMA copy contracts its products */
__attribute__((always_inline))
#endif
static inline sc_int sc_psd_solve(sc_int n, double *A, sc_int ld, double *b, double rcond,
                                  double *x, double *work, sc_int *perm) {
  sc_int i, j, k, rank = 0;
  double d0 = 0.0, *c = work;
  for (j = 0; j < n; ++j) perm[j] = j;
  for (k = 0; k < n; ++k) {
    sc_int p = k;
    double d, t;
    for (j = k + 1; j < n; ++j)
      if (A[j * ld + j] > A[p * ld + p]) p = j;
    d = A[p * ld + p];
    if (k == 0) d0 = d;
    if (!(d > 0) || !(d > rcond * d0)) break;
    if (p != k) { /* rows and columns k and p, in the lower triangle */
#define SC_SWAP(u, v) (t = (u), (u) = (v), (v) = t)
      SC_SWAP(A[k * ld + k], A[p * ld + p]);
      for (j = 0; j < k; ++j) SC_SWAP(A[k * ld + j], A[p * ld + j]);
      for (i = k + 1; i < p; ++i) SC_SWAP(A[i * ld + k], A[p * ld + i]);
      for (i = p + 1; i < n; ++i) SC_SWAP(A[i * ld + k], A[i * ld + p]);
      SC_SWAP(b[k], b[p]);
#undef SC_SWAP
      j = perm[k]; perm[k] = perm[p]; perm[p] = j;
    }
    for (i = k + 1; i < n; ++i) c[i] = A[i * ld + k]; /* column k, then L's */
    for (i = k + 1; i < n; ++i) {
      double l = c[i] / d, *row = A + i * ld;
      j = k + 1;
#if defined(__GNUC__)
      for (; j < i; j += 2) SC_P2(row + j) -= l * SC_P2C(c + j); /* by pairs, a scalar tail */
#endif
      for (; j <= i; ++j) row[j] -= l * c[j];
      row[k] = l;
    }
    ++rank;
  }
  for (i = 0; i < rank; ++i) /* L y = b_1, D z = y, L^T x_1 = z */
    for (k = 0; k < i; ++k) b[i] -= A[i * ld + k] * b[k];
  for (i = 0; i < rank; ++i) b[i] /= A[i * ld + i];
  for (i = rank - 1; i >= 0; --i)
    for (k = i + 1; k < rank; ++k) b[i] -= A[k * ld + i] * b[k];
  for (j = 0; j < n; ++j) x[j] = 0.0;
  for (i = 0; i < rank; ++i) x[perm[i]] = b[i];
  return rank;
}

/* sc_psd_solve's basic solutions for nr more right-hand sides by its factor (B, X n x nr, row
 * i: unknown i's; B kept, may be X), nr at once: L Y = (P^T B)_1, D Z = Y, L^T X_1 = Z */
static inline void sc_psd_resolve(sc_int n, const double *A, sc_int ld, sc_int rank,
                                  const sc_int *perm, sc_int nr, const double *B, double *X,
                                  double *restrict W) { /* W: rank x nr */
  sc_int i, k, c;
  for (i = 0; i < rank * nr; ++i) W[i] = B[perm[i / nr] * nr + i % nr];
  for (i = 0; i < rank; ++i)
    for (k = 0; k < i; ++k)
      for (c = 0; c < nr; ++c) W[i * nr + c] -= A[i * ld + k] * W[k * nr + c];
  for (i = rank - 1; i >= 0; --i) {
    for (c = 0; c < nr; ++c) W[i * nr + c] /= A[i * ld + i];
    for (k = i + 1; k < rank; ++k)
      for (c = 0; c < nr; ++c) W[i * nr + c] -= A[k * ld + i] * W[k * nr + c];
  }
  for (i = 0; i < n * nr; ++i) X[i] = 0.0;
  for (i = 0; i < rank * nr; ++i) X[perm[i / nr] * nr + i % nr] = W[i];
}

/* y = A x + b for the n x n row-major A, each row's dot product in four partial sums */
static inline void sc_matvec_plus(sc_int n, const double *A, const double *x, const double *b,
                                  double *y) {
  sc_int i, j;
  for (i = 0; i < n; ++i) {
    const double *g = A + i * n;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (j = 0; j + 3 < n; j += 4) {
      s0 += g[j] * x[j], s1 += g[j + 1] * x[j + 1];
      s2 += g[j + 2] * x[j + 2], s3 += g[j + 3] * x[j + 3];
    }
    for (; j < n; ++j) s0 += g[j] * x[j];
    y[i] = b[i] + ((s0 + s1) + (s2 + s3));
  }
}

/* x := L^-1 x, L the lower triangle of sc_cholesky's factor (n x n, row-major) */
static inline void sc_lower_solve(sc_int n, const double *L, double *x) {
  sc_int i, k;
  for (i = 0; i < n; ++i) {
    double t = x[i];
    for (k = 0; k < i; ++k) t -= L[i * n + k] * x[k];
    x[i] = t / L[i * n + i];
  }
}

/* x := L^-T x, L as sc_lower_solve's */
static inline void sc_lower_t_solve(sc_int n, const double *L, double *x) {
  sc_int i, k;
  for (i = n - 1; i >= 0; --i) {
    double t = x[i];
    for (k = i + 1; k < n; ++k) t -= L[k * n + i] * x[k];
    x[i] = t / L[i * n + i];
  }
}

/* fmax(x, y) for x not NaN, inlined (libm's fmax is a call: its NaN rules for x) */
static inline double sc_max(double x, double y) { return y > x ? y : x; }
#endif
