/* snakecg's engine: the tiny solve's set-up and accelerations (scene_tiny_setup.c), for
 * scene_tiny.c. Included after engine.h and scene_tiny.h. */
#ifndef SNAKECG_ENGINE_SCENE_TINY_SETUP_H
#define SNAKECG_ENGINE_SCENE_TINY_SETUP_H

/* the set-up compiled for the snake's n_s coordinates and 0-2 objects where n_s is at most this
 * (beyond, scene_small.c's loops: a fully unrolled factor grows as n_s^3) */
#define TINY_FIXED_NS 9

/* Each function below has two copies: fused 1, the one with AVX2 and FMA (only where
 * sc_tiny_fma says the processor has both), 0 the plain one. */
SC_INTERNAL int sc_tiny_fma(void);
/* The inertia's factor M = L D L^T (L, n x n: unit lower, D on its diagonal, L D above it;
 * r: D's reciprocals) for n coordinates; shape: the objects' count where the factor is
 * compiled for n (the snake's dense block, then the objects' diagonal rows), else -1 (the
 * dense block found as sc_inertia_factor finds it); *t: the dense block's size. 0: singular. */
SC_INTERNAL int sc_tiny_factored(int fused, sc_int n, int shape, const double *M,
                                 const double *f, double *L, double *r, sc_int *t);
/* Y = D^-1 L^-1 [A^T f] (n x (m + 1)) and G = Z^T D^-1 Z (m x m), b = Z^T D^-1 g + c (c may
 * be null), Z = L^-1 A^T, g = L^-1 f, for sc_tiny_factored's L, r and t (m at most
 * SC_TINY_M). */
SC_INTERNAL void sc_tiny_gram(int fused, sc_int m, sc_int n, sc_int t, const double *L,
                              const double *r, const double *A, const double *f,
                              const double *c, double *Y, double *G, double *b);
/* a = L^-T (Y_g + Y lam) = M^-1 (f + A^T lam) (n; a force that is not finite taken as 0) */
SC_INTERNAL void sc_tiny_accel(int fused, sc_int m, sc_int n, int shape, sc_int t,
                               const double *L, const double *Y, const double *lam, double *a);
#endif
