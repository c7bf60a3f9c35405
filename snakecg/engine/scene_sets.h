/* snakecg's engine: the pieces' reading of the general scene's solve (scene_sets.c), used by
 * scene_solve.c, scene_tiny.c, scene_piece.c and scene_primal.c. Included after engine.h
 * (and math.h). */
#ifndef SNAKECG_ENGINE_SCENE_SETS_H
#define SNAKECG_ENGINE_SCENE_SETS_H

/* The solve's info fields and pass budgets, shared by scene_solve.c and its tiny problems'
 * copy of the same passes (scene_tiny.c) */
enum { INFO_STATUS = 0, INFO_DEPENDENT, INFO_PRIMAL, INFO_DUAL, INFO_COMPL, INFO_SWEEPS,
       INFO_PASSES, INFO_RANK_DEFECT, INFO_WIDTH };
#define GUESS_PASSES 3 /* active-set passes from the held guess (rows <= coordinates) */
#define FROM_PASSES 4 /* from the caller's start (the last time step's pieces) */

/* Each block's piece (held, zero, sliding) read from p's lam and w: a contact row below
 * rel * fscale reads zero where w > 0, a box within rel of its bound and a 2-D block within
 * rel2 of its boundary (relative) read sliding (gamma from w); a set {0} reads zero. With
 * wtol > 0 (w converged: read from its accelerations as well), a contact row or a 2-D block
 * that accelerates by more than wtol * wscale reads zero or sliding whatever its force (a
 * held row keeps no acceleration: on nearly dependent rows the forces drift along the
 * nearly singular direction for thousands of sweeps while w has settled). */
SC_INTERNAL void sc_read_states(sc_problem *p, double rel, double rel2, double wtol);

/* (inline: called per block in the solve's checks and the primal's face, a few tens of times a
 * solve) P of a 2-D block at lam (diag, 2 entries): the set is lam^T P lam <= 1 */
static inline void sc_block_P(const sc_problem *p, sc_int k, const double *l, double *P) {
  const double *q = p->par + 3 * k;
  if (p->kind[k] == K_DISC) {
    P[0] = P[1] = 1.0 / (q[0] * q[0]);
  } else {
    double st = l[0] < 0 ? q[0] : q[1];
    P[0] = 1.0 / (st * st);
    P[1] = 1.0 / (q[2] * q[2]);
  }
}

/* 1 if block k's rows do not accelerate (|w| within the acceptance tolerance). */
static inline int sc_still(const sc_problem *p, sc_int k) {
  sc_int i;
  for (i = 0; i < sc_block_size(p->kind[k]); ++i)
    if (fabs(p->w[p->start[k] + i]) > TOL_ACCEPT * p->wscale) return 0;
  return 1;
}
#endif
