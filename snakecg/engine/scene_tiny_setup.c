/* snakecg's engine: the tiny solve's set-up and its accelerations (scene_tiny.c's; scene_tiny.h
 * says what the tiny solve takes).
 *
 * The inertia M = L D L^T (sc_inertia_factor's pivot rule on the same pivots, without square
 * roots: one division a column, its reciprocal times the column's entries), compiled with every
 * loop over the coordinates unrolled for the snake with 0-2 objects; then Y = D^-1 Z,
 * Z = L^-1 [A^T f] (the last column from g = L^-1 f), and Z's Gram matrix weighted by D^-1,
 * G = Z^T D^-1 Z and b = Z^T D^-1 g + c, in one sweep over the coordinates compiled once per
 * row count; the accelerations a = L^-T D^-1 (g + Z lam) = L^-T (Y_g + Y lam). Each part twice:
 * plain, and with AVX2 and FMA (the products fused into the sums by GNU C's default
 * contraction, the sweep's sums vectorized: within rounding of the plain copy, not bit for
 * bit); the caller chooses (scene_tiny.c: one copy for every problem of a process). */
#include <math.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_tiny.h"
#include "scene_tiny_setup.h"

#if defined(__GNUC__)
#define TINY_FLAT static inline __attribute__((always_inline))
#define TINY_CALLED static __attribute__((noinline))
#else
#define TINY_FLAT static inline
#define TINY_CALLED static
#endif
#define TINY_UNROLL _Pragma("GCC unroll 16")

/* The inertia's factor M = L D L^T for n coordinates whose rows from t on are their diagonal
 * (n, t constants where the caller's branch makes them so): sc_inertia_factor's pivot rule on
 * the same pivots (D_j, the Cholesky's squared diagonal), without its square roots and with
 * one division a column (r_j = 1 / D_j; the column's entries products with it: on the chain
 * from one column to the next a division and a product, where the Cholesky has a square root
 * and a division). L: unit lower triangle (the dense block's; its diagonal holds D), r: the
 * pivots' reciprocals (n). Returns 0 where the pivot rule fails. */
TINY_FLAT int factor(const sc_int n, const sc_int t, const double *M, double *L, double *r) {
  const double rel = 1e-14;
  double big = 0.0, big_t = 0.0, rel_t, s[SC_TINY_N];
  sc_int i, j, k;
  for (i = 0; i < n; ++i) {
    const double d = M[i * n + i];
    if (d > big) big = d;
    if (i < t && d > big_t) big_t = d;
  }
  if (!(big > 0.0) || !isfinite(big) || !(big_t > 0.0) || !isfinite(big_t)) return 0;
  rel_t = big_t == big ? rel : rel * (big / big_t);
  TINY_UNROLL for (j = 0; j < t; ++j) { /* L[i, k] D_k (k < j) kept in L's upper triangle */
    double d = M[j * n + j], q;
    TINY_UNROLL for (k = 0; k < j; ++k) d -= L[j * n + k] * L[k * n + j];
    if (!(d > rel_t * big_t)) return 0;
    L[j * n + j] = d;
    r[j] = q = 1.0 / d;
    TINY_UNROLL for (i = j + 1; i < t; ++i) {
      double u = M[i * n + j];
      TINY_UNROLL for (k = 0; k < j; ++k) u -= L[i * n + k] * L[k * n + j];
      s[i] = u;
    }
    TINY_UNROLL for (i = j + 1; i < t; ++i) {
      L[j * n + i] = s[i];
      L[i * n + j] = s[i] * q;
    }
  }
  TINY_UNROLL for (i = t; i < n; ++i) { /* the diagonal tail */
    if (!(M[i * n + i] > rel * big)) return 0;
    L[i * n + i] = M[i * n + i];
    r[i] = 1.0 / M[i * n + i];
  }
  return 1;
}

/* Y = D^-1 Z, Z = L^-1 [A^T f] (n x (m + 1): row i coordinate i's, Y's last column
 * D^-1 g, g = L^-1 f) and Z's Gram matrix weighted by D^-1 in one sweep over the coordinates
 * (m a constant; each coordinate's row z of Z added to the sums as it is made, from the rows
 * of Y before it and L D in factor's upper triangle: z_i = [A^T f]_i - sum_k L_ik D_k Y_k):
 * G = Z_A^T D^-1 Z_A (m x m), b = Z_A^T D^-1 g + c (c may be null). */
TINY_FLAT void gram(const sc_int m, sc_int n, sc_int t, const double *restrict L,
                    const double *restrict r, const double *restrict A,
                    const double *restrict f, const double *restrict c, double *restrict Y,
                    double *restrict G, double *restrict b) {
  const sc_int w = m + 1;
  double S[(SC_TINY_M + 1) * (SC_TINY_M + 1)];
  sc_int i, j, k;
  TINY_UNROLL for (j = 0; j < w; ++j) /* (the sums below only: S zeroed whole, a rep stos) */
    for (k = 0; k <= (j < m ? j : m - 1); ++k) S[j * w + k] = 0.0;
  for (i = 0; i < n; ++i) {
    double z[SC_TINY_M + 1], y[SC_TINY_M + 1];
    const double ri = r[i];
    for (j = 0; j < m; ++j) z[j] = A[j * n + i];
    z[m] = f[i];
    for (k = 0; k < (i < t ? i : 0); ++k) {
      const double u = L[k * n + i];
      for (j = 0; j < w; ++j) z[j] -= u * Y[k * w + j];
    }
    for (j = 0; j < w; ++j) Y[i * w + j] = y[j] = z[j] * ri;
    for (j = 0; j < w; ++j)
      for (k = 0; k <= (j < m ? j : m - 1); ++k) S[j * w + k] += y[j] * z[k]; /* (not g D^-1 g) */
  }
  for (j = 0; j < m; ++j) {
    for (k = 0; k <= j; ++k) G[j * m + k] = G[k * m + j] = S[j * w + k];
    b[j] = c ? S[m * w + j] + c[j] : S[m * w + j];
  }
}

/* v = D^-1 (g + Z lam) (gram's Y, its last column D^-1 g; a force that is not finite taken as
 * 0) */
TINY_FLAT void g_plus_z_lam(const sc_int m, sc_int n, const double *restrict Z,
                            const double *restrict lam, double *restrict v) {
  double lz[SC_TINY_M];
  const sc_int w = m + 1;
  sc_int i, j;
  for (j = 0; j < m; ++j) lz[j] = isfinite(lam[j]) ? lam[j] : 0.0;
  for (i = 0; i < n; ++i) {
    double s = Z[i * w + m];
    for (j = 0; j < m; ++j) s += Z[i * w + j] * lz[j];
    v[i] = s;
  }
}

/* a := L^-T a (eq. 18's a = L^-T D^-1 (g + Z lam) from the factor and g_plus_z_lam's v) for
 * factor's L (its dense block's t rows, unit; n, t constants where the caller's branch makes
 * them so) */
TINY_FLAT void back(const sc_int n, const sc_int t, const double *restrict L, double *restrict a) {
  sc_int i, k;
  TINY_UNROLL for (i = t - 1; i >= 0; --i) {
    double s = a[i];
    TINY_UNROLL for (k = i + 1; k < t; ++k) s -= L[k * n + i] * a[k];
    a[i] = s;
  }
}


/* The inertia's factor M = L D L^T (L, n x n: unit lower, D on its diagonal; r: D's
 * reciprocals) for n coordinates; shape: the objects' count where the factor is compiled for n
 * (else -1); t: the dense block's size. 0: singular. */
TINY_FLAT int factored_body(sc_int n, int shape, const double *M, const double *f, double *L,
                              double *r, sc_int *t) {
  const sc_int s = SNAKECG_NS;
  sc_int i, j;
  *t = s;
  switch (shape) {
#if SNAKECG_NS <= TINY_FIXED_NS
    case 0: return factor(s, s, M, L, r);
    case 1: return factor(s + 3, s, M, L, r);
    case 2: return factor(s + 6, s, M, L, r);
#endif
    default: /* (scene_small.c's Cholesky, its columns over their diagonal: a fully unrolled
      factor grows as n_s^3; r its scratch for g) */
      if (!sc_inertia_factor(n, M, f, 1e-14, L, r, t)) return 0;
      for (j = 0; j < n; ++j) {
        const double q = 1.0 / L[j * n + j];
        for (i = j + 1; i < *t; ++i) { /* (L D above the diagonal, as factor's) */
          L[j * n + i] = L[i * n + j] * L[j * n + j];
          L[i * n + j] *= q;
        }
        L[j * n + j] *= L[j * n + j];
        r[j] = q * q;
      }
      return 1;
  }
}


#if SNAKECG_NS <= TINY_FIXED_NS
#define TINY_ONE_OBJECT(n, t) ((n) == SNAKECG_NS + 3 && (t) == SNAKECG_NS)
#else
#define TINY_ONE_OBJECT(n, t) 0
#endif
/* the inertia's factor, the sweep (once per row count) and the accelerations (once per row
 * count, then L^-T for the shape), each in a plain copy and one with AVX2 and FMA */
#define TINY_BY_M(r, x, attr) \
  attr void gram##x##_##r(sc_int n, sc_int t, const double *L, const double *rc, \
                          const double *A, const double *f, const double *c, double *Y, \
                          double *G, double *b) { \
    if (TINY_ONE_OBJECT(n, t)) /* (one object: n, t constants, the sweep unrolled) */ \
      gram(r, SNAKECG_NS + 3, SNAKECG_NS, L, rc, A, f, c, Y, G, b); \
    else \
      gram(r, n, t, L, rc, A, f, c, Y, G, b); \
  } \
  attr void accel##x##_##r(sc_int n, const double *Y, const double *lam, double *a) { \
    g_plus_z_lam(r, n, Y, lam, a); \
  }
#define TINY_COPY(x, attr) \
  attr int factored##x(sc_int n, int shape, const double *M, const double *f, double *L, \
                       double *r, sc_int *t) { \
    return factored_body(n, shape, M, f, L, r, t); \
  } \
  attr void backs##x(sc_int n, int shape, sc_int t, const double *L, double *a) { \
    const int fixed = SNAKECG_NS <= TINY_FIXED_NS; /* (factored's shapes) */ \
    if (fixed && shape == 0) back(SNAKECG_NS, SNAKECG_NS, L, a); \
    else if (fixed && shape == 1) back(SNAKECG_NS + 3, SNAKECG_NS, L, a); \
    else if (fixed && shape == 2) back(SNAKECG_NS + 6, SNAKECG_NS, L, a); \
    else back(n, t, L, a); \
  } \
  TINY_BY_M(1, x, attr) TINY_BY_M(2, x, attr) TINY_BY_M(3, x, attr) \
  TINY_BY_M(4, x, attr) TINY_BY_M(5, x, attr) TINY_BY_M(6, x, attr)
TINY_COPY(, TINY_CALLED)
#if defined(__x86_64__) && !defined(__clang__) && __GNUC__ >= 6 && !defined(SC_NO_AVX)
#define TINY_FMA 1
TINY_COPY(_fma, static __attribute__((noinline, target("avx2,fma"))))
#endif
#undef TINY_COPY
#undef TINY_BY_M
#define TINY_SWITCH_M(m, call) \
  switch (m) { \
    case 1: call(1); break; case 2: call(2); break; case 3: call(3); break; \
    case 4: call(4); break; case 5: call(5); break; default: call(6); \
  }

SC_INTERNAL int sc_tiny_fma(void) {
#ifdef TINY_FMA
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return 0;
#endif
}

SC_INTERNAL int sc_tiny_factored(int fused, sc_int n, int shape, const double *M,
                                 const double *f, double *L, double *r, sc_int *t) {
#ifdef TINY_FMA
  if (fused) return factored_fma(n, shape, M, f, L, r, t);
#endif
  (void)fused;
  return factored(n, shape, M, f, L, r, t);
}

SC_INTERNAL void sc_tiny_gram(int fused, sc_int m, sc_int n, sc_int t, const double *L,
                              const double *r, const double *A, const double *f,
                              const double *c, double *Y, double *G, double *b) {
#define TINY_GRAM(k) gram_##k(n, t, L, r, A, f, c, Y, G, b)
#define TINY_GRAM_F(k) gram_fma_##k(n, t, L, r, A, f, c, Y, G, b)
#ifdef TINY_FMA
  if (fused) {
    TINY_SWITCH_M(m, TINY_GRAM_F)
    return;
  }
#endif
  (void)fused;
  TINY_SWITCH_M(m, TINY_GRAM)
#undef TINY_GRAM
#undef TINY_GRAM_F
}

SC_INTERNAL void sc_tiny_accel(int fused, sc_int m, sc_int n, int shape, sc_int t,
                               const double *L, const double *Y, const double *lam, double *a) {
#define TINY_ACCEL(k) accel_##k(n, Y, lam, a)
#define TINY_ACCEL_F(k) accel_fma_##k(n, Y, lam, a)
#ifdef TINY_FMA
  if (fused) {
    TINY_SWITCH_M(m, TINY_ACCEL_F)
    backs_fma(n, shape, t, L, a);
    return;
  }
#endif
  (void)fused;
  TINY_SWITCH_M(m, TINY_ACCEL)
  backs(n, shape, t, L, a);
#undef TINY_ACCEL
#undef TINY_ACCEL_F
}
