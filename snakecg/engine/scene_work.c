/* snakecg's engine: the scratch of a general scene's batch call (scene_rows.c's forward, a
 * state's rows), one allocation laid out once per call or kept across calls.
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_broad.h"
#include "scene_work.h"

enum { SW_HEAD = (sizeof(sc_scene_work) + sizeof(double) - 1) / sizeof(double) };

/* The scratch of a batch call, one allocation (doubles, then the generated functions'
 * pointers and integers, the blocks' integers, the shapes; 8-byte fields throughout): 0, or
 * -1 out of memory. With own 0 the rows' room (A, par, kind, start: mcap rows) is the
 * caller's to set and none of what mcap scales is allocated (a state's rows). */
SC_INTERNAL int sc_scene_work_alloc(sc_scene_work *sw, const double *pk, sc_int ccap,
                                    sc_int mcap, int own) {
  const sc_work_fn fns[] = {SNAKECG_LP_WORK, SNAKECG_LJ_WORK, SNAKECG_SK_WORK};
  const sc_int mc = own ? mcap : 0;
  sc_int n, nd, k, i, sz[4], most[4] = {0, 0, 0, 0}, pad;
  double *d;
  sw->pk = pk;
  sw->tol = pk[SP_TOL];
  sw->no = (sc_int)pk[SP_NO];
  sw->nob = (sc_int)pk[SP_NOB];
  sw->ng = (sc_int)pk[SP_NG];
  sw->mg = (sc_int)pk[SP_MG];
  sw->n = n = SNAKECG_NS + 3 * sw->no;
  sw->ccap = ccap;
  sw->mcap = mcap;
  sw->nbody = SNAKECG_NL + sw->no + sw->nob;
  pad = sc_broad_pad(sw->nbody); /* (the bounding circles' room: scene_broad.h) */
  for (k = 0; k < SC_COUNT(fns); ++k) {
    sz[0] = sz[1] = sz[2] = sz[3] = 0;
    if (fns[k](sz, sz + 1, sz + 2, sz + 3)) return -1;
    for (i = 0; i < 4; ++i) most[i] = sz[i] > most[i] ? sz[i] : most[i];
  }
  nd = mc * n + 2 * n * n + 7 * n + 3 * mc + 3 * mc + 5 * SNAKECG_NL +
       3 * SNAKECG_NL * SNAKECG_NS + SNAKECG_NS * SNAKECG_NS + 3 * pad + 3 * sw->no + 8 +
       3 * mc + (pk[SP_FRICTION] != 0.0 ? ccap * n : 0);
  sw->base = (double *)malloc((size_t)(SW_HEAD + nd + most[3] + 1) * sizeof(double) +
                              (size_t)(most[0] + most[1] + 2) * sizeof(double *) +
                              (size_t)(2 * mc + 2 + most[2] + 1) * sizeof(sc_int) +
                              (size_t)(sw->nbody + 1) * sizeof(sc_shape) +
                              (size_t)((SNAKECG_NL + sw->no) * sc_broad_words(sw->nbody)) *
                                  sizeof(uint64_t));
  if (!sw->base) return -1;
  sw->A = d = sw->base + SW_HEAD; /* (the head: a kept state scratch's struct) */
  sw->ws.w = d + nd;
  sw->ws.arg = (const double **)(d + nd + most[3] + 1);
  sw->ws.res = (double **)(sw->ws.arg + most[0] + 1);
  sw->kind = (sc_int *)(sw->ws.res + most[1] + 1);
  sw->ws.iw = sw->kind + 2 * mc + 2;
  sw->shape = (sc_shape *)(sw->ws.iw + most[2] + 1);
  sw->near = (uint64_t *)(sw->shape + sw->nbody + 1);
  d += mc * n; /* the rows, then what is written before it is read: not zeroed */
  sw->M = d; d += n * n; /* (the forward's full_inertia) */
  sw->L = d; d += n * n;
  sw->f = d, d += n, sw->g = d, d += n;
  sw->D = d; d += 2 * n;
  sw->par = d; d += 3 * mc;
  sw->lam = d, d += mc, sw->w = d, d += mc, sw->st = d, d += mc;
  sw->prev = d; d += 3 * mc; /* (read once a sample has written it: pnb) */
  sw->P = d; d += 3 * SNAKECG_NL; /* (the generated functions' outputs are dense) */
  sw->J = d; d += 3 * SNAKECG_NL * SNAKECG_NS;
  sw->Ms = d; d += SNAKECG_NS * SNAKECG_NS;
  sw->centre = d, d += 2 * pad, sw->reach = d, d += pad, sw->pose = d, d += 3 * sw->no;
  for (i = sw->nbody; i < pad; ++i) sw->centre[i] = sw->centre[pad + i] = sw->reach[i] = 0.0;
  sw->cs = d, sw->T = pk[SP_FRICTION] != 0.0 ? d + 2 * SNAKECG_NL : 0; /* (cs: 2 NL) */
  /* zeros: the generated functions' pointers, the shapes (not what the model's sizes or mcap
   * scale: written before it is read) */
  memset((void *)sw->ws.arg, 0, (size_t)((char *)sw->kind - (char *)sw->ws.arg));
  memset(sw->shape, 0, sizeof(sc_shape) * (size_t)(sw->nbody + 1));
  sw->start = sw->kind + mc;
  sw->placed = 0, sw->pnb = -1, sw->gnc = -1, sw->ftol = NAN; /* (nothing placed or kept) */
  sw->qnc = -1, sw->qbuf = sw->qown = 0, sw->sk.ok = 0;
  sw->sk.face.face = 0, sw->sk.face.v = sw->sk.face.mu = 0; /* (no null space kept) */
  sw->sk.face.nf = -1, sw->sk.face.has_mu = 0, sw->sk.pieces = 0;
  return 0;
}
