/* snakecg's engine: the optimal-torque queries of snakecg.optimize, every objective and
 * every input region, for a batch of configurations in one call (types and codes in
 * engine.h; the methods in docs/how-to/optimize.md).
 *
 * This file is part of the runtime (not generated); like forward.c it is compiled once per
 * model into the model's shared library. It holds the batch loop, what the kinds share and
 * the forward check; the kinds are max_sr.c, push.c and wheel_states.c. Per configuration:
 *
 * 1. the system at rest with the object placed and the all-held maps (maps.c); dependent held
 *    rows (pivot ratio at or below pivot_tol) leave the maps undefined: "failed";
 * 2. one frictionless point contact pushes the object along its normal only, a_obj = a_dir
 *    lam_c with a_dir = A l / (l . l) (l = L_c, the contact force's row): every push task is a
 *    bound on lam_c, and k = a_dir^T I_obj a_dir makes Omega = k l l^T (eq. 29);
 * 3. the solve: max_sr.c (every row held: the generalized eigenproblem of eqs. 28-30),
 *    wheel_states.c (max_sr with wheels allowed to slide), push.c (least_slip_push: a convex
 *    QP or QCQP; strongest_push: an LP or its QCQP), on the QP block of qp.c;
 * 4. the certificate on the original problem in tau (qp.c sc_kkt_certificate, or for max_sr
 *    the eigenproblem's residual and the top eigenvalue of Omega - sr (Omega + Xi)): "optimal"
 *    only when it holds;
 * 5. the exact forward solve at the answer (forward.c's core_forward, as SceneModel.forward
 *    runs it) and the forward check: the objective read from it, the limits, the contact and
 *    the wheels as the optimiser kept them.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
/* ---------------------------------------------------------------------------------------
 * what the kinds share */
void sc_optimal_bind(sc_optimal *o, int code) {
  int nb = (int)o->out[OPT_OUT_n_binding], j;
  for (j = 0; j < nb; ++j)
    if ((int)o->out[OPT_OUT_binding + j] == code) return;
  o->out[OPT_OUT_binding + nb] = code;
  o->out[OPT_OUT_n_binding] = nb + 1;
}

/* the forward solve at tau, one sample at rest, the object placed: core_forward's status
 * (0: the row's own status tells whether it is exact) */
int sc_optimal_forward(sc_optimal *o, const double *tau, double *row) {
  static const double zero[NS + 3] = {0.0};
  const double *in[7];
  sc_int stride[7] = {0, 0, 0, 0, 0, 0, 0};
  in[IN_q] = o->q;
  in[IN_v] = zero;
  in[IN_tau] = tau;
  in[IN_q_obj] = 0;
  in[IN_v_obj] = zero;
  in[IN_f_obj] = zero;
  in[IN_rho] = 0;
  return SNAKECG_EXPORT(core_forward)(1, o->scene, o->fw_constants, o->max_iter, in, stride,
                                      row);
}

/* The verdict on the residuals (stationarity, primal feasibility, complementarity, gap; NaN
 * gap: not defined), written as the answer's certificate; 1 when every one is within its
 * tolerance. */
void sc_optimal_certify(sc_optimal *o, int kind, const double *values, int resolved) {
  const double *in = o->in;
  int ok = fabs(values[0]) <= in[OPT_IN_tol_stationarity] &&
           fabs(values[1]) <= in[OPT_IN_tol_primal] &&
           fabs(values[2]) <= in[OPT_IN_tol_complementarity] &&
           (isnan(values[3]) || fabs(values[3]) <= in[OPT_IN_tol_gap]);
  SC_SET(o, certificate, kind);
  SC_SET(o, certified, ok);
  SC_SET(o, stationarity, values[0]);
  SC_SET(o, primal_feasibility, values[1]);
  SC_SET(o, complementarity, values[2]);
  SC_SET(o, duality_gap, values[3]);
  SC_SET(o, resolved, resolved);
}

int sc_optimal_certified(const sc_optimal *o) { return o->out[OPT_OUT_certified] != 0.0; }

void sc_optimal_status(sc_optimal *o, int status, int reason) {
  SC_SET(o, status, status);
  SC_SET(o, reason, reason);
}

/* the answer becomes "optimal" when certified, else "failed" with the certificate's reason */
void sc_optimal_if_certified(sc_optimal *o) {
  if (sc_optimal_certified(o)) sc_optimal_status(o, SC_OPTIMAL, SC_REASON_NONE);
  else sc_optimal_status(o, SC_FAILED, SC_REASON_CERTIFICATE);
}

void sc_optimal_count(sc_optimal *o, const sc_qp_solution *s, int qcqp) {
  o->out[OPT_OUT_qp_solves] += qcqp ? (double)s->iterations : 1.0;
  o->out[OPT_OUT_newton_steps] += (double)s->newton;
}

/* ---------------------------------------------------------------------------------------
 * the query and the model's bounded wheels, read once per call */
static void read_query(sc_optimal *o) {
  const double *in = o->in, *present = o->scene + SCENE_present, *bounds = o->scene + SCENE_bounds;
  int r;
  o->kind = (int)in[OPT_IN_kind];
  o->radius = in[OPT_IN_radius];
  o->r2 = isfinite(o->radius) ? o->radius * o->radius : 0.0;
  o->tau_max = isnan(in[OPT_IN_tau_max]) ? 0 : in + OPT_IN_tau_max;
  o->direction = isnan(in[OPT_IN_direction]) ? 0 : in + OPT_IN_direction;
  o->a_obj = isnan(in[OPT_IN_a_obj]) ? 0 : in + OPT_IN_a_obj;
  o->a_min = in[OPT_IN_a_min];
  o->any_slide = 0;
  o->nw = 0;
  for (r = 0; r < NC; ++r) {
    o->slide[r] = in[OPT_IN_slide + r] != 0.0;
    o->any_slide |= o->slide[r];
    if (r > 0 && present[r] != 0.0 && isfinite(bounds[r])) {
      o->wheel_row[o->nw] = r;
      o->wheel_ub[o->nw++] = bounds[r] * (1.0 - in[OPT_IN_friction_margin]);
    }
  }
}

/* ---------------------------------------------------------------------------------------
 * the forward check */

/* The objective read from the forward row and the check of an "optimal" answer against it
 * (the row must be exact: out[OPT_OUT_forward + OUT_status] == 0). */
static void objective_and_check(const double *in, double *out) {
  const double *row = out + OPT_OUT_forward, *tau = out + OPT_OUT_tau;
  double value, *cd = out + OPT_OUT_check_detail, expected = out[OPT_OUT_expected];
  int kind = (int)in[OPT_IN_kind], j, i;
  if (kind == SC_MAX_SR) {
    value = row[OUT_sr];
  } else if (kind == SC_LEAST_SLIP_PUSH) {
    value = row[OUT_norm_qdd];
  } else {
    double d[3], nd = 0.0;
    if (!isnan(in[OPT_IN_direction])) {
      for (j = 0; j < 3; ++j) d[j] = in[OPT_IN_direction + j];
      nd = 1.0;
    } else {
      for (j = 0; j < 3; ++j) {
        d[j] = out[OPT_OUT_a_dir + j];
        nd += d[j] * d[j];
      }
      nd = sqrt(nd);
      nd = nd > 1e-300 ? nd : 1e-300;
    }
    value = 0.0;
    for (j = 0; j < 3; ++j) value += d[j] / nd * row[OUT_a_obj + j];
  }
  out[OPT_OUT_objective_value] = value;
  out[OPT_OUT_check] = SC_CHECK_PASSED;
  if (out[OPT_OUT_status] != SC_OPTIMAL) return;
  if (isnan(value) && row[OUT_status] >= 2) { /* the forward solve has no answer there */
    out[OPT_OUT_status] = SC_FAILED;
    out[OPT_OUT_reason] = SC_REASON_NO_ANSWER;
    out[OPT_OUT_detail + 1] = row[OUT_status]; /* its reason's code */
    return;
  }
#define FAIL(code) (out[OPT_OUT_check] = (code), out[OPT_OUT_status] = SC_FAILED, \
                    out[OPT_OUT_reason] = SC_REASON_FORWARD_CHECK)
  if (!isnan(in[OPT_IN_tau_max])) {
    double worst = 0.0;
    int at = 0;
    for (j = 0; j < NA; ++j)
      if (fabs(tau[j]) / in[OPT_IN_tau_max + j] > worst) {
        worst = fabs(tau[j]) / in[OPT_IN_tau_max + j];
        at = j;
      }
    if (worst > 1 + 1e-9) {
      cd[0] = at;
      cd[1] = fabs(tau[at]);
      cd[2] = in[OPT_IN_tau_max + at];
      FAIL(SC_CHECK_TAU_MAX);
      return;
    }
  }
  if (isfinite(in[OPT_IN_radius])) {
    double r2 = in[OPT_IN_radius] * in[OPT_IN_radius];
    if (out[OPT_OUT_form] > r2 * (1 + 1e-7)) {
      cd[0] = out[OPT_OUT_form];
      cd[1] = r2;
      FAIL(SC_CHECK_ELLIPSOID);
      return;
    }
  }
  if (row[OUT_state] != HELD) {
    FAIL(SC_CHECK_SEPARATES);
    return;
  }
  for (i = 1; i < NC; ++i) {
    int s = (int)row[OUT_state + i];
    if ((s == SLIDE_POS || s == SLIDE_NEG) && in[OPT_IN_slide + i] == 0.0) {
      cd[0] = i;
      cd[1] = s;
      FAIL(SC_CHECK_SLIDES);
      return;
    }
  }
  if (!isnan(expected)) {
    double scale = fabs(expected), alt = kind == SC_MAX_SR ? 1.0 : fabs(value);
    scale = alt > scale ? alt : scale;
    scale = scale > 1e-300 ? scale : 1e-300;
    if (!(fabs(value - expected) <= in[OPT_IN_check_tol] * scale)) {
      cd[0] = value;
      cd[1] = expected;
      FAIL(SC_CHECK_OBJECTIVE);
      return;
    }
  }
  if (kind == SC_LEAST_SLIP_PUSH) {
    if (!isnan(in[OPT_IN_a_obj])) {
      double e = 0.0, an = 0.0;
      for (j = 0; j < 3; ++j) {
        double dj = row[OUT_a_obj + j] - in[OPT_IN_a_obj + j];
        e += dj * dj;
        an += in[OPT_IN_a_obj + j] * in[OPT_IN_a_obj + j];
      }
      an = sqrt(an);
      if (sqrt(e) > 1e-6 * (an > 1e-12 ? an : 1e-12)) {
        cd[0] = sqrt(e);
        FAIL(SC_CHECK_A_OBJ);
        return;
      }
    } else {
      double got = 0.0;
      for (j = 0; j < 3; ++j) got += in[OPT_IN_direction + j] * row[OUT_a_obj + j];
      if (got < in[OPT_IN_a_min] * (1 - 1e-6)) {
        cd[0] = got;
        cd[1] = in[OPT_IN_a_min];
        FAIL(SC_CHECK_A_MIN);
        return;
      }
    }
  }
#undef FAIL
}

/* ---------------------------------------------------------------------------------------
 * one configuration */
static void clear_answer(double *out) {
  int j;
  for (j = 0; j < OPT_OUT_WIDTH; ++j) out[j] = 0.0;
  out[OPT_OUT_status] = SC_FAILED;
  out[OPT_OUT_expected] = NAN;
  out[OPT_OUT_duality_gap] = NAN;
  for (j = 0; j < NC; ++j) out[OPT_OUT_wheel_states + j] = -1.0;
}

static void configuration(sc_optimal *o) {
  signed char state[NC];
  const double *present = o->scene + SCENE_present;
  double Lc[NA * NA], e[NA], ll, Io[3];
  const double *ell;
  int r, i, j, ok;
  clear_answer(o->out);
  /* 1. the system at rest and the all-held maps */
  for (r = 0; r < NC; ++r) state[r] = present[r] != 0.0 ? HELD : ABSENT;
  ok = sc_rest_system(o->ws, o->scene, o->q, &o->rest) == 0; /* M_s positive definite */
  if (ok) {
    double ratio = sc_state_maps(&o->rest, o->scene, state, 1, &o->held);
    if (isfinite(ratio) && !(ratio > o->fw_constants[0])) {
      sc_optimal_status(o, SC_FAILED, SC_REASON_SINGULAR); /* dependent held rows */
      return;
    }
    ok = isfinite(ratio);
  }
  for (i = 0; ok && i < NC * NA; ++i) ok = isfinite(o->held.L[i]);
  for (i = 0; ok && i < NA1 * NA1; ++i) ok = isfinite(o->held.Xih[i]);
  for (i = 0; ok && i < NA * NA; ++i) ok = isfinite(o->rest.N[i]) && isfinite(o->held.Om[i]);
  if (!ok) { /* the system at rest is not usable in float64: the caller asks the forward
              * solve at zero torque why */
    sc_optimal_status(o, SC_FAILED, SC_REASON_UNANSWERABLE);
    return;
  }
  /* 2. a_obj = a_dir lam_c, k = a_dir^T I_obj a_dir */
  ell = o->held.L;
  ll = sc_dot(ell, ell, NA);
  Io[0] = Io[1] = o->scene[SCENE_object_mass];
  Io[2] = o->scene[SCENE_object_inertia];
  o->k = 0.0;
  for (i = 0; i < 3; ++i) {
    o->a_dir[i] = ll > 0 ? sc_dot(o->held.A + i * NA, ell, NA) / ll : 0.0;
    o->k += Io[i] * o->a_dir[i] * o->a_dir[i];
    o->out[OPT_OUT_a_dir + i] = o->a_dir[i];
  }
  SC_SET(o, k, o->k);
  /* the region's bounding box: the box, and r sqrt((N^-1)_jj) of the ellipsoid */
  for (j = 0; j < NA; ++j) o->widths[j] = o->tau_max ? o->tau_max[j] : INFINITY;
  if (o->r2 > 0) {
    memcpy(Lc, o->rest.N, sizeof Lc);
    if (!sc_cholesky(NA, Lc, NA, 0.0)) {
      sc_optimal_status(o, SC_FAILED, SC_REASON_UNANSWERABLE);
      return;
    }
    for (j = 0; j < NA; ++j) {
      double b;
      for (i = 0; i < NA; ++i) e[i] = i == j ? 1.0 : 0.0;
      sc_cholesky_solve(NA, Lc, NA, e);
      b = o->radius * sqrt(e[j]);
      if (b < o->widths[j]) o->widths[j] = b;
    }
  }
  /* 3-4. the solve and its certificate */
  if (o->kind == SC_MAX_SR) sc_max_sr(o);
  else if (o->kind == SC_LEAST_SLIP_PUSH) sc_least_slip_push(o);
  else sc_strongest_push(o);
  SC_SET(o, form, sc_quad(NA, o->rest.N, NA, SC_OUT(o, tau)));
}

/* The answers of n configurations q (n x NS, row-major) to the query `in` (OPT_IN_*), into out
 * (n x OPT_OUT_WIDTH): the solve, its certificate, the forward solve at the answer and the
 * forward check (left to the caller, OPT_OUT_check = SC_CHECK_PENDING, where the forward row
 * is not exact: the reference path then solves it, and core_optimal_check finishes).
 * Returns 0; -1 when out of memory. */
int SNAKECG_EXPORT(core_optimal)(sc_int n, const double *scene, const double *fw_constants,
                                 sc_int max_iter, const double *in, const double *q,
                                 double *out) {
  sc_optimal o;
  sc_int i;
#if SC_QP_WORK_DOUBLES(NA1, SC_ROWS_MAX) <= 65536
  /* the QP block's scratch on the stack (at most 512 kB): a large allocation per call costs
   * more than the solve when the process's heap is busy (malloc consolidates its bins) */
  double qd[SC_QP_WORK_DOUBLES(NA1, SC_ROWS_MAX)];
  sc_int qi[SC_QP_WORK_INTS(NA1, SC_ROWS_MAX)];
  sc_qp_work_init(&o.qw, NA1, SC_ROWS_MAX, qd, qi);
#define SC_QP_WORK_FREE(w)
#else
  if (sc_qp_work_alloc(&o.qw, NA1, SC_ROWS_MAX)) return -1;
#define SC_QP_WORK_FREE(w) sc_qp_work_free(w)
#endif
  o.scene = scene;
  o.fw_constants = fw_constants;
  o.max_iter = max_iter;
  o.in = in;
  read_query(&o);
  o.ws = sc_rest_work_new();
  if (!o.ws) {
    SC_QP_WORK_FREE(&o.qw);
    return -1;
  }
  for (i = 0; i < n; ++i) {
    double *tau, *row;
    int j, finite = 1;
    o.q = q + i * NS;
    o.out = out + i * OPT_OUT_WIDTH;
    configuration(&o);
    tau = o.out + OPT_OUT_tau;
    row = o.out + OPT_OUT_forward;
    if (o.out[OPT_OUT_reason] == SC_REASON_UNANSWERABLE) { /* (the caller words why) */
      o.out[OPT_OUT_objective_value] = NAN;
      continue;
    }
    for (j = 0; j < NA; ++j) finite &= fabs(tau[j]) <= fw_constants[5];
    if (!finite) { /* no torque to check (the caller words why): the answer has failed */
      double big = 0.0;
      for (j = 0; j < NA; ++j)
        if (!(fabs(tau[j]) <= big)) big = fabs(tau[j]); /* NaN wins */
      o.out[OPT_OUT_detail] = big;
      sc_optimal_status(&o, SC_FAILED, SC_REASON_NOT_FINITE);
      o.out[OPT_OUT_objective_value] = NAN;
      continue;
    }
    o.out[OPT_OUT_forward_status] = sc_optimal_forward(&o, tau, row);
    if (o.out[OPT_OUT_forward_status] != 0 || row[OUT_status] != 0) {
      o.out[OPT_OUT_check] = SC_CHECK_PENDING;
      continue;
    }
    objective_and_check(in, o.out);
  }
  SC_QP_WORK_FREE(&o.qw);
#undef SC_QP_WORK_FREE
  sc_rest_work_free(o.ws);
  return 0;
}

/* The forward check of the answers whose forward row the caller has solved by the reference
 * path (OPT_OUT_check == SC_CHECK_PENDING, the row now in place). */
int SNAKECG_EXPORT(core_optimal_check)(sc_int n, const double *in, double *out) {
  sc_int i;
  for (i = 0; i < n; ++i)
    if (out[i * OPT_OUT_WIDTH + OPT_OUT_check] == SC_CHECK_PENDING)
      objective_and_check(in, out + i * OPT_OUT_WIDTH);
  return 0;
}

/* ---------------------------------------------------------------------------------------
 * The building blocks alone, for tests against independent references (snakecg.engine.optimal:
 * the QP, the QCQP, the certificate, the symmetric eigensolver). Sizes up to n variables and m
 * rows of the caller's choosing. */
int SNAKECG_EXPORT(core_qp_solve)(sc_int n, sc_int m, const double *H, const double *g,
                                  const double *A, const double *lo, const double *hi,
                                  const double *N, double rho2, double mu0, double *x,
                                  double *lam, double *info) {
  sc_qp_work w;
  sc_qp qp;
  sc_qp_solution s;
  sc_int *act;
  int st;
  if (sc_qp_work_alloc(&w, n, m)) return -1;
  act = (sc_int *)malloc(sizeof(sc_int) * (size_t)(n + 1));
  if (!act) {
    sc_qp_work_free(&w);
    return -1;
  }
  sc_qp_define(&qp, n, m, H, g, A, lo, hi);
  sc_qp_solution_define(&s, x, lam, act);
  st = N ? sc_qcqp_ellipsoid(&qp, N, rho2, mu0, &w, &s) : sc_qp_solve(&qp, &w, &s);
  info[0] = (double)s.n_active;
  info[1] = (double)s.iterations;
  info[2] = (double)s.newton;
  info[3] = s.mu;
  free(act);
  sc_qp_work_free(&w);
  return st;
}

int SNAKECG_EXPORT(core_kkt_certificate)(sc_int n, const double *x, const double *H,
                                         const double *c, sc_int m, const double *G,
                                         const double *lo, const double *hi, const double *Q,
                                         double r2, sc_int convex, double active,
                                         double stationarity_tol, double *values, double *lam,
                                         double *mu) {
  sc_qp_work w;
  if (sc_qp_work_alloc(&w, n, m)) return -1;
  sc_kkt_certificate(n, x, H, c, m, G, lo, hi, Q, r2, (int)convex, active, stationarity_tol,
                     values, lam, mu, &w);
  sc_qp_work_free(&w);
  return 0;
}

int SNAKECG_EXPORT(core_eigen_symmetric)(sc_int n, double *A, double *w, double *V) {
  return sc_eigen_symmetric(n, A, n, w, V, n);
}
