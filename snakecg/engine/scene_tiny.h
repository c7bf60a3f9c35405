/* snakecg's engine: the general scene's solve compiled for tiny problems (scene_tiny.c) and
 * its switch. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_TINY_H
#define SNAKECG_ENGINE_SCENE_TINY_H

#define SC_TINY_M 6 /* rows (every block one row) */
#define SC_TINY_N 16 /* coordinates */

/* scene_solve.c's solve_sample for a problem of one-row blocks and at most SC_TINY_M rows on
 * SC_TINY_N coordinates, where its answer needs none of the general path's machinery: returns
 * 1 with lam, a, w, state_out and info written, else 0 with nothing written (the caller's
 * general path answers). Its arguments are solve_sample's. */
SC_INTERNAL int sc_tiny_solve(sc_int n, sc_int m, sc_int nb, const double *M, const double *f,
                              const double *A, const double *c, const sc_int *kind,
                              const sc_int *start, const double *par, const double *from,
                              double *lam, double *a, double *w, double *state_out,
                              double *info);
/* sc_tiny_solve for the forward (c null; M's rows from n_s on diagonal, as the forward makes
 * them), and where the inertia was factored whether answered or not (*t >= 0: the dense
 * block's size, else -1) its factor: sc_tiny_inertia's L and r */
SC_INTERNAL int sc_tiny_forward(sc_int n, sc_int m, sc_int nb, const double *M, const double *f,
                                const double *A, const sc_int *kind, const sc_int *start,
                                const double *par, const double *from, double *lam, double *a,
                                double *w, double *state_out, double *info, double *L,
                                double *r, sc_int *t);
/* The bodies' inertia M (n x n, its rows from n_s on diagonal, as the forward makes them)
 * factored as the tiny path factors it, M = L D L^T: L unit lower (its dense block's, the
 * block's size *t; the rest of L's lower triangle zero, L's upper triangle scratch) with D on
 * its diagonal, r (n) D's reciprocals. Returns 0 (*t = -1) where the pivot rule fails
 * (sc_inertia_factor's, on the same pivots). */
SC_INTERNAL int sc_tiny_inertia(sc_int n, const double *M, const double *f, double *L,
                                double *r, sc_int *t);
/* its switch (mode 1 on, 2 on without its FMA copy, 0 off, -1 left) and counts (problems
 * tried, answered) */
int SNAKECG_EXPORT(core_scene_tiny)(sc_int mode, double *counts);
#endif
