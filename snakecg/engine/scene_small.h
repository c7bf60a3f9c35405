/* snakecg's engine: what scene_small.c's factor unrolled for the snake's block lends to the
 * primal piece (scene_primal.c: its Hessian's Cholesky, n = n_s). Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_SMALL_H
#define SNAKECG_ENGINE_SCENE_SMALL_H

#if SNAKECG_NS <= 16 && defined(__GNUC__) && !defined(SC_GENERAL_ONLY)
#define SC_FIXED 1 /* the snake's block unrolled (code of O(n_s^3); SC_GENERAL_ONLY: not) */
/* L = chol(M) and a = L^-1 f for n_s x n_s M (row-major, its lower triangle read; L's lower
 * triangle written, M's room may be L's): sc_cholesky's L bit for bit, the same pivot rule
 * (a pivot not above thr, thr = rel times M's largest diagonal entry: 0, L and a unwritten). */
SC_INTERNAL int sc_small_factor(const double *M, const double *f, double thr, double *L,
                                double *a);
#if defined(__x86_64__) && !defined(__clang__) && __GNUC__ >= 6 && !defined(SC_NO_AVX)
#define SC_SMALL_FMA 1
/* The same for the primal piece's Hessian alone where the processor has AVX2 and FMA (the
 * caller checks): within rounding of sc_small_factor (by L D L^T, fused multiply-adds), rl
 * L's diagonal's reciprocals, Lt L's columns (column k at Lt + k n_s, from the diagonal). */
SC_INTERNAL int sc_small_factor_fma(const double *M, const double *f, double thr, double *L,
                                    double *a, double *rl, double *Lt);
#endif
#endif
#endif
