/* snakecg's engine: max_sr with wheels allowed to slide (engine.h, docs/how-to/optimize.md).
 *
 * This file is part of the runtime (not generated), compiled once per model into the model's
 * shared library.
 *
 * The map from the torque to the forces is piecewise affine: each wheel state (stick, slide+,
 * slide-) has its own affine map (maps.c), valid on a polyhedral cone of z = (tau, t): held
 * wheels within their bound, sliding wheels' accelerations opposing their friction force. One
 * frictionless point contact gives a rank-one numerator ||a_obj||^2 = k lam_c^2, so on one state
 * sr = k / (k + z^T Xi_h z / (l . z)^2) and
 *     max sr  <=>  min z^T Xi_h z  s.t.  l . z = 1, z in the state's cone, the region
 * (the Charnes-Cooper transformation of a fractional program; the box as |tau_j| <= w_j t, the
 * ellipsoid as the second-order cone tau^T N tau <= r^2 t^2). The states are visited best
 * upper bound first: without the cone the problem's optimum is sr = k c / (k c + 1),
 * c = l^T Xi_h^+ l (exact), and a state that cannot beat the best answer so far is skipped.
 * Each state is solved in the always-feasible form min z^T Xi_h z - M l . z s.t. l . z <= 1
 * and the cone, whose optimum is s z* with s = min(1, M / (2 m*)) (m* the state's optimum):
 * z* = z / (l . z) exactly, and a cone that misses l . z > 0 gives l . z = 0 instead of an
 * infeasible QP. M is twice the value a state must beat.
 *
 * With the ellipsoid, the QP over its bounding box comes first; when its optimum leaves the
 * ellipsoid, the state's convex problem is solved exactly by its value function in t: for a
 * fixed t the problem is a convex QCQP in tau (the ellipsoid of radius r t; qp.c's secular
 * equation), its optimal value F(t) is convex in t (the partial minimum of a jointly convex
 * problem), F'(t) is the derivative of the Lagrangian in t at the QCQP's multipliers, and the
 * root of the nondecreasing F' (or the end of F's domain) is found by safeguarded regula
 * falsi (Illinois), the domain being an interval [0, t_max] (z = 0 is feasible).
 *
 * The candidates that beat the all-held answer are ranked by the exact forward solve (a
 * state's optimum often lies on its boundary with another state, where the maps' rounding
 * cannot separate them; ties keep the all-held answer); the winner's problem is certified by
 * its KKT conditions (the homogeneous ellipsoid is not a convex quadratic form: no gap).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
/* most wheel states visited (3^n_w - 1): beyond, the query fails with its reason */
#define SC_STATES_MAX 531441

/* one wheel state's problem in z = (tau, t), scaled by s = (w, 1) and its rows normalised */
typedef struct {
  double H[NA1 * NA1], g[NA1];
  double A[SC_ROWS_MAX * NA1], lo[SC_ROWS_MAX], hi[SC_ROWS_MAX];
  int code[SC_ROWS_MAX]; /* binding code, -1: no name (the l . z row, t >= 0) */
  int m;
  double s[NA1];         /* the scale */
  double ell[NA1];       /* l in the scaled variables */
} state_problem;

typedef struct {
  double ub;
  sc_int index;
} ranked;

static int by_bound(const void *a, const void *b) {
  const ranked *x = (const ranked *)a, *y = (const ranked *)b;
  if (x->ub != y->ub) return x->ub > y->ub ? -1 : 1;
  return x->index < y->index ? -1 : x->index > y->index;
}

/* the row states of state number `index` (base 3 over the wheels allowed to slide, the first
 * such row most significant; digit 0 stick, 1 slide+, 2 slide-) */
static void decode(const sc_optimal *o, const int *rows, int nr, sc_int index, signed char *st) {
  const double *present = o->scene + SCENE_present;
  int r, k;
  for (r = 0; r < NC; ++r) st[r] = present[r] != 0.0 ? HELD : ABSENT;
  for (k = nr - 1; k >= 0; --k) {
    int digit = (int)(index % 3);
    index /= 3;
    st[rows[k]] = digit == 0 ? HELD : digit == 1 ? SLIDE_POS : SLIDE_NEG;
  }
}

static void add_row(state_problem *p, const double *row, double lo, double hi, int code) {
  double rn = 0.0;
  int j;
  for (j = 0; j < NA1; ++j) {
    p->A[p->m * NA1 + j] = row[j] * p->s[j];
    if (fabs(p->A[p->m * NA1 + j]) > rn) rn = fabs(p->A[p->m * NA1 + j]);
  }
  if (!(rn > 0)) return;
  for (j = 0; j < NA1; ++j) p->A[p->m * NA1 + j] /= rn;
  p->lo[p->m] = lo / rn;
  p->hi[p->m] = hi / rn;
  p->code[p->m++] = code;
}

/* The state's problem: min z^T Xi_h z - M l . z s.t. l . z <= 1, the cone, |tau_j| <= b_j t
 * (b: the region's bounding box with `bbox`, else the box alone), t >= 0. */
static void build(const sc_optimal *o, const sc_affine_maps *mp, const signed char *st,
                  double M, int bbox, state_problem *p) {
  const double *bounds = o->scene + SCENE_bounds;
  double row[NA1], fs = 0.0, reg = 0.0;
  int i, j, r;
  p->m = 0;
  for (j = 0; j < NA; ++j) p->s[j] = o->widths[j];
  p->s[NA] = 1.0;
  for (j = 0; j < NA; ++j) row[j] = mp->L[j]; /* l = (L_c, l0_c) */
  row[NA] = mp->l0[0];
  for (j = 0; j < NA1; ++j) p->ell[j] = row[j] * p->s[j];
  add_row(p, row, -INFINITY, 1.0, -1);
  for (r = 1; r < NC; ++r) {
    const double ub = bounds[r] * (1.0 - o->in[OPT_IN_friction_margin]);
    if (st[r] == HELD && isfinite(bounds[r]) && o->scene[SCENE_present + r] != 0.0) {
      for (j = 0; j < NA; ++j) row[j] = -mp->L[r * NA + j]; /* ub t - lam_i >= 0 */
      row[NA] = ub - mp->l0[r];
      add_row(p, row, 0.0, INFINITY, SC_BIND_WHEEL(r));
      for (j = 0; j < NA; ++j) row[j] = mp->L[r * NA + j]; /* ub t + lam_i >= 0 */
      row[NA] = ub + mp->l0[r];
      add_row(p, row, 0.0, INFINITY, SC_BIND_WHEEL(r));
    } else if (st[r] == SLIDE_POS || st[r] == SLIDE_NEG) { /* w_i opposes the force */
      double sg = st[r] == SLIDE_POS ? -1.0 : 1.0;
      for (j = 0; j < NA; ++j) row[j] = sg * mp->W[r * NA + j];
      row[NA] = sg * mp->w0[r];
      add_row(p, row, 0.0, INFINITY, SC_BIND_WHEEL(r));
    }
  }
  for (j = 0; j < NA; ++j) {
    double b = bbox ? o->widths[j] : (o->tau_max ? o->tau_max[j] : INFINITY);
    int code = (o->tau_max && o->tau_max[j] <= b * (1 + 1e-12)) ? SC_BIND_JOINT + j
                                                                 : SC_BIND_ELLIPSOID;
    if (!isfinite(b)) continue;
    for (i = 0; i < NA1; ++i) row[i] = 0.0;
    row[j] = 1.0; /* tau_j + b_j t >= 0 */
    row[NA] = b;
    add_row(p, row, 0.0, INFINITY, code);
    row[j] = -1.0; /* b_j t - tau_j >= 0 */
    add_row(p, row, 0.0, INFINITY, code);
  }
  for (i = 0; i < NA1; ++i) row[i] = i == NA ? 1.0 : 0.0; /* t >= 0 */
  add_row(p, row, 0.0, INFINITY, -1);
  /* the objective, scaled, normalised, with the relative Tikhonov term */
  for (i = 0; i < NA1; ++i) {
    p->g[i] = -M * p->ell[i];
    if (fabs(p->g[i]) > fs) fs = fabs(p->g[i]);
    for (j = 0; j < NA1; ++j) {
      p->H[i * NA1 + j] = 2.0 * mp->Xih[i * NA1 + j] * p->s[i] * p->s[j];
      if (fabs(p->H[i * NA1 + j]) > fs) fs = fabs(p->H[i * NA1 + j]);
    }
  }
  fs = fs > 0 ? fs : 1.0;
  for (i = 0; i < NA1; ++i) {
    p->g[i] /= fs;
    for (j = 0; j < NA1; ++j) p->H[i * NA1 + j] /= fs;
    if (fabs(p->H[i * NA1 + i]) > reg) reg = fabs(p->H[i * NA1 + i]);
  }
  reg = o->in[OPT_IN_hessian_reg] * (reg > 1e-300 ? reg : 1e-300);
  for (i = 0; i < NA1; ++i) p->H[i * NA1 + i] += reg;
}

/* sr of the state's map at z: k / (k + z^T Xi_h z / (l . z)^2), z unscaled */
static double state_sr(const sc_optimal *o, const sc_affine_maps *mp, const double *z) {
  double lz = sc_dot(mp->L, z, NA) + mp->l0[0] * z[NA];
  double m = sc_quad(NA1, mp->Xih, NA1, z) / (lz * lz);
  return o->k / (o->k + m);
}

/* the binding codes of an answer's active rows (multipliers above 1e-7 of the largest) */
typedef struct {
  int code[SC_ROWS_MAX + 1], n;
} binding;

static void collect(const state_problem *p, const double *zs, const double *lam, double mu,
                    binding *b) {
  double big = fabs(mu);
  int r;
  b->n = 0;
  for (r = 0; r < p->m; ++r)
    if (fabs(lam[r]) > big) big = fabs(lam[r]);
  if (!(big > 0)) return;
  for (r = 0; r < p->m; ++r)
    if (fabs(lam[r]) > 1e-7 * big && p->code[r] >= 0) {
      double az = sc_dot(p->A + r * NA1, zs, NA1), dl = fabs(az - p->lo[r]),
             dh = fabs(az - p->hi[r]);
      if ((dl < dh ? dl : dh) <= 1e-6) b->code[b->n++] = p->code[r];
    }
  if (fabs(mu) > 1e-7 * big) b->code[b->n++] = SC_BIND_ELLIPSOID;
}

/* the problem at a fixed t: the QP in the scaled tau (the ellipsoid of radius r t through its
 * multiplier); F'(t) in *dF. Returns the solver status. */
static int at_scale(sc_optimal *o, const state_problem *p, const double *Ns, double t,
                    double *y, double *lam, double *mu, double *dF) {
  double H[NA * NA], g[NA], A[SC_ROWS_MAX * NA], lo[SC_ROWS_MAX], hi[SC_ROWS_MAX], z[NA1],
      Hz_t, phi;
  sc_int act[NA1];
  sc_qp qp;
  sc_qp_solution s;
  int i, j, r, st;
  for (i = 0; i < NA; ++i) {
    g[i] = p->g[i] + p->H[i * NA1 + NA] * t;
    for (j = 0; j < NA; ++j) H[i * NA + j] = p->H[i * NA1 + j];
  }
  for (r = 0; r < p->m; ++r) {
    for (j = 0; j < NA; ++j) A[r * NA + j] = p->A[r * NA1 + j];
    lo[r] = p->lo[r] - p->A[r * NA1 + NA] * t;
    hi[r] = p->hi[r] - p->A[r * NA1 + NA] * t;
  }
  sc_qp_define(&qp, NA, p->m, H, g, A, lo, hi);
  sc_qp_solution_define(&s, y, lam, act);
  *mu = 0.0;
  st = sc_qp_solve(&qp, &o->qw, &s);
  o->out[OPT_OUT_qp_solves] += 1.0;
  if (st != SC_QP_OPTIMAL) return st;
  phi = sc_quad(NA, Ns, NA, y);
  if (phi > o->r2 * t * t) {
    double trH = 0.0, trN = 0.0;
    for (i = 0; i < NA; ++i) {
      trH += H[i * NA + i];
      trN += Ns[i * NA + i];
    }
    st = sc_qcqp_ellipsoid(&qp, Ns, o->r2 * t * t, trH / trN, &o->qw, &s);
    o->out[OPT_OUT_qp_solves] += (double)s.iterations;
    o->out[OPT_OUT_newton_steps] += (double)s.newton;
    if (st != SC_QP_OPTIMAL) return st;
    *mu = s.mu;
  }
  /* F'(t) = (H z)_t + g_t - sum_r lam_r a_rt - mu r^2 t */
  for (j = 0; j < NA; ++j) z[j] = y[j];
  z[NA] = t;
  Hz_t = sc_dot(p->H + NA * NA1, z, NA1);
  *dF = Hz_t + p->g[NA] - *mu * o->r2 * t;
  for (r = 0; r < p->m; ++r) *dF -= lam[r] * p->A[r * NA1 + NA];
  return SC_QP_OPTIMAL;
}

/* The state's problem with the exact ellipsoid (module comment): the scaled z at the minimum
 * of F over t > 0, its multipliers; 0 when the problem cannot be solved. t0 > 0: a guess (the
 * bounding-box relaxation's t). */
static int ellipsoid_exact(sc_optimal *o, const state_problem *p, double t0, double *zs,
                           double *lam, double *mu) {
  double Ns[NA * NA], y[NA], lm[SC_ROWS_MAX], m_, d, lo = 0.0, hi = INFINITY, dlo = NAN,
         dhi = NAN, t = t0;
  int i, j, k, side = 0, st, have = 0;
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) Ns[i * NA + j] = o->rest.N[i * NA + j] * p->s[i] * p->s[j];
  for (k = 0; k < 200; ++k) {
    st = at_scale(o, p, Ns, t, y, lm, &m_, &d);
    if (st == SC_QP_OPTIMAL) { /* keep the latest feasible evaluation */
      for (j = 0; j < NA; ++j) zs[j] = y[j];
      zs[NA] = t;
      for (j = 0; j < p->m; ++j) lam[j] = lm[j];
      *mu = m_;
      have = 1;
    }
    if (st == SC_QP_OPTIMAL && d < 0) { /* left of the minimum */
      lo = t;
      dlo = d;
      if (side == -1 && !isnan(dhi)) dhi *= 0.5;
      side = -1;
    } else if (st == SC_QP_OPTIMAL || st == SC_QP_INFEASIBLE || st == SC_QP_EMPTY) {
      hi = t; /* right of it, or beyond the domain */
      dhi = st == SC_QP_OPTIMAL ? d : NAN;
      if (side == 1 && !isnan(dlo)) dlo *= 0.5;
      side = 1;
      if (st == SC_QP_OPTIMAL && d == 0.0) break;
    } else {
      return 0;
    }
    if (!isfinite(hi)) {
      t = 2.0 * t;
      continue;
    }
    if (hi - lo <= 4e-16 * hi) break;
    if (!isnan(dlo) && !isnan(dhi) && dhi > dlo) /* regula falsi (Illinois) */
      t = hi - dhi * (hi - lo) / (dhi - dlo);
    else
      t = 0.5 * (lo + hi);
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
  }
  return have;
}

/* a growing list of the states that beat the all-held answer */
typedef struct {
  sc_int index;
  double z[NA1], val;
  binding b;
} candidate;

typedef struct {
  sc_int index;
  double val, t;
} cut_state;

static int grow(void **list, sc_int *cap, sc_int n, size_t size) {
  void *more;
  if (n < *cap) return 1;
  *cap = *cap ? 2 * *cap : 16;
  more = realloc(*list, size * (size_t)*cap);
  if (!more) return 0;
  *list = more;
  return 1;
}

static void fail(sc_optimal *o, int st) {
  o->out[OPT_OUT_status] = SC_FAILED;
  o->out[OPT_OUT_reason] = SC_REASON_SOLVER;
  o->out[OPT_OUT_detail + 5] = st;
}

/* The winner's certificate: the state's problem in z unscaled with l . z = 1, its cone, the
 * box, t >= 0 and the ellipsoid as z^T diag(N, -r^2) z <= 0. */
static void state_certificate(sc_optimal *o, const sc_affine_maps *mp, const signed char *st,
                              const double *z) {
  state_problem p;
  double G[SC_ROWS_MAX * NA1], H[NA1 * NA1], c0[NA1], Q[NA1 * NA1], values[4];
  int r, j, c;
  build(o, mp, st, 0.0, 0, &p);
  for (r = 0; r < p.m; ++r) /* the rows in z: A_scaled / s (normalised rows, same bounds) */
    for (j = 0; j < NA1; ++j) G[r * NA1 + j] = p.A[r * NA1 + j] / p.s[j];
  for (j = 0; j < NA; ++j) G[j] = mp->L[j]; /* row 0: l . z = 1 */
  G[NA] = mp->l0[0];
  p.lo[0] = p.hi[0] = 1.0;
  for (j = 0; j < NA1 * NA1; ++j) {
    H[j] = 2.0 * mp->Xih[j];
    Q[j] = 0.0;
  }
  for (j = 0; j < NA1; ++j) c0[j] = 0.0;
  for (j = 0; j < NA; ++j)
    for (c = 0; c < NA; ++c) Q[j * NA1 + c] = o->rest.N[j * NA + c];
  Q[NA * NA1 + NA] = -o->r2;
  sc_kkt_certificate(NA1, z, H, c0, p.m, G, p.lo, p.hi, o->r2 > 0 ? Q : 0, 0.0, 0,
                     o->in[OPT_IN_active_tol], o->in[OPT_IN_tol_stationarity], values, 0, 0,
                     &o->qw);
  sc_optimal_certify(o, SC_CERT_STATE, values, 0);
  if (o->out[OPT_OUT_certified] != 0.0) {
    o->out[OPT_OUT_status] = SC_OPTIMAL;
    o->out[OPT_OUT_reason] = SC_REASON_NONE;
  } else {
    o->out[OPT_OUT_status] = SC_FAILED;
    o->out[OPT_OUT_reason] = SC_REASON_CERTIFICATE;
  }
}

/* the penalty M of a state's always-feasible form: twice the value it must beat */
static double penalty(const sc_optimal *o, double best) {
  double m_ref = o->k * (1.0 / fmin(fmax(best, 1e-12), 1.0) - 1.0);
  return 2.0 * fmin(fmax(m_ref, 1e-12), 1e12);
}

/* max_sr's all-held answer (certified, in o->out) against every admissible wheel state */
void sc_max_sr_sliding(sc_optimal *o) {
  const double *present = o->scene + SCENE_present, *bounds = o->scene + SCENE_bounds;
  double stick = o->out[OPT_OUT_expected], best = stick, tie = o->in[OPT_IN_sr_tie];
  int rows[NC], nr = 0, r, j, c;
  sc_int n_states = 1, s, i, ncand = 0, cap_cand = 0, n_cut = 0, cap_cut = 0, solved = 0;
  ranked *order;
  candidate *cand = 0;
  cut_state *cut = 0;
  sc_affine_maps mp;
  state_problem p;
  signed char st[NC];
  o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | SC_METHOD_STATES;
  for (r = 1; r < NC; ++r)
    if (o->slide[r] && present[r] != 0.0 && isfinite(bounds[r])) rows[nr++] = r;
  for (r = 0; r < nr && n_states <= SC_STATES_MAX; ++r) n_states *= 3;
  o->out[OPT_OUT_states] = (double)(n_states - 1);
  if (nr == 0) return;
  if (n_states > SC_STATES_MAX) {
    fail(o, SC_QP_SIZE);
    return;
  }
  order = (ranked *)malloc(sizeof(ranked) * (size_t)n_states);
  if (!order) {
    fail(o, SC_QP_SIZE);
    return;
  }
  /* the exact upper bound of each state: k c / (k c + 1), c = l^T Xi_h^+ l */
  for (s = 1; s < n_states; ++s) {
    double E[NA1 * NA1], V[NA1 * NA1], w[NA1], l[NA1], top, cc = 0.0;
    decode(o, rows, nr, s, st);
    order[s - 1].index = s;
    order[s - 1].ub = -1.0;
    if (!(sc_state_maps(&o->rest, o->scene, st, 0, &mp) > o->fw_constants[0])) continue;
    memcpy(E, mp.Xih, sizeof E);
    for (j = 0; j < NA; ++j) l[j] = mp.L[j];
    l[NA] = mp.l0[0];
    sc_eigen_symmetric(NA1, E, NA1, w, V, NA1);
    top = fabs(w[NA1 - 1]) > fabs(w[0]) ? fabs(w[NA1 - 1]) : fabs(w[0]);
    for (j = 0; j < NA1; ++j)
      if (w[j] > 1e-12 * top) {
        double t = 0.0;
        for (c = 0; c < NA1; ++c) t += V[c * NA1 + j] * l[c];
        cc += t * t / w[j];
      }
    order[s - 1].ub = cc > 0 ? o->k * cc / (o->k * cc + 1.0) : 0.0;
  }
  qsort(order, (size_t)(n_states - 1), sizeof(ranked), by_bound);
  /* phase 1: each state's QP (the ellipsoid by its bounding box), best bounds first; a
   * relaxed optimum inside the region is the state's optimum */
  for (s = 0; s < n_states - 1; ++s) {
    double zs[NA1], z[NA1], lam[SC_ROWS_MAX], lz, val;
    sc_int act[NA1];
    sc_qp qp;
    sc_qp_solution sol;
    if (order[s].ub <= best + tie) break;
    decode(o, rows, nr, order[s].index, st);
    sc_state_maps(&o->rest, o->scene, st, 0, &mp);
    build(o, &mp, st, penalty(o, best), 1, &p);
    sc_qp_define(&qp, NA1, p.m, p.H, p.g, p.A, p.lo, p.hi);
    sc_qp_solution_define(&sol, zs, lam, act);
    ++solved;
    o->out[OPT_OUT_qp_solves] += 1.0;
    if (sc_qp_solve(&qp, &o->qw, &sol) != SC_QP_OPTIMAL) continue;
    lz = sc_dot(p.ell, zs, NA1);
    if (!(lz > 1e-9 * sc_norm(p.ell, NA1) * sc_norm(zs, NA1)) || !(zs[NA] > 0)) continue;
    for (j = 0; j < NA1; ++j) z[j] = zs[j] * p.s[j] / lz;
    val = state_sr(o, &mp, z);
    if (o->r2 > 0 && sc_quad(NA, o->rest.N, NA, z) > o->r2 * z[NA] * z[NA] * (1 + 1e-9)) {
      if (!grow((void **)&cut, &cap_cut, n_cut, sizeof(cut_state))) break;
      cut[n_cut].index = order[s].index; /* cut by the ellipsoid: phase 2 */
      cut[n_cut].val = val;
      cut[n_cut++].t = zs[NA];
    } else if (val > stick + tie) {
      if (!grow((void **)&cand, &cap_cand, ncand, sizeof(candidate))) break;
      if (val > best) best = val;
      cand[ncand].index = order[s].index;
      cand[ncand].val = val;
      memcpy(cand[ncand].z, z, sizeof z);
      collect(&p, zs, lam, 0.0, &cand[ncand].b);
      ++ncand;
    }
  }
  /* phase 2: the states cut by the ellipsoid, best relaxed value first, solved exactly */
  for (s = 0; s < n_cut; ++s) {
    double zs[NA1], z[NA1], lam[SC_ROWS_MAX], mu, lz, val;
    sc_int k = s;
    for (i = s + 1; i < n_cut; ++i) /* the best remaining (few of them) */
      if (cut[i].val > cut[k].val) k = i;
    if (k != s) {
      cut_state tmp = cut[s];
      cut[s] = cut[k];
      cut[k] = tmp;
    }
    if (cut[s].val <= best + tie) break;
    decode(o, rows, nr, cut[s].index, st);
    sc_state_maps(&o->rest, o->scene, st, 0, &mp);
    build(o, &mp, st, penalty(o, best), 0, &p);
    o->out[OPT_OUT_method] = (int)o->out[OPT_OUT_method] | SC_METHOD_SCALE;
    ++solved;
    if (!ellipsoid_exact(o, &p, cut[s].t, zs, lam, &mu)) continue;
    lz = sc_dot(p.ell, zs, NA1);
    if (!(lz > 1e-9 * sc_norm(p.ell, NA1) * sc_norm(zs, NA1)) || !(zs[NA] > 0)) continue;
    for (j = 0; j < NA1; ++j) z[j] = zs[j] * p.s[j] / lz;
    val = state_sr(o, &mp, z);
    if (val > stick + tie) {
      if (!grow((void **)&cand, &cap_cand, ncand, sizeof(candidate))) break;
      if (val > best) best = val;
      cand[ncand].index = cut[s].index;
      cand[ncand].val = val;
      memcpy(cand[ncand].z, z, sizeof z);
      collect(&p, zs, lam, mu, &cand[ncand].b);
      ++ncand;
    }
  }
  o->out[OPT_OUT_states_solved] = (double)solved;
  { /* rank the candidates by the exact forward solve */
    double row[OUT_WIDTH], best_sr = -1.0, tau[NA];
    sc_int win = -1;
    for (i = 0; i < ncand; ++i) {
      int ok = 1;
      for (j = 0; j < NA; ++j) tau[j] = cand[i].z[j] / cand[i].z[NA];
      if (sc_optimal_forward(o, tau, row) != 0 || row[OUT_status] != 0) continue;
      if (row[OUT_state] != HELD) ok = 0;
      for (r = 1; r < NC; ++r) {
        int sr = (int)row[OUT_state + r];
        if ((sr == SLIDE_POS || sr == SLIDE_NEG) && !o->slide[r]) ok = 0;
      }
      if (ok && row[OUT_sr] > best_sr) {
        best_sr = row[OUT_sr];
        win = i;
      }
    }
    if (win >= 0 && best_sr > stick + tie) {
      const candidate *w = &cand[win];
      int b;
      decode(o, rows, nr, w->index, st);
      sc_state_maps(&o->rest, o->scene, st, 0, &mp);
      for (j = 0; j < NA; ++j) o->out[OPT_OUT_tau + j] = w->z[j] / w->z[NA];
      o->out[OPT_OUT_expected] = best_sr;
      o->out[OPT_OUT_n_binding] = 0;
      for (b = 0; b < w->b.n; ++b) sc_optimal_bind(o, w->b.code[b]);
      for (r = 0; r < NC; ++r) o->out[OPT_OUT_wheel_states + r] = st[r];
      state_certificate(o, &mp, st, w->z);
    }
  }
  free(order);
  free(cand);
  free(cut);
}
