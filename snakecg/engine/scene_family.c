/* snakecg's engine: a Coulomb family of forces at a solution of the contact-friction solve
 * (scene_friction.c): whether Coulomb's piece leaves the forces free while every acceleration
 * stays, and where it does, the family's minimum-norm member.
 *
 * The unknowns: the forces that may move while every acceleration stays, as scene_sets.h's
 * face rows for the convex sets. A block still (its rows' w zero within TOL_ACCEPT of W,
 * whatever its state: a contact read held at zero force may be opening) and of a set larger
 * than {0}: its rows; for a frictional contact so, its normal row with its tangent row
 * beside it where it sticks (w_t zero: its friction may move inside the cone, at its edge
 * too) or tied to it (lam_t = -+ mu lam_n, the direction fixed by the slip) where it slips.
 * The defect: these unknowns' directions D (rows of A, tied pairs summed) are dependent where
 * D M^-1 D^T, their Gram in G, is singular (pivots at most DEP_TOL of the first, as the convex
 * pieces'). A one-dimensional family (null direction v) may still be pinned where the forces
 * are: it moves only where v or -v keeps the sets' active bounds (within TOL_ACCEPT of F: a
 * normal force at 0, a wheel's at its bound, a friction at its cone's edge; a disc or ellipse
 * counts as free).
 * The minimum-norm member: min 1/2 |lam_F|^2 over the unknowns' rows F (the other forces are
 * fixed by the accelerations), lam_F - lam moved in the null space of G_FF (pivots at most
 * DEP_TOL of the first: A_F^T moves nothing, the accelerations stay), each unknown in its set:
 * a held block's own, a sticking contact's (normal, tangent) in Coulomb's cone
 * |lam_t| <= mu lam_n (K_CONE), a slipping one's on its ray lam_t = c lam_n, lam_n >= 0
 * (K_RAY). Convex, its minimiser unique: scene_min_norm.c's Newton on its dual, with the
 * cone's and the ray's projections. The caller checks the accelerations of the new forces.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"
#include "scene_solve.h"
#include "scene_family.h"

enum { U_FREE = 0, U_NORMAL, U_BOUND, U_CONE }; /* an unknown's set */

/* Whether v (the one null direction, v + t u for unknown t) or -v keeps every active bound:
 * 0 where neither does (the forces pinned). */
static int moves(sc_int u, const double *v, const sc_int *r1, const sc_int *typ,
                 const sc_int *nrm, const double *bd, const double *lam, double tf) {
  int ok[2] = {1, 1};
  sc_int i, side;
  for (i = 0; i < u; ++i) {
    const double l = lam[r1[i]], d = v[i * u];
    for (side = 0; side < 2; ++side) {
      const double e = side ? -d : d;
      if (typ[i] == U_NORMAL && l <= tf && e < -TOL_ACCEPT) ok[side] = 0;
      if (typ[i] == U_BOUND && fabs(l) >= bd[i] - tf && (l > 0 ? e : -e) > TOL_ACCEPT)
        ok[side] = 0;
      if (typ[i] == U_CONE) { /* lam_t -+ mu lam_n <= 0 where at the edge */
        const double ln = lam[r1[nrm[i]]], en = side ? -v[nrm[i] * u] : v[nrm[i] * u];
        if (l >= bd[i] * ln - tf && e - bd[i] * en > TOL_ACCEPT) ok[side] = 0;
        if (-l >= bd[i] * ln - tf && -e - bd[i] * en > TOL_ACCEPT) ok[side] = 0;
      }
    }
  }
  return ok[0] || ok[1];
}

SC_INTERNAL sc_int sc_coulomb_family(const sc_family *c, double *lam, int *chosen) {
  const sc_int mt = c->mt, m = c->m, *kind = c->kind, *start = c->start;
  const double *par = c->par, *w = c->w, *G = c->G, tol = TOL_ACCEPT * c->W,
               tf = TOL_ACCEPT * c->F;
  sc_int k, i, j, u = 0, rank, def, nf = 0, nfb = 0;
  sc_int *r1, *r2, *typ, *nrm, *blk, *perm, *F, *fk, *fkind;
  double *P, *Q, *v, *cf, *x, *bd, *sw, *fpar, *Gf, *lf, *wk;
  sc_problem fp;
  *chosen = 0;
  P = (double *)malloc(sizeof(double) * (size_t)(7 * mt * mt + 24 * mt + 8));
  r1 = (sc_int *)malloc(sizeof(sc_int) * (size_t)(10 * mt + 8));
  if (!P || !r1) {
    free(P), free(r1);
    return -1;
  }
  Q = P + mt * mt, v = Q + mt * mt, Gf = v + mt * mt, wk = Gf + mt * mt; /* (wk: 3 mt^2
    + 14 mt) */
  cf = wk + 3 * mt * mt + 14 * mt, x = cf + mt, bd = x + mt, sw = bd + mt, fpar = sw + 2 * mt;
  lf = fpar + 3 * mt;
  r2 = r1 + mt, typ = r2 + mt, nrm = typ + mt, blk = nrm + mt, perm = blk + mt, F = perm + mt;
  fk = F + mt, fkind = fk + mt;
  for (k = 0; k < c->nb; ++k) {
    const sc_int r = start[k], nk = sc_block_size(kind[k]);
    int still = 1, free_set = kind[k] == K_FREE || kind[k] == K_UNILATERAL ||
                               (kind[k] == K_SPLIT ? par[3 * k + 2] > 0 && (par[3 * k] > 0 ||
                                par[3 * k + 1] > 0) : par[3 * k] > 0);
    for (i = 0; i < nk; ++i) still &= fabs(w[r + i]) <= tol;
    if (!free_set || !still) continue; /* (held or not: a force moves only where its rows
      do not accelerate; a contact read held at zero force may open) */
    for (i = 0; i < nk; ++i, ++u) {
      r1[u] = r + i, r2[u] = -1, cf[u] = 0.0, bd[u] = par[3 * k], blk[u] = k;
      typ[u] = kind[k] == K_UNILATERAL ? U_NORMAL : kind[k] == K_BOX ? U_BOUND : U_FREE;
    }
    if (k >= c->nt || !(c->mu[k] > 0) || r != c->rn[k]) continue; /* (a contact's normal) */
    if (fabs(w[m + k]) <= tol) { /* sticks */
      r1[u] = m + k, r2[u] = -1, cf[u] = 0.0, typ[u] = U_CONE, nrm[u] = u - 1;
      bd[u] = c->mu[k], blk[u] = k;
      ++u;
    } else /* slips: lam_t = -mu lam_n sign(w_t) */
      r2[u - 1] = m + k, cf[u - 1] = w[m + k] < 0 ? c->mu[k] : -c->mu[k];
  }
  for (i = 0; i < u; ++i) /* the Gram matrix of the directions A_r1 + cf A_r2 */
    for (j = 0; j <= i; ++j) {
      double t = G[r1[i] * mt + r1[j]];
      if (r2[j] >= 0) t += cf[j] * G[r1[i] * mt + r2[j]];
      if (r2[i] >= 0) t += cf[i] * G[r2[i] * mt + r1[j]];
      if (r2[i] >= 0 && r2[j] >= 0) t += cf[i] * cf[j] * G[r2[i] * mt + r2[j]];
      P[i * u + j] = P[j * u + i] = Q[i * u + j] = Q[j * u + i] = t;
    }
  for (i = 0; i < u; ++i) x[i] = 0.0; /* (a right-hand side: only the rank is read) */
  rank = u > 0 ? sc_psd_solve(u, P, u, x, DEP_TOL, sw, sw + mt, perm) : 0;
  def = u - rank;
  if (def == 1) { /* the null direction (Q's least eigenvalue's vector), pinned or not */
    sc_eigen_symmetric(u, Q, u, x, v, u);
    if (!moves(u, v, r1, typ, nrm, bd, lam, tf)) def = 0;
  }
  if (def > 0) { /* the family's rows in blocks: a contact's normal with its tangent as its
    cone (sticks) or ray (slips), every other block's rows in its own set */
    for (i = 0; i < u; ++i) {
      const sc_int b = blk[i];
      if (typ[i] == U_CONE) continue; /* (with its normal) */
      if (r2[i] >= 0 || (i + 1 < u && typ[i + 1] == U_CONE)) {
        const int ray = r2[i] >= 0;
        fkind[nfb] = ray ? K_RAY : K_CONE;
        fpar[3 * nfb] = ray ? cf[i] : c->mu[b], fpar[3 * nfb + 1] = fpar[3 * nfb + 2] = 0.0;
        F[nf] = r1[i], F[nf + 1] = ray ? r2[i] : r1[i + 1];
        fk[nf] = fk[nf + 1] = nfb++;
        nf += 2;
        continue;
      }
      if (i > 0 && blk[i - 1] == b && typ[i - 1] != U_CONE) { /* (a 2-D block's second row) */
        F[nf] = r1[i], fk[nf++] = nfb - 1;
        continue;
      }
      fkind[nfb] = kind[b];
      memcpy(fpar + 3 * nfb, par + 3 * b, 3 * sizeof(double));
      F[nf] = r1[i], fk[nf++] = nfb++;
    }
    for (i = 0; i < nf; ++i) {
      lf[i] = lam[F[i]];
      for (j = 0; j <= i; ++j) Gf[i * nf + j] = G[F[i] * mt + F[j]];
    }
    memset(&fp, 0, sizeof fp);
    fp.nb = nfb, fp.kind = fkind, fp.par = fpar, fp.fscale = c->F;
    if (sc_min_norm_rows(&fp, nf, fk, Gf, DEP_TOL, lf, wk) == 1) {
      for (i = 0; i < nf; ++i) lam[F[i]] = lf[i];
      *chosen = 1;
    }
  }
  free(P), free(r1);
  return def;
}
