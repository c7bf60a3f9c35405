/* snakecg's engine: the general scene's solve of one sample (scene_solve.c) for a caller that
 * tries the tiny path itself. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_SOLVE_H
#define SNAKECG_ENGINE_SCENE_SOLVE_H

/* held rows dependent where a pivot of their equations falls below this ratio to the first
 * (snakecg.solver.PIVOT_TOL; the pieces' rows, and Coulomb's piece in scene_friction.c):
 * nearly dependent rows are statically indeterminate to double precision, their forces are
 * taken minimum-norm rather than huge and cancelling */
#define DEP_TOL 1e-10

/* What a batch's samples at one configuration share: Z = L^-1 A^T (n x m) and G = Z^T Z
 * (m x m) of the inertia and rows they all have, held for the next sample's solve (ok: 0
 * nothing held, 1 Z, 2 Z and G; the caller zeroes it where the inertia or the rows change). */
typedef struct sc_piece_keep sc_piece_keep; /* (scene_piece.c's) */
typedef struct {
  double *Z, *G;
  int ok;
  sc_face_keep face; /* (the minimum-norm choice's last null space, where face.face is not
    null: kept while G is) */
  sc_piece_keep *pieces; /* (the last pieces' factors, or NULL: kept while G is) */
} sc_solve_keep;

/* The last pieces' factors on one G (scene_piece.c; a contact-friction fixed point's inner
 * solves keep them): room for m rows and nb blocks, one block (free()); nothing kept again */
SC_INTERNAL sc_piece_keep *sc_piece_keep_new(sc_int m, sc_int nb);
SC_INTERNAL void sc_piece_forget(sc_piece_keep *pk);

/* core_scene_solve_s, its arguments and returns; tiny 0: scene_tiny.c's path not tried (the
 * caller tried sc_tiny_solve and it declined: tried once, counted once), 1: tried first; kp:
 * the Z and G held from the last sample at the same inertia and rows, and kept for the next
 * (null: none; the answers are the same bits either way) */
SC_INTERNAL int sc_scene_solve_one(sc_int n, sc_int m, sc_int nb, const double *M,
                                   const double *f, const double *A, const double *c,
                                   const sc_int *kind, const sc_int *start, const double *par,
                                   sc_int max_sweeps, const double *from, double *lam,
                                   double *a, double *w, double *state, double *info,
                                   int tiny, sc_solve_keep *kp);
#endif
