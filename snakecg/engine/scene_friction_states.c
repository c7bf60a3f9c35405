/* snakecg's engine: Coulomb friction at a general scene's contacts, the pieces' side
 * (scene_friction.c: the fixed point on the tangent rows' bounds, whose notation this file
 * keeps; scene_friction_states.h: what the two share).
 *
 * 1. Coulomb's residuals of a solution, apart from the method that found it.
 * 2. The enumeration of every piece (scene_friction.c's header: uniqueness), where every
 *    block is polyhedral and the pieces are at most ENUM_MAX.
 * 3. The candidates (sc_friction_states), where the fixed point did not settle (its passes
 *    swing between a contact's stick and slip pieces, or between two nearly parallel
 *    contacts' loads): the frictional contacts' states fixed (open, stick, slip either way),
 *    each candidate's equations are solved exactly: an open contact's forces 0, a sticking
 *    one's normal and tangent rows held (bilateral), a slipping one's normal force s the
 *    unknown, applied with its friction -+ mu s along its tangent (Coulomb's slip law exact,
 *    whatever the rounding: with two nearly parallel rows the normal forces are ill-conditioned
 *    but the rows' w are not), the other blocks (frictionless contacts, the ground's sets) as
 *    the convex solve has them; its normal row's w_n(s) = 0 solved by Newton on s (w_n is
 *    affine in s on a piece of the other blocks, smooth on a sliding disc's: one or a few
 *    steps), each evaluation one exact convex solve (at most CAND_SWEEPS sweeps). A group of
 *    equal normal rows (scene_friction.c's bound_of) is one contact: its forces on its
 *    first's rows. A candidate is accepted only where Coulomb's residuals (1., from the
 *    accelerations) and the convex solve's own hold within TOL_ACCEPT. Tried: an active set
 *    on the states from the last pass's (the contacts whose conditions fail switched as they
 *    ask; where that comes back to a candidate, only the worst one), every contact sticking,
 *    then the candidates in order of how many contacts' states differ from the last pass's
 *    (0, 1, 2, ..), at most CAND_QUICK after the fixed point's first start's FP_QUICK
 *    passes, CAND_MAX after its restarts.
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_friction_states.h"

#define ENUM_MAX 4096   /* pieces enumerated for the uniqueness check */
#define ENUM_TOL 1e-9   /* a piece's solution meets Coulomb's conditions within this */
#define SAME_TOL 1e-7   /* two solutions are one within this of the forces' scale */
#define CAND_MAX 1100   /* candidates tried (every one of up to 5 contacts) */
#define CAND_NEWTON 40  /* Newton steps on a candidate's slipping contacts' normal forces */
#define CAND_QUICK 16   /* of them, after the fixed point's first start */
#define CAND_SWEEPS 1000 /* a candidate's solve: at most these sweeps (else not solved) */
#define GUIDED_MAX 32   /* active-set passes on the contacts' states */

/* Coulomb's residuals of (lam, w) on the frictional contacts (normal rows rn[j], tangent rows
 * m + j), relative to the scales: res[0] primal (a normal force below 0, a tangent force
 * outside the cone), res[1] dual (a normal row that accelerates into the contact, a sliding
 * tangent row whose force is not -mu lam_n sign(w_t)), res[2] complementarity (lam_n w_n);
 * a group's (bound_of) on its summed forces. */
void sc_coulomb_residuals(sc_int m, sc_int nt, const sc_int *rn, const sc_int *lead,
                          const double *mu, const double *lam, const double *w,
                          const double *scale, double *res) {
  const double F = scale[0], W = scale[1];
  sc_int j, k;
  for (j = 0; j < nt; ++j) {
    double ln = lam[rn[j]], lt = lam[m + j], wn = w[rn[j]], wt = w[m + j], N = 0.0, T = 0.0;
    int count = 0, slips = 0;
    res[1] = fmax(res[1], fmax(0.0, -wn) / W);
    res[2] = fmax(res[2], fabs(ln * wn) / (F * W));
    res[0] = fmax(res[0], fmax(0.0, -ln) / F);
    if (lead[j] != j) continue; /* (a group: at its first) */
    for (k = j; k < nt; ++k) {
      if (lead[k] != j) continue;
      N += lam[rn[k]], T += fabs(lam[m + k]), ++count;
      if (fabs(w[m + k]) > TOL_ACCEPT * W) { /* slip: the force against it */
        ++slips;
        res[1] = fmax(res[1], fmax(0.0, lam[m + k] * (w[m + k] > 0 ? 1.0 : -1.0)) / F);
      }
    }
    res[0] = fmax(res[0], fmax(0.0, T - mu[j] * N) / F);
    if (count == 1 && slips) /* at the cone's edge */
      res[1] = fmax(res[1], fabs(lt + (wt > 0 ? mu[j] : -mu[j]) * ln) / F);
    else if (slips == count)
      res[1] = fmax(res[1], fabs(T - mu[j] * N) / F);
  }
}


/* The piece digit[]'s equations: K x = x (in place): w_r = 0 where held or sticking, else the
 * force fixed (0 open, +-p a wheel sliding, -+ mu lam_n a contact slipping as w_t > 0, < 0). */
static void piece_equations(sc_enum *e) {
  const sc_int m = e->m, mt = m + e->nt;
  sc_int k, r, u;
  memset(e->K, 0, sizeof(double) * (size_t)(mt * mt));
  for (u = m; u < mt; ++u) e->K[u * mt + u] = 1.0, e->x[u] = 0.0; /* no friction: 0 */
  for (k = 0; k < e->nb; ++k) {
    const sc_int kd = e->kind[k], dg = e->digit[k], t = e->tc[k];
    const double p = e->par[3 * k];
    r = e->start[k];
    u = t >= 0 ? m + t : -1;
    e->x[r] = -e->b[r];
    if (kd == K_BOX && (dg > 0 || !(p > 0))) {
      e->K[r * mt + r] = 1.0;
      e->x[r] = !(p > 0) ? 0.0 : dg == 1 ? p : -p;
    } else if (kd == K_UNILATERAL && dg == (t >= 0 ? 0 : 1)) {
      e->K[r * mt + r] = 1.0, e->x[r] = 0.0; /* open */
    } else {
      memcpy(e->K + r * mt, e->G + r * mt, sizeof(double) * (size_t)mt);
    }
    if (u < 0 || dg == 0) continue; /* (open: no tangent force) */
    if (dg == 1) { /* stick */
      e->x[u] = -e->b[u];
      memcpy(e->K + u * mt, e->G + u * mt, sizeof(double) * (size_t)mt);
    } else { /* slip */
      e->K[u * mt + u] = 1.0;
      e->K[u * mt + r] = dg == 2 ? e->mu[t] : -e->mu[t];
    }
  }
}

/* Coulomb's conditions on a piece's solution x as margins (out, >= 0 where met within
 * ENUM_TOL of the scales; every one affine in x); their count. */
static sc_int piece_margins(const sc_enum *e, const double *x, double *out) {
  const sc_int m = e->m, mt = m + e->nt;
  const double F = e->scale[0], W = e->scale[1];
  sc_int k, q = 0;
  for (k = 0; k < e->nb; ++k) {
    const sc_int r = e->start[k], dg = e->digit[k], t = e->tc[k];
    const double l = x[r], wr = e->b[r] + sc_dot(e->G + r * mt, x, mt), p = e->par[3 * k];
    if (e->kind[k] == K_UNILATERAL) {
      out[q++] = l / F + ENUM_TOL;
      out[q++] = wr / W + ENUM_TOL;
    }
    if (e->kind[k] == K_BOX && p > 0 && dg == 0) {
      out[q++] = (p - l) / F + ENUM_TOL;
      out[q++] = (p + l) / F + ENUM_TOL;
    } else if (e->kind[k] == K_BOX && p > 0) {
      out[q++] = (dg == 1 ? -wr : wr) / W + ENUM_TOL;
    }
    if (t >= 0 && dg > 0) {
      const double lt = x[m + t], wt = e->b[m + t] + sc_dot(e->G + (m + t) * mt, x, mt);
      if (dg == 1) {
        out[q++] = (e->mu[t] * l - lt) / F + ENUM_TOL;
        out[q++] = (e->mu[t] * l + lt) / F + ENUM_TOL;
      } else {
        out[q++] = (dg == 2 ? wt : -wt) / W + ENUM_TOL;
      }
    }
  }
  return q;
}

static int piece_feasible(const sc_enum *e) {
  sc_int i, q = piece_margins(e, e->x, e->c0);
  for (i = 0; i < q; ++i)
    if (e->c0[i] < 0) return 0;
  return 1;
}

/* y = g + Z x: the accelerations in the inertia's metric (a = L^-T y); index of the one in
 * list (count) it equals, or -1. Equal within SAME_TOL of the larger of the accelerations
 * and a floor from the problem's data, never from the answer alone: sqrt(F W), F and W the
 * forces' and the rows' accelerations' scales (e->scale: the certificate's, as scene_solve.c's
 * scales() and scene_friction.c's delassus() define them). It is those two scales in the
 * metric of y: a force dl on row j moves y by Z_j dl, |Z_j| = sqrt(G_jj) <= sqrt(W / F), so
 * forces within the margins' tolerance of F (piece_margins) move y by at most that tolerance
 * of sqrt(F W). Without it, where the true accelerations are ~0 (a torque of 1e-16 on a
 * scene whose wheels' bounds set F) every piece meets its margins within rounding and their
 * solutions, apart by rounding alone, counted as distinct solutions. Homogeneous of degree 1
 * in (f, the sets' sizes): the count does not move when both are scaled together. */
static sc_int same_as(const sc_enum *e, const double *list, sc_int count) {
  sc_int j, i;
  double big = fmax(sc_max_abs(e->g, e->n), sqrt(e->scale[0] * e->scale[1]));
  for (i = 0; i < e->n; ++i) {
    double t = e->g[i];
    for (j = 0; j < e->m + e->nt; ++j) t += e->Z[j * e->n + i] * e->x[j];
    e->y[i] = t;
    big = fmax(big, fabs(t));
  }
  for (j = 0; j < count && j < SOL_MAX; ++j) {
    double d = 0.0;
    for (i = 0; i < e->n; ++i) d = fmax(d, fabs(e->y[i] - list[j * e->n + i]));
    if (d <= SAME_TOL * big) return j;
  }
  return -1;
}

/* A singular piece (its equations in e->Kc, right-hand side in e->qw + mt): 1 where its
 * solutions fix the accelerations and a point of them meets Coulomb's conditions (in e->x),
 * 0 where it has none (inconsistent, or a one-parameter family none of whose points meets
 * them), -1 where it cannot tell (the accelerations vary on it, or a larger family). By the
 * SVD: the least-norm point x0 and the null space N; on a line x0 + z h v the margins are
 * affine in z, so their interval is exact. The step h is the forces' scale F (data, as the
 * margins'): a margin's change over it is dimensionless, so the test of a slope that is 0
 * to rounding reads alike at every scale of the problem (a step of 1 in force units is 1e14 F
 * at a torque of 1e-16, where rounding read as a slope and a bound 1e8 F away). The point
 * kept: the one of the interval without the margins' tolerance nearest x0 (the family's
 * accelerations are fixed only to rounding, so not far along it), else the tolerance
 * interval's middle. */
static int singular_piece(sc_enum *e) {
  const sc_int mt = e->m + e->nt, n = e->n;
  double *U = e->S, *V = e->K, *sv = e->qw, *rhs = e->qw + mt, *v = e->qw + 2 * mt, smax = 0.0,
         res = 0.0, lo = -INFINITY, hi = INFINITY, lo0 = -INFINITY, hi0 = INFINITY,
         h = e->scale[0];
  sc_int i, j, null = 0, q;
  for (i = 0; i < mt; ++i)
    for (j = 0; j < mt; ++j) U[j * mt + i] = e->Kc[i * mt + j]; /* columns of K */
  sc_svd_jacobi(mt, mt, U, mt, V, sv);
  for (j = 0; j < mt; ++j) smax = fmax(smax, sv[j]);
  sc_svd_least_norm(mt, mt, U, mt, V, sv, rhs, 1e-10, 0, e->x);
  for (i = 0; i < mt; ++i) res = fmax(res, fabs(sc_dot(e->Kc + i * mt, e->x, mt) - rhs[i]));
  if (res > 1e-9 * fmax(sc_max_abs(rhs, mt), smax * sc_max_abs(e->x, mt))) return 0;
  for (j = 0; j < mt; ++j) {
    double zn = 0.0, zs = 0.0;
    if (sv[j] > 1e-10 * smax) continue;
    ++null;
    memcpy(v, V + j * mt, sizeof(double) * (size_t)mt);
    for (i = 0; i < n; ++i) { /* the accelerations along v: Z v */
      double t = 0.0;
      sc_int k;
      for (k = 0; k < mt; ++k) t += e->Z[k * n + i] * v[k];
      zn = fmax(zn, fabs(t));
    }
    for (i = 0; i < n * mt; ++i) zs = fmax(zs, fabs(e->Z[i]));
    if (zn > 1e-9 * zs) return -1;
  }
  if (piece_feasible(e)) return 1;
  if (null != 1) return -1;
  q = piece_margins(e, e->x, e->c0); /* the margins along x0 + z h v (v: the last) */
  for (i = 0; i < mt; ++i) rhs[i] = e->x[i] + h * v[i];
  piece_margins(e, rhs, e->c1);
  for (i = 0; i < q; ++i) {
    const double s = e->c1[i] - e->c0[i], c = e->c0[i], c0 = c - ENUM_TOL; /* (c0: without
      the tolerance) */
    if (fabs(s) <= 1e-15 * (1 + fabs(c))) {
      if (c < 0) return 0;
      if (c0 < 0) lo0 = INFINITY;
    } else if (s > 0) {
      lo = fmax(lo, -c / s), lo0 = fmax(lo0, -c0 / s);
    } else {
      hi = fmin(hi, -c / s), hi0 = fmin(hi0, -c0 / s);
    }
  }
  if (!(lo <= hi)) return 0;
  {
    double z = lo0 <= hi0 ? fmin(fmax(0.0, lo0), hi0) : isfinite(lo) && isfinite(hi) ?
               0.5 * (lo + hi) : fmin(fmax(0.0, lo), hi);
    for (i = 0; i < mt; ++i) e->x[i] += z * h * v[i];
  }
  return 1;
}

/* The enumeration of every piece (header): the count of distinct accelerations that meet
 * Coulomb's conditions, negated where a piece may hold others it cannot tell (singular_piece's
 * -1), 0 where not enumerated; the first solution's forces in e->best. */
int sc_friction_enumerate(sc_enum *e) {
  const sc_int mt = e->m + e->nt;
  sc_int k, i, found = 0, total = 1, combo;
  int unsure = 0;
  for (k = 0; k < e->nb; ++k) { /* the pieces per block */
    const sc_int kd = e->kind[k];
    if (kd == K_FREE) e->opt[k] = 1;
    else if (kd == K_UNILATERAL) e->opt[k] = e->tc[k] >= 0 ? 4 : 2;
    else if (kd == K_BOX) e->opt[k] = e->par[3 * k] > 0 ? 3 : 1;
    else return 0; /* a conic set: not enumerated */
    if (total > ENUM_MAX / e->opt[k]) return 0;
    total *= e->opt[k];
  }
  for (combo = 0; combo < total; ++combo) {
    sc_int rest = combo;
    double big = 0.0, small = INFINITY;
    int regular;
    for (k = 0; k < e->nb; ++k) {
      e->digit[k] = rest % e->opt[k];
      rest /= e->opt[k];
    }
    piece_equations(e);
    memcpy(e->Kc, e->K, sizeof(double) * (size_t)(mt * mt));
    memcpy(e->qw + mt, e->x, sizeof(double) * (size_t)mt); /* (the right-hand side) */
    regular = sc_lu_factor(mt, e->K, mt, e->piv);
    for (i = 0; regular && i < mt; ++i) {
      big = fmax(big, fabs(e->K[i * mt + i]));
      small = fmin(small, fabs(e->K[i * mt + i]));
    }
    if (regular && small > 1e-12 * big) {
      sc_lu_solve(mt, e->K, mt, e->piv, e->x);
      if (!piece_feasible(e)) continue;
    } else {
      int got = singular_piece(e);
      if (got < 0) unsure = 1;
      if (got <= 0) continue;
    }
    if (same_as(e, e->ys, found) >= 0) continue;
    if (found == 0) memcpy(e->best, e->x, sizeof(double) * (size_t)mt);
    if (found < SOL_MAX) memcpy(e->ys + e->n * found, e->y, sizeof(double) * (size_t)e->n);
    ++found;
  }
  return (int)(unsure ? -found : found);
}


/* ---- 3. the candidates ------------------------------------------------------------------ */
/* One candidate's scratch: the frictional contacts list[nf] (contact indices), the base
 * digits d0 and the candidate's dg (0 open, 1 stick, 2 slip with w_t > 0: lam_t = -mu lam_n,
 * 3 slip with w_t < 0: lam_t = +mu lam_n), the slipping ones' normal forces s, R their
 * normal rows' w; two solutions (the present one and a trial) swapped by pointers. */
typedef struct {
  const sc_fr_prob *p;
  const double *scale, *from;
  sc_int nf, ns, sweeps, *list, *d0, *dg, *slip, *piv;
  double *fm, *s, *sv, *ds, *D, *R, *R2, *l0, *sol[2][5];
} sc_cand;

enum { C_LAM = 0, C_A, C_W, C_ST, C_INFO };

/* The candidate's exact solve at the slipping contacts' normal forces s (each applied with
 * its friction: s along the normal row, -+ mu s along the tangent row; Coulomb's slip law
 * exact, whatever the rounding of the solve) into solution `into`: R the slipping contacts'
 * w_n (A a + c); 1 where solved. */
static int cand_solve(sc_cand *c, const double *s, int into, double *R) {
  const sc_fr_prob *p = c->p;
  const sc_int n = p->n;
  double **x = c->sol[into];
  sc_int i, j;
  memcpy(c->fm, p->f, sizeof(double) * (size_t)n);
  for (i = 0; i < c->ns; ++i) {
    const sc_int k = c->list[c->slip[i]];
    const double lt = (c->dg[c->slip[i]] == 2 ? -p->mu[k] : p->mu[k]) * s[i],
                 *an = p->A + p->rn[k] * n, *t = p->A + (p->m + k) * n;
    for (j = 0; j < n; ++j) c->fm[j] += s[i] * an[j] + lt * t[j];
  }
  if (sc_scene_solve_one(n, p->mt, p->nb + p->nt, p->M, c->fm, p->A, p->c, p->kind, p->start,
                         p->par, c->sweeps, c->from, x[C_LAM], x[C_A], x[C_W], x[C_ST],
                         x[C_INFO], 1, p->kp) || /* (core_scene_solve_s, Z and G held) */
      x[C_INFO][0] != 0.0)
    return 0;
  for (i = 0; i < c->ns; ++i) {
    const sc_int k = c->list[c->slip[i]];
    x[C_LAM][p->rn[k]] = s[i];
    x[C_LAM][p->m + k] = (c->dg[c->slip[i]] == 2 ? -p->mu[k] : p->mu[k]) * s[i];
    R[i] = sc_dot(p->A + p->rn[k] * n, x[C_A], n) + (p->c ? p->c[p->rn[k]] : 0.0);
  }
  return 1;
}

/* The candidate dg: its blocks set, Newton on the slipping contacts' w_n(s) = 0 (affine in s
 * on a piece of the other blocks: one step; the derivative by differences of exact solves,
 * the step cut in halves until |w_n|^2 falls), then Coulomb's residuals apart from the
 * accelerations. 1 where accepted (the solution in c->sol[0]), 0 where not (its w there too),
 * -1 where its solve failed. */
static int candidate(sc_cand *c) {
  const sc_fr_prob *p = c->p;
  const sc_int n = p->n, m = p->m, nb = p->nb;
  const double F = c->scale[0], W = c->scale[1];
  sc_int i, j, k, it;
  double r2, res[3];
  c->ns = 0;
  for (i = 0; i < c->nf; ++i) { /* open: both rows' forces 0; stick: both rows held; slip:
    the normal force applied (s), both rows' forces 0 in the solve */
    k = c->list[i];
    p->kind[k] = c->dg[i] == 1 ? K_FREE : K_BOX;
    p->kind[nb + k] = c->dg[i] == 1 ? K_FREE : K_BOX;
    p->par[3 * k] = p->par[3 * (nb + k)] = 0.0;
    if (c->dg[i] >= 2) { /* (s from the last pass's normal force) */
      c->s[c->ns] = fmax(0.0, c->l0[p->rn[k]]);
      c->slip[c->ns++] = i;
    }
  }
  if (!cand_solve(c, c->s, 0, c->R)) return -1;
  for (it = 0; it < CAND_NEWTON && c->ns > 0; ++it) {
    double t = 1.0;
    r2 = 0.0;
    for (i = 0; i < c->ns; ++i) r2 += c->R[i] * c->R[i];
    if (sqrt(r2) <= FP_TOL * W) break;
    for (j = 0; j < c->ns; ++j) { /* the derivative: column j */
      double h = 1e-7 * fmax(fabs(c->s[j]), F);
      memcpy(c->sv, c->s, sizeof(double) * (size_t)c->ns);
      c->sv[j] += h;
      if (!cand_solve(c, c->sv, 1, c->R2)) break;
      for (i = 0; i < c->ns; ++i) c->D[i * c->ns + j] = (c->R2[i] - c->R[i]) / h;
    }
    for (i = 0; i < c->ns; ++i) c->ds[i] = -c->R[i];
    if (j < c->ns || !sc_lu_factor(c->ns, c->D, c->ns, c->piv)) break; /* (or w_n does not
      move with s) */
    sc_lu_solve(c->ns, c->D, c->ns, c->piv, c->ds);
    for (k = 0; k < 30; ++k, t *= 0.5) {
      double q2 = 0.0;
      for (i = 0; i < c->ns; ++i) c->sv[i] = c->s[i] + t * c->ds[i];
      if (!cand_solve(c, c->sv, 1, c->R2)) continue;
      for (i = 0; i < c->ns; ++i) q2 += c->R2[i] * c->R2[i];
      if (q2 <= (1.0 - 1e-4 * t) * r2) break;
    }
    if (k == 30) break; /* no cut lowers |w_n|: the point as it is (checked below) */
    for (i = 0; i < 5; ++i) { /* the trial is the present solution */
      double *tmp = c->sol[0][i];
      c->sol[0][i] = c->sol[1][i], c->sol[1][i] = tmp;
    }
    memcpy(c->s, c->sv, sizeof(double) * (size_t)c->ns);
    memcpy(c->R, c->R2, sizeof(double) * (size_t)c->ns);
  }
  { /* Coulomb's residuals apart: w = A a + c on every row */
    double *lam = c->sol[0][C_LAM], *a = c->sol[0][C_A], *w = c->sol[0][C_W],
           *info = c->sol[0][C_INFO];
    for (i = 0; i < p->mt; ++i) w[i] = sc_dot(p->A + i * n, a, n) + (p->c ? p->c[i] : 0.0);
    res[0] = info[2], res[1] = info[3], res[2] = info[4];
    sc_coulomb_residuals(m, p->nt, p->rn, p->lead, p->mu, lam, w, c->scale, res);
    return res[0] <= TOL_ACCEPT && res[1] <= TOL_ACCEPT && res[2] <= TOL_ACCEPT;
  }
}

/* An active-set pass on the contacts' states: each contact of the rejected candidate in
 * c->sol[0] whose conditions fail switched as they ask (an open one that closes: stick, or
 * slip the way it slides; a sticking or slipping one pulled: open; a sticking one outside its
 * cone: slip against its force; a slipping one sliding back: stick); `one`: only the one that
 * fails most (relative to the scales). 1 where any did. */
static int switch_states(sc_cand *c, int one) {
  const sc_fr_prob *p = c->p;
  const double *lam = c->sol[0][C_LAM], *w = c->sol[0][C_W], F = c->scale[0], W = c->scale[1];
  sc_int i, moved = 0, worst = -1, to = 0;
  double most = 0.0;
  for (i = 0; i < c->nf; ++i) {
    const sc_int k = c->list[i], d = c->dg[i];
    const double ln = lam[p->rn[k]], lt = lam[p->m + k], wn = w[p->rn[k]], wt = w[p->m + k],
                 b = p->mu[k] * ln;
    sc_int e = d;
    double by = 0.0;
    if (d == 0) {
      if (wn < -TOL_ACCEPT * W) e = wt > TOL_ACCEPT * W ? 2 : wt < -TOL_ACCEPT * W ? 3 : 1;
      by = -wn / W;
    } else if (ln < -TOL_ACCEPT * F) {
      e = 0, by = -ln / F;
    } else if (d == 1) {
      e = lt > b + TOL_ACCEPT * F ? 3 : lt < -b - TOL_ACCEPT * F ? 2 : 1;
      by = (fabs(lt) - b) / F;
    } else if ((d == 2 && wt < -TOL_ACCEPT * W) || (d == 3 && wt > TOL_ACCEPT * W)) {
      e = 1, by = fabs(wt) / W;
    }
    if (e != d && by > most) most = by, worst = i, to = e;
    if (e != d && !one) c->dg[i] = e, ++moved;
  }
  if (one && worst >= 0) c->dg[worst] = to, ++moved;
  return moved > 0;
}

/* The candidate's code (base 4), and whether it is among the first `count` of seen. */
static sc_int code_of(const sc_cand *c) {
  sc_int i, code = 0;
  for (i = c->nf - 1; i >= 0; --i) code = 4 * code + c->dg[i];
  return code;
}
static int seen_in(const sc_int *seen, sc_int count, sc_int code) {
  sc_int i;
  for (i = 0; i < count; ++i)
    if (seen[i] == code) return 1;
  return 0;
}

int sc_friction_states(const sc_fr_prob *p, const double *scale, const double *from, int quick,
                       double *lam, double *a, double *w, double *st, double *info) {
  const sc_int n = p->n, mt = p->mt, nb = p->nb, nt = p->nt, nbt = nb + nt;
  sc_int i, j, k, dist, tried = 0, *iw, *kind0, *pos, *seen, nseen = 0, *prev;
  double *d, *par0;
  int ok = 0;
  sc_cand c;
  d = (double *)malloc(sizeof(double) * (size_t)(3 * nbt + n + 6 * nt + nt * nt + mt +
                                                 2 * (2 * mt + n + nbt + 8)));
  iw = (sc_int *)malloc(sizeof(sc_int) * (size_t)(nbt + 7 * nt + GUIDED_MAX + 1));
  if (!d || !iw) {
    free(d), free(iw);
    return 0;
  }
  par0 = d, c.fm = par0 + 3 * nbt, c.s = c.fm + n, c.sv = c.s + nt, c.ds = c.sv + nt;
  c.R = c.ds + nt, c.R2 = c.R + nt, c.D = c.R2 + nt, c.l0 = c.D + nt * nt;
  for (i = 0; i < 2; ++i) { /* (each: lam, a, w, st, info) */
    double *q = c.l0 + mt + i * (2 * mt + n + nbt + 8);
    c.sol[i][C_LAM] = q, c.sol[i][C_A] = q + mt, c.sol[i][C_W] = q + mt + n;
    c.sol[i][C_ST] = q + 2 * mt + n, c.sol[i][C_INFO] = q + 2 * mt + n + nbt;
  }
  kind0 = iw, c.list = kind0 + nbt, c.d0 = c.list + nt, c.dg = c.d0 + nt, c.slip = c.dg + nt;
  c.piv = c.slip + nt, pos = c.piv + nt, prev = pos + nt, seen = prev + nt;
  c.p = p, c.scale = scale, c.from = from, c.nf = 0;
  c.sweeps = p->sweeps < CAND_SWEEPS ? p->sweeps : CAND_SWEEPS;
  memcpy(kind0, p->kind, sizeof(sc_int) * (size_t)nbt);
  memcpy(par0, p->par, sizeof(double) * (size_t)(3 * nbt));
  for (k = 0; k < nt; ++k) /* the normal forces of the last pass's pieces (its solve's own
    where it did not converge) */
    c.l0[p->rn[k]] = from ? from[3 * k + 1] : lam[p->rn[k]];
  for (k = 0; k < nt; ++k) /* a group's other contacts open: its forces on its first's rows
    (the same rows within SAME_ROW: the same accelerations; Coulomb's law on the group's sums) */
    if (p->mu[k] > 0 && p->lead[k] != k) {
      p->kind[k] = p->kind[nb + k] = K_BOX;
      p->par[3 * k] = p->par[3 * (nb + k)] = 0.0;
    }
  for (k = 0; k < nt; ++k) /* the frictional contacts, their states in the last pass */
    if (p->mu[k] > 0 && p->lead[k] == k) {
      const double l = from ? from[3 * (nb + k)] : st[nb + k];
      c.list[c.nf] = k;
      c.d0[c.nf++] = !(c.l0[p->rn[k]] > 0) ? 0 : l == 3.0 ? 3 : l == 4.0 ? 2 : 1;
    }
  memcpy(c.dg, c.d0, sizeof(sc_int) * (size_t)c.nf);
  while (nseen < GUIDED_MAX && c.nf <= 30) { /* the active-set passes from the last pass's
    states; where they come back to a candidate, only the worst contact switched */
    int got;
    seen[nseen++] = code_of(&c);
    got = candidate(&c);
    ++tried;
    if ((ok = got == 1) || got < 0) break;
    memcpy(prev, c.dg, sizeof(sc_int) * (size_t)c.nf);
    if (!switch_states(&c, 0)) break;
    if (seen_in(seen, nseen, code_of(&c))) {
      memcpy(c.dg, prev, sizeof(sc_int) * (size_t)c.nf);
      if (!switch_states(&c, 1) || seen_in(seen, nseen, code_of(&c))) break;
    }
  }
  for (i = 0; i < c.nf; ++i) c.dg[i] = 1; /* every contact sticking (the restarts' first) */
  if (!ok && nseen < GUIDED_MAX && !seen_in(seen, nseen, code_of(&c))) {
    seen[nseen++] = code_of(&c);
    ok = candidate(&c) == 1;
    ++tried;
  }
  for (dist = 0; dist <= c.nf && !ok && tried < (quick ? CAND_QUICK : CAND_MAX); ++dist) {
    for (i = 0; i < dist; ++i) pos[i] = i; /* the contacts whose state differs */
    for (;;) {
      sc_int noff = 1, o;
      for (i = 0; i < dist; ++i) noff *= 3;
      for (o = 0; o < noff && !ok && tried < (quick ? CAND_QUICK : CAND_MAX); ++o, ++tried) {
        sc_int r = o;
        memcpy(c.dg, c.d0, sizeof(sc_int) * (size_t)c.nf);
        for (i = 0; i < dist; ++i, r /= 3) c.dg[pos[i]] = (c.d0[pos[i]] + 1 + r % 3) % 4;
        if (c.nf > 30 || !seen_in(seen, nseen, code_of(&c))) ok = candidate(&c) == 1;
      }
      if (ok || tried >= (quick ? CAND_QUICK : CAND_MAX)) break;
      for (i = dist - 1; i >= 0 && pos[i] == c.nf - dist + i; --i) continue;
      if (i < 0) break;
      for (++pos[i], j = i + 1; j < dist; ++j) pos[j] = pos[j - 1] + 1;
    }
  }
  memcpy(p->kind, kind0, sizeof(sc_int) * (size_t)nbt);
  memcpy(p->par, par0, sizeof(double) * (size_t)(3 * nbt));
  if (ok) { /* the solution, its blocks' states as the original blocks read them */
    memcpy(lam, c.sol[0][C_LAM], sizeof(double) * (size_t)mt);
    memcpy(a, c.sol[0][C_A], sizeof(double) * (size_t)n);
    memcpy(w, c.sol[0][C_W], sizeof(double) * (size_t)mt);
    memcpy(st, c.sol[0][C_ST], sizeof(double) * (size_t)nbt);
    memcpy(info, c.sol[0][C_INFO], sizeof(double) * 8);
    for (i = 0; i < c.nf; ++i) {
      k = c.list[i];
      st[k] = c.dg[i] == 0 ? S_ZERO : S_HELD;
      st[nb + k] = c.dg[i] == 0 ? S_ZERO : c.dg[i] == 1 ? S_HELD : c.dg[i] == 2 ? 4.0 : 3.0;
      p->par[3 * (nb + k)] = p->mu[k] * fmax(0.0, lam[p->rn[k]]);
    }
    for (k = 0; k < nt; ++k)
      if (p->mu[k] > 0 && p->lead[k] != k) st[k] = st[nb + k] = S_ZERO;
  }
  free(d);
  free(iw);
  return ok;
}
