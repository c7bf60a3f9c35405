/* snakecg's engine: the pieces' reading of the general scene's solve (scene_sets.c), used by
 * scene_solve.c. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_SETS_H
#define SNAKECG_ENGINE_SCENE_SETS_H

/* Each block's piece (held, zero, sliding) read from p's lam and w: a contact row below
 * rel * fscale reads zero where w > 0, a box within rel of its bound and a 2-D block within
 * rel2 of its boundary (relative) read sliding (gamma from w); a set {0} reads zero. */
SC_INTERNAL void sc_read_states(sc_problem *p, double rel, double rel2);
#endif
