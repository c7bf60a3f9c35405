/* snakecg's engine: a general scene's metrics from the inertia's factor (scene_metrics.c), for
 * the forward (scene_rows.c). Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_METRICS_H
#define SNAKECG_ENGINE_SCENE_METRICS_H

/* The metrics of a solved sample from the bodies' inertia M = L D L^T (n x n, block diagonal:
 * M_s on the snake's n_s coordinates, then m, m, I per object; L and r as sc_tiny_inertia
 * writes them: L unit lower with D on its diagonal, its rows from t on their diagonal, r = D^-1),
 * the force f (n), the accelerations a and the m rows A (m x n) with their forces lam (the
 * scale of a's rounding, for sr's zero): norms (4: ||qdd_s||^2, ||a_o||^2 summed,
 * ||lambda||^2, sr) and each object's ||a_o||^2 (no). */
SC_INTERNAL void sc_scene_metrics(sc_int n, sc_int no, sc_int t, const double *L,
                                  const double *r, const double *f, const double *a,
                                  sc_int m, const double *A, const double *lam, double *norms,
                                  double *obj);
#endif
