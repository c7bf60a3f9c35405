/* snakecg's engine: the pieces' reading of the general scene's solve (scene_sets.c), used by
 * scene_solve.c and scene_tiny.c. Included after engine.h. */
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
 * rel2 of its boundary (relative) read sliding (gamma from w); a set {0} reads zero. */
SC_INTERNAL void sc_read_states(sc_problem *p, double rel, double rel2);
#endif
