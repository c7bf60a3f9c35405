/* snakecg's engine: the general scene's KKT conditions at one piece's solution (scene_solve.c's
 * certificate) and the active set's switches where they are violated.
 *
 * The dual of Gauss's principle (scene_solve.c's header) is solved where lam is in its sets K
 * (primal feasibility), w = G lam + b is in -N_K(lam) (dual feasibility: held rows, and blocks
 * inside their sets, do not accelerate; a contact does not accelerate into its obstacle; a
 * sliding block accelerates against its force) and lam . w = 0 (complementarity). */
#include <math.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"
#include "scene_kkt.h"

/* The KKT residuals (relative): primal (outside the set), dual (w not in -N_K(lam)),
 * complementarity (to the accelerations' scale times the larger of the forces' and the
 * largest force: nearly dependent rows, a peg across an ideal wheel's line, can ask for forces
 * 1e7 times the scale that cancel, whose products with w's rounding would otherwise pass
 * 1e-9); and the states switched where they are violated (returns 1 if any). The
 * largest of each kind summed before its one division by its scale (a correctly rounded
 * division by a positive scale keeps the order: the same maxima bit for bit, NaN terms left
 * out as sc_max leaves them; pr's 2-D blocks' terms, not scaled, apart). */
SC_INTERNAL int sc_kkt(sc_problem *p, double *res, int do_switch) {
  double pr = 0.0, p1 = 0.0, du = 0.0, co = 0.0, F = p->fscale, W = p->wscale, Fl = F;
  int moved = 0;
  sc_int k;
  for (k = 0; k < p->m; ++k) Fl = sc_max(Fl, fabs(p->lam[k]));
  for (k = 0; k < p->nb; ++k) {
    sc_int r = p->start[k];
    const double *q = p->par + 3 * k, *l = p->lam + r, *w = p->w + r;
    double e;
    switch (p->kind[k]) {
      case K_FREE:
        du = sc_max(du, fabs(w[0]));
        break;
      case K_UNILATERAL:
        pr = sc_max(pr, sc_max(0.0, -l[0]));
        du = sc_max(du, sc_max(0.0, -w[0]));
        co = sc_max(co, fabs(l[0] * w[0]));
        if (do_switch) {
          if (p->state[k] == S_HELD && l[0] < -TOL_ACCEPT * F) { p->state[k] = S_ZERO; moved = 1; }
          else if (p->state[k] == S_ZERO && w[0] < -TOL_ACCEPT * W) { p->state[k] = S_HELD; moved = 1; }
        }
        break;
      case K_BOX:
        pr = sc_max(pr, sc_max(0.0, fabs(l[0]) - q[0]));
        if (!(q[0] > 0)) break; /* the set {0}: its normal cone is every w */
        if (fabs(l[0]) < q[0]) e = fabs(w[0]);
        else e = l[0] > 0 ? sc_max(0.0, w[0]) : sc_max(0.0, -w[0]);
        du = sc_max(du, e);
        co = sc_max(co, fabs(fmin(q[0] - fabs(l[0]), 0.0) * w[0]));
        if (do_switch) {
          if (p->state[k] == S_HELD && fabs(l[0]) > q[0] * (1 + TOL_ACCEPT)) { p->state[k] = S_SLIDE; moved = 1; }
          else if (p->state[k] == S_SLIDE && e > TOL_ACCEPT * W) { p->state[k] = S_HELD; moved = 1; }
        }
        break;
      default: {
        double P[2], phi, nrm[2], nn, wn, wt;
        int zero = sc_zero_set(p, k);
        if (zero) break;
        sc_block_P(p, k, l, P);
        phi = sqrt(P[0] * l[0] * l[0] + P[1] * l[1] * l[1]);
        p1 = sc_max(p1, sc_max(0.0, phi - 1.0));
        if (p->state[k] == S_HELD || phi < 1.0 - 1e-12) {
          e = sqrt(w[0] * w[0] + w[1] * w[1]);
          if (do_switch && p->state[k] == S_HELD && phi > 1.0 + TOL_ACCEPT) {
            p->state[k] = S_SLIDE;
            p->gamma[k] = 0.0;
            moved = 1;
          }
        } else {
          nrm[0] = P[0] * l[0];
          nrm[1] = P[1] * l[1];
          nn = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1]);
          nrm[0] /= nn;
          nrm[1] /= nn;
          wn = w[0] * nrm[0] + w[1] * nrm[1]; /* must be <= 0 */
          wt = w[1] * nrm[0] - w[0] * nrm[1]; /* must be 0 */
          e = sc_max(sc_max(0.0, wn), fabs(wt));
          if (do_switch && p->state[k] == S_SLIDE && wn > TOL_ACCEPT * W) {
            p->state[k] = S_HELD;
            moved = 1;
          }
        }
        du = sc_max(du, e);
      }
    }
  }
  res[0] = sc_max(sc_max(0.0, pr / F), p1);
  res[1] = sc_max(0.0, du / W);
  res[2] = sc_max(0.0, co / (Fl * W));
  return moved;
}
