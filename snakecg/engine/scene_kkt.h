/* snakecg's engine: the general scene's KKT check (scene_kkt.c), used by scene_solve.c.
 * Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_KKT_H
#define SNAKECG_ENGINE_SCENE_KKT_H

/* The KKT residuals (res: primal, dual, complementarity, relative to p's scales) of p's forces
 * and w; with do_switch, the violated blocks' states switched (returns 1 where any was). */
SC_INTERNAL int sc_kkt(sc_problem *p, double *res, int do_switch);
#endif
