/* snakecg's engine: Coulomb friction at a general scene's contacts (optional: a scene's
 * contact coefficient mu_c, a body's own mu_contact), at rest and in a velocity-level step.
 *
 * A contact whose pair has mu > 0 gets a tangent row beside its normal row: w_t = t . (a_B -
 * a_A) at its two points, t = (-n_y, n_x) (sc_friction_row, called where scene_rows.c builds
 * the normal row). Coulomb's law on the rows' accelerations w = G lam + b (or a step's
 * velocities, with b the offsets' and h the sets' scale):
 *   lam_n >= 0, w_n >= 0, lam_n w_n = 0;  |lam_t| <= mu lam_n;
 *   stick: w_t = 0;  slip: lam_t = -mu lam_n sign(w_t).
 * The bound moves with lam_n, so the problem is not convex and is not one more set of the
 * convex solve: it is solved by a fixed point on the tangent rows' bounds (Panagiotopoulos'
 * successive approximation of Tresca problems):
 *   1. the tangent rows are BOX blocks of half-width s (s = 0 first: the frictionless
 *      answer); each inner problem is solved exactly by scene_solve.c's core_scene_solve_s;
 *   2. s <- mu lam_n(s) while the pieces (every block's state) change and it makes progress;
 *   3. once the pieces repeat, or the passes stall (the normal split between two nearly
 *      parallel rows, a peg by a joint, swings with the bounds), a semismooth Newton on
 *      R(s) = mu lam_n(s) - s (each evaluation an exact inner solve): its derivative on the
 *      present piece by differences of inner solves along the sliding contacts' s (lam_n is
 *      affine in s on a polyhedral piece; a sticking or open bound moves nothing), the step
 *      cut in halves until |R|^2 falls (Armijo), a relaxed pass where no cut does, until
 *      |mu lam_n - s| is rounding (FP_TOL of the forces' scale); not settled in FP_QUICK
 *      passes: a few candidates (5.); where they fail, the passes on to FP_MAX, then 1.-3.
 *      again from s = 10, 1, 0.1 times mu max|lam| (every contact sticking..), then the
 *      candidates, more;
 *   4. Coulomb's residuals apart from the final accelerations (w = A a + c: the normal
 *      complementarity, the cone, stick, slip against the sliding) into the certificate; not
 *      settled, or above TOL_ACCEPT: not solved (FR_NOT_SETTLED, NaN); solved, Coulomb's
 *      own piece checked (scene_family.c): where it leaves the forces a family with the same
 *      accelerations, its minimum-norm member taken (the dependent flag 1; 2 where it was
 *      not found, 0 where the forces are unique, whatever the last exact solve's rows);
 *   5. the candidates (scene_friction_states.c): the frictional contacts' states (open,
 *      stick, slip either way) fixed, each candidate's equations solved exactly (a slipping
 *      contact's normal force the unknown, its friction tied to it), accepted only where 4.'s
 *      residuals hold; an active set on the states from the last pass's, then the nearest.
 * Uniqueness. Coulomb problems can have several solutions, or none (Painleve). Where every
 * other block is polyhedral (contacts, bounded and ideal wheels, frictionless ground) and the
 * pieces are at most ENUM_MAX, every piece is enumerated (a frictional contact open, stick,
 * slip either way; a contact held or open; a wheel stick or slide either way), its linear
 * equations solved and kept where Coulomb's conditions hold: *solutions is the count of
 * distinct solutions (1: unique, certified), negated where some piece's equations were
 * singular (a family the count does not see, so uniqueness is not certified), 0 where not
 * enumerated (a Coulomb or anisotropic ground set, or too many pieces). A fixed point that
 * did not settle takes the enumeration's solution where it is the only one.
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_friction_states.h"
#include "scene_family.h"

#define FP_MAX 400      /* fixed-point and Newton passes from each start */
#define FP_QUICK 100    /* passes of the first start before a few candidates */
#define SAME_ROW 1e-8   /* two normal rows are one (bound_of's groups) within this */
#define FR_NOT_SETTLED 7 /* a sample's status: the fixed point did not settle */
enum { REC_MU = 13, REC_FT = 14, REC_ST = 15 }; /* a contact record's friction fields */

/* The pair's coefficient: the larger of the bodies' own (a link has none: -1), else the
 * scene's (snakecg.scenes.description.pair_mu). */
static double pair_mu(const double *pk, sc_int ia, sc_int ib) {
  const double *own = pk + (sc_int)pk[SP_MU];
  return own[ia] < 0 && own[ib] < 0 ? pk[SP_MUC] : fmax(own[ia], own[ib]);
}

void sc_friction_row(const double *pk, sc_int ia, sc_int ib, const double *nrm,
                     const double *Dx, const double *Dy, sc_int n, double *row, double *rec) {
  sc_int j;
  rec[REC_MU] = pair_mu(pk, ia, ib);
  for (j = 0; j < n; ++j) row[j] = -nrm[1] * Dx[j] + nrm[0] * Dy[j];
}

/* Rows a and b (n) equal to rounding. */
static int same_row(const double *a, const double *b, sc_int n) {
  double d = 0.0, big = 0.0;
  sc_int j;
  for (j = 0; j < n; ++j) {
    d = fmax(d, fabs(a[j] - b[j]));
    big = fmax(big, fmax(fabs(a[j]), fabs(b[j])));
  }
  return d <= SAME_ROW * big;
}

/* a = M^-1 (f + A^T lam) = L^-T (g + Z lam), with delassus' factors. */
static void accelerations(sc_int n, sc_int mt, const double *L, const double *Z,
                          const double *g, const double *lam, double *a) {
  sc_int i, j;
  for (i = 0; i < n; ++i) {
    double t = g[i];
    for (j = 0; j < mt; ++j) t += Z[j * n + i] * lam[j];
    a[i] = t;
  }
  for (i = n - 1; i >= 0; --i) {
    double t = a[i];
    for (j = i + 1; j < n; ++j) t -= L[j * n + i] * a[j];
    a[i] = t / L[i * n + i];
  }
}

/* The problem's G = A M^-1 A^T, b = A M^-1 f + c (mt rows) by M = L L^T, and the scales of
 * the forces and accelerations (as scene_solve.c's); 0 where M is not positive definite. */
static int delassus(sc_int n, sc_int mt, sc_int nbt, const double *M, const double *f,
                    const double *A, const double *c, const double *par, double *L, double *Z,
                    double *G, double *b, double *g, double *scale) {
  sc_int i, j, k;
  double fs = 0.0, ws = 0.0;
  memcpy(L, M, sizeof(double) * (size_t)(n * n));
  if (!sc_cholesky(n, L, n, 1e-14)) return 0;
  memcpy(g, f, sizeof(double) * (size_t)n);
  sc_lower_solve(n, L, g);
  for (j = 0; j < mt; ++j) { /* Z's column j: L^-1 A_j^T */
    double *z = Z + j * n;
    memcpy(z, A + j * n, sizeof(double) * (size_t)n);
    sc_lower_solve(n, L, z);
  }
  for (i = 0; i < mt; ++i) {
    b[i] = sc_dot(Z + i * n, g, n) + (c ? c[i] : 0.0);
    for (j = 0; j <= i; ++j) G[i * mt + j] = G[j * mt + i] = sc_dot(Z + i * n, Z + j * n, n);
  }
  for (i = 0; i < mt; ++i)
    if (G[i * mt + i] > 0 && fabs(b[i]) / G[i * mt + i] > fs) fs = fabs(b[i]) / G[i * mt + i];
  for (k = 0; k < nbt; ++k)
    for (i = 0; i < 3; ++i)
      if (isfinite(par[3 * k + i]) && fabs(par[3 * k + i]) > fs) fs = fabs(par[3 * k + i]);
  fs = fs > 0 ? fs : 1.0;
  for (i = 0; i < mt; ++i) ws = fmax(ws, fmax(fabs(b[i]), G[i * mt + i] * fs));
  scale[0] = fs;
  scale[1] = ws > 0 ? ws : 1.0;
  return 1;
}

/* Contacts whose normal rows are one (a peg at a joint touching both links' rounded ends)
 * share their normal force, split arbitrarily between them (statically indeterminate); as
 * each contact's friction is bounded by its own share, together they allow exactly
 * sum_k |lam_t,k| <= mu N (N their summed normal force), a slipping one's force against its
 * slip, and sum_k |lam_t,k| = mu N where every one slips. The group: contacts k with
 * lead[k] = its first. Contact j's bound: mu lam_n alone; in a group, its share of mu N in
 * proportion to the friction forces (equal shares where they are all 0). */
static double bound_of(sc_int j, sc_int nt, sc_int m, const sc_int *lead, const sc_int *rn,
                       const double *mu, const double *lam) {
  double N = 0.0, T = 0.0;
  sc_int k, g = lead[j], count = 0;
  for (k = g; k < nt; ++k)
    if (lead[k] == g) N += lam[rn[k]], T += fabs(lam[m + k]), ++count;
  if (count == 1) return mu[j] * lam[rn[j]];
  return mu[j] * N * (T > 0 ? fabs(lam[m + j]) / T : 1.0 / (double)count);
}

/* The minimum-norm member lam of a Coulomb family (pl: the solution's forces, a and w its
 * accelerations) kept: its accelerations pa = M^-1 (f + A^T lam) move from a by little (the
 * kinetic metric's |Z (lam - pl)| at most 5e-10 of sqrt(F W), as a convex face's loose
 * choice: the family's null space is G_FF's to DEP_TOL, nearly dependent rows taken as
 * dependent) and Coulomb's residuals hold at them; a and w are then lam's, res its
 * residuals. 0 where not (nothing changed). */
static int family_kept(sc_int n, sc_int mt, sc_int nt, sc_int m, const double *L,
                       const double *Z, const double *g, const double *c, const double *A,
                       const sc_int *rn, const sc_int *lead, const double *mu, const double *pl,
                       const double *lam, double *a, double *pa, double *pw, double *w,
                       const double *scale, double *res) {
  double quad = 0.0, r[3];
  sc_int i, j;
  for (i = 0; i < n; ++i) {
    double t = 0.0;
    for (j = 0; j < mt; ++j) t += Z[j * n + i] * (lam[j] - pl[j]);
    quad += t * t;
  }
  if (!(quad <= 25e-20 * scale[0] * scale[1])) return 0;
  accelerations(n, mt, L, Z, g, lam, pa);
  for (i = 0; i < mt; ++i) pw[i] = sc_dot(A + i * n, pa, n) + (c ? c[i] : 0.0);
  memcpy(r, res, sizeof r);
  sc_coulomb_residuals(m, nt, rn, lead, mu, lam, pw, scale, r);
  if (!(r[0] <= TOL_ACCEPT && r[1] <= TOL_ACCEPT && r[2] <= TOL_ACCEPT)) return 0;
  memcpy(a, pa, sizeof(double) * (size_t)n);
  memcpy(w, pw, sizeof(double) * (size_t)mt);
  memcpy(res, r, sizeof r);
  return 1;
}

/* The pieces of the last inner solve as the next one's start (core_scene_solve_s's `from`). */
static void pieces(sc_int nbt, const sc_int *kind, const sc_int *start, const double *st,
                   const double *lam, double *from) {
  sc_int k;
  for (k = 0; k < nbt; ++k) {
    from[3 * k] = st[k];
    from[3 * k + 1] = lam[start[k]];
    from[3 * k + 2] = sc_block_size(kind[k]) == 2 ? lam[start[k] + 1] : 0.0;
  }
}

/* The inner (Tresca) solve at the bounds s from the pieces `from`: core_scene_solve_s's code
 * (its Z and G held in p->kp: the same inertia and rows at every inner solve, the same bits),
 * 1 where it did not converge; rb the bounds it gives (bound_of), *r2 = |rb - s|^2, *F its
 * largest force. */
static int inner(const sc_fr_prob *p, const double *s, const double *from, double *lam,
                 double *a, double *w, double *st, double *info, double *rb, double *r2,
                 double *F) {
  sc_int j, i;
  int code;
  for (j = 0; j < p->nt; ++j) p->par[3 * (p->nb + j)] = s[j];
  code = sc_scene_solve_one(p->n, p->mt, p->nb + p->nt, p->M, p->f, p->A, p->c, p->kind,
                            p->start, p->par, p->sweeps, from, lam, a, w, st, info, 1, p->kp);
  if (code) return code;
  if (info[0] != 0.0) return 1;
  *F = 0.0, *r2 = 0.0;
  for (i = 0; i < p->mt; ++i) *F = fmax(*F, fabs(lam[i]));
  for (j = 0; j < p->nt; ++j) {
    rb[j] = bound_of(j, p->nt, p->m, p->lead, p->rn, p->mu, lam);
    *r2 += (rb[j] - s[j]) * (rb[j] - s[j]);
  }
  return 0;
}

int sc_friction_solve(sc_int n, sc_int m, sc_int nb, sc_int nc, const double *M,
                      const double *f, double *A, double *c, sc_int *kind, sc_int *start,
                      double *par, const double *T, double *rec, sc_int sweeps,
                      const double *from, double *lam, double *a, double *w, double *st,
                      double *info, double *solutions) {
  sc_int nt = 0, k, j, i, it, mt, nbt, *iw, *tc, *rn, *piv, *slide, *lead, ns;
  double *d, *mu, *s, *fr, *L, *Z, *G, *b, *g, *pl, *pw, *pa, *pst, *pinfo, *D, *rhs, *r0,
      *sv, *rb, *dv, *Dss, scale[2], res[3];
  sc_enum e;
  sc_fr_prob pr;
  sc_solve_keep kp = {0};
  int code = 0, ok = 0, same, stall = 0, newton = 0, restarts = 0, cands = 0, taken = 0;
  double omega = 1.0, best = INFINITY; /* the passes' relaxation (halved where they stall) */
  double r2k = 0.0, Fk = 0.0; /* (the line search's last inner solve's, where taken) */
  *solutions = 0.0;
  if (!T) /* no contact friction in the scene: the convex solve alone */
    return SNAKECG_EXPORT(core_scene_solve_s)(n, m, nb, M, f, A, c, kind, start, par, sweeps,
                                              from, lam, a, w, st, info);
  for (k = 0; k < nc; ++k) { /* contact k's tangent row m + k: a BOX block after the ground's
    (of size 0 where the pair has no friction) */
    rec[CR_W * k + REC_FT] = rec[CR_W * k + REC_ST] = 0.0;
    if (T + k * n != A + (m + k) * n) /* (the forward's; a step's rows have them in place) */
      memcpy(A + (m + k) * n, T + k * n, sizeof(double) * (size_t)n);
    kind[nb + k] = K_BOX;
    start[nb + k] = m + k;
    par[3 * (nb + k)] = par[3 * (nb + k) + 1] = par[3 * (nb + k) + 2] = 0.0;
    lam[m + k] = 0.0;
    if (c) c[m + k] = 0.0;
    nt += rec[CR_W * k + REC_MU] > 0;
  }
  if (nt == 0) { /* no frictional contact here: convex, the accelerations unique */
    *solutions = 1.0;
    return SNAKECG_EXPORT(core_scene_solve_s)(n, m, nb, M, f, A, c, kind, start, par, sweeps,
                                              from, lam, a, w, st, info);
  }
  nt = nc, mt = m + nt, nbt = nb + nt;
  d = (double *)malloc(sizeof(double) * (size_t)(7 * nt + 3 * nt * nt + 16 * nbt + n * n +
                                                 2 * n * mt + 4 * mt * mt + 10 * mt + 4 * n +
                                                 SOL_MAX * n + 16));
  iw = (sc_int *)malloc(sizeof(sc_int) * (size_t)(3 * nbt + 3 * nt + 2 * mt + 8));
  kp.Z = (double *)malloc(sizeof(double) * (size_t)(n * mt + 2 * mt * mt + mt)); /* (Z, G,
    then the minimum-norm choice's null space and dual point: nearly every inner solve's
    choice is on one face) */
  kp.face.face = (sc_int *)malloc(sizeof(sc_int) * (size_t)mt);
  kp.pieces = sc_piece_keep_new(mt, nbt); /* (and the last pieces' factors) */
  if (!d || !iw || !kp.Z || !kp.face.face || !kp.pieces) goto done;
  kp.G = kp.Z + n * mt;
  kp.face.v = kp.G + mt * mt, kp.face.mu = kp.face.v + mt * mt, kp.face.nf = -1;
  kp.face.cap = mt, kp.face.has_mu = 0;
  mu = d, s = mu + nt, r0 = s + nt, rhs = r0 + nt, sv = rhs + nt, rb = sv + nt, dv = rb + nt;
  Dss = dv + nt, fr = Dss + nt * nt, L = fr + 3 * nbt;
  Z = L + n * n, G = Z + n * mt, b = G + mt * mt, g = b + mt, pl = g + n, pw = pl + mt;
  pa = pw + mt, pst = pa + n, pinfo = pst + nbt, D = pinfo + 8; /* (pinfo: INFO_WIDTH) */
  e.K = D + nt * nt, e.Kc = e.K + mt * mt, e.S = e.Kc + mt * mt, e.x = e.S + (mt + n) * mt;
  e.y = e.x + mt, e.ys = e.y + n, e.c0 = e.ys + SOL_MAX * n, e.c1 = e.c0 + 6 * nbt;
  e.qw = e.c1 + 6 * nbt, e.best = e.qw + 5 * mt + n;
  tc = iw, rn = tc + nbt, piv = rn + nt, slide = piv + mt;
  e.opt = slide + nt, e.digit = e.opt + nbt, lead = e.digit + nbt;
  for (k = 0; k < nbt; ++k) tc[k] = -1;
  for (k = 0; k < nc; ++k) { /* (tc: the contact's tangent where it has friction) */
    tc[k] = rec[CR_W * k + REC_MU] > 0 ? k : -1;
    rn[k] = start[k], mu[k] = fmax(0.0, rec[CR_W * k + REC_MU]), s[k] = 0.0, lead[k] = k;
    for (j = 0; j < k && tc[k] >= 0; ++j) /* one normal row: the first one's group */
      if (tc[j] >= 0 && lead[j] == j && mu[j] == mu[k] &&
          same_row(A + rn[j] * n, A + rn[k] * n, n)) {
        lead[k] = j;
        break;
      }
  }
  pr.n = n, pr.mt = mt, pr.nb = nb, pr.nt = nt, pr.m = m, pr.sweeps = sweeps, pr.M = M;
  pr.f = f, pr.A = A, pr.c = c, pr.kind = kind, pr.start = start, pr.par = par, pr.mu = mu;
  pr.lead = lead, pr.rn = rn, pr.kp = &kp;
  it = 0;
passes:
  for (; it < 4 * FP_MAX; ++it) {
    double F = 0.0, err = 0.0, r2 = 0.0, r2t = 0.0, Ft = 0.0, t = 1.0;
    if (it == FP_QUICK && !cands) { /* not settled yet: a few candidates (below) */
      taken = 0;
      break;
    }
    if (it && it % FP_MAX == 0) /* then again from s = 10, 1, 0.1 mu |lam| */
      for (j = 0, ++restarts, newton = stall = taken = 0, omega = 1.0, best = INFINITY; j < nt;
           ++j)
        s[j] = 10.0 * pow(0.1, (double)(restarts - 1)) * mu[j] * sc_max_abs(lam, mt);
    if (taken) { /* the line search's last inner solve: at this s, from these pieces */
      memcpy(lam, pl, sizeof(double) * (size_t)mt), memcpy(w, pw, sizeof(double) * (size_t)mt);
      memcpy(a, pa, sizeof(double) * (size_t)n), memcpy(st, pst, sizeof(double) * (size_t)nbt);
      memcpy(info, pinfo, sizeof(double) * 8), memcpy(r0, rb, sizeof(double) * (size_t)nt);
      r2 = r2k, F = Fk, taken = 0;
    } else if ((code = inner(&pr, s, it ? fr : NULL, lam, a, w, st, info, r0, &r2, &F)))
      break;
    for (j = 0; j < nt; ++j) err = fmax(err, fabs(r0[j] - s[j]));
    if (err <= FP_TOL * F) {
      ok = 1;
      break;
    }
    if (err < 0.9 * best) best = err, stall = 0; /* progress */
    else if (++stall >= 6) /* no progress in 6 passes (a cycle of pieces): Newton, relaxed */
      omega = fmax(0.5 * omega, 1.0 / 1024), stall = 0, best = err, newton = 1;
    same = it > 0;
    for (k = 0; k < nbt && same; ++k) same = fr[3 * k] == st[k];
    pieces(nbt, kind, start, st, lam, fr);
    newton |= same;
    for (j = ns = 0; j < nt; ++j) /* the sliding tangents (on the bound, s > 0) */
      if (st[nb + j] == 3.0 || st[nb + j] == 4.0) slide[ns++] = j;
    if (!newton || ns == 0) { /* s <- mu lam_n */
      for (j = 0; j < nt; ++j) s[j] += omega * (r0[j] - s[j]);
      continue;
    }
    /* Newton on R(s) = bound(s) - s (3. of the header), a line search on |R|^2 */
    for (i = 0; i < ns; ++i) {
      sc_int q = slide[i];
      double h = 1e-7 * fmax(s[q], F);
      memcpy(sv, s, sizeof(double) * (size_t)nt);
      sv[q] += h;
      if (inner(&pr, sv, fr, pl, pa, pw, pst, pinfo, rb, &r2t, &Ft)) break;
      for (j = 0; j < nt; ++j) D[j * ns + i] = (rb[j] - r0[j]) / h;
    }
    for (j = 0; i == ns && j < ns; ++j) {
      for (k = 0; k < ns; ++k) Dss[j * ns + k] = D[slide[j] * ns + k] - (j == k);
      dv[j] = -(r0[slide[j]] - s[slide[j]]);
    }
    if (i < ns || !sc_lu_factor(ns, Dss, ns, piv)) { /* a relaxed pass */
      for (j = 0; j < nt; ++j) s[j] += omega * (r0[j] - s[j]);
      continue;
    }
    sc_lu_solve(ns, Dss, ns, piv, dv);
    for (j = 0; j < nt; ++j) /* the step: the others' s to their linearized bounds */
      for (rhs[j] = r0[j] - s[j], k = 0; k < ns; ++k) rhs[j] += D[j * ns + k] * dv[k];
    for (k = 0; k < ns; ++k) rhs[slide[k]] = dv[k];
    for (i = 0; i < 30; ++i, t *= 0.5) {
      for (j = 0; j < nt; ++j) sv[j] = fmax(0.0, s[j] + t * rhs[j]);
      if (!inner(&pr, sv, fr, pl, pa, pw, pst, pinfo, rb, &r2t, &Ft) &&
          r2t <= (1.0 - 1e-4 * t) * r2)
        break;
    }
    if (i < 30) { /* (its inner solve is the next pass's) */
      memcpy(s, sv, sizeof(double) * (size_t)nt);
      r2k = r2t, Fk = Ft, taken = 1;
    } else
      for (j = 0; j < nt; ++j) s[j] += omega * (r0[j] - s[j]);
  }
  if (code == -1) goto done;
  scale[0] = scale[1] = 1.0;
  if (!delassus(n, mt, nbt, M, f, A, c, par, L, Z, G, b, g, scale)) ok = 0;
  else {
    int count;
    e.n = n, e.m = m, e.nb = nb, e.nt = nt, e.kind = kind, e.start = start, e.tc = tc;
    e.par = par, e.mu = mu, e.G = G, e.b = b, e.Z = Z, e.g = g, e.scale = scale, e.piv = piv;
    count = sc_friction_enumerate(&e);
    *solutions = (double)count;
    if (!ok && count == 1) { /* the one solution, where the fixed point did not settle */
      memcpy(lam, e.best, sizeof(double) * (size_t)mt);
      accelerations(n, mt, L, Z, g, lam, a);
      for (k = 0; k < nbt; ++k) { /* the states read off the solution */
        double l = lam[start[k]];
        st[k] = kind[k] == K_UNILATERAL ? (l > 0 ? S_HELD : S_ZERO) :
                kind[k] == K_BOX && par[3 * k] > 0 && fabs(l) >= par[3 * k] ? (l > 0 ? 3 : 4) :
                S_HELD;
      }
      info[0] = 0.0, info[2] = info[3] = info[4] = 0.0;
      ok = 1;
    }
    if (!ok) { /* the contacts' candidate states solved exactly (5. of the header;
      scene_friction_states.c): a few after the first start, where they fail the restarts, then
      more */
      ok = sc_friction_states(&pr, scale, it > 0 ? fr : NULL, cands ? 0 : 1, lam, a, w, st,
                              info);
      if (!ok && !cands++ && it == FP_QUICK) goto passes;
    }
  }
  if (ok) { /* Coulomb's residuals apart, from the accelerations: w = A a + c */
    int moved = 0;
    for (i = 0; i < mt; ++i) w[i] = sc_dot(A + i * n, a, n) + (c ? c[i] : 0.0);
    for (j = 0; j < nc; ++j) { /* a group's normal force split as Coulomb allows it: a
      slipping contact |lam_t| / mu, the sticking ones the rest in equal parts */
      double N = 0.0, need = 0.0;
      sc_int count = 0, stick = 0;
      if (lead[j] != j || !(mu[j] > 0)) continue;
      for (k = j; k < nc; ++k)
        if (lead[k] == j) {
          N += lam[rn[k]], need += fabs(lam[m + k]) / mu[j], ++count;
          stick += !(fabs(w[m + k]) > TOL_ACCEPT * scale[1]);
        }
      for (k = j; count > 1 && k < nc; ++k)
        if (lead[k] == j) {
          int sticks = !(fabs(w[m + k]) > TOL_ACCEPT * scale[1]);
          lam[rn[k]] = fabs(lam[m + k]) / mu[j] + (sticks ? fmax(0.0, N - need) / stick : 0.0);
          st[k] = lam[rn[k]] > 0 ? S_HELD : S_ZERO;
          moved = 1;
        }
    }
    if (moved) { /* (the rows equal to within SAME_ROW: the accelerations again) */
      accelerations(n, mt, L, Z, g, lam, a);
      for (i = 0; i < mt; ++i) w[i] = sc_dot(A + i * n, a, n) + (c ? c[i] : 0.0);
    }
    res[0] = info[2], res[1] = info[3], res[2] = info[4];
    sc_coulomb_residuals(m, nt, rn, lead, mu, lam, w, scale, res);
    info[2] = res[0], info[3] = res[1], info[4] = res[2];
    ok = res[0] <= TOL_ACCEPT && res[1] <= TOL_ACCEPT && res[2] <= TOL_ACCEPT;
    if (ok && info[1] != 3.0) { /* Coulomb's own piece (scene_family.c), whatever the last
      exact solve's rows: a family of forces (a contact sticking at its cone's edge, bounded
      as a saturated box by the fixed point; a slip candidate's normal force that no row's
      acceleration reads; dependent rows), its minimum-norm member, kept where its
      accelerations are the same to rounding and Coulomb's residuals hold */
      const sc_family fam = {mt, nb, nt, m, kind, start, rn, par, mu, G, w, scale[0], scale[1]};
      int chosen;
      sc_int def;
      memcpy(pl, lam, sizeof(double) * (size_t)mt);
      if ((def = sc_coulomb_family(&fam, lam, &chosen)) < 0) {
        code = -1;
        goto done;
      }
      if (chosen && !family_kept(n, mt, nt, m, L, Z, g, c, A, rn, lead, mu, pl, lam, a, pa, pw,
                                 w, scale, res)) {
        memcpy(lam, pl, sizeof(double) * (size_t)mt);
        chosen = 0;
      }
      for (k = 0; chosen && k < nb; ++k) /* (a contact's state: held where it now pushes) */
        if (kind[k] == K_UNILATERAL && lam[start[k]] != pl[start[k]])
          st[k] = lam[start[k]] > 0 ? S_HELD : S_ZERO;
      info[1] = def == 0 ? 0.0 : chosen ? 1.0 : 2.0, info[7] = (double)def;
      info[2] = res[0], info[3] = res[1], info[4] = res[2];
    }
  }
  if (!ok) { /* (an inner solve's own status kept: not converged, a singular mass matrix) */
    if (info[0] == 0.0) info[0] = FR_NOT_SETTLED;
    for (i = 0; i < n; ++i) a[i] = NAN;
    for (i = 0; i < mt; ++i) lam[i] = NAN;
  }
  for (k = 0; k < nc; ++k) { /* the contacts' state (open where it pushes not and opens:
    a reading of held at zero force is the inner solve's), friction force and its state */
    if (ok && kind[k] == K_UNILATERAL && !(lam[rn[k]] > 0) && w[rn[k]] > TOL_ACCEPT * scale[1])
      st[k] = S_ZERO;
    if (mu[k] > 0) {
      rec[CR_W * k + REC_FT] = lam[m + k];
      rec[CR_W * k + REC_ST] = !(lam[rn[k]] > 0) ? 1.0 : fabs(w[m + k]) > TOL_ACCEPT *
                               scale[1] ? 2.0 : 0.0;
    }
  }
  code = 0;
done:
  free(d);
  free(iw);
  free(kp.Z);
  free(kp.face.face);
  free(kp.pieces);
  return d && iw && kp.Z && kp.face.face && kp.pieces ? code : -1;
}
