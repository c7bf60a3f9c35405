/* snakecg's engine: the set-up of a general scene's solve (scene_solve.c) for small problems:
 * the inertia's factor with the work its diagonal tail does not need left out, and
 * Z = L^-1 A^T, G = Z^T Z, b = Z^T g + c, with the sizes known to the compiler.
 *
 * The inertia I of a general scene is the snake's M_s (dense, its first coordinates) followed
 * by 3 coordinates per object whose rows are diagonal (m, m, I_o: eq. 12). From the first
 * row t whose entries before the diagonal are all zero to the end, L = chol(I) is the square
 * roots of the diagonal alone: the Cholesky runs on the dense t x t block only, and
 * g = L^-1 f divides the tail by its roots. What is left out are products with L's zeros, so
 * L and g are bit for bit those of the full factor (sc_cholesky on all n rows) and the pivot
 * rule is the same: a pivot is not above rel times the largest diagonal entry of all n (the
 * dense block's sc_cholesky is given rel scaled by that entry over its own largest, which
 * moves the threshold by at most an ulp). In the paper's scene (9 coordinates, t = 6) this
 * is a fifth of the full factor's work.
 *
 * The factor's loops run over the dense block's t rows, Z's and G's over the m rows inside
 * loops over the coordinates; for t (and m) up to 8 they are compiled once per size (SC_BY: the
 * same loops with the size a constant, unrolled, no remainder or alias checks), the arithmetic
 * and its order unchanged, so their results are bit for bit the general loops'. Where the
 * dense block is the snake's (t = n_s, up to 16: the pegs row's 13) the factor and Z are
 * unrolled whole (SC_FIXED, GCC's vector types: two doubles an operation): the factor column
 * by column with each column's entries in registers, the same terms in the same order, bit
 * for bit (tests/test_scenes_small_fixed.py); Z two of A's rows at a time with their t
 * entries in registers, each row's sum grouped so that its chain from the row before is short
 * and multiplied by 1 / L_ii: within rounding of the general loops' (their divisions, one per
 * entry, bound Z's time); four rows at a time in AVX registers where the processor has them
 * (chosen at run time; each lane's operations the same, bit for bit). The pegs step
 * (callgrind; CPU time in a harness at m = 25): the factor 4,050 -> 1,980 instructions
 * (340 -> 240 ns), Z 9,850 -> 4,100 (570 -> 370 ns; with AVX 240 ns).
 */
#include <math.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_small.h"

#if defined(__GNUC__)
#define SC_FLAT static inline __attribute__((always_inline))
#else
#define SC_FLAT static inline
#endif

#ifdef SC_FIXED /* (scene_small.h: the snake's block unrolled) */
typedef double __attribute__((vector_size(16))) sc_v2;

/* factor's dense block where it is the snake's (t = n_s, every loop's bounds constants and
 * unrolled), column by column (each a column of pairs; f is its row n_s, g = L^-1 f the
 * factor's row of f): column k less the columns before it times their row k, its pivot, its
 * entries. Every entry gets the same products subtracted in the same order (j ascending) as
 * sc_cholesky's and factor's dot products, and the same divisions: L and g bit for bit theirs,
 * the same pivots against thr = rel_t times the block's largest diagonal entry (sc_cholesky's
 * threshold). A pair's entry above a column's diagonal is worked on and never read. Returns 0
 * at a pivot not above thr (L and a then unwritten). One copy (factor is compiled per size). */
static __attribute__((noinline)) int factor_ns(sc_int n, const double *M, const double *f,
                                               double thr, double *L, double *a) {
  enum { T = SNAKECG_NS, P = (SNAKECG_NS + 2) / 2 }; /* (P pairs a column: rows 0..T, f's) */
  sc_v2 C[T][P];
  sc_int i, j, k, p;
  SC_UNROLL for (k = 0; k < T; ++k) {
    double *c = (double *)C[k];
    SC_UNROLL for (i = 0; i < 2 * P; ++i) c[i] = i >= k && i < T ? M[i * n + k] : 0.0;
    c[T] = f[k];
  }
  SC_UNROLL for (k = 0; k < T; ++k) { /* column k, held in registers */
    sc_v2 c[P];
    double d;
    SC_UNROLL for (p = k / 2; p < P; ++p) c[p] = C[k][p];
    SC_UNROLL for (j = 0; j < k; ++j) {
      const double b = C[j][k / 2][k % 2]; /* L_kj */
      SC_UNROLL for (p = k / 2; p < P; ++p) c[p] -= b * C[j][p];
    }
    d = c[k / 2][k % 2];
    if (!(d > thr)) return 0;
    d = sqrt(d);
    SC_UNROLL for (p = k / 2; p < P; ++p) C[k][p] = c[p] / d;
    C[k][k / 2][k % 2] = d;
  }
  SC_UNROLL for (i = 0; i < T; ++i) {
    SC_UNROLL for (k = 0; k <= i; ++k) L[i * n + k] = C[k][i / 2][i % 2];
    a[i] = C[i][T / 2][T % 2];
  }
  return 1;
}

/* factor_ns for an n_s x n_s M alone (scene_small.h: the primal piece's Hessian) */
SC_INTERNAL int sc_small_factor(const double *M, const double *f, double thr, double *L,
                                double *a) {
  return factor_ns(SNAKECG_NS, M, f, thr, L, a);
}

#ifdef SC_SMALL_FMA
/* factor_ns's variant for the primal piece's Hessian alone (never the inertia's: that one
 * stays factor_ns, bit for bit sc_cholesky's), its rounding its own: the columns four
 * entries a register, without square roots on the chain from column to column (L D L^T:
 * W_k = D_k L_k each column less the columns before times L_kj = W_kj / D_j, fused
 * multiply-adds, one division a column), then R = L D^1/2 (each column W_k times
 * s_k = sqrt(1 / D_k), the columns' square roots side by side) and a = R^-1 f (f as row n_s).
 * Kept for the piece's triangular solves: s (rl: R's diagonal's reciprocals) and R's columns
 * (Lt: column k at Lt + k n_s, its entries from the diagonal on). The same pivot rule on
 * D_k = R_kk^2 (a pivot not above thr: 0, L, a, rl and Lt unwritten). */
typedef double __attribute__((vector_size(32))) sc_v4f;
typedef double __attribute__((vector_size(32), aligned(8))) sc_v4u; /* (at any double) */
__attribute__((target("avx2,fma"), noinline)) SC_INTERNAL int
sc_small_factor_fma(const double *M, const double *f, double thr, double *L, double *a,
                    double *rl, double *Lt) {
  enum { T = SNAKECG_NS, Q = (SNAKECG_NS + 4) / 4 }; /* (Q quads a column: rows 0..T, f's) */
  sc_v4f C[T][Q];
  double r[T];
  sc_int i, j, k, p;
  SC_UNROLL for (k = 0; k < T; ++k) {
    double *c = (double *)C[k];
    SC_UNROLL for (i = 0; i < 4 * Q; ++i) c[i] = i >= k && i < T ? M[i * T + k] : 0.0;
    c[T] = f[k];
  }
  SC_UNROLL for (k = 0; k < T; ++k) { /* column k, held in registers */
    sc_v4f c[Q];
    double d;
    SC_UNROLL for (p = k / 4; p < Q; ++p) c[p] = C[k][p];
    SC_UNROLL for (j = 0; j < k; ++j) {
      const double b = C[j][k / 4][k % 4] * r[j]; /* L_kj */
      SC_UNROLL for (p = k / 4; p < Q; ++p) c[p] -= b * C[j][p];
    }
    d = c[k / 4][k % 4];
    if (!(d > thr)) return 0;
    r[k] = 1.0 / d;
    SC_UNROLL for (p = k / 4; p < Q; ++p) C[k][p] = c[p];
  }
  SC_UNROLL for (k = 0; k < T; ++k) { /* R's columns: W_k s_k */
    const double sk = sqrt(r[k]);
    SC_UNROLL for (p = k / 4; p < Q; ++p) C[k][p] *= sk;
    rl[k] = sk;
  }
  SC_UNROLL for (i = 0; i < T; ++i) {
    SC_UNROLL for (k = 0; k <= i; ++k) L[i * T + k] = C[k][i / 4][i % 4];
    a[i] = C[i][T / 4][T % 4];
  }
  SC_UNROLL for (k = 0; k < T; ++k) {
    SC_UNROLL for (p = k / 4; p < T / 4; ++p) *(sc_v4u *)(Lt + k * T + 4 * p) = C[k][p];
    SC_UNROLL for (i = 4 * (T / 4); i < T; ++i) Lt[k * T + i] = C[k][i / 4][i % 4];
  }
  return 1;
}
#endif
#endif

/* The dense block's factor (t x t, its threshold rel_t; big_t its largest diagonal entry) and
 * the tail's square roots, g = L^-1 f (sc_inertia_factor's; t a constant where the caller's
 * switch makes it one; the snake's block t = n_s: factor_ns). */
SC_FLAT int factor(sc_int n, sc_int t, const double *M, const double *f, double rel,
                   double big, double rel_t, double big_t, double *L, double *a) {
  sc_int i, j, i0 = 0;
#ifdef SC_FIXED
  if (t == SNAKECG_NS) {
    if (!factor_ns(n, M, f, rel_t * big_t, L, a)) return 0;
    i0 = t;
  } else
#endif
  {
    for (i = 0; i < t; ++i)
      for (j = 0; j <= i; ++j) L[i * n + j] = M[i * n + j];
    if (t > 0 && !sc_cholesky(t, L, n, rel_t)) return 0;
  }
  (void)big_t;
  for (i = t; i < n; ++i) {
    const double d = M[i * n + i];
    if (!(d > rel * big)) return 0;
    L[i * n + i] = sqrt(d);
  }
  for (i = i0; i < n; ++i) { /* g = L^-1 f */
    double s = f[i];
    for (j = 0; j < (i < t ? i : 0); ++j) s -= L[i * n + j] * a[j];
    a[i] = s / L[i * n + i];
  }
  return 1;
}

/* call, with the size m (a variable's name) a constant of the same name where it is 1..8 */
#define SC_BY(m, call) \
  switch (m) { \
    case 1: { const sc_int m = 1; call; } break; case 2: { const sc_int m = 2; call; } break; \
    case 3: { const sc_int m = 3; call; } break; case 4: { const sc_int m = 4; call; } break; \
    case 5: { const sc_int m = 5; call; } break; case 6: { const sc_int m = 6; call; } break; \
    case 7: { const sc_int m = 7; call; } break; case 8: { const sc_int m = 8; call; } break; \
    default: call; \
  }

/* call, with n (a variable's name) a constant of the same name where it is the snake's
 * coordinates n_s and those of 0, 1 or 2 objects (n_s + 3 per object), and t (the same)
 * n_s where it is */
#define SC_BY_N(n, t, call) \
  if (t == SNAKECG_NS && n == SNAKECG_NS) { \
    const sc_int n = SNAKECG_NS, t = SNAKECG_NS; (void)t; call; \
  } else if (t == SNAKECG_NS && n == SNAKECG_NS + 3) { \
    const sc_int n = SNAKECG_NS + 3, t = SNAKECG_NS; (void)t; call; \
  } else if (t == SNAKECG_NS && n == SNAKECG_NS + 6) { \
    const sc_int n = SNAKECG_NS + 6, t = SNAKECG_NS; (void)t; call; \
  } else { \
    call; \
  }

/* L = chol(M) (n x n row-major; only the dense block's lower triangle and the diagonal are
 * written, the rest of L is left as it was and must not be read), a := L^-1 f, *t_out: the
 * dense block's size (L's rows from t on are their diagonal). Returns 0 where a pivot is not
 * above rel times M's largest diagonal entry (or that entry is not positive and finite). */
SC_INTERNAL int sc_inertia_factor(sc_int n, const double *M, const double *f, double rel,
                                  double *L, double *a, sc_int *t_out) {
  sc_int i, j, t;
  double big = 0.0, big_t = 0.0, rel_t;
  for (t = n; t > 0; --t) { /* the diagonal tail: rows t.. with zeros before the diagonal */
    for (j = 0; j < t - 1 && M[(t - 1) * n + j] == 0.0; ++j) continue;
    if (j < t - 1) break;
  }
  for (i = 0; i < n; ++i) {
    const double d = M[i * n + i];
    if (d > big) big = d;
    if (i < t && d > big_t) big_t = d;
  }
  if (!(big > 0.0) || !isfinite(big)) return 0;
  rel_t = big_t == big ? rel : rel * (big / big_t);
  *t_out = t;
  SC_BY_N(n, t, SC_BY(t, return factor(n, t, M, f, rel, big, rel_t, big_t, L, a)))
  return 0;
}

#ifdef SC_FIXED
/* Z's columns of A's rows a0 and a1 (both: else a0's alone) in the snake's block (t = n_s,
 * unrolled), at Z (row stride m), from L's entries each in both lanes and its diagonal's
 * reciprocals (Lb, row stride n_s). Row i waits on the rows before it: its sum takes the
 * terms of rows before i - 4 by fours (as z_rows' groups) and the last ones alone, so that
 * the chain from one row to the next is a product, a difference and a product; z_i is that
 * sum times 1 / L_ii (a division per row and pair of columns was what bound the time). */
SC_FLAT void z_pair(sc_int m, const sc_v2 *Lb, const double *a0, const double *a1, double *Z,
                    int both) {
  enum { T = SNAKECG_NS };
  sc_v2 z[T];
  sc_int i, k;
  SC_UNROLL for (i = 0; i < T; ++i) {
    const sc_v2 *Li = Lb + i * T;
    sc_v2 s = {a0[i], a1[i]};
    SC_UNROLL for (k = 0; k + 4 < i; k += 4)
      s -= (Li[k] * z[k] + Li[k + 1] * z[k + 1]) + (Li[k + 2] * z[k + 2] + Li[k + 3] * z[k + 3]);
    SC_UNROLL for (; k < i; ++k) s -= Li[k] * z[k];
    z[i] = s * Li[i];
    Z[i * m] = z[i][0];
    if (both) Z[i * m + 1] = z[i][1];
  }
}

/* Lb: L's entries of the snake's block each in both lanes, its diagonal's reciprocals. */
SC_FLAT void z_lanes(sc_int n, const double *L, sc_v2 *Lb) {
  sc_int i, k;
  SC_UNROLL for (i = 0; i < SNAKECG_NS; ++i)
    SC_UNROLL for (k = 0; k <= i; ++k) Lb[i * SNAKECG_NS + k] = (sc_v2){L[i * n + k], L[i * n + k]};
  SC_UNROLL for (i = 0; i < SNAKECG_NS; ++i)
    Lb[i * SNAKECG_NS + i] = 1.0 / Lb[i * SNAKECG_NS + i];
}

#if defined(__x86_64__) && !defined(__clang__) && __GNUC__ >= 6 && !defined(SC_NO_AVX)
#define SC_FIXED_AVX 1 /* Z's rows four at a time where the processor has AVX (SC_NO_AVX: not) */
typedef double __attribute__((vector_size(32))) sc_v4;

/* z_pair's sums for four of A's rows (nc of them stored, the rest copies of the last), in
 * one AVX register each (no FMA: each lane's operations are z_pair's, bit for bit). */
__attribute__((target("avx"), always_inline)) static inline void z_quad(sc_int m, const sc_v2 *Lb,
                                                         const double *a0, const double *a1,
                                                         const double *a2, const double *a3,
                                                         double *Z, sc_int nc) {
  enum { T = SNAKECG_NS };
  sc_v4 z[T];
  sc_int i, k;
  SC_UNROLL for (i = 0; i < T; ++i) {
    const sc_v2 *Li = Lb + i * T;
    sc_v4 s = {a0[i], a1[i], a2[i], a3[i]};
    SC_UNROLL for (k = 0; k + 4 < i; k += 4)
      s -= (Li[k][0] * z[k] + Li[k + 1][0] * z[k + 1]) +
           (Li[k + 2][0] * z[k + 2] + Li[k + 3][0] * z[k + 3]);
    SC_UNROLL for (; k < i; ++k) s -= Li[k][0] * z[k];
    z[i] = s * Li[i][0];
    SC_UNROLL for (k = 0; k < 4; ++k)
      if (k < nc) Z[i * m + k] = z[i][k];
  }
}

/* z_fixed's pairs four rows at a time (AVX: the chains of a row's sums side by side). */
__attribute__((target("avx"), noinline)) static void z_avx(sc_int n, sc_int m, const double *L,
                                                           const double *A, double *Z) {
  sc_v2 Lb[SNAKECG_NS * SNAKECG_NS];
  sc_int j;
  z_lanes(n, L, Lb);
  for (j = 0; j + 3 < m; j += 4)
    z_quad(m, Lb, A + j * n, A + (j + 1) * n, A + (j + 2) * n, A + (j + 3) * n, Z + j, 4);
  if (j < m) { /* (the last one to three rows, the last copied into the missing) */
    const double *last = A + (m - 1) * n;
    z_quad(m, Lb, A + j * n, j + 1 < m ? A + (j + 1) * n : last, j + 2 < m ? A + (j + 2) * n : last,
           last, Z + j, m - j);
  }
}
#endif

/* Z's rows of the snake's block (t = n_s), every pair of A's rows (one copy of the unrolled
 * code: z_rows is compiled once per size); four at a time with AVX, the same answers. */
static __attribute__((noinline)) void z_fixed(sc_int n, sc_int m, const double *L,
                                              const double *A, double *Z) {
  sc_v2 Lb[SNAKECG_NS * SNAKECG_NS]; /* (L's entries in both lanes: one load a product) */
  sc_int j;
#ifdef SC_FIXED_AVX
  if (__builtin_cpu_supports("avx")) {
    z_avx(n, m, L, A, Z);
    return;
  }
#endif
  z_lanes(n, L, Lb);
  for (j = 0; j + 1 < m; j += 2) z_pair(m, Lb, A + j * n, A + (j + 1) * n, Z + j, 1);
  if (j < m) z_pair(m, Lb, A + j * n, A + j * n, Z + j, 0);
}
#endif

/* Z = L^-1 A^T (n x m: coordinate i's row at Z + i m, every row of A at once). L's rows from t
 * on are their diagonal: there Z's row is A's column over it (the terms left out are zeros). */
SC_FLAT void z_rows(sc_int n, sc_int m, sc_int t, const double *L, const double *A, double *Z) {
  sc_int i, j, k;
  for (i = t; i < n; ++i) {
    double *restrict zi = Z + i * m;
    for (j = 0; j < m; ++j) zi[j] = A[j * n + i] / L[i * n + i];
  }
#ifdef SC_FIXED
  if (t == SNAKECG_NS) { /* (the snake's block: two of A's rows at a time, in registers) */
    z_fixed(n, m, L, A, Z);
    return;
  }
#endif
  for (i = 0; i < t; ++i) { /* (four rows of Z at a time: a fourth of the loads and stores) */
    double *restrict zi = Z + i * m;
    const double *Li = L + i * n;
    for (j = 0; j < m; ++j) zi[j] = A[j * n + i];
    for (k = 0; k + 3 < i; k += 4) {
      const double *restrict z0 = Z + k * m, *restrict z1 = z0 + m, *restrict z2 = z1 + m,
                   *restrict z3 = z2 + m;
      for (j = 0; j < m; ++j)
        zi[j] -= (Li[k] * z0[j] + Li[k + 1] * z1[j]) + (Li[k + 2] * z2[j] + Li[k + 3] * z3[j]);
    }
    for (; k < i; ++k)
      for (j = 0; j < m; ++j) zi[j] -= Li[k] * Z[k * m + j];
    for (j = 0; j < m; ++j) zi[j] /= Li[i];
  }
}

/* G = Z^T Z and b = Z^T g + c (c may be null), summed over the coordinates four at a time
 * (G's lower triangle, mirrored: symmetric by construction). The last n mod 4 coordinates
 * are one more group with its missing terms left out: they were products of zeros, whose
 * sum (+0) leaves every partial sum as it was (G and b start at +0 and never become -0), so
 * the results are bit for bit those of the group padded with zeros. For the same reason a
 * group's terms of a row j whose entries in it are zero (an object's coordinates: Z's row
 * there is A's column over L_ii, zero on every row that does not touch that object) are left
 * out: the full group's sum is then the remaining terms' sum plus zeros, bit for bit (Z
 * finite); a third of G's work in the 10-joint benchmark's scene. zero: unused. */
SC_FLAT void gram(sc_int n, sc_int m, const double *Z, const double *g, const double *c,
                  double *G, double *b, double *zero, const int with_g) {
  sc_int i, j, k;
  const sc_int n4 = n - n % 4;
  (void)zero;
  for (j = 0; j < m; ++j) {
    b[j] = 0.0;
    for (k = 0; with_g && k <= j; ++k) G[j * m + k] = 0.0;
  }
  for (i = 0; i < n4; i += 4) {
    const double *restrict z0 = Z + i * m, *restrict z1 = z0 + m, *restrict z2 = z1 + m,
                 *restrict z3 = z2 + m;
    const double a0 = g[i], a1 = g[i + 1], a2 = g[i + 2], a3 = g[i + 3];
    for (j = 0; j < m; ++j) {
      double *restrict gj = with_g ? G + j * m : NULL;
      const double y0 = z0[j], y1 = z1[j], y2 = z2[j], y3 = z3[j];
      if (i + 3 >= SNAKECG_NS && y1 == 0.0 && y2 == 0.0 && y3 == 0.0) { /* (objects' zeros) */
        if (y0 != 0.0) {
          for (k = 0; with_g && k <= j; ++k) gj[k] += y0 * z0[k];
          b[j] += y0 * a0;
        }
        continue;
      }
      for (k = 0; with_g && k <= j; ++k)
        gj[k] += (y0 * z0[k] + y1 * z1[k]) + (y2 * z2[k] + y3 * z3[k]);
      b[j] += (y0 * a0 + y1 * a1) + (y2 * a2 + y3 * a3);
    }
  }
  if (n - n4 == 1) {
    const double *restrict z0 = Z + n4 * m;
    const double a0 = g[n4];
    for (j = 0; j < m; ++j) {
      double *restrict gj = with_g ? G + j * m : NULL;
      const double y0 = z0[j];
      if (n4 >= SNAKECG_NS && y0 == 0.0) continue; /* (an object's zeros) */
      for (k = 0; with_g && k <= j; ++k) gj[k] += y0 * z0[k];
      b[j] += y0 * a0;
    }
  } else if (n - n4 == 2) {
    const double *restrict z0 = Z + n4 * m, *restrict z1 = z0 + m;
    const double a0 = g[n4], a1 = g[n4 + 1];
    for (j = 0; j < m; ++j) {
      double *restrict gj = with_g ? G + j * m : NULL;
      const double y0 = z0[j], y1 = z1[j];
      if (n4 >= SNAKECG_NS && y0 == 0.0 && y1 == 0.0) continue; /* (an object's zeros) */
      for (k = 0; with_g && k <= j; ++k) gj[k] += y0 * z0[k] + y1 * z1[k];
      b[j] += y0 * a0 + y1 * a1;
    }
  } else if (n - n4 == 3) {
    const double *restrict z0 = Z + n4 * m, *restrict z1 = z0 + m, *restrict z2 = z1 + m;
    const double a0 = g[n4], a1 = g[n4 + 1], a2 = g[n4 + 2];
    for (j = 0; j < m; ++j) {
      double *restrict gj = with_g ? G + j * m : NULL;
      const double y0 = z0[j], y1 = z1[j], y2 = z2[j];
      if (n4 >= SNAKECG_NS && y0 == 0.0 && y1 == 0.0 && y2 == 0.0) continue; /* (zeros) */
      for (k = 0; with_g && k <= j; ++k) gj[k] += (y0 * z0[k] + y1 * z1[k]) + y2 * z2[k];
      b[j] += (y0 * a0 + y1 * a1) + y2 * a2;
    }
  }
  for (j = 0; j < m; ++j) {
    for (k = 0; with_g && k < j; ++k) G[k * m + j] = G[j * m + k];
    if (c) b[j] += c[j];
  }
}

/* Z = L^-1 A^T for sc_inertia_factor's L and t (A: m x n row-major). */
SC_INTERNAL void sc_scene_z(sc_int n, sc_int m, sc_int t, const double *L, const double *A,
                            double *Z) {
  SC_BY_N(n, t, SC_BY(m, z_rows(n, m, t, L, A, Z)))
}

/* G = Z^T Z (m x m), b = Z^T g + c (c null: none); zero: m doubles of scratch. G null: b
 * alone (a batch's next sample at the same rows: the same sums, the same bits). */
SC_INTERNAL void sc_scene_gram(sc_int n, sc_int m, const double *Z, const double *g,
                               const double *c, double *G, double *b, double *zero) {
  const sc_int t = SNAKECG_NS; /* (n alone a constant) */
  if (!G) {
    SC_BY_N(n, t, gram(n, m, Z, g, c, G, b, zero, 0))
    return;
  }
  SC_BY_N(n, t, SC_BY(m, gram(n, m, Z, g, c, G, b, zero, 1)))
}
