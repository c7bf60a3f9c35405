/* snakecg's runtime core: the optimal-torque queries of snakecg.optimize, every objective and
 * every input region, for a batch of configurations in one call (types and codes in
 * optimal.h; the methods in docs/optimize.md).
 *
 * This file is part of the runtime (not generated); like forward.c it is compiled once per
 * model into the model's shared library. Per configuration (sc_optimal_configuration):
 *
 * 1. the system at rest with the object placed and the all-held maps (maps.c); dependent held
 *    rows (pivot ratio at or below pivot_tol) leave the maps undefined: "failed";
 * 2. one frictionless point contact pushes the object along its normal only, a_obj = a_dir
 *    lam_c with a_dir = A l / (l . l) (l = L_c, the contact force's row): every push task is a
 *    bound on lam_c, and k = a_dir^T I_obj a_dir makes Omega = k l l^T (eq. 29);
 * 3. the solve:
 *    - max_sr, every row held: sr is the generalized Rayleigh quotient of (Omega, Omega + Xi)
 *      (eqs. 28-30), homogeneous of degree 0; its top eigenvector, signed so that lam_c >= 0,
 *      is the maximiser over any region star-shaped about 0, returned at the largest magnitude
 *      that keeps every limit. With Omega = k l l^T the top is the closed form
 *      sr = k c / (k c + 1) at v = Xi^-1 l, c = l^T Xi^-1 l; otherwise (Xi not safely
 *      definite) the eigenproblem restricted to the range of Omega + Xi, by Jacobi rotations;
 *      wheels allowed to slide: wheel_states.c;
 *    - least_slip_push: min tau^T Xi tau (eq. 26) s.t. the task on lam_c, the contact, every
 *      wheel within its friction bound (backed off by the friction margin) and the region: a
 *      convex QP (the box) or QCQP (the ellipsoid of eq. 31), in the torque scaled by the
 *      region's bounding box, by the dual active set and the ellipsoid's multiplier (qp.c); an
 *      infeasible task is diagnosed by the strongest push;
 *    - strongest_push: max lam_c (d . a_obj = gamma lam_c) s.t. the same limits: an LP (solved
 *      as the QP with the tiny curvature lp_reg, which picks the vertex exactly and, on a
 *      degenerate optimal face, the face's point nearest the origin), with the ellipsoid
 *      through its multiplier, in closed form on the ellipsoid alone; a degenerate optimum is
 *      broken by the least slip among the strongest pushes;
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
#include "optimal.h"

#define OUTP(o, f) ((o)->out + OPT_OUT_##f)
#define SET(o, f, v) ((o)->out[OPT_OUT_##f] = (v))

/* ---------------------------------------------------------------------------------------
 * small pieces shared with wheel_states.c */
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
  SET(o, certificate, kind);
  SET(o, certified, ok);
  SET(o, stationarity, values[0]);
  SET(o, primal_feasibility, values[1]);
  SET(o, complementarity, values[2]);
  SET(o, duality_gap, values[3]);
  SET(o, resolved, resolved);
}

static int certified(const sc_optimal *o) { return o->out[OPT_OUT_certified] != 0.0; }

static void set_status(sc_optimal *o, int status, int reason) {
  SET(o, status, status);
  SET(o, reason, reason);
}

/* the answer becomes "optimal" when certified, else "failed" with the certificate's reason */
static void optimal_if_certified(sc_optimal *o) {
  if (certified(o)) set_status(o, SC_OPTIMAL, SC_REASON_NONE);
  else set_status(o, SC_FAILED, SC_REASON_CERTIFICATE);
}

static void count_solve(sc_optimal *o, const sc_qp_solution *s, int qcqp) {
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
 * max_sr with every row held */

/* the largest s > 0 with s v inside every limit, the limits that set it bound (in the order
 * ellipsoid, joints, wheels) */
static double scale_onto_limits(sc_optimal *o, const double *v) {
  double cand[1 + NA + NC], s = INFINITY;
  int code[1 + NA + NC], nc = 0, j, w;
  if (o->r2 > 0) {
    double qv = sc_quad(NA, o->rest.N, NA, v);
    cand[nc] = o->radius / sqrt(qv > 1e-300 ? qv : 1e-300);
    code[nc++] = SC_BIND_ELLIPSOID;
  }
  if (o->tau_max)
    for (j = 0; j < NA; ++j)
      if (fabs(v[j]) > 0) {
        cand[nc] = o->tau_max[j] / fabs(v[j]);
        code[nc++] = SC_BIND_JOINT + j;
      }
  for (w = 0; w < o->nw; ++w) {
    double li = sc_dot(o->held.L + o->wheel_row[w] * NA, v, NA);
    if (fabs(li) > 0) {
      cand[nc] = o->wheel_ub[w] / fabs(li);
      code[nc++] = SC_BIND_WHEEL(o->wheel_row[w]);
    }
  }
  for (j = 0; j < nc; ++j)
    if (cand[j] < s) s = cand[j];
  for (j = 0; j < nc; ++j)
    if (cand[j] <= s * (1 + 1e-9)) sc_optimal_bind(o, code[j]);
  return s;
}

/* the top generalized eigenpair of (Om, D), D positive semidefinite, restricted to the range of
 * D (directions outside it move nothing: sr is 0/0 there): D = V diag(w) V^T, Vr the columns
 * with w_j > 1e-12 max w scaled by w_j^-1/2, then the top eigenpair of Vr^T Om Vr. */
static double top_rayleigh(const double *Om, const double *D, double *v) {
  double E[NA * NA], V[NA * NA], w[NA], Vr[NA * NA], C[NA * NA], U[NA * NA], lw[NA], top;
  int i, j, l, r = 0, keep[NA];
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) E[i * NA + j] = 0.5 * (D[i * NA + j] + D[j * NA + i]);
  sc_eigen_symmetric(NA, E, NA, w, V, NA);
  top = w[NA - 1] > 1e-300 ? w[NA - 1] : 1e-300;
  for (j = 0; j < NA; ++j)
    if (w[j] > 1e-12 * top) keep[r++] = j;
  for (i = 0; i < NA; ++i)
    for (j = 0; j < r; ++j) Vr[i * NA + j] = V[i * NA + keep[j]] / sqrt(w[keep[j]]);
  for (i = 0; i < r; ++i)
    for (j = 0; j < r; ++j) {
      double s = 0.0;
      for (l = 0; l < NA; ++l) {
        double t = 0.0;
        int m;
        for (m = 0; m < NA; ++m) t += Om[l * NA + m] * Vr[m * NA + j];
        s += Vr[l * NA + i] * t;
      }
      C[i * NA + j] = s;
    }
  for (i = 0; i < r; ++i) /* symmetric part */
    for (j = 0; j < i; ++j) C[i * NA + j] = C[j * NA + i] = 0.5 * (C[i * NA + j] + C[j * NA + i]);
  if (!r) {
    for (i = 0; i < NA; ++i) v[i] = 0.0;
    return 0.0;
  }
  sc_eigen_symmetric(r, C, NA, lw, U, NA);
  for (i = 0; i < NA; ++i) {
    double s = 0.0;
    for (j = 0; j < r; ++j) s += Vr[i * NA + j] * U[j * NA + r - 1];
    v[i] = s;
  }
  return lw[r - 1];
}

/* largest relative violation at tau of the all-held limits (wheels within their backed-off
 * bounds, the box, the contact kept, the ellipsoid), each relative to its row's size */
static double held_violation(const sc_optimal *o, const double *tau) {
  const double *ell = o->held.L;
  double worst = 0.0, at[NA], g;
  int j, w;
  for (j = 0; j < NA; ++j) at[j] = fabs(tau[j]);
  for (w = 0; w < o->nw; ++w) {
    const double *row = o->held.L + o->wheel_row[w] * NA;
    double ub = o->wheel_ub[w];
    g = fabs(sc_dot(row, tau, NA));
    if (g > ub) {
      double rs = ub, v;
      for (j = 0; j < NA; ++j) rs += fabs(row[j]) * at[j];
      v = (g - ub) / (rs > 0 ? rs : 1.0);
      if (v > worst) worst = v;
    }
  }
  if (o->tau_max)
    for (j = 0; j < NA; ++j) {
      double t = at[j], m = o->tau_max[j];
      if (t > m && (t - m) / (t + m) > worst) worst = (t - m) / (t + m);
    }
  g = sc_dot(ell, tau, NA);
  if (g < 0) {
    double rs = 0.0, v;
    for (j = 0; j < NA; ++j) rs += fabs(ell[j]) * at[j];
    v = -g / (rs > 0 ? rs : 1.0);
    if (v > worst) worst = v;
  }
  if (o->r2 > 0) {
    double e = sc_quad(NA, o->rest.N, NA, tau);
    if (e > o->r2) {
      double qs = o->r2, v;
      int i;
      for (i = 0; i < NA; ++i)
        for (j = 0; j < NA; ++j) qs += at[i] * fabs(o->rest.N[i * NA + j]) * at[j];
      v = (e - o->r2) / (qs > 0 ? qs : 1.0);
      if (v > worst) worst = v;
    }
  }
  return worst;
}

/* tau maximises the Rayleigh quotient of eqs. (28)-(30) iff Omega - sr(tau) D is negative
 * semidefinite (D = Omega + Xi): its largest eigenvalue relative to ||D|| is the gap, the
 * residual of Omega tau = sr D tau the stationarity; plus primal feasibility */
static void eigen_certificate(sc_optimal *o, const double *tau, int resolved) {
  double D[NA * NA], S[NA * NA], Dt[NA], Ot[NA], rr[NA], w[NA], values[4], den, sr, nD, top,
      scale;
  const double *Om = o->held.Om;
  int i, j;
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) D[i * NA + j] = Om[i * NA + j] + o->held.Xih[i * NA1 + j];
  sc_matvec(NA, NA, D, NA, tau, Dt);
  sc_matvec(NA, NA, Om, NA, tau, Ot);
  den = sc_dot(tau, Dt, NA);
  sr = den > 0 ? sc_dot(tau, Ot, NA) / den : 0.0;
  nD = sc_frobenius(NA, NA, D, NA);
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j)
      S[i * NA + j] = 0.5 * ((Om[i * NA + j] - sr * D[i * NA + j]) +
                             (Om[j * NA + i] - sr * D[j * NA + i]));
  sc_eigen_symmetric(NA, S, NA, w, 0, NA);
  top = w[NA - 1];
  scale = (sc_frobenius(NA, NA, Om, NA) + nD) * sc_norm(tau, NA);
  for (i = 0; i < NA; ++i) rr[i] = Ot[i] - sr * Dt[i];
  values[0] = scale > 0 ? sc_norm(rr, NA) / scale : 0.0;
  values[1] = held_violation(o, tau);
  values[2] = 0.0;
  values[3] = (top > 0.0 ? top : 0.0) / (nD > 1e-300 ? nD : 1e-300);
  sc_optimal_certify(o, SC_CERT_EIGEN, values, resolved);
}

/* the answer of the eigenproblem, the closed form first (unless `general`) */
static void max_sr_direction(sc_optimal *o, int general) {
  double Xi[NA * NA], D[NA * NA], v[NA], *tau = OUTP(o, tau), lam, s;
  const double *ell = o->held.L;
  int i, j, closed = 0;
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) {
      Xi[i * NA + j] = o->held.Xih[i * NA1 + j];
      D[i * NA + j] = Xi[i * NA + j] + o->held.Om[i * NA + j];
    }
  if (!general && sc_cholesky(NA, Xi, NA, 1e-12)) { /* the rank-one closed form */
    double c;
    memcpy(v, ell, sizeof v);
    sc_cholesky_solve(NA, Xi, NA, v);
    c = sc_dot(ell, v, NA);
    if (c > 0) {
      double kc = o->k * c;
      lam = kc / (kc + 1.0);
      closed = 1;
    }
  }
  if (!closed) {
    lam = top_rayleigh(o->held.Om, D, v);
    if (sc_dot(ell, v, NA) < 0)
      for (i = 0; i < NA; ++i) v[i] = -v[i];
  }
  SET(o, method, closed ? SC_METHOD_RANK_ONE : SC_METHOD_EIGEN);
  SET(o, n_binding, 0);
  s = scale_onto_limits(o, v);
  for (i = 0; i < NA; ++i) tau[i] = s * v[i];
  SET(o, expected, lam > 0.0 ? (lam < 1.0 ? lam : 1.0) : 0.0);
}

static void max_sr(sc_optimal *o) {
  const double *ell = o->held.L;
  int j, any = 0;
  for (j = 0; j < NA; ++j) any |= ell[j] != 0.0;
  if (!(o->k > 0) || !any) {
    set_status(o, SC_INFEASIBLE, SC_REASON_NO_PUSH);
    sc_optimal_bind(o, SC_BIND_CONTACT);
    SET(o, method, SC_METHOD_EIGEN);
    return;
  }
  max_sr_direction(o, 0);
  eigen_certificate(o, OUTP(o, tau), 0);
  if (!certified(o) && ((int)o->out[OPT_OUT_method] & SC_METHOD_RANK_ONE)) {
    max_sr_direction(o, 1); /* the general eigenproblem instead of the closed form */
    eigen_certificate(o, OUTP(o, tau), 1);
  }
  optimal_if_certified(o);
  if (o->any_slide && certified(o)) sc_max_sr_sliding(o);
}

/* ---------------------------------------------------------------------------------------
 * the push tasks */

/* The task as a bound on the contact force (a_obj = a_dir lam_c): lam_c >= lam_lo (== when
 * equal), gain = d . a_dir (|a_dir| for a full acceleration); 0, or the reason why no torque
 * can do the task (with its binding code and the normal in the details). */
static int push_target(sc_optimal *o, const double *d, int *has_lo, double *lam_lo, int *equal,
                       double *gain) {
  const double *a = o->a_dir;
  double na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), h = hypot(a[0], a[1]);
  double *det = OUTP(o, detail);
  *has_lo = 0;
  *equal = 0;
  *lam_lo = 0.0;
  *gain = 0.0;
  if (na == 0 || !(o->k > 0)) {
    sc_optimal_bind(o, SC_BIND_CONTACT);
    return SC_REASON_NO_PUSH;
  }
  h = h > 1e-300 ? h : 1e-300;
  det[0] = a[0] / h; /* the contact normal n (in the plane) */
  det[1] = a[1] / h;
  det[2] = a[0];
  det[3] = a[1];
  det[4] = a[2];
  if (!d) { /* a full planar acceleration */
    const double *ao = o->a_obj;
    double s0 = (a[0] * ao[0] + a[1] * ao[1] + a[2] * ao[2]) / (na * na), e = 0.0, an = 0.0;
    int j;
    for (j = 0; j < 3; ++j) {
      e += (ao[j] - s0 * a[j]) * (ao[j] - s0 * a[j]);
      an += ao[j] * ao[j];
    }
    *gain = na;
    if (sqrt(e) > 1e-6 * (sqrt(an) > 1e-300 ? sqrt(an) : 1e-300)) {
      sc_optimal_bind(o, SC_BIND_NORMAL);
      return SC_REASON_OFF_NORMAL;
    }
    if (s0 < 0) {
      sc_optimal_bind(o, SC_BIND_CONTACT);
      return SC_REASON_AGAINST_NORMAL;
    }
    *has_lo = *equal = 1;
    *lam_lo = s0;
    return SC_REASON_NONE;
  }
  *gain = d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
  if (*gain <= 1e-9 * na) {
    sc_optimal_bind(o, SC_BIND_CONTACT);
    return SC_REASON_DIRECTION;
  }
  if (!isnan(o->a_min)) {
    *has_lo = 1;
    *lam_lo = o->a_min / *gain;
  }
  return SC_REASON_NONE;
}

/* one push problem in the torque scaled by the region's bounding box (y = tau / w), its rows
 * normalised to a largest coefficient of 1 and its objective to a largest coefficient of 1 */
typedef struct {
  double A[SC_ROWS_MAX * NA], lo[SC_ROWS_MAX], hi[SC_ROWS_MAX];
  int code[SC_ROWS_MAX]; /* binding code of the row, -1 for the task */
  int m;
  double H[NA * NA], g[NA];
} push_problem;

static void add_row(push_problem *p, const double *row, const double *w, double lo, double hi,
                    int code) {
  double rn = 0.0;
  int j;
  for (j = 0; j < NA; ++j) {
    p->A[p->m * NA + j] = row[j] * w[j];
    if (fabs(p->A[p->m * NA + j]) > rn) rn = fabs(p->A[p->m * NA + j]);
  }
  if (!(rn > 0)) return; /* a row without variables: nothing to hold (0 within its bounds) */
  for (j = 0; j < NA; ++j) p->A[p->m * NA + j] /= rn;
  p->lo[p->m] = lo / rn;
  p->hi[p->m] = hi / rn;
  p->code[p->m++] = code;
}

/* The push problem (the least-slip QP, or the strongest-push LP when lp) solved: tau, the
 * binding rows and, for the LP, whether its optimum is unique; the solver's status. */
static int solve_push(sc_optimal *o, int lp, int has_lo, double lam_lo, int equal, double *tau,
                      int *unique, int bind) {
  push_problem p;
  const double *w = o->widths, *ell = o->held.L;
  double y[NA], lam[SC_ROWS_MAX], Ns[NA * NA], fs = 0.0, big = 0.0, phi;
  sc_int act[NA1];
  sc_qp qp;
  sc_qp_solution s;
  int i, j, r, st, nact = 0, secular = 0;
  p.m = 0;
  if (has_lo) add_row(&p, ell, w, lam_lo, equal ? lam_lo : INFINITY, -1);
  if (!has_lo || lam_lo < 0) add_row(&p, ell, w, 0.0, INFINITY, SC_BIND_CONTACT);
  for (r = 0; r < o->nw; ++r) {
    int i_ = o->wheel_row[r];
    add_row(&p, o->held.L + i_ * NA, w, -o->wheel_ub[r], o->wheel_ub[r], SC_BIND_WHEEL(i_));
  }
  if (o->tau_max)
    for (j = 0; j < NA; ++j) {
      double e[NA];
      for (i = 0; i < NA; ++i) e[i] = i == j ? 1.0 : 0.0;
      add_row(&p, e, w, -o->tau_max[j], o->tau_max[j], SC_BIND_JOINT + j);
    }
  if (lp) { /* min -l . tau, scaled; the curvature lp_reg */
    for (j = 0; j < NA; ++j) {
      p.g[j] = -ell[j] * w[j];
      if (fabs(p.g[j]) > fs) fs = fabs(p.g[j]);
    }
    fs = fs > 0 ? fs : 1.0;
    for (j = 0; j < NA; ++j) p.g[j] /= fs;
    for (i = 0; i < NA; ++i)
      for (j = 0; j < NA; ++j) p.H[i * NA + j] = i == j ? o->in[OPT_IN_lp_reg] : 0.0;
  } else { /* min tau^T Xi tau, scaled, plus the relative Tikhonov term hessian_reg */
    double reg = 0.0;
    for (i = 0; i < NA; ++i)
      for (j = 0; j < NA; ++j) {
        p.H[i * NA + j] = 2.0 * o->held.Xih[i * NA1 + j] * w[i] * w[j];
        if (fabs(p.H[i * NA + j]) > fs) fs = fabs(p.H[i * NA + j]);
      }
    fs = fs > 0 ? fs : 1.0;
    for (i = 0; i < NA * NA; ++i) p.H[i] /= fs;
    for (i = 0; i < NA; ++i)
      if (fabs(p.H[i * NA + i]) > reg) reg = fabs(p.H[i * NA + i]);
    reg = o->in[OPT_IN_hessian_reg] * (reg > 1e-300 ? reg : 1e-300);
    for (i = 0; i < NA; ++i) p.H[i * NA + i] += reg;
    for (j = 0; j < NA; ++j) p.g[j] = 0.0;
  }
  qp.n = NA;
  qp.m = p.m;
  qp.H = p.H;
  qp.g = p.g;
  qp.A = p.A;
  qp.lo = p.lo;
  qp.hi = p.hi;
  s.x = y;
  s.lam = lam;
  s.active = act;
  st = sc_qp_solve(&qp, &o->qw, &s);
  count_solve(o, &s, 0);
  o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | (lp ? SC_METHOD_LP : SC_METHOD_QP);
  if (st != SC_QP_OPTIMAL) return st;
  if (o->r2 > 0) { /* the ellipsoid: y^T (W N W) y <= r^2 */
    for (i = 0; i < NA; ++i)
      for (j = 0; j < NA; ++j) Ns[i * NA + j] = o->rest.N[i * NA + j] * w[i] * w[j];
    phi = sc_quad(NA, Ns, NA, y);
    if (phi > o->r2) {
      double Hb[NA * NA], mu0 = 0.0, trH = 0.0, trN = 0.0;
      if (lp) { /* a linear objective: the curvature comes from the ellipsoid alone */
        double Lc[NA * NA], gi[NA];
        for (i = 0; i < NA * NA; ++i) Hb[i] = 0.0;
        memcpy(Lc, Ns, sizeof Lc);
        memcpy(gi, p.g, sizeof gi);
        if (sc_cholesky(NA, Lc, NA, 0.0)) {
          sc_cholesky_solve(NA, Lc, NA, gi);
          mu0 = sqrt(fabs(sc_dot(p.g, gi, NA)) / o->r2);
        }
      } else {
        memcpy(Hb, p.H, sizeof Hb);
        for (i = 0; i < NA; ++i) {
          trH += p.H[i * NA + i];
          trN += Ns[i * NA + i];
        }
        mu0 = trH / trN;
      }
      qp.H = Hb;
      st = sc_qcqp_ellipsoid(&qp, Ns, o->r2, mu0, &o->qw, &s);
      count_solve(o, &s, 1);
      o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | SC_METHOD_SECULAR;
      if (st != SC_QP_OPTIMAL) return st;
      secular = 1;
    }
  }
  for (j = 0; j < NA; ++j) tau[j] = y[j] * w[j];
  /* the binding rows: active with a multiplier above 1e-7 of the largest */
  for (r = 0; r < p.m; ++r)
    if (fabs(lam[r]) > big) big = fabs(lam[r]);
  if (big > 0)
    for (r = 0; r < p.m; ++r)
      if (fabs(lam[r]) > 1e-7 * big) {
        double ay = sc_dot(p.A + r * NA, y, NA), dl = fabs(ay - p.lo[r]), dh = fabs(ay - p.hi[r]);
        if ((dl < dh ? dl : dh) <= 1e-6) {
          ++nact;
          if (bind && p.code[r] >= 0) sc_optimal_bind(o, p.code[r]);
        }
      }
  if (secular && bind) sc_optimal_bind(o, SC_BIND_ELLIPSOID);
  /* an LP vertex with n_a independent rows active, all with non-zero multipliers (the active
   * set of the dual method is independent): no other torque reaches the optimum; on a
   * strictly convex ellipsoid the maximiser of a linear function is unique too */
  if (unique) *unique = secular || nact >= NA;
  return SC_QP_OPTIMAL;
}

/* The certificate of a push answer on the original problem in tau: the wheels (backed off),
 * the box, the contact kept, the task; the ellipsoid; H = 2 Xi (QP) or the objective -l (LP). */
static void push_certificate(sc_optimal *o, const double *tau, int lp, int has_lo,
                             double lam_lo, int equal) {
  double G[SC_ROWS_MAX * NA], lo[SC_ROWS_MAX], hi[SC_ROWS_MAX], H[NA * NA], c[NA], values[4];
  const double *ell = o->held.L;
  int m = 0, i, j, w, kind;
  for (w = 0; w < o->nw; ++w) {
    memcpy(G + m * NA, o->held.L + o->wheel_row[w] * NA, sizeof(double) * NA);
    lo[m] = -o->wheel_ub[w];
    hi[m++] = o->wheel_ub[w];
  }
  if (o->tau_max)
    for (j = 0; j < NA; ++j) {
      for (i = 0; i < NA; ++i) G[m * NA + i] = i == j ? 1.0 : 0.0;
      lo[m] = -o->tau_max[j];
      hi[m++] = o->tau_max[j];
    }
  memcpy(G + m * NA, ell, sizeof(double) * NA);
  lo[m] = 0.0;
  hi[m++] = INFINITY;
  if (has_lo) {
    memcpy(G + m * NA, ell, sizeof(double) * NA);
    lo[m] = lam_lo;
    hi[m++] = equal ? lam_lo : INFINITY;
  }
  for (i = 0; i < NA; ++i) {
    c[i] = lp ? -ell[i] : 0.0;
    for (j = 0; j < NA; ++j) H[i * NA + j] = 2.0 * o->held.Xih[i * NA1 + j];
  }
  kind = o->r2 > 0 ? SC_CERT_QCQP : lp ? SC_CERT_LP : SC_CERT_QP;
  sc_kkt_certificate(NA, tau, lp ? 0 : H, c, m, G, lo, hi, o->r2 > 0 ? o->rest.N : 0, o->r2, 1,
                     o->in[OPT_IN_active_tol], o->in[OPT_IN_tol_stationarity], values, 0, 0,
                     &o->qw);
  sc_optimal_certify(o, kind, values, 0);
}

/* The strongest push within the limits with every wheel sticking: tau, lam_c there, its
 * binding limits, whether it is the only maximiser; the solver's status. */
static int strongest_lam(sc_optimal *o, double *tau, double *lam_max, int *unique) {
  const double *ell = o->held.L;
  int st, j, w;
  if (!o->tau_max) { /* the ellipsoid alone: tau = r N^-1 l / sqrt(l^T N^-1 l) */
    double Lc[NA * NA], ni[NA], c, ok = 1;
    memcpy(Lc, o->rest.N, sizeof Lc);
    memcpy(ni, ell, sizeof ni);
    if (sc_cholesky(NA, Lc, NA, 0.0)) {
      sc_cholesky_solve(NA, Lc, NA, ni);
      c = sc_dot(ell, ni, NA);
      if (c > 0) {
        for (j = 0; j < NA; ++j) tau[j] = o->radius * ni[j] / sqrt(c);
        for (w = 0; w < o->nw; ++w)
          if (!(fabs(sc_dot(o->held.L + o->wheel_row[w] * NA, tau, NA)) <= o->wheel_ub[w]))
            ok = 0;
        if (ok) {
          sc_optimal_bind(o, SC_BIND_ELLIPSOID);
          o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | SC_METHOD_CLOSED_ELLIPSOID;
          *lam_max = sc_dot(ell, tau, NA);
          *unique = 1;
          return SC_QP_OPTIMAL;
        }
      }
    }
  }
  st = solve_push(o, 1, 0, 0.0, 0, tau, unique, 1);
  if (st == SC_QP_OPTIMAL) *lam_max = sc_dot(ell, tau, NA);
  return st;
}

static void least_slip_push(sc_optimal *o) {
  double *tau = OUTP(o, tau), lam_lo, gain, t2[NA], lam_max, *det = OUTP(o, detail);
  int has_lo, equal, reason, st, st2, unique, j;
  const double *d = o->a_obj ? 0 : o->direction;
  reason = push_target(o, d, &has_lo, &lam_lo, &equal, &gain);
  SET(o, gain, gain);
  if (reason != SC_REASON_NONE) {
    set_status(o, SC_INFEASIBLE, reason);
    return;
  }
  st = solve_push(o, 0, has_lo, lam_lo, equal, tau, 0, 1);
  if (st == SC_QP_OPTIMAL) {
    double xt[NA];
    for (j = 0; j < NA; ++j) xt[j] = sc_dot(o->held.Xih + j * NA1, tau, NA);
    SET(o, expected, sc_dot(xt, tau, NA));
    push_certificate(o, tau, 0, has_lo, lam_lo, equal);
    optimal_if_certified(o);
    return;
  }
  /* diagnose: the strongest push the limits allow, and what limits it */
  SET(o, n_binding, 0);
  o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | SC_METHOD_DIAGNOSIS;
  st2 = strongest_lam(o, t2, &lam_max, &unique);
  det[5] = st;
  if (st2 != SC_QP_OPTIMAL) {
    set_status(o, SC_FAILED, SC_REASON_SOLVER);
    SET(o, n_binding, 0);
    return;
  }
  if (lam_max >= lam_lo * (1 - 1e-7)) {
    set_status(o, SC_FAILED, SC_REASON_WITHIN_REACH);
    SET(o, n_binding, 0);
    return;
  }
  for (j = 0; j < NA; ++j) tau[j] = t2[j];
  det[6] = o->a_obj ? sqrt(o->a_obj[0] * o->a_obj[0] + o->a_obj[1] * o->a_obj[1] +
                           o->a_obj[2] * o->a_obj[2])
                    : o->a_min;
  det[7] = gain * lam_max;
  set_status(o, SC_INFEASIBLE, SC_REASON_OUT_OF_REACH);
}

static void strongest_push(sc_optimal *o) {
  double *tau = OUTP(o, tau), lam_lo, gain, lam_max, d[3], na;
  const double *a = o->a_dir;
  int has_lo, equal, reason, st, unique, j;
  if (o->direction) {
    for (j = 0; j < 3; ++j) d[j] = o->direction[j];
  } else { /* straight along the contact normal */
    na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    na = na > 1e-300 ? na : 1e-300;
    for (j = 0; j < 3; ++j) d[j] = a[j] / na;
  }
  reason = push_target(o, d, &has_lo, &lam_lo, &equal, &gain);
  SET(o, gain, gain);
  if (reason != SC_REASON_NONE) {
    set_status(o, SC_INFEASIBLE, reason);
    SET(o, expected, 0.0);
    return;
  }
  st = strongest_lam(o, tau, &lam_max, &unique);
  if (st != SC_QP_OPTIMAL) {
    OUTP(o, detail)[5] = st;
    set_status(o, SC_FAILED, SC_REASON_SOLVER);
    return;
  }
  if (lam_max <= 0) {
    for (j = 0; j < NA; ++j) tau[j] = 0.0;
    set_status(o, SC_INFEASIBLE, SC_REASON_NO_STRONG_PUSH);
    SET(o, expected, 0.0);
    return;
  }
  if (!unique) { /* ties (a degenerate LP optimum): among the strongest, the least slip */
    double t2[NA];
    if (solve_push(o, 0, 1, lam_max * (1 - 1e-9), 0, t2, 0, 0) == SC_QP_OPTIMAL) {
      for (j = 0; j < NA; ++j) tau[j] = t2[j];
      o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | SC_METHOD_TIE_BREAK;
    }
  }
  SET(o, expected, gain * sc_dot(o->held.L, tau, NA));
  push_certificate(o, tau, 1, 0, 0.0, 0);
  optimal_if_certified(o);
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
  ok = sc_rest_system(&o->ws, o->scene, o->q, &o->rest) == 0 &&
       sc_state_maps(&o->rest, o->scene, state, 1, &o->held) > o->fw_constants[0];
  for (i = 0; ok && i < NC * NA; ++i) ok = isfinite(o->held.L[i]);
  for (i = 0; ok && i < NA1 * NA1; ++i) ok = isfinite(o->held.Xih[i]);
  for (i = 0; ok && i < NA * NA; ++i) ok = isfinite(o->rest.N[i]) && isfinite(o->held.Om[i]);
  if (!ok) {
    set_status(o, SC_FAILED, SC_REASON_SINGULAR);
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
  SET(o, k, o->k);
  /* the region's bounding box: the box, and r sqrt((N^-1)_jj) of the ellipsoid */
  for (j = 0; j < NA; ++j) o->widths[j] = o->tau_max ? o->tau_max[j] : INFINITY;
  if (o->r2 > 0) {
    memcpy(Lc, o->rest.N, sizeof Lc);
    if (!sc_cholesky(NA, Lc, NA, 0.0)) {
      set_status(o, SC_FAILED, SC_REASON_SINGULAR);
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
  if (o->kind == SC_MAX_SR) max_sr(o);
  else if (o->kind == SC_LEAST_SLIP_PUSH) least_slip_push(o);
  else strongest_push(o);
  SET(o, form, sc_quad(NA, o->rest.N, NA, OUTP(o, tau)));
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
  const sc_work_fn fns[] = {SC_CS_WORKS};
  sc_int i;
  o.scene = scene;
  o.fw_constants = fw_constants;
  o.max_iter = max_iter;
  o.in = in;
  read_query(&o);
  if (sc_work_alloc(&o.ws, fns, SC_COUNT(fns))) return -1;
  if (sc_qp_work_alloc(&o.qw, NA1, SC_ROWS_MAX)) {
    sc_work_free(&o.ws);
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
    for (j = 0; j < NA; ++j) finite &= fabs(tau[j]) <= fw_constants[5];
    if (!finite) { /* no torque to check: the answer has failed */
      for (j = 0; j < NA; ++j) tau[j] = 0.0;
      set_status(&o, SC_FAILED, SC_REASON_NOT_FINITE);
    }
    o.out[OPT_OUT_forward_status] = sc_optimal_forward(&o, tau, row);
    if (o.out[OPT_OUT_forward_status] != 0 || row[OUT_status] != 0) {
      o.out[OPT_OUT_check] = SC_CHECK_PENDING;
      continue;
    }
    objective_and_check(in, o.out);
  }
  sc_qp_work_free(&o.qw);
  sc_work_free(&o.ws);
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
 * The building blocks alone, for tests against independent references (snakecg.core.optimal:
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
  qp.n = n;
  qp.m = m;
  qp.H = H;
  qp.g = g;
  qp.A = A;
  qp.lo = lo;
  qp.hi = hi;
  s.x = x;
  s.lam = lam;
  s.active = act;
  s.mu = 0.0;
  s.newton = 0;
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
