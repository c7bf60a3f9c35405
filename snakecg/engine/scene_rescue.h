/* snakecg's engine: the rescue of the general scene's solve (scene_rescue.c), used by
 * scene_solve.c. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_RESCUE_H
#define SNAKECG_ENGINE_SCENE_RESCUE_H

/* Active-set passes on pieces with nearly dependent held rows solved from Z (scene_solve.c's
 * last resort; kkt: its check); returns 1 when a piece's solution satisfies the KKT conditions */
SC_INTERNAL int sc_rescue(sc_problem *p, const double *Z, const double *g, const double *c,
                          double *work, sc_int *iwork, sc_int *was, sc_int *passes,
                          sc_int *defect, double *res, int (*kkt)(sc_problem *, double *, int));

/* Every row's w = Z^T (g + Z lam) + c, from Z (y: n scratch, left g + Z lam) */
SC_INTERNAL void sc_rescue_w(sc_problem *p, const double *Z, const double *g, const double *c,
                             double *y);
#endif
