/* snakecg's engine: scene_piece.c's entry for the active set's passes (scene_solve.c). */
#ifndef SNAKECG_ENGINE_SCENE_PIECE_H
#define SNAKECG_ENGINE_SCENE_PIECE_H

/* sc_polish, whose Newton may stop early (*early nonzero on entry) where a block certainly
 * breaks the KKT conditions; *early says on return whether it did */
SC_INTERNAL sc_int sc_polish_pass(sc_problem *p, double *work, sc_int *iwork, int *early);
#endif
