/* snakecg's engine: the push tasks least_slip_push and strongest_push (engine.h,
 * docs/how-to/optimize.md).
 *
 * This file is part of the runtime (not generated), compiled once per model into the model's
 * shared library.
 *
 * With every row held the limits are linear in tau: the contact kept (l . tau >= 0), every
 * wheel within its friction bound (|L_i tau| <= u_i, backed off by the friction margin), the
 * box; the ellipsoid of eq. (31) is tau^T N tau <= r^2. One frictionless point contact pushes
 * the object along its normal only (a_obj = a_dir lam_c), so the task is a bound on the
 * contact force. least_slip_push minimises tau^T Xi tau (eq. 26): a convex QP or, with the
 * ellipsoid, QCQP; strongest_push maximises lam_c: an LP (as the QP of curvature lp_reg) or,
 * with the ellipsoid, its QCQP, in closed form on the ellipsoid alone. Both are posed in the
 * torque scaled by the region's bounding box and solved by the QP block (qp.c: the dual active
 * set, the ellipsoid's multiplier); an infeasible task is diagnosed by the strongest push, a
 * degenerate strongest push broken by the least slip among the strongest.
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
/* The task as a bound on the contact force (a_obj = a_dir lam_c): lam_c >= lam_lo (== when
 * equal), gain = d . a_dir (|a_dir| for a full acceleration); 0, or the reason why no torque
 * can do the task (with its binding code and the normal in the details). */
static int push_target(sc_optimal *o, const double *d, int *has_lo, double *lam_lo, int *equal,
                       double *gain) {
  const double *a = o->a_dir;
  double na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), h = hypot(a[0], a[1]);
  double *det = SC_OUT(o, detail);
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
  sc_qp_define(&qp, NA, p.m, p.H, p.g, p.A, p.lo, p.hi);
  sc_qp_solution_define(&s, y, lam, act);
  st = sc_qp_solve(&qp, &o->qw, &s);
  sc_optimal_count(o, &s, 0);
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
      sc_optimal_count(o, &s, 1);
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
    double Lc[NA * NA], ni[NA], c;
    int ok = 1;
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

void sc_least_slip_push(sc_optimal *o) {
  double *tau = SC_OUT(o, tau), lam_lo, gain, t2[NA], lam_max, *det = SC_OUT(o, detail);
  int has_lo, equal, reason, st, st2, unique, j;
  const double *d = o->a_obj ? 0 : o->direction;
  reason = push_target(o, d, &has_lo, &lam_lo, &equal, &gain);
  SC_SET(o, gain, gain);
  if (reason != SC_REASON_NONE) {
    sc_optimal_status(o, SC_INFEASIBLE, reason);
    return;
  }
  st = solve_push(o, 0, has_lo, lam_lo, equal, tau, 0, 1);
  if (st == SC_QP_OPTIMAL) {
    double xt[NA];
    for (j = 0; j < NA; ++j) xt[j] = sc_dot(o->held.Xih + j * NA1, tau, NA);
    SC_SET(o, expected, sc_dot(xt, tau, NA));
    push_certificate(o, tau, 0, has_lo, lam_lo, equal);
    sc_optimal_if_certified(o);
    return;
  }
  /* diagnose: the strongest push the limits allow, and what limits it */
  SC_SET(o, n_binding, 0);
  o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | SC_METHOD_DIAGNOSIS;
  st2 = strongest_lam(o, t2, &lam_max, &unique);
  det[5] = st;
  if (st2 != SC_QP_OPTIMAL) {
    sc_optimal_status(o, SC_FAILED, SC_REASON_SOLVER);
    SC_SET(o, n_binding, 0);
    return;
  }
  if (lam_max >= lam_lo * (1 - 1e-7)) {
    sc_optimal_status(o, SC_FAILED, SC_REASON_WITHIN_REACH);
    SC_SET(o, n_binding, 0);
    return;
  }
  for (j = 0; j < NA; ++j) tau[j] = t2[j];
  det[6] = o->a_obj ? sqrt(o->a_obj[0] * o->a_obj[0] + o->a_obj[1] * o->a_obj[1] +
                           o->a_obj[2] * o->a_obj[2])
                    : o->a_min;
  det[7] = gain * lam_max;
  sc_optimal_status(o, SC_INFEASIBLE, SC_REASON_OUT_OF_REACH);
}

void sc_strongest_push(sc_optimal *o) {
  double *tau = SC_OUT(o, tau), lam_lo, gain, lam_max, d[3], na;
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
  SC_SET(o, gain, gain);
  if (reason != SC_REASON_NONE) {
    sc_optimal_status(o, SC_INFEASIBLE, reason);
    SC_SET(o, expected, 0.0);
    return;
  }
  st = strongest_lam(o, tau, &lam_max, &unique);
  if (st != SC_QP_OPTIMAL) {
    SC_OUT(o, detail)[5] = st;
    sc_optimal_status(o, SC_FAILED, SC_REASON_SOLVER);
    return;
  }
  if (lam_max <= 0) {
    for (j = 0; j < NA; ++j) tau[j] = 0.0;
    sc_optimal_status(o, SC_INFEASIBLE, SC_REASON_NO_STRONG_PUSH);
    SC_SET(o, expected, 0.0);
    return;
  }
  if (!unique) { /* ties (a degenerate LP optimum): among the strongest, the least slip */
    double t2[NA];
    if (solve_push(o, 0, 1, lam_max * (1 - 1e-9), 0, t2, 0, 0) == SC_QP_OPTIMAL) {
      for (j = 0; j < NA; ++j) tau[j] = t2[j];
      o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | SC_METHOD_TIE_BREAK;
    }
  }
  SC_SET(o, expected, gain * sc_dot(o->held.L, tau, NA));
  push_certificate(o, tau, 1, 0, 0.0, 0);
  sc_optimal_if_certified(o);
}

