/* snakecg's engine: a general scene's batch inputs checked before any work (scene_inputs.c,
 * for scene_rows.c). Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_INPUTS_H
#define SNAKECG_ENGINE_SCENE_INPUTS_H

/* A base position (q's x, y) at most this many times the scene's size from the origin
 * (snakecg.scenes.model.POSITION_SPAN): the contacts' geometry rounds to 1.1e-10 of the
 * scene's size there, 1 % of their default tolerance; farther, it rounds beyond it */
#define POSITION_SPAN 1e6
/* The first of n samples with an entry of q (n_s) not finite or its base position beyond
 * qlim (m), or of tau (n_a) or fo (no3) not finite or beyond +-1e150
 * (snakecg.engine.rules.FORCE_LIMIT), each sample's row a stride (sq, st, sf; 0: one row for
 * all) after the last; -1 where none. */
SC_INTERNAL sc_int sc_inputs_bad(sc_int n, const double *q, sc_int sq, const double *tau,
                                 sc_int st, const double *fo, sc_int sf, sc_int no3,
                                 double qlim);
#endif
