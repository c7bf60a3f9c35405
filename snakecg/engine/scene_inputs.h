/* snakecg's engine: a general scene's batch inputs checked before any work (scene_inputs.c,
 * for scene_rows.c). Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_INPUTS_H
#define SNAKECG_ENGINE_SCENE_INPUTS_H

/* The first of n samples with an entry of q (n_s), tau (n_a) or fo (no3) not finite, each
 * sample's row a stride (sq, st, sf; 0: one row for all) after the last; -1 where none. */
SC_INTERNAL sc_int sc_inputs_bad(sc_int n, const double *q, sc_int sq, const double *tau,
                                 sc_int st, const double *fo, sc_int sf, sc_int no3);
#endif
