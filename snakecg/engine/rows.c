/* The samples the fast path of forward.c does not answer exactly, answered here by the
 * rules of the reference solve (snakecg/solver.py with snakecg/rows.py's completion):
 *
 *   1. the active-set iteration on the Delassus matrix from "every present row held"; a state
 *      whose held rows are dependent (pivot ratio at most pivot_tol) or whose forces are not
 *      finite is solved with a Tikhonov term, reg = REGULARIZATION max_r |G_rr| on the held
 *      rows' diagonal (the least-norm forces in the limit), and the sample is flagged; when it
 *      has not settled after max_iter passes, every active set is enumerated
 *      (2 x 3^wheels) and the one of least KKT residual kept;
 *   2. where the held rows are weakly independent (pivot ratio at most `weak`) or dependent,
 *      and the mass matrix is factorable (its pivot ratio above pivot_tol), the whole solve
 *      again with the rows factored directly: in z = L^T a (I = L L^T) the held rows are
 *      R_H = L^T K_H (K = I^-1 A^T, the generated maps of eq. 18), factored by Householder QR,
 *      lam_H = -R_1^-1 (Q^T z_0 + R_1^-T Adot_H v), z = z_0 - Q (Q^T z_0 + R_1^-T Adot_H v);
 *      relative error ~1e-16 / sqrt(ratio) instead of 1e-16 / ratio. Rows dependent even so
 *      (QR pivot ratio at most ROW_TOL) get the least-norm forces (one-sided Jacobi SVD, the
 *      truncation of numpy.linalg.lstsq at rcond 1e-10) and the flag;
 *   3. the flags: the mass matrix numerically singular (pivot ratio at most mass_tol), a
 *      result physically impossible (non-finite, a negative squared norm, sr outside [0, 1])
 *      or a system not finite: NaN results, no row state, the reason's code in the status.
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"

#define ND (SNAKECG_NS + 3) /* snake and object accelerations */

/* reason codes of the status column (snakecg.rows.REASONS) */
enum { R_ROWS = 1, R_DEPENDENT = 2, R_MASS = 3, R_IMPOSSIBLE = 4, R_NOT_FINITE = 5 };

static int finite_all(const double *x, int n) {
  int k;
  for (k = 0; k < n; ++k)
    if (!isfinite(x[k])) return 0;
  return 1;
}

/* ---- the Delassus solve of one state, with the Tikhonov term where it is singular ---- */

/* lam and w (w may be null) of `state`, `extra` (may be null) added to the held rows'
 * right-hand side as in sc_held_forces; *singular set when regularized; the pivot ratio. */
double sc_delassus_state(const sc_system *sys, const sc_constants *c, const signed char *state,
                         const double *u, const double *extra, double *lam, double *w,
                         int *singular) {
  const int nc = SNAKECG_NC;
  double pivot = sc_held_forces(state, sys->G, sys->b, u, extra, lam);
  int r, i;
  *singular = 0;
  if (!(pivot > c->pivot_tol) || !finite_all(lam, nc)) {
    double Greg[SNAKECG_NC * SNAKECG_NC], scale = 0.0, reg;
    for (r = 0; r < nc; ++r) {
      double d = fabs(sys->G[r + nc * r]);
      if (d > scale || isnan(d)) scale = d; /* numpy's max: NaN wins */
    }
    reg = c->regularization * (scale > 1e-300 || isnan(scale) ? scale : 1e-300);
    memcpy(Greg, sys->G, sizeof(Greg));
    for (r = 0; r < nc; ++r)
      if (state[r] == HELD) Greg[r + nc * r] += reg;
    pivot = sc_held_forces(state, Greg, sys->b, u, extra, lam);
    *singular = 1;
  }
  for (r = 0; r < nc && w; ++r) { /* w = G_c lam + b (eq. 13) */
    double t = sys->b[r];
    for (i = 0; i < nc; ++i) t += sys->G[r + nc * i] * lam[i];
    w[r] = t;
  }
  return pivot;
}

/* ---- the rows factored directly (snakecg.rows.RowSystem) ---- */

typedef struct {
  double L[ND * ND];                 /* I = L L^T, row-major lower */
  double R[ND * SNAKECG_NC];         /* R = L^T K, column r at R + ND r */
  double G[SNAKECG_NC * SNAKECG_NC]; /* R^T R, column-major */
  double zf[ND];                     /* L^T I^-1 (f - p): z at zero force */
  double adv[SNAKECG_NC];            /* Adot v */
  int ok;                            /* the system is finite and I positive definite */
} rows_system;

static void rows_build(const sc_system *sys, const double *scene, int at_rest, rows_system *rs) {
  const int ns = SNAKECG_NS, nc = SNAKECG_NC;
  const double *present = scene + SCENE_present;
  double K[ND * SNAKECG_NC], af[ND];
  int i, j, r;
  memset(rs->L, 0, sizeof(rs->L));
  for (i = 0; i < ns; ++i)
    for (j = 0; j <= i; ++j) rs->L[i * ND + j] = sys->M[i + ns * j];
  rs->L[ns * ND + ns] = rs->L[(ns + 1) * ND + ns + 1] = scene[SCENE_object_mass];
  rs->L[(ns + 2) * ND + ns + 2] = scene[SCENE_object_inertia];
  for (r = 0; r < nc; ++r) {
    for (i = 0; i < ns; ++i) K[i + ND * r] = sys->Kq[i + ns * r];
    for (i = 0; i < 3; ++i) K[ns + i + ND * r] = sys->Ka[i + 3 * r];
  }
  for (i = 0; i < ns; ++i) af[i] = sys->qdd_free[i];
  for (i = 0; i < 3; ++i) af[ns + i] = sys->a_free[i];
  rs->ok = finite_all(rs->L, ND * ND) && finite_all(K, ND * nc) && finite_all(af, ND) &&
           finite_all(sys->b, nc) && sc_cholesky(ND, rs->L, ND, 0.0);
  if (rs->ok)
    for (i = 0; i < ND; ++i) rs->ok &= rs->L[i * ND + i] > 0.0 && isfinite(rs->L[i * ND + i]);
  if (!rs->ok) return;
  for (r = 0; r < nc; ++r) /* R = L^T K (an absent row: zero, as its row of A) */
    for (i = 0; i < ND; ++i) {
      double t = 0.0;
      for (j = i; j < ND && present[r] != 0.0; ++j) t += rs->L[j * ND + i] * K[j + ND * r];
      rs->R[i + ND * r] = t;
    }
  for (i = 0; i < ND; ++i) {
    double t = 0.0;
    for (j = i; j < ND; ++j) t += rs->L[j * ND + i] * af[j];
    rs->zf[i] = t;
  }
  for (r = 0; r < nc; ++r) { /* b = R^T z_free + Adot v: Adot v at rest is 0 */
    rs->adv[r] = at_rest || present[r] == 0.0 ? 0.0
                                              : sys->b[r] - sc_dot(rs->R + ND * r, rs->zf, ND);
    for (j = 0; j < nc; ++j) rs->G[r + nc * j] = sc_dot(rs->R + ND * r, rs->R + ND * j, ND);
  }
  rs->ok = finite_all(rs->R, ND * nc) && finite_all(rs->G, nc * nc) && finite_all(rs->adv, nc);
}

/* The held rows' forces from the rows (snakecg.rows._held_rows): lamH, z, the pivot ratio. */
static double held_rows(int m, const double *RH, const double *z0, const double *adv,
                        const sc_constants *c, double *lamH, double *z) {
  double A[ND * SNAKECG_NC], rd[SNAKECG_NC], beta[SNAKECG_NC], col[SNAKECG_NC], t[ND],
      y[SNAKECG_NC], ratio = INFINITY;
  int i, k;
  memcpy(A, RH, sizeof(double) * ND * m);
  for (k = 0; k < m; ++k) col[k] = sc_norm(RH + ND * k, ND);
  sc_qr_factor(ND, m, A, ND, rd, beta);
  for (k = 0; k < m; ++k) {
    double q = fabs(rd[k]) / (col[k] > 0 ? col[k] : 1.0);
    if (!(q * q >= ratio)) ratio = q * q; /* NaN propagates */
  }
  if (!(ratio > c->row_tol)) { /* dependent even for the rows: least-norm forces */
    double U[ND * SNAKECG_NC], V[SNAKECG_NC * SNAKECG_NC], s[SNAKECG_NC], x[SNAKECG_NC];
    memcpy(U, RH, sizeof(double) * ND * m);
    sc_svd_jacobi(ND, m, U, ND, V, s);
    sc_svd_least_norm(ND, m, U, ND, V, s, z0, 1e-10, 0, lamH); /* lstsq(RH, z0) */
    sc_svd_least_norm(ND, m, U, ND, V, s, adv, 1e-10, 1, x);   /* lstsq(RH^T RH, adv) */
    for (k = 0; k < m; ++k) lamH[k] = -lamH[k] - x[k];
    for (i = 0; i < ND; ++i) {
      double v = z0[i];
      for (k = 0; k < m; ++k) v += RH[i + ND * k] * lamH[k];
      z[i] = v;
    }
    return ratio;
  }
  memcpy(t, z0, sizeof(t));
  sc_qr_apply(ND, m, A, ND, beta, t, 1); /* Q^T z0 */
  for (i = 0; i < m; ++i) { /* y = R_1^-T adv */
    double v = adv[i];
    for (k = 0; k < i; ++k) v -= A[k + ND * i] * y[k];
    y[i] = v / rd[i];
  }
  for (i = 0; i < m; ++i) t[i] += y[i]; /* t = Q^T z0 + y */
  for (i = m - 1; i >= 0; --i) { /* lamH = -R_1^-1 t */
    double v = -t[i];
    for (k = i + 1; k < m; ++k) v -= A[i + ND * k] * lamH[k];
    lamH[i] = v / rd[i];
  }
  for (i = 0; i < ND; ++i) z[i] = i < m ? t[i] : 0.0; /* z = z0 - Q [t; 0] */
  sc_qr_apply(ND, m, A, ND, beta, z, 0);
  for (i = 0; i < ND; ++i) z[i] = z0[i] - z[i];
  return ratio;
}

/* lam, w, z of `state` solved from the rows; returns the pivot ratio (NaN when not ok). */
static double rows_state(const rows_system *rs, const sc_constants *c, const signed char *state,
                         const double *u, double *lam, double *w, double *z) {
  const int nc = SNAKECG_NC;
  double z0[ND], RH[ND * SNAKECG_NC], advH[SNAKECG_NC], lamH[SNAKECG_NC], ratio = 1.0;
  int held[SNAKECG_NC], m = 0, i, r;
  for (r = 0; r < nc; ++r) {
    lam[r] = state[r] == SLIDE_POS ? u[r] : state[r] == SLIDE_NEG ? -u[r] : 0.0;
    if (!isfinite(lam[r])) lam[r] = 0.0;
    if (state[r] == HELD) held[m++] = r;
  }
  if (!rs->ok) {
    for (r = 0; r < nc; ++r) lam[r] = w[r] = NAN;
    for (i = 0; i < ND; ++i) z[i] = NAN;
    return NAN;
  }
  for (i = 0; i < ND; ++i) { /* z0 = L^-1 (f - p + A^T lam_F) */
    double t = rs->zf[i];
    for (r = 0; r < nc; ++r)
      if (lam[r] != 0.0) t += rs->R[i + ND * r] * lam[r];
    z0[i] = t;
  }
  for (i = 0; i < m; ++i) {
    memcpy(RH + ND * i, rs->R + ND * held[i], sizeof(double) * ND);
    advH[i] = rs->adv[held[i]];
  }
  if (m) {
    ratio = held_rows(m, RH, z0, advH, c, lamH, z);
    for (i = 0; i < m; ++i) lam[held[i]] = lamH[i];
  } else {
    memcpy(z, z0, sizeof(z0));
  }
  if (!finite_all(z, ND)) { /* the rows gave up: no answer for this sample */
    for (r = 0; r < nc; ++r) lam[r] = NAN;
    for (i = 0; i < ND; ++i) z[i] = NAN;
    ratio = NAN;
  }
  for (r = 0; r < nc; ++r) w[r] = sc_dot(rs->R + ND * r, z, ND) + rs->adv[r]; /* A a + Adot v */
  return ratio;
}

/* ---- the active set of either solve ---- */

/* The KKT residual of a candidate state over the free rows (snakecg.solver._enumerate): 0 for
 * the solution. */
static double kkt_residual(const signed char *s, const double *free, const double *lam,
                           const double *w, const double *u) {
  double res = free[0] == 0.0 ? 0.0 : s[0] == HELD ? fmax(-lam[0], 0.0) : fmax(-w[0], 0.0);
  int r;
  for (r = 1; r < SNAKECG_NC; ++r) {
    if (free[r] == 0.0) continue;
    if (s[r] == HELD && isfinite(u[r])) res += fmax(fabs(lam[r]) - u[r], 0.0);
    else if (s[r] == SLIDE_POS) res += fmax(w[r], 0.0);
    else if (s[r] == SLIDE_NEG) res += fmax(-w[r], 0.0);
  }
  return res;
}

typedef struct {
  const sc_system *sys;
  const rows_system *rs; /* null: the Delassus solve */
  const sc_constants *c;
  const double *u;
} solver_ctx;

static double eval_state(const solver_ctx *x, const signed char *state, double *lam, double *w,
                         double *z, int *singular) {
  double p;
  if (!x->rs) return sc_delassus_state(x->sys, x->c, state, x->u, 0, lam, w, singular);
  p = rows_state(x->rs, x->c, state, x->u, lam, w, z);
  *singular = !(p > x->c->pivot_tol) || !finite_all(lam, SNAKECG_NC);
  return p;
}

/* The active set of the `free` rows from "every free row held" (snakecg.solver.
 * solve_active_set), then enumeration; the other rows keep their state as given in `state`
 * (ABSENT, or a forced one: LOST, a wheel sliding at its bound). The state, lam, w, z, the
 * pivot ratio and the singular flag of the answer. */
static double active_set(const solver_ctx *x, const double *free, long max_iter,
                         signed char *state, double *lam, double *w, double *z, int *singular) {
  const int nc = SNAKECG_NC;
  const double *G = x->rs ? x->rs->G : x->sys->G;
  signed char given[SNAKECG_NC];
  double pivot = 1.0;
  long it;
  int r, moved = 1;
  for (r = 0; r < nc; ++r) given[r] = state[r] = free[r] != 0.0 ? HELD : state[r];
  for (it = 0; it < max_iter && moved; ++it) {
    pivot = eval_state(x, state, lam, w, z, singular);
    sc_next_states(state, lam, w, G, x->u, x->c->rel_tol);
    for (moved = 0, r = 0; r < nc; ++r) { /* the rows not free never move */
      if (free[r] == 0.0) state[r] = given[r];
      else if (state[r] != given[r]) moved = 1;
      given[r] = state[r];
    }
  }
  if (moved) { /* not settled: every active set, the least KKT residual */
    signed char s[SNAKECG_NC], best[SNAKECG_NC];
    double l2[SNAKECG_NC], w2[SNAKECG_NC], z2[ND], p2, res, best_res = INFINITY;
    int sing2, found = 0, k;
    for (r = 0; r < nc; ++r) s[r] = free[r] == 0.0 ? state[r] : HELD;
    for (;;) {
      p2 = eval_state(x, s, l2, w2, z2, &sing2);
      res = kkt_residual(s, free, l2, w2, x->u);
      if (!found || res < best_res) {
        found = 1;
        best_res = res;
        memcpy(best, s, sizeof(best));
        memcpy(lam, l2, sizeof(l2));
        memcpy(w, w2, sizeof(w2));
        if (x->rs) memcpy(z, z2, sizeof(z2));
        pivot = p2;
        *singular = sing2;
      }
      for (k = nc - 1; k >= 0; --k) { /* the next state, the last row fastest */
        if (free[k] == 0.0) continue;
        if (k == 0) {
          if (s[0] == HELD) { s[0] = LOST; break; }
          s[0] = HELD;
        } else if (isfinite(x->u[k])) {
          if (s[k] == HELD) { s[k] = SLIDE_POS; break; }
          if (s[k] == SLIDE_POS) { s[k] = SLIDE_NEG; break; }
          s[k] = HELD;
        } else {
          continue;
        }
      }
      if (k < 0) break;
    }
    memcpy(state, best, sizeof(best));
  }
  return pivot;
}

/* The active set of the free rows at an event (events.c: the simulation's Events.decide) by
 * the same rules, on the Delassus matrix with the Tikhonov term; its pivot ratio. */
double sc_decide_states(const sc_system *sys, const sc_constants *c, const double *u,
                        const double *free, long max_iter, signed char *state, int *singular) {
  double lam[SNAKECG_NC], w[SNAKECG_NC], z[ND];
  solver_ctx x;
  x.sys = sys;
  x.rs = 0;
  x.c = c;
  x.u = u;
  return active_set(&x, free, max_iter, state, lam, w, z, singular);
}

static void no_answer(double *out, int code) {
  const int nc = SNAKECG_NC;
  int r;
  for (r = 0; r < SNAKECG_NS; ++r) out[OUT_qdd + r] = NAN;
  for (r = 0; r < 3; ++r) out[OUT_a_obj + r] = NAN;
  for (r = 0; r < nc; ++r) {
    out[OUT_lam + r] = out[OUT_w + r] = NAN;
    out[OUT_state + r] = (double)ABSENT;
  }
  out[OUT_norm_lambda] = out[OUT_norm_a_obj] = out[OUT_norm_qdd] = out[OUT_sr] = NAN;
  out[OUT_conditioning] = 0.0;
  out[OUT_singular] = 1.0;
  out[OUT_status] = (double)code;
}

/* One sample's answer from its system (sys from sc_contact_system, or null when that failed):
 * the row of `out` filled, its status the reason code (1: answered exactly here). */
void sc_forward_edge(const sc_system *sys, const double *scene, const sc_constants *c,
                     long max_iter, int at_rest, double mass, double *out) {
  const int nc = SNAKECG_NC, ns = SNAKECG_NS;
  const double *present = scene + SCENE_present, *u = scene + SCENE_bounds;
  signed char state[SNAKECG_NC];
  double *lam = out + OUT_lam, *w = out + OUT_w, *qdd = out + OUT_qdd, *a = out + OUT_a_obj;
  double z[ND], acc[ND], pivot, cond, nq = 0.0, na, nl = 0.0, I_obj[3], scale, sr;
  int singular = 0, unfinite, reason, r, i, sane;
  solver_ctx x;
  rows_system rs;
  if (!sys) {
    no_answer(out, R_NOT_FINITE);
    return;
  }
  x.sys = sys;
  x.rs = 0;
  x.c = c;
  x.u = u;
  unfinite = !finite_all(sys->G, nc * nc);
  I_obj[0] = I_obj[1] = scene[SCENE_object_mass];
  I_obj[2] = scene[SCENE_object_inertia];
  for (r = 0; r < nc; ++r) state[r] = ABSENT; /* (the rows not present) */
  pivot = active_set(&x, present, max_iter, state, lam, w, z, &singular);
  cond = singular ? 0.0 : (pivot < 1.0 ? pivot : 1.0);
  if ((singular || !(cond > c->weak)) && mass > c->pivot_tol) { /* from the rows */
    rows_build(sys, scene, at_rest, &rs);
    x.rs = &rs;
    pivot = active_set(&x, present, max_iter, state, lam, w, z, &singular);
    if (pivot > 1.0) pivot = 1.0;
    singular = !(pivot > c->row_tol);
    cond = singular ? 0.0 : sqrt(pivot);
    unfinite |= !rs.ok;
    for (i = ND - 1; i >= 0; --i) { /* a = L^-T z */
      double t = z[i];
      for (r = i + 1; r < ND; ++r) t -= rs.L[r * ND + i] * acc[r];
      acc[i] = t / rs.L[i * ND + i];
    }
    memcpy(qdd, acc, sizeof(double) * ns);
    memcpy(a, acc + ns, sizeof(double) * 3);
    for (i = 0; i < ND; ++i) { /* |R lam|^2 */
      double t = 0.0;
      for (r = 0; r < nc; ++r) t += rs.R[i + ND * r] * lam[r];
      nl += t * t;
    }
  } else { /* eq. (18): the forces back into the accelerations */
    for (i = 0; i < ns; ++i) {
      double t = sys->qdd_free[i];
      for (r = 0; r < nc; ++r) t += sys->Kq[i + ns * r] * lam[r];
      qdd[i] = t;
    }
    for (i = 0; i < 3; ++i) {
      double t = sys->a_free[i];
      for (r = 0; r < nc; ++r) t += sys->Ka[i + 3 * r] * lam[r];
      a[i] = t;
    }
    for (i = 0; i < nc; ++i) {
      double t = 0.0;
      for (r = 0; r < nc; ++r) t += sys->G[i + nc * r] * lam[r];
      nl += lam[i] * t;
    }
  }
  for (i = 0; i < ns; ++i) { /* eq. (26) */
    double t = 0.0;
    for (r = 0; r < ns; ++r) t += sys->M[i + ns * r] * qdd[r];
    nq += qdd[i] * t;
  }
  na = I_obj[0] * a[0] * a[0] + I_obj[1] * a[1] * a[1] + I_obj[2] * a[2] * a[2]; /* eq. (27) */
  sr = na / (na + nq > 1e-300 ? na + nq : 1e-300); /* eq. (30) */
  out[OUT_norm_qdd] = nq;
  out[OUT_norm_a_obj] = na;
  out[OUT_norm_lambda] = nl;
  out[OUT_gap] = sys->gap;
  /* physically possible (snakecg.rows._sane) */
  scale = fmax(fabs(nq), fmax(fabs(na), fabs(nl)));
  sane = isfinite(nq) && isfinite(na) && isfinite(nl) && isfinite(sr) &&
         finite_all(qdd, ns) && finite_all(lam, nc);
  sane = sane && nq >= -c->sane_tol * scale && na >= -c->sane_tol * scale &&
         nl >= -c->sane_tol * scale && sr >= -c->sane_tol && sr <= 1.0 + c->sane_tol;
  reason = singular ? R_DEPENDENT : 0;
  if (!sane) reason = unfinite ? R_NOT_FINITE : R_IMPOSSIBLE;
  if (!(mass > c->mass_tol)) reason = R_MASS;
  if (reason > R_DEPENDENT) {
    no_answer(out, reason);
    return;
  }
  out[OUT_sr] = state[0] == HELD || isnan(sr) ? sr : 0.0; /* eq. 30 */
  out[OUT_singular] = reason ? 1.0 : 0.0;
  out[OUT_conditioning] = reason ? 0.0 : (cond < mass ? cond : mass);
  for (r = 0; r < nc; ++r) out[OUT_state + r] = (double)state[r];
  out[OUT_status] = (double)(reason > R_ROWS ? reason : R_ROWS);
}
