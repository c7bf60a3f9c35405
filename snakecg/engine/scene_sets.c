/* snakecg's engine: the friction and contact sets of the general-scene solve
 * (scene_solve.c); the exact minimiser of a quadratic over each of them is scene_block.c's.
 *
 * A block k of the dual, min 1/2 lam^T G lam + b^T lam over lam in K_1 x ... x K_nb, is one
 * row (FREE: R; UNILATERAL: lam >= 0; BOX: |lam| <= p0) or two (DISC: |lam| <= p0; SPLIT: the
 * split ellipse with semi-axes p0 for lam_t <= 0, p1 for lam_t >= 0, p2 across). On a 2-D
 * set's boundary, lam^T P lam = 1 with P diagonal (block_P). sc_on_boundary parametrizes a
 * 2-D set's boundary by a direction (the sliding pieces' unknowns). Used by scene_solve.c.
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"

/* A sliding 2-D block k's force on its set's boundary in the direction u (a unit vector:
 * (cos t, sin t) at the angle t) and the tangent T = dlam/dt there: a disc s u; a split ellipse
 * (st u0, p2 u1), st the semi-axis of the half that u points into. Both have dT/dt = -lam. */
SC_INTERNAL void sc_on_boundary(const sc_problem *p, sc_int k, const double *u, double *l,
                                double *T) {
  const double *q = p->par + 3 * k;
  const double ax = p->kind[k] == K_DISC ? q[0] : (u[0] < 0 ? q[0] : q[1]),
               ay = p->kind[k] == K_DISC ? q[0] : q[2];
  l[0] = ax * u[0];
  l[1] = ay * u[1];
  T[0] = -ax * u[1];
  T[1] = ay * u[0];
}

/* The direction u (unit) of a 2-D block's force in sc_on_boundary's parametrization, radially
 * onto the boundary ((1, 0) for no force). */
SC_INTERNAL void sc_direction_of(const sc_problem *p, sc_int k, const double *l, double *u) {
  const double *q = p->par + 3 * k;
  const double ax = l[0] < 0 ? q[0] : q[1];
  double x = l[0], y = l[1], r;
  if (p->kind[k] != K_DISC) {
    x = ax > 0 ? l[0] / ax : 0.0;
    y = l[1] / q[2];
  }
  r = sqrt(x * x + y * y);
  u[0] = r > 0 ? x / r : 1.0;
  u[1] = r > 0 ? y / r : 0.0;
}

/* 1 if the forces l of block k lie in its set, to the relative tolerance tol; with clip,
 * forces outside by at most that are first moved onto the set. */
SC_INTERNAL int sc_in_set(const sc_problem *p, sc_int k, double *l, double tol, int clip) {
  const double *q = p->par + 3 * k;
  double P[2], phi;
  switch (p->kind[k]) {
    case K_FREE: return 1;
    case K_UNILATERAL:
      if (!(l[0] >= -tol * p->fscale)) return 0;
      if (clip && l[0] < 0) l[0] = 0.0;
      return 1;
    case K_BOX:
      if (!(fabs(l[0]) <= q[0] * (1 + tol))) return 0;
      if (clip) l[0] = fmax(-q[0], fmin(q[0], l[0]));
      return 1;
    default:
      if (sc_zero_set(p, k))
        return l[0] == 0.0 && l[1] == 0.0;
      sc_block_P(p, k, l, P);
      phi = sqrt(P[0] * l[0] * l[0] + P[1] * l[1] * l[1]);
      if (!(phi <= 1 + tol)) return 0;
      if (clip && phi > 1) {
        l[0] /= phi;
        l[1] /= phi;
      }
      return 1;
  }
}

/* The pieces read from the current lam and w (declared in scene_sets.h). */
SC_INTERNAL void sc_read_states(sc_problem *p, double rel, double rel2, double wtol) {
  const double wmax = wtol > 0 ? wtol * p->wscale : INFINITY;
  sc_int k;
  for (k = 0; k < p->nb; ++k) {
    sc_int r = p->start[k];
    const double *q = p->par + 3 * k, *l = p->lam + r;
    switch (p->kind[k]) {
      case K_FREE: p->state[k] = S_HELD; break;
      case K_UNILATERAL:
        p->state[k] = p->w[r] > wmax ? S_ZERO :
                      l[0] > rel * p->fscale ? S_HELD : (p->w[r] > 0 ? S_ZERO : S_HELD);
        break;
      case K_BOX:
        p->state[k] = !(q[0] > 0) ? S_ZERO : (fabs(l[0]) < q[0] * (1 - rel) ? S_HELD : S_SLIDE);
        break;
      default: {
        double P[2], phi;
        if (sc_zero_set(p, k)) {
          p->state[k] = S_ZERO;
          break;
        }
        sc_block_P(p, k, l, P);
        phi = P[0] * l[0] * l[0] + P[1] * l[1] * l[1];
        p->state[k] = phi < (1 - rel2) * (1 - rel2) &&
                      !(p->w[r] * p->w[r] + p->w[r + 1] * p->w[r + 1] > wmax * wmax) ? S_HELD :
                      S_SLIDE;
        if (p->state[k] == S_SLIDE) {
          double g = -(p->w[r] * P[0] * l[0] + p->w[r + 1] * P[1] * l[1]) /
                     (P[0] * P[0] * l[0] * l[0] + P[1] * P[1] * l[1] * l[1]);
          p->gamma[k] = g > 0 ? g : 0.0;
        }
      }
    }
  }
}
