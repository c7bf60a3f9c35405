/* snakecg's engine: the pieces' reading of the general scene's solve (scene_sets.c), used by
 * scene_solve.c, scene_tiny.c, scene_piece.c and scene_primal.c. Included after engine.h
 * (and math.h). */
#ifndef SNAKECG_ENGINE_SCENE_SETS_H
#define SNAKECG_ENGINE_SCENE_SETS_H

/* The solve's info fields and pass budgets, shared by scene_solve.c and its tiny problems'
 * copy of the same passes (scene_tiny.c) */
enum { INFO_STATUS = 0, INFO_DEPENDENT, INFO_PRIMAL, INFO_DUAL, INFO_COMPL, INFO_SWEEPS,
       INFO_PASSES, INFO_RANK_DEFECT, INFO_WIDTH };
/* Two more sets, of a Coulomb family's minimum-norm member only (scene_family.c; par: mu, c):
 * a contact's (normal, tangent) forces in Coulomb's cone |lam_t| <= mu lam_n, or on the ray
 * lam_t = c lam_n, lam_n >= 0 of a slipping contact. */
enum { K_CONE = 5, K_RAY = 6 };

/* The minimum-norm forces lam (nf rows, in: one member, out: the minimum-norm one; fk: their
 * blocks in p, whose kind, par and fscale are read) among those with the same accelerations:
 * lam moved in the null space of the rows' Gram matrix Gff (nf x nf, row-major, its lower
 * triangle read and overwritten; pivots at most tol of the first) and kept in the blocks'
 * sets (scene_min_norm.c's Newton on the dual). Returns 0 where that null space is empty,
 * 1 with the minimum-norm forces in lam, 2 where they were not found (lam as it was).
 * Work: 3 nf^2 + 14 nf doubles. */
SC_INTERNAL int sc_min_norm_rows(const sc_problem *p, sc_int nf, const sc_int *fk, double *Gff,
                                 double tol, double *lam, double *work);

#define GUESS_PASSES 3 /* active-set passes from the held guess (rows <= coordinates) */
#define FROM_PASSES 4 /* from the caller's start (the last time step's pieces) */

/* Each block's piece (held, zero, sliding) read from p's lam and w: a contact row below
 * rel * fscale reads zero where w > 0, a box within rel of its bound and a 2-D block within
 * rel2 of its boundary (relative) read sliding (gamma from w); a set {0} reads zero. With
 * wtol > 0 (w converged: read from its accelerations as well), a contact row or a 2-D block
 * that accelerates by more than wtol * wscale reads zero or sliding whatever its force (a
 * held row keeps no acceleration: on nearly dependent rows the forces drift along the
 * nearly singular direction for thousands of sweeps while w has settled). */
SC_INTERNAL void sc_read_states(sc_problem *p, double rel, double rel2, double wtol);

/* sc_min_norm_face's choice on the face's rows F (nf; fk: their blocks) with the caller's null
 * space V (nnull orthonormal vectors, V + t nf): scene_rescue.c's, from Z's QR. Returns 1 when
 * the minimum-norm forces were found, 2 when not, 3 when within loose only (kept: nf doubles
 * for that try, NULL: none). fkp (or NULL): the dual point kept on this face, where V is the
 * one kept with it, the Newton's start, and kept again where it succeeds. */
SC_INTERNAL int sc_min_norm_basis(sc_problem *p, const double *Z, sc_int nf, const sc_int *F,
                                  const sc_int *fk, double *V, sc_int nnull, double *work,
                                  double eps, double loose, double *kept, sc_face_keep *fkp);

/* (inline: called per block in the solve's checks and the primal's face, a few tens of times a
 * solve) P of a 2-D block at lam (diag, 2 entries): the set is lam^T P lam <= 1 */
static inline void sc_block_P(const sc_problem *p, sc_int k, const double *l, double *P) {
  const double *q = p->par + 3 * k;
  if (p->kind[k] == K_DISC) {
    P[0] = P[1] = 1.0 / (q[0] * q[0]);
  } else {
    double st = l[0] < 0 ? q[0] : q[1];
    P[0] = 1.0 / (st * st);
    P[1] = 1.0 / (q[2] * q[2]);
  }
}

/* 1 where block k's set is {0} (a box, disc or split ellipse of no extent: its forces stay
 * zero, and its normal cone is every acceleration). */
static inline int sc_zero_set(const sc_problem *p, sc_int k) {
  const double *q = p->par + 3 * k;
  switch (p->kind[k]) {
    case K_BOX:
    case K_DISC: return !(q[0] > 0);
    case K_SPLIT: return !(q[2] > 0 && (q[0] > 0 || q[1] > 0));
    default: return 0;
  }
}

/* 1 if block k's rows do not accelerate (|w| within the acceptance tolerance). */
static inline int sc_still(const sc_problem *p, sc_int k) {
  sc_int i;
  for (i = 0; i < sc_block_size(p->kind[k]); ++i)
    if (fabs(p->w[p->start[k] + i]) > TOL_ACCEPT * p->wscale) return 0;
  return 1;
}

/* The face's rows (every block held or whose rows do not accelerate, but those whose set is
 * a single point: their forces are zero whatever the others') in F, their blocks in fk (at
 * most 512); returns their number. */
static inline sc_int sc_face_rows(const sc_problem *p, sc_int *F, sc_int *fk) {
  sc_int k, i, nf = 0;
  for (k = 0; k < p->nb; ++k) {
    if ((p->state[k] != S_HELD && !sc_still(p, k)) || sc_zero_set(p, k)) continue;
    for (i = 0; i < sc_block_size(p->kind[k]) && nf < 512; ++i) {
      fk[nf] = k;
      F[nf++] = p->start[k] + i;
    }
  }
  return nf;
}

/* (inline: the primal's piece is compiled per processor) A piece's parts for a solve in the
 * coordinates (scene_primal.c, scene_rescue.c): the held rows in hr (h), the sliding discs'
 * first rows in sl and their radii in rad (ns), their forces put on their discs' boundaries;
 * zero rows' forces 0; saturated boxes' forces at their bounds, applied in g_F = g + Z_i lam_i
 * (gF, n). With sd (2 per sliding disc: its rows' scales, 1), a sliding split ellipse is a disc
 * of radius 1 on its rows scaled by its semi-axes on its force's side (sd: those; its support
 * function there |D w|, its force -D u); without, returns 0 where the piece has one (not
 * treated there). Else 1. */
static inline int sc_piece_parts(sc_problem *p, sc_int n, const double *Z, const double *g,
                                 double *gF, sc_int *hr, sc_int *h, sc_int *sl, double *rad,
                                 sc_int *ns, double *sd) {
  const sc_int m = p->m;
  sc_int i, k;
  *h = *ns = 0;
  for (i = 0; i < n; ++i) gF[i] = g[i];
  for (k = 0; k < p->nb; ++k) {
    sc_int r = p->start[k], nk = sc_block_size(p->kind[k]);
    const double *par = p->par + 3 * k;
    double *l = p->lam + r;
    if (p->state[k] == S_ZERO) {
      for (i = 0; i < nk; ++i) l[i] = 0.0;
    } else if (p->state[k] == S_HELD) {
      for (i = 0; i < nk; ++i) hr[(*h)++] = r + i;
    } else if (p->kind[k] == K_BOX) {
      l[0] = l[0] >= 0 ? par[0] : -par[0];
      for (i = 0; i < n; ++i) gF[i] += Z[i * m + r] * l[0];
    } else if (p->kind[k] == K_DISC) {
      double nl = sqrt(l[0] * l[0] + l[1] * l[1]);
      if (!(nl > 0)) return 0;
      l[0] *= par[0] / nl; /* (the start: on the disc's boundary) */
      l[1] *= par[0] / nl;
      if (sd) sd[2 * *ns] = sd[2 * *ns + 1] = 1.0;
      rad[*ns] = par[0];
      sl[(*ns)++] = r;
    } else if (p->kind[k] == K_SPLIT && sd) { /* (on the ellipse's boundary) */
      const double d0 = l[0] < 0 ? par[0] : par[1], d1 = par[2],
                   nl = sqrt(l[0] * l[0] / (d0 * d0) + l[1] * l[1] / (d1 * d1));
      if (!(nl > 0) || !(d0 > 0 && d1 > 0)) return 0;
      l[0] /= nl, l[1] /= nl;
      sd[2 * *ns] = d0, sd[2 * *ns + 1] = d1;
      rad[*ns] = 1.0;
      sl[(*ns)++] = r;
    } else {
      return 0; /* a sliding split ellipse, or a sliding one-row block */
    }
  }
  return 1;
}

/* The solve's scales (scene_solve.c's scales) with the friction sets' sizes replaced by the
 * largest force of lam: where the sets are far larger than every force a sample asks
 * (|b_i| / G_ii) and holds (a torque 1e-10 of what friction holds), 1e-9 of their size is
 * more than all of the rows' accelerations and every piece meets it. 1 where that force scale
 * is below 1e-3 of F (*fs, *ws: the forces' and accelerations' scales; the answer is checked
 * again at them), shared by scene_solve.c and scene_tiny.c. dg: G's diagonal at stride. */
static inline int sc_tight_scales(sc_int m, const double *dg, sc_int stride, const double *b,
                                  const double *lam, double F, double *fs, double *ws) {
  double f = 0.0, w = 0.0;
  sc_int i;
  for (i = 0; i < m; ++i) {
    const double d = dg[i * stride];
    if (d > 0 && fabs(b[i]) / d > f) f = fabs(b[i]) / d;
    if (fabs(lam[i]) > f) f = fabs(lam[i]);
    if (fabs(b[i]) > w) w = fabs(b[i]);
  }
  if (!(f > 0) || !(f < 1e-3 * F)) return 0;
  for (i = 0; i < m; ++i)
    if (dg[i * stride] * f > w) w = dg[i * stride] * f;
  *fs = f;
  *ws = w;
  return 1;
}
#endif
