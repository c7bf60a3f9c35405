/* snakecg's engine: the exact contact/wheel complementarity solve of one sample, and the
 * batch loop over samples, in C.
 *
 * This file is part of the runtime (not generated). It is compiled once per model into the
 * model's shared library, beside CasADi's C of the generated functions, with a header
 * `snakecg_layout.h` that the runtime writes from the model's manifest
 * (snakecg/engine/layout.py): the sizes, the generated functions' symbols and the index of every
 * input and output by name. Nothing here knows an argument's position.
 *
 * Per sample (eqs. 12-30 of Reyes & Ma 2017; the rules of snakecg/solver.py):
 *   1-2. the problem before any active set (generated `contact_system`, which also places
 *      the object at the scene's contact from q unless its pose is given): the Delassus matrix
 *      G_c (eq. 14), the rows' accelerations at zero force b (eq. 13), the accelerations
 *      without constraint forces and the maps of the forces into them (eqs. 12, 18), M_s;
 *   3. the primal-dual active-set iteration: from "every present row held", solve the held
 *      rows G_HH lam_H = -(b_H + G_HF lam_F) (eq. 16; sliding wheels at their bound) by an
 *      LDL^T factorization in row order (the masked factorization of the generated
 *      `constrained_dynamics`), w = G_c lam + b, move every row that violates its
 *      complementarity condition, repeat until no row moves (the KKT conditions hold to the
 *      sample's own relative tolerance);
 *   4. the accelerations (eq. 18), the norms (eqs. 26, 27, lam^T G_c lam) and sr (eq. 30);
 *      the conditioning: the held rows' pivot ratio and the mass matrix's (a scaled Cholesky
 *      factorization), and a check that the result is physically possible (finite,
 *      norms >= 0, 0 <= sr <= 1).
 * A sample that this path does not answer exactly (dependent or weakly independent held rows,
 * no convergence within max_iter passes, an ill-conditioned mass matrix, an impossible result)
 * is answered by rows.c with the reference rules (the Tikhonov term, enumeration of active
 * sets, the rows factored directly, the flags), its status the reason's code (1: exact).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"

/* Bounds that follow the solution (a spatial scene, SCENE_friction): row r's bound is
 * friction_r times the force of row normal_row_r (mu times the link's solved normal force,
 * none where negative), found by iterating the solve on the bounds to a fixed point; at most
 * this many passes. */
#define SC_BOUND_PASSES 100

/* sample status */
enum { STATUS_EXACT = 0, STATUS_FALLBACK = 1 };


static int all_finite(const double *x, int n, double limit) {
  int k;
  for (k = 0; k < n; ++k)
    if (!(fabs(x[k]) <= limit)) return 0; /* also false for NaN */
  return 1;
}

/* Smallest pivot of the Cholesky factorization of M scaled to a unit diagonal, squared
 * (snakecg.rows.mass_pivot_ratio); 0 where M is not numerically positive definite. The
 * scaled factor's squared pivots are the LDL^T pivots of M over its diagonal, d_j / M_jj
 * (scaling by a diagonal leaves L unit and scales d), so no square root is taken. */
static double mass_pivot_ratio(const double *M, double *L) {
  double d[SNAKECG_NS], dinv[SNAKECG_NS], work[SNAKECG_NS], best;
  int j;
  best = sc_ldl_factor(SNAKECG_NS, M, SNAKECG_NS, 0, L, SNAKECG_NS, d, dinv, 0, 0.0, work);
  for (j = 0; j < SNAKECG_NS; ++j)
    if (!(d[j] > 0) || !(M[j + SNAKECG_NS * j] > 0)) return 0.0;
  return isfinite(best) ? best : 0.0;
}

/* One sample. `scene` holds the scene's constant inputs (layout in snakecg_layout.h); `out`
 * one output row (OUT_* offsets). Returns the status. */
static int solve_one(sc_work_t *ws, const double *scene, const sc_constants *c, long max_iter,
                     const double *q, const double *v, const double *tau, const double *q_obj_in,
                     const double *v_obj, const double *f_obj, const double *rho_in,
                     double *out) {
  const int nc = SNAKECG_NC, ns = SNAKECG_NS;
  sc_system sys;
  double S[SNAKECG_NS * SNAKECG_NS], pivot = 0.0, mass, scale, nq, na, nl, I_obj[3];
  const double *M = sys.M, *G = sys.G, *b = sys.b, *Kq = sys.Kq, *Ka = sys.Ka;
  const double *bounds = scene + SCENE_bounds, *present = scene + SCENE_present;
  signed char state[SNAKECG_NC];
  double u[SNAKECG_NC]; /* the rows' bounds */
  long it;
  int r, i, moved = 1, pass, coupled = 0, system_ok = 1;
  double *lam = out + OUT_lam, *w = out + OUT_w, *qdd = out + OUT_qdd, *a = out + OUT_a_obj;

  memcpy(out + OUT_tau, tau, sizeof(double) * SNAKECG_NA);
  /* q_obj_in == NULL: the object placed at the scene's contact from q */
  if (sc_contact_system(ws, scene, q, v, tau, q_obj_in, v_obj, f_obj, rho_in, &sys)) {
    system_ok = 0;
    goto edge;
  }
  /* present 2: a SUPPORT row (held always, may depend on the others) */
  for (r = 0; r < nc; ++r)
    state[r] = present[r] == 2.0 ? SUPPORT : present[r] != 0.0 ? HELD : ABSENT;
  for (r = 0; r < nc; ++r) u[r] = bounds[r];
#ifdef SCENE_friction
  for (r = 0; r < nc; ++r) coupled |= scene[SCENE_friction + r] > 0.0;
#endif
  for (pass = 0;; ++pass) {
    double change = 0.0, size = 0.0;
    moved = 1;
    for (it = 0; it < max_iter && moved; ++it) {
      pivot = sc_held_forces(state, G, b, u, 0, lam);
      if (!(pivot > c->pivot_tol) || !all_finite(lam, nc, INFINITY)) goto edge;
      for (r = 0; r < nc; ++r) { /* w = G_c lam + b (eq. 13) */
        double t = b[r];
        for (i = 0; i < nc; ++i) t += G[r + nc * i] * lam[i];
        w[r] = t;
      }
      moved = sc_next_states(state, lam, w, G, u, c->rel_tol);
    }
    if (moved) goto edge; /* not settled: enumeration, in the reference path */
    if (!coupled) break;
#ifdef SCENE_friction
    for (r = 0; r < nc; ++r) { /* the bounds from the forces just solved */
      double mu = scene[SCENE_friction + r], nr, f;
      if (!(mu > 0.0)) continue;
      nr = lam[(int)scene[SCENE_normal_row + r]];
      f = mu * (nr > 0.0 ? nr : 0.0);
      if (!(fabs(f - u[r]) <= change)) change = fabs(f - u[r]); /* the first pass: inf */
      if (f > size) size = f;
      u[r] = f;
    }
#endif
    if (change <= 1e-14 * size) break;
    if (pass >= SC_BOUND_PASSES) goto edge;
  }
  if (!(pivot > c->weak)) goto edge; /* weak rows: factored directly there */
  mass = mass_pivot_ratio(M, S);
  if (!(mass > c->mass_tol)) goto edge;
  /* eq. (18): the forces back into the accelerations */
  for (i = 0; i < ns; ++i) {
    double t = sys.qdd_free[i];
    for (r = 0; r < nc; ++r) t += Kq[i + ns * r] * lam[r];
    qdd[i] = t;
  }
  for (i = 0; i < 3; ++i) {
    double t = sys.a_free[i];
    for (r = 0; r < nc; ++r) t += Ka[i + 3 * r] * lam[r];
    a[i] = t;
  }
  I_obj[0] = I_obj[1] = scene[SCENE_object_mass];
  I_obj[2] = scene[SCENE_object_inertia];
  nq = 0.0; /* eq. (26) */
  for (i = 0; i < ns; ++i) {
    double t = 0.0;
    for (r = 0; r < ns; ++r) t += M[i + ns * r] * qdd[r];
    nq += qdd[i] * t;
  }
  na = I_obj[0] * a[0] * a[0] + I_obj[1] * a[1] * a[1] + I_obj[2] * a[2] * a[2]; /* eq. (27) */
  nl = 0.0;
  for (i = 0; i < nc; ++i) {
    double t = 0.0;
#ifdef SCENE_in_norm /* the rows of the norm (a spatial scene: not the ground's support) */
    if (scene[SCENE_in_norm + i] == 0.0) continue;
    for (r = 0; r < nc; ++r) t += scene[SCENE_in_norm + r] != 0.0 ? G[i + nc * r] * lam[r] : 0.0;
#else
    for (r = 0; r < nc; ++r) t += G[i + nc * r] * lam[r];
#endif
    nl += lam[i] * t;
  }
  out[OUT_norm_qdd] = nq;
  out[OUT_norm_a_obj] = na;
  out[OUT_norm_lambda] = nl;
  out[OUT_sr] = na / (na + nq > 1e-300 ? na + nq : 1e-300); /* eq. (30) */
  /* physically possible (snakecg.rows._sane) */
  scale = fabs(nq);
  if (fabs(na) > scale) scale = fabs(na);
  if (fabs(nl) > scale) scale = fabs(nl);
  if (!isfinite(scale) || !isfinite(out[OUT_sr]) || !all_finite(qdd, ns, INFINITY) ||
      !all_finite(a, 3, INFINITY))
    goto edge;
  if (nq < -c->sane_tol * scale || na < -c->sane_tol * scale || nl < -c->sane_tol * scale ||
      out[OUT_sr] < -c->sane_tol || out[OUT_sr] > 1.0 + c->sane_tol)
    goto edge;
  if (state[0] != HELD) out[OUT_sr] = 0.0; /* eq. 30: no interaction without contact */
  out[OUT_gap] = sys.gap;
  out[OUT_conditioning] = pivot < mass ? (pivot < 1.0 ? pivot : 1.0) : (mass < 1.0 ? mass : 1.0);
  out[OUT_singular] = 0.0;
  for (r = 0; r < nc; ++r) out[OUT_state + r] = (double)state[r];
  return STATUS_EXACT;
edge: /* the rare sample: the reference rules, in rows.c (a spatial scene flags it) */
#ifdef SCENE_in_norm
  (void)system_ok;
  return STATUS_FALLBACK;
#else
  {
    int at_rest = 1;
    for (r = 0; r < ns; ++r) at_rest &= v[r] == 0.0;
    for (r = 0; r < 3; ++r) at_rest &= v_obj[r] == 0.0;
    sc_forward_edge(system_ok ? &sys : 0, scene, c, max_iter, at_rest,
                    system_ok ? mass_pivot_ratio(M, S) : 0.0, out);
    return (int)out[OUT_status];
  }
#endif
}


/* The forward analysis of n samples.
 *
 * in[k] (k = IN_q, IN_v, IN_tau, IN_q_obj, IN_v_obj, IN_f_obj, IN_rho): sample i at
 * in[k] + i * stride[k] (stride 0 broadcasts); in[IN_q_obj] == NULL places the object from q
 * (then in[IN_rho] is ignored). out: row i at out + i * OUT_WIDTH.
 *
 * Returns 0 when every sample was evaluated (out[OUT_status] of each row tells whether the
 * reference path must redo it), -1 when out of memory, and -(2 + i) when an input of sample i
 * is not finite or beyond the force limit (nothing is worth keeping then: the runtime raises
 * before any result is used). */
int SNAKECG_EXPORT(core_forward)(sc_int n, const double *scene, const double *constants,
                                 sc_int max_iter, const double *const *in, const sc_int *stride,
                                 double *out) {
  sc_work_t ws;
  const sc_work_fn fns[] = {SC_CS_WORKS};
  sc_constants c;
  sc_int i;
  double vlim;
  c.pivot_tol = constants[0];
  c.weak = constants[1];
  c.rel_tol = constants[2];
  c.mass_tol = constants[3];
  c.sane_tol = constants[4];
  c.force_limit = constants[5];
  c.row_tol = constants[6];
  c.regularization = constants[7];
  vlim = sqrt(c.force_limit);
  /* inputs first: bad input refuses the whole call before any work */
  for (i = 0; i < n; ++i) {
    if (!all_finite(in[IN_q] + i * stride[IN_q], SNAKECG_NQ, INFINITY) ||
        !all_finite(in[IN_v] + i * stride[IN_v], SNAKECG_NS, vlim) ||
        !all_finite(in[IN_tau] + i * stride[IN_tau], SNAKECG_NA, c.force_limit) ||
        !all_finite(in[IN_v_obj] + i * stride[IN_v_obj], 3, vlim) ||
        !all_finite(in[IN_f_obj] + i * stride[IN_f_obj], 3, c.force_limit) ||
        (in[IN_q_obj] && (!all_finite(in[IN_q_obj] + i * stride[IN_q_obj], 3, INFINITY) ||
                          !all_finite(in[IN_rho] + i * stride[IN_rho], 2, INFINITY))))
      return (int)(-2 - (i < 2000000000 ? i : 2000000000));
  }
  if (sc_work_alloc(&ws, fns, SC_COUNT(fns))) return -1;
  for (i = 0; i < n; ++i) {
    double *row = out + i * OUT_WIDTH;
    const double *qo = in[IN_q_obj] ? in[IN_q_obj] + i * stride[IN_q_obj] : 0;
    const double *rh = in[IN_q_obj] ? in[IN_rho] + i * stride[IN_rho] : 0;
    row[OUT_status] = (double)solve_one(
        &ws, scene, &c, (long)max_iter, in[IN_q] + i * stride[IN_q], in[IN_v] + i * stride[IN_v],
        in[IN_tau] + i * stride[IN_tau], qo, in[IN_v_obj] + i * stride[IN_v_obj],
        in[IN_f_obj] + i * stride[IN_f_obj], rh, row);
  }
  sc_work_free(&ws);
  return 0;
}

/* core_forward with its arguments in one struct: the runtime's one-sample calls pass a single
 * pointer (a foreign call's cost grows with its argument count). */
typedef struct {
  sc_int n;
  const double *scene;
  const double *constants;
  sc_int max_iter;
  const double *const *in;
  const sc_int *stride;
  double *out;
} sc_call;

int SNAKECG_EXPORT(core_forward_call)(const sc_call *call) {
  return SNAKECG_EXPORT(core_forward)(call->n, call->scene, call->constants, call->max_iter,
                                      call->in, call->stride, call->out);
}

/* The state update alone, for the tests that hold it against snakecg/solver.py's rules at the
 * tolerance edges: state (SNAKECG_NC codes, as doubles) is updated in place; returns 1 if a row
 * moved. */
int SNAKECG_EXPORT(core_next_states)(double *state, const double *lam, const double *w,
                                     const double *G, const double *bounds, double rel_tol) {
  signed char s[SNAKECG_NC];
  int r, moved;
  for (r = 0; r < SNAKECG_NC; ++r) s[r] = (signed char)state[r];
  moved = sc_next_states(s, lam, w, G, bounds, rel_tol);
  for (r = 0; r < SNAKECG_NC; ++r) state[r] = (double)s[r];
  return moved;
}
