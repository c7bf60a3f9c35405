/* snakecg's engine: G's diagonal and Z^T g as the Gram loop sums them (scene_diag.c), for
 * scene_solve.c's warm start. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_DIAG_H
#define SNAKECG_ENGINE_SCENE_DIAG_H

SC_INTERNAL void sc_diag_b(sc_int n, sc_int m, const double *Z, const double *g, double *d,
                           double *e);
#endif
