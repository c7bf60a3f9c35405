/* snakecg's engine: the general scene's dual on its log-barrier path (scene_barrier.c), used
 * by scene_solve.c. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_BARRIER_H
#define SNAKECG_ENGINE_SCENE_BARRIER_H

/* p->lam := the barrier path's point whose gap to the dual's optimum is below 1e-11 of the
 * scales (p->G, p->b, the sets and scales read, Z = L^-1 A^T: n x m; p->w untouched). Returns
 * the Newton steps taken, 0 where it stopped short (no descent, or NEWTON_MAX steps, before the
 * last centring). Work: n^2 + nm + 3n + 5m + 6nb doubles (scene_solve.c's rest holds more),
 * iwork: n sc_ints. */
SC_INTERNAL sc_int sc_barrier(sc_problem *p, const double *Z, double *work, sc_int *iwork);

/* The point put onto the pieces read from it (p->state; p->w untouched). */
SC_INTERNAL void sc_barrier_onto(sc_problem *p);
#endif
