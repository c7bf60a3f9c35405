/* The per-state system and its complementarity solve: one evaluation of the generated
 * `contact_system` (the object given or placed), the held rows' forces of eq. (16) and the
 * active-set rule; the generated functions' work arrays, and the
 * wall clock of the long calls. Shared by forward.c, integrate.c, events.c, run.c and maps.c
 * through engine.h. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime (before the first include) */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "snakecg_layout.h"
#include "engine.h"


/* Wall-clock seconds from an arbitrary origin (POSIX's monotonic clock; elsewhere the CPU
 * time): the long calls of the simulation pause after a budget of them, so that Python can
 * handle a Ctrl-C. */
double sc_wall_time(void) {
#if defined(CLOCK_MONOTONIC)
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
#else
  return (double)clock() / CLOCKS_PER_SEC;
#endif
}

void sc_work_free(sc_work_t *ws) {
  free((void *)ws->arg);
  free(ws->res);
  free(ws->iw);
  free(ws->w);
  ws->arg = 0;
  ws->res = 0;
  ws->iw = 0;
  ws->w = 0;
}

/* 0, or -1 when a size query or an allocation failed (then nothing is left allocated). */
int sc_work_alloc(sc_work_t *ws, const sc_work_fn *fns, int n) {
  sc_int a, r, i, w, ma = 0, mr = 0, mi = 0, mw = 0;
  int k;
  ws->arg = 0;
  ws->res = 0;
  ws->iw = 0;
  ws->w = 0;
  for (k = 0; k < n; ++k) {
    a = r = i = w = 0;
    if (fns[k](&a, &r, &i, &w)) return -1;
    if (a > ma) ma = a;
    if (r > mr) mr = r;
    if (i > mi) mi = i;
    if (w > mw) mw = w;
  }
  ws->arg = (const double **)calloc((size_t)(ma + 1), sizeof(double *));
  ws->res = (double **)calloc((size_t)(mr + 1), sizeof(double *));
  ws->iw = (sc_int *)malloc(sizeof(sc_int) * (size_t)(mi + 1));
  ws->w = (double *)malloc(sizeof(double) * (size_t)(mw + 1));
  if (!ws->arg || !ws->res || !ws->iw || !ws->w) {
    sc_work_free(ws);
    return -1;
  }
  return 0;
}

/* Point the arguments and results of generated function F (CS or CR: the indices differ) at
 * sc_contact_system's own parameters and locals, by their names. */
#define SC_SET_SYSTEM_ARGS(F)                                           \
  do {                                                                   \
    ws->arg[F##_IN_q] = q;                                               \
    ws->arg[F##_IN_tau] = tau;                                           \
    ws->arg[F##_IN_q_obj] = q_obj ? q_obj : zeros;                       \
    ws->arg[F##_IN_f_obj] = f_obj;                                       \
    ws->arg[F##_IN_K] = scene + SCENE_K;                                 \
    ws->arg[F##_IN_contact_link] = scene + SCENE_contact_link;           \
    ws->arg[F##_IN_side] = scene + SCENE_side;                           \
    ws->arg[F##_IN_object_mass] = scene + SCENE_object_mass;             \
    ws->arg[F##_IN_object_inertia] = scene + SCENE_object_inertia;       \
    ws->arg[F##_IN_rho] = q_obj ? rho : zeros;                           \
    ws->arg[F##_IN_wheel_offset] = scene + SCENE_wheel_offset;           \
    ws->arg[F##_IN_contact_offset] = scene + SCENE_contact_offset;       \
    ws->arg[F##_IN_object_distance] = scene + SCENE_object_distance;     \
    ws->arg[F##_IN_placed] = q_obj ? &zero : &one;                       \
    ws->res[F##_OUT_M] = out->M;                                         \
    ws->res[F##_OUT_delassus] = out->G;                                  \
    ws->res[F##_OUT_b] = out->b;                                         \
    ws->res[F##_OUT_qdd_free] = out->qdd_free;                           \
    ws->res[F##_OUT_a_obj_free] = out->a_free;                           \
    ws->res[F##_OUT_qdd_from_lam] = out->Kq;                             \
    ws->res[F##_OUT_a_obj_from_lam] = out->Ka;                           \
    ws->res[F##_OUT_gap] = &out->gap;                                    \
    ws->res[F##_OUT_s] = &out->s;                                        \
  } while (0)

int sc_contact_system(sc_work_t *ws, const double *scene, const double *q_in,
                      const double *v, const double *tau, const double *q_obj_in,
                      const double *v_obj, const double *f_obj, const double *rho,
                      sc_system *out) {
  static const double zeros[3] = {0.0, 0.0, 0.0}, one = 1.0, zero = 0.0;
  /* the base at the origin, the object's pose moved with it: the scene has no fixed body, so
   * every output is the same at any base position (up to rounding), and far from the origin
   * the contact's and the object's world coordinates cancelled (at x = 1e16 m the forces'
   * norm was three times the true one) */
  double qs[SNAKECG_NQ], qos[3];
  const double *q = qs, *q_obj = q_obj_in ? qos : NULL;
  int k, rest = 1;
  memcpy(qs, q_in, sizeof qs);
  qs[0] = qs[1] = 0.0;
  if (q_obj_in) qos[0] = q_obj_in[0] - q_in[0], qos[1] = q_obj_in[1] - q_in[1],
                qos[2] = q_obj_in[2];
  for (k = 0; k < SNAKECG_NS; ++k) rest &= v[k] == 0.0;
  for (k = 0; k < 3; ++k) rest &= v_obj[k] == 0.0;
  if (rest) {
    SC_SET_SYSTEM_ARGS(CR);
    return SNAKECG_CR(ws->arg, ws->res, ws->iw, ws->w, 0);
  }
  SC_SET_SYSTEM_ARGS(CS);
  ws->arg[CS_IN_v] = v;
  ws->arg[CS_IN_v_obj] = v_obj;
  return SNAKECG_CS(ws->arg, ws->res, ws->iw, ws->w, 0);
}

/* A SUPPORT row whose pivot ratio is at most this depends on the held rows before it. */
#define SC_SUPPORT_TOL 1e-10

/* The held forces y (m of them) made least-norm where SUPPORT rows were dropped (drop[j]):
 * the solutions differ by the null vectors z_j = e_j - G_KK^-1 G_Kj (K: the rows kept), so
 * y <- y - Z (Z^T Z)^-1 Z^T y (Z^T Z by linalg.h's Cholesky: Z has an identity block, so it
 * is positive definite). */
static void sc_least_norm(int m, const int *held, const int *drop, const double *G,
                          const double *L, const double *dinv, double *y) {
  const int nc = SNAKECG_NC;
  double Z[SNAKECG_NC * SNAKECG_NC], C[SNAKECG_NC * SNAKECG_NC], c[SNAKECG_NC];
  int nd = 0, i, j, k;
  for (j = 0; j < m; ++j) {
    double *z = Z + nc * nd;
    if (!drop[j]) continue;
    for (i = 0; i < m; ++i) z[i] = drop[i] ? 0.0 : G[held[i] + nc * held[j]];
    sc_ldl_solve(m, L, nc, dinv, z);
    for (i = 0; i < m; ++i) z[i] = -z[i];
    z[j] = 1.0;
    ++nd;
  }
  for (j = 0; j < nd; ++j) { /* C = Z^T Z (its lower triangle, row-major), c = Z^T y */
    double t = 0.0;
    for (i = 0; i < m; ++i) t += Z[i + nc * j] * y[i];
    c[j] = t;
    for (k = 0; k <= j; ++k) {
      double s = 0.0;
      for (i = 0; i < m; ++i) s += Z[i + nc * j] * Z[i + nc * k];
      C[j * nc + k] = s;
    }
  }
  if (!sc_cholesky(nd, C, nc, 0.0)) { /* not reached (see above); NaN flags the sample */
    for (i = 0; i < m; ++i) y[i] = NAN;
    return;
  }
  sc_cholesky_solve(nd, C, nc, c); /* c <- (Z^T Z)^-1 Z^T y */
  for (j = 0; j < nd; ++j)
    for (i = 0; i < m; ++i) y[i] -= Z[i + nc * j] * c[j];
}

/* The constraint forces for row states `state` (eq. 16): lam_F fixed (0, or +-bound for a
 * sliding wheel), lam_H solving G_HH lam_H = -(b_H + G_HF lam_F) - extra_H by LDL^T in row
 * order (the masked factorization of the generated `constrained_dynamics`); `extra` (may be
 * null) adds to the right-hand side per row (the simulator's Baumgarte terms). A SUPPORT row
 * is held; where it depends on the held rows before it (pivot ratio at most SC_SUPPORT_TOL)
 * it is dropped from the factorization, and the held forces are then the least-norm ones.
 * Returns the pivot ratio min_j d_j / G_jj over the held rows not dropped (1 when none). */
double sc_held_forces(const signed char *state, const double *G, const double *b,
                      const double *bounds, const double *extra, double *lam) {
  const int nc = SNAKECG_NC;
  int held[SNAKECG_NC], drop[SNAKECG_NC], m = 0, dropped = 0, i, j;
  double L[SNAKECG_NC * SNAKECG_NC], d[SNAKECG_NC], dinv[SNAKECG_NC], y[SNAKECG_NC],
      work[SNAKECG_NC], ratio;
  for (i = 0; i < nc; ++i) {
    lam[i] = state[i] == SLIDE_POS ? bounds[i] : state[i] == SLIDE_NEG ? -bounds[i] : 0.0;
    if (!isfinite(lam[i])) lam[i] = 0.0;
    if (state[i] == HELD || state[i] == SUPPORT) held[m++] = i;
  }
  for (i = 0; i < m; ++i) { /* right-hand side -(b_H + G_HF lam_F) - extra_H */
    double t = b[held[i]];
    for (j = 0; j < nc; ++j)
      if (state[j] != HELD) t += G[held[i] + nc * j] * lam[j];
    y[i] = -t;
    if (extra) y[i] -= extra[held[i]];
  }
  for (j = 0; j < m; ++j) drop[j] = state[held[j]] == SUPPORT; /* may drop out */
  ratio = sc_ldl_factor(m, G, nc, held, L, nc, d, dinv, drop, SC_SUPPORT_TOL, work);
  for (j = 0; j < m; ++j) dropped |= drop[j];
  sc_ldl_solve(m, L, nc, dinv, y);
  if (dropped) sc_least_norm(m, held, drop, G, L, dinv, y);
  for (i = 0; i < m; ++i) lam[held[i]] = y[i];
  return ratio;
}

/* Relative weight of the rounding term of a row's scale (snakecg.solver.ROUND_REL). */
#define SC_ROUND_REL 1e-5

/* The next row states (snakecg.solver._violations with _tolerances): returns 1 if any moved.
 * Each row is judged against its own scale (force units), s_r = max(|lam_r|, |w_r| / G_rr,
 * |b_r| / G_rr, ROUND_REL sum_j |G_rj lam_j| / G_rr) with b = w - G lam (the row's
 * acceleration at zero force): tol_lam_r = rel_tol s_r, tol_w_r = rel_tol G_rr s_r. Scaling
 * every input force scales every term: the decisions do not depend on units; and the huge
 * forces of nearly dependent rows (which cancel in the other rows) no longer widen the
 * tolerance of a row they barely move. */
int sc_next_states(signed char *state, const double *lam, const double *w,
                   const double *G, const double *bounds, double rel_tol) {
  const int nc = SNAKECG_NC;
  double g = 0.0, tol_lam[SNAKECG_NC], tol_w[SNAKECG_NC];
  signed char next[SNAKECG_NC];
  int r, j, moved = 0;
  for (r = 0; r < nc; ++r) {
    double d = fabs(G[r + nc * r]);
    if (d > g) g = d; /* NaN never wins */
  }
  if (!(g > 0) || !isfinite(g)) g = 1.0;
  for (r = 0; r < nc; ++r) {
    double gr = fabs(G[r + nc * r]), b = w[r], cross = 0.0, s;
    if (!(gr > 0) || !isfinite(gr)) gr = g;
    for (j = 0; j < nc; ++j) {
      double t = G[r + nc * j] * lam[j];
      b -= t;
      cross += fabs(t);
    }
    s = fabs(lam[r]);
    if (fabs(w[r]) / gr > s) s = fabs(w[r]) / gr;
    if (fabs(b) / gr > s) s = fabs(b) / gr;
    if (SC_ROUND_REL * cross / gr > s) s = SC_ROUND_REL * cross / gr;
    tol_lam[r] = rel_tol * s;
    tol_w[r] = rel_tol * gr * s;
  }
  memcpy(next, state, sizeof(next));
  if (state[0] == HELD && lam[0] < -tol_lam[0]) next[0] = LOST;
  else if (state[0] == LOST && w[0] < -tol_w[0]) next[0] = HELD;
  for (r = 1; r < nc; ++r) {
    const double u = bounds[r];
    if (state[r] == HELD && isfinite(u)) {
      if (lam[r] > u + tol_lam[r]) next[r] = SLIDE_POS;
      else if (lam[r] < -u - tol_lam[r]) next[r] = SLIDE_NEG;
    } else if (state[r] == SLIDE_POS && w[r] > tol_w[r]) {
      next[r] = HELD;
    } else if (state[r] == SLIDE_NEG && w[r] < -tol_w[r]) {
      next[r] = HELD;
    }
  }
  for (r = 0; r < nc; ++r) {
    if (next[r] != state[r]) moved = 1;
    state[r] = next[r];
  }
  return moved;
}
