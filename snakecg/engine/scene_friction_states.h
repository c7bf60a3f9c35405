/* snakecg's engine: what scene_friction.c (the fixed point on the tangent rows' bounds) shares
 * with scene_friction_states.c (Coulomb's residuals, the enumeration of every piece, and the
 * exact solve of the frictional contacts' candidate states). Included after engine.h. */
#ifndef SNAKECG_SCENE_FRICTION_STATES_H
#define SNAKECG_SCENE_FRICTION_STATES_H

#include "scene_solve.h"

#define FP_TOL 1e-12    /* |mu lam_n - s| at most this of the forces' scale: settled */
#define SOL_MAX 16      /* distinct solutions kept by the enumeration */

/* The fixed point's problem: the convex solve's arguments with the tangent blocks (contact k's
 * normal block k, row rn[k]; its tangent block nb + k, row m + k; mt = m + nt rows; lead[k]
 * the first contact of its group of equal normal rows); kp: the Z and G of its inertia and
 * rows, held from its first inner solve for the others (only the bounds and forces change). */
typedef struct { sc_int n, m, nb, nt, mt, sweeps; const double *M, *f, *mu; double *A, *c, *par;
  sc_int *kind, *start; const sc_int *lead, *rn; sc_solve_keep *kp; } sc_fr_prob;

/* The enumeration's problem and scratch. */
typedef struct {
  sc_int n, m, nb, nt;
  const sc_int *kind, *start, *tc; /* tc: a contact block's tangent (or -1) */
  const double *par, *mu, *G, *b, *Z, *g, *scale;
  double *K, *Kc, *S, *x, *y, *ys, *c0, *c1, *qw, *best;
  sc_int *piv, *opt, *digit;
} sc_enum;

/* Coulomb's residuals of (lam, w) on the contacts into res (primal, dual, complementarity) */
SC_INTERNAL void sc_coulomb_residuals(sc_int m, sc_int nt, const sc_int *rn, const sc_int *lead,
                                      const double *mu, const double *lam, const double *w,
                                      const double *scale, double *res);
/* Every piece enumerated: the count of distinct solutions (negated: not certified; 0: not
 * enumerated), the first one's forces in e->best */
SC_INTERNAL int sc_friction_enumerate(sc_enum *e);
/* The frictional contacts' candidate states solved exactly, accepted where Coulomb's residuals
 * hold (quick: the active-set passes and the nearest few only): 1 with lam, a, w, st, info
 * the solution's; 0 where none of those tried does */
SC_INTERNAL int sc_friction_states(const sc_fr_prob *p, const double *scale, const double *from,
                                   int quick, double *lam, double *a, double *w, double *st,
                                   double *info);
#endif
