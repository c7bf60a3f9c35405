/* snakecg's engine: the scratch of a general scene's batch call (scene_work.c), which
 * scene_rows.c's forward and its state's rows fill and read. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_WORK_H
#define SNAKECG_ENGINE_SCENE_WORK_H

#include <stdint.h>
#include "scene_broad.h"
#include "scene_solve.h"

/* The scene's sizes and the scratch of one batch call. */
typedef struct {
  const double *pk;
  sc_int no, nob, ng, mg, n, ccap, mcap, nbody;
  int placed; /* the bodies' parts that do not move are placed (sc_scene_place's how & 1) */
  double tol; /* the contact tolerance (m) */
  sc_work_t ws;
  double *base, *A, *M, *f, *par, *lam, *w, *st, *P, *J, *Ms, *L, *g, *D, *cs;
  double *prev; /* the last sample's pieces (3 per block: state, forces) */
  const double *prec; /* and its contacts' records */
  sc_int *kind, *start, pnb; /* pnb: its blocks (-1: none, not solved) */
  sc_int cool, backoff; /* samples left cold after a start that fell back, the next count */
  sc_int gnc; /* the contacts before the ground's rows the forward last wrote (-1: none) */
  /* a batch's samples at one configuration: the q (pq, the caller's), contact count (qnc, -1:
   * none) and records (qrec, the caller's row) of the last sample whose rows were found in
   * this call, kept with its poses, rows and the solve's Z and G (sk, in qbuf: allocated at
   * the first repeat) for the next samples at the same q */
  const double *pq, *qrec;
  sc_int qnc;
  double *qbuf;
  /* the one-sample calls' scratch (kept from call to call): its own copy of that q and
   * those records (n_s, then CR_W a contact), as the caller's buffer is overwritten by the
   * next call's (null: not made, nothing kept from one call to the next) */
  double *qown;
  sc_solve_keep sk;
  sc_shape *shape;
  double *centre, *reach, *pose, *T; /* T: the contacts' tangent rows (null: no friction) */
  uint64_t *near; /* the broad phase's bits (scene_broad.h), sc_broad_words per moving body */
  /* with few bodies (SC_BROAD_FEW) the broad phase's pairs instead, and their squared far at
   * the tolerance ftol (NaN: not made) */
  sc_int npair;
  unsigned char pair[SC_BROAD_PAIRS][2];
  double far2[SC_BROAD_PAIRS], ftol;
} sc_scene_work;

/* The scratch of a batch call for the scene packed in pk, room for ccap contacts and mcap
 * rows (scene_work.c): 0, or -1 out of memory; freed by sc_scene_work_free. */
SC_INTERNAL int sc_scene_work_alloc(sc_scene_work *sw, const double *pk, sc_int ccap,
                                    sc_int mcap, int own);
static inline void sc_scene_work_free(sc_scene_work *sw) {
  double *q = sw->qbuf, *o = sw->qown; /* (read first: a kept scratch's struct is in its
    base) */
  free(sw->base);
  free(q);
  free(o);
}
#endif
