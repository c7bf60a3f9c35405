/* snakecg's runtime core, part 2: one integration segment of a simulation within a mode, in C.
 *
 * This file is part of the runtime (not generated). Like forward.c it is compiled once per
 * model into the model's shared library, beside CasADi's C of the generated functions, with
 * the header `snakecg_layout.h` written from the model's manifest (snakecg/engine/layout.py):
 * sizes, symbols and every input/output index by name.
 *
 * What it computes is what snakecg/simulate does with scipy.integrate.solve_ivp, for a mode
 * (an active set) and a torque held constant over the segment:
 *   - the right-hand side of snakecg/simulate/dynamics.py (Dynamics.rates): the generated
 *     `contact_system` at (q, v, tau, q_obj, v_obj, f_obj) (G_c, eq. 14; b, eq. 13; the free
 *     accelerations and the force maps, eqs. 12, 18), the held rows' forces with the mode's
 *     fixed forces (eq. 16, LDL^T in row order as forward.c's held_forces) and the Baumgarte
 *     terms (held rows accelerate at -2 alpha A_F V, - alpha^2 g for the contact), the rows'
 *     velocities A V from the generated `link_jacobians` (Dynamics.row_velocities), and the
 *     rates of the three work integrals;
 *   - Dormand-Prince 8(5,3) (DOP853) with the tableau, error norm, step-size control, initial
 *     step and dense output of scipy.integrate.DOP853 (Hairer, Norsett & Wanner, Solving ODE
 *     I, sec. II.10), output at requested times from the dense output;
 *   - the mode's terminal event functions (snakecg/simulate/events.py, all with direction
 *     -1, an exact zero counted as positive), detected as solve_ivp does (g >= 0 before a
 *     step, <= 0 after) and located on the dense output by Brent's method with
 *     xtol = rtol = 4 EPS (scipy.optimize.brentq);
 *   - the contact check (geometry.c, sg->geo): the largest overlap of the bodies at the
 *     segment's start, at every output time and at every step's end; the first time it
 *     exceeds the tolerance is located between the last two of these on the dense output by
 *     the same Brent's method, and stops the segment (SEG_GEOMETRY) or is recorded.
 * Dependent held rows (pivot ratio at most pivot_tol) get rows.c's Tikhonov term (the
 * least-norm forces in the limit; counted in nsingular). A failed evaluation or a derivative
 * that is not finite ends the segment with SEG_FAILED at the step's start (t_end, y_end).
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime (before the first include) */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#define NA SNAKECG_NA
#define NL SNAKECG_NL
#define MAX_EVENTS (3 + NC)
#define SC_LEAST_POSITIVE (DBL_MIN * DBL_EPSILON) /* 2^-1074, events.py's LEAST_POSITIVE */


/* DOP853: 12 stages, 16 with the dense output's, interpolant of 7 terms (scipy's
 * dop853_coefficients: N_STAGES, N_STAGES_EXTENDED, INTERPOLATOR_POWER) */
#define DP_NS 12
#define DP_NX 16
#define DP_NP 7
static const double DP_A[DP_NX][DP_NX] = {
    {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.05260015195876773, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.0197250569845379, 0.0591751709536137, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.02958758547680685, 0.0, 0.08876275643042054, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.2413651341592667, 0.0, -0.8845494793282861, 0.924834003261792, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.037037037037037035, 0.0, 0.0, 0.17082860872947386, 0.12546768756682242, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.037109375, 0.0, 0.0, 0.17025221101954405, 0.06021653898045596, -0.017578125, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.03709200011850479, 0.0, 0.0, 0.17038392571223998, 0.10726203044637328, -0.015319437748624402, 0.008273789163814023, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.6241109587160757, 0.0, 0.0, -3.3608926294469414, -0.868219346841726, 27.59209969944671, 20.154067550477894, -43.48988418106996, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.47766253643826434, 0.0, 0.0, -2.4881146199716677, -0.590290826836843, 21.230051448181193, 15.279233632882423, -33.28821096898486, -0.020331201708508627, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {-0.9371424300859873, 0.0, 0.0, 5.186372428844064, 1.0914373489967295, -8.149787010746927, -18.52006565999696, 22.739487099350505, 2.4936055526796523, -3.0467644718982196, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {2.273310147516538, 0.0, 0.0, -10.53449546673725, -2.0008720582248625, -17.9589318631188, 27.94888452941996, -2.8589982771350235, -8.87285693353063, 12.360567175794303, 0.6433927460157636, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.054293734116568765, 0.0, 0.0, 0.0, 0.0, 4.450312892752409, 1.8915178993145003, -5.801203960010585, 0.3111643669578199, -0.1521609496625161, 0.20136540080403034, 0.04471061572777259, 0.0, 0.0, 0.0, 0.0},
    {0.056167502283047954, 0.0, 0.0, 0.0, 0.0, 0.0, 0.25350021021662483, -0.2462390374708025, -0.12419142326381637, 0.15329179827876568, 0.00820105229563469, 0.007567897660545699, -0.008298, 0.0, 0.0, 0.0},
    {0.03183464816350214, 0.0, 0.0, 0.0, 0.0, 0.028300909672366776, 0.053541988307438566, -0.05492374857139099, 0.0, 0.0, -0.00010834732869724932, 0.0003825710908356584, -0.00034046500868740456, 0.1413124436746325, 0.0, 0.0},
    {-0.42889630158379194, 0.0, 0.0, 0.0, 0.0, -4.697621415361164, 7.683421196062599, 4.06898981839711, 0.3567271874552811, 0.0, 0.0, 0.0, -0.0013990241651590145, 2.9475147891527724, -9.15095847217987, 0.0}};
static const double DP_B[DP_NS] = {0.054293734116568765, 0.0, 0.0, 0.0, 0.0, 4.450312892752409, 1.8915178993145003, -5.801203960010585, 0.3111643669578199, -0.1521609496625161, 0.20136540080403034, 0.04471061572777259};
/* (the stages' times C are not needed: the right-hand side does not depend on t) */
static const double DP_E3[DP_NS + 1] = {-0.18980075407240762, 0.0, 0.0, 0.0, 0.0, 4.450312892752409, 1.8915178993145003, -5.801203960010585, -0.4226823213237919, -0.1521609496625161, 0.20136540080403034, 0.02265179219836082, 0.0};
static const double DP_E5[DP_NS + 1] = {0.01312004499419488, 0.0, 0.0, 0.0, 0.0, -1.2251564463762044, -0.4957589496572502, 1.6643771824549864, -0.35032884874997366, 0.3341791187130175, 0.08192320648511571, -0.022355307863886294, 0.0};
static const double DP_D[DP_NP - 3][DP_NX] = {
    {-8.428938276109013, 0.0, 0.0, 0.0, 0.0, 0.5667149535193777, -3.0689499459498917, 2.38466765651207, 2.117034582445028, -0.871391583777973, 2.2404374302607883, 0.6315787787694688, -0.08899033645133331, 18.148505520854727, -9.194632392478356, -4.436036387594894},
    {10.427508642579134, 0.0, 0.0, 0.0, 0.0, 242.28349177525817, 165.20045171727028, -374.5467547226902, -22.113666853125306, 7.733432668472264, -30.674084731089398, -9.332130526430229, 15.697238121770845, -31.139403219565178, -9.35292435884448, 35.81684148639408},
    {19.985053242002433, 0.0, 0.0, 0.0, 0.0, -387.0373087493518, -189.17813819516758, 527.8081592054236, -11.57390253995963, 6.8812326946963, -1.0006050966910838, 0.7777137798053443, -2.778205752353508, -60.19669523126412, 84.32040550667716, 11.99229113618279},
    {-25.69393346270375, 0.0, 0.0, 0.0, 0.0, -154.18974869023643, -231.5293791760455, 357.6391179106141, 93.40532418362432, -37.45832313645163, 104.0996495089623, 29.8402934266605, -43.53345659001114, 96.32455395918828, -39.17726167561544, -149.72683625798564}};


typedef struct {
  sc_work_t ws;
  const sc_segment *sg;
  signed char state[NC];
  double bounds[NC];
  sc_int nfev, nsingular;
  sc_constants k; /* pivot_tol and regularization: rows.c's Tikhonov rule */
  /* the last evaluation's quantities (for the event functions and the samples) */
  double lam[NC], av[NC];
  sc_system sys; /* contact_system at the last state: gap, s and M_s among it */
} sc_ctx;

/* The context of the segment sg: 0, or -1 when its work arrays could not be allocated. */
static int ctx_alloc(sc_ctx *c, const sc_segment *sg) {
  const sc_work_fn fns[] = {SC_CS_WORKS, SNAKECG_LJ_WORK};
  int i;
  c->sg = sg;
  c->nfev = c->nsingular = 0;
  memset(&c->k, 0, sizeof(c->k));
  c->k.pivot_tol = sg->pivot_tol;
  c->k.regularization = sg->regularization;
  for (i = 0; i < NC; ++i) {
    c->state[i] = (signed char)sg->state[i];
    c->bounds[i] = sg->scene[SCENE_bounds + i];
  }
  return sc_work_alloc(&c->ws, fns, SC_COUNT(fns));
}

/* The right-hand side in the mode at y (Dynamics.rates); keeps lam, A V, gap and s in c.
 * Returns 0, or SEG_FAILED (a failed evaluation, a derivative not finite). */
static int rhs(sc_ctx *c, const double *y, double *ydot) {
  const sc_segment *sg = c->sg;
  const double *q = y, *qo = y + NS, *v = y + NX, *vo = y + NX + NS;
  const sc_system *sys = &c->sys;
  const double *qdd_free = sys->qdd_free, *a_free = sys->a_free, *Kq = sys->Kq, *Ka = sys->Ka;
  double baumgarte[NC], *lam = c->lam, *av = c->av;
  double p_tau = 0.0, p_fric = 0.0, p_obj = 0.0;
  int singular, i, r;
  c->nfev++;
  if (sc_contact_system(&c->ws, sg->scene, q, v, sg->tau, qo, vo, sg->f_obj, sg->rho, &c->sys))
    return SEG_FAILED;
  if (sc_row_velocities(&c->ws, sg->scene, sg->rho, (int)sg->contact_index, sg->c_k, q, v, qo,
                        vo, sys->s, av))
    return SEG_FAILED;
  /* eq. (16) with the mode's fixed forces, the held rows Baumgarte-stabilised:
   * G_HH lam_H = -(b_H + G_HF lam_F) - 2 alpha (A V)_H [- alpha^2 g for the contact] */
  for (r = 0; r < NC; ++r) baumgarte[r] = sg->alpha > 0 ? 2.0 * sg->alpha * av[r] : 0.0;
  if (sg->alpha > 0) baumgarte[0] += sg->alpha * sg->alpha * sys->gap;
  /* (dependent held rows: Tikhonov, the whole right-hand side least-norm) */
  sc_delassus_state(sys, &c->k, c->state, c->bounds, baumgarte, lam, 0, &singular);
  c->nsingular += singular;
  /* eq. (18) and the state's rates */
  memcpy(ydot, v, sizeof(double) * NS);
  memcpy(ydot + NS, vo, sizeof(double) * 3);
  for (i = 0; i < NS; ++i) {
    double t = qdd_free[i];
    for (r = 0; r < NC; ++r) t += Kq[i + NS * r] * lam[r];
    ydot[NX + i] = t;
  }
  for (i = 0; i < 3; ++i) {
    double t = a_free[i];
    for (r = 0; r < NC; ++r) t += Ka[i + 3 * r] * lam[r];
    ydot[NX + NS + i] = t;
  }
  for (i = 0; i < NA; ++i) p_tau += sg->tau[i] * v[3 + i];
  for (r = 0; r < NC; ++r)
    if (c->state[r] == SLIDE_POS || c->state[r] == SLIDE_NEG) p_fric += lam[r] * av[r];
  for (i = 0; i < 3; ++i) p_obj += sg->f_obj[i] * vo[i];
  ydot[2 * NX] = p_tau;
  ydot[2 * NX + 1] = p_fric;
  ydot[2 * NX + 2] = p_obj;
  for (i = 0; i < NY; ++i)
    if (!isfinite(ydot[i])) return SEG_FAILED;
  return 0;
}

/* The event functions at the last evaluation (Events.functions). An event is the quantity
 * becoming negative: an exact zero counts as the least positive double (events.py's
 * not_crossed), so that a quantity that stays at zero (a contact held at rest with exactly no
 * force, a closed gap that does not move) is no crossing. */
static double event_value(const sc_ctx *c, int e) {
  const sc_segment *sg = c->sg;
  const int r = (int)sg->ev_row[e];
  double g;
  switch ((int)sg->ev_kind[e]) {
    case EV_SEPARATION: g = c->lam[0]; break;
    case EV_S_LOW: g = c->sys.s; break;
    case EV_S_HIGH: g = sg->l_k - c->sys.s; break;
    case EV_GAP: g = c->sys.gap; break;
    case EV_BREAKAWAY: g = c->bounds[r] - fabs(c->lam[r]); break;
    default: /* EV_SLIDE_STOP: the sliding velocity's sign returning to zero */
      g = (c->state[r] == SLIDE_POS ? -1.0 : 1.0) * c->av[r];
  }
  return g == 0.0 ? SC_LEAST_POSITIVE : g;
}

static double rms(const double *x, const double *scale, int n) {
  double s = 0.0;
  int i;
  for (i = 0; i < n; ++i) s += (x[i] / scale[i]) * (x[i] / scale[i]);
  return sqrt(s) / sqrt((double)n);
}

/* The dense output of the last step (scipy's Dop853DenseOutput). */
typedef struct {
  double t_old, h, y_old[NY], F[DP_NP][NY];
} sc_dense;

static void dense_eval(const sc_dense *D, double t, double *y) {
  const double x = (t - D->t_old) / D->h;
  int i, k;
  for (k = 0; k < NY; ++k) y[k] = 0.0;
  for (i = 0; i < DP_NP; ++i) { /* reversed(F): F[6], F[5], ..., F[0] */
    const double *f = D->F[DP_NP - 1 - i];
    const double m = (i % 2 == 0) ? x : 1.0 - x;
    for (k = 0; k < NY; ++k) y[k] = (y[k] + f[k]) * m;
  }
  for (k = 0; k < NY; ++k) y[k] += D->y_old[k];
}

/* The event function e at time t on the dense output: 0 or SEG_FAILED. */
static int event_at(sc_ctx *c, const sc_dense *D, int e, double t, double *g) {
  double y[NY], f[NY];
  int st;
  dense_eval(D, t, y);
  st = rhs(c, y, f);
  *g = event_value(c, e);
  return st;
}

/* The event function e on the dense output D (an sc_root_fn). */
typedef struct {
  sc_ctx *c;
  const sc_dense *D;
  int e;
} sc_event_arg;

static int event_fn(void *arg, double t, double *g) {
  sc_event_arg *a = (sc_event_arg *)arg;
  return event_at(a->c, a->D, a->e, t, g);
}

/* The contact check's margin, tolerance - largest overlap, on the dense output D (an
 * sc_root_fn). */
typedef struct {
  const sc_geometry *geo;
  const sc_dense *D;
} sc_geo_arg;

static int sc_geo_fn(void *arg, double t, double *g) {
  const sc_geo_arg *a = (const sc_geo_arg *)arg;
  double y[NY];
  sc_int pair;
  dense_eval(a->D, t, y);
  *g = a->geo->tol - sc_geo_depth(a->geo, y, &pair);
  return 0;
}

/* One DOP853 step of size h from (t, y) with f = f(t, y): K (DP_NX x NY) filled up to stage
 * DP_NS (f_new), y_new. Returns 0 or SEG_FAILED. */
static int rk_step(sc_ctx *c, double t, const double *y, const double *f, double h,
                   double (*K)[NY], double *y_new) {
  double yy[NY];
  int s, j, k, st;
  (void)t;
  memcpy(K[0], f, sizeof(double) * NY);
  for (s = 1; s < DP_NS; ++s) {
    for (k = 0; k < NY; ++k) {
      double dy = 0.0;
      for (j = 0; j < s; ++j) dy += K[j][k] * DP_A[s][j];
      yy[k] = y[k] + dy * h;
    }
    if ((st = rhs(c, yy, K[s]))) return st;
  }
  for (k = 0; k < NY; ++k) {
    double dy = 0.0;
    for (j = 0; j < DP_NS; ++j) dy += K[j][k] * DP_B[j];
    y_new[k] = y[k] + h * dy;
  }
  return rhs(c, y_new, K[DP_NS]);
}

static double error_norm(double (*K)[NY], double h, const double *scale) {
  double e5 = 0.0, e3 = 0.0;
  int j, k;
  for (k = 0; k < NY; ++k) {
    double a = 0.0, b = 0.0;
    for (j = 0; j <= DP_NS; ++j) {
      a += K[j][k] * DP_E5[j];
      b += K[j][k] * DP_E3[j];
    }
    a /= scale[k];
    b /= scale[k];
    e5 += a * a;
    e3 += b * b;
  }
  if (e5 == 0 && e3 == 0) return 0.0;
  return fabs(h) * e5 / sqrt((e5 + 0.01 * e3) * NY);
}

/* The dense output of the step (t_old, y_old) -> (t_old + h, y_new) with its stages K. */
static int dense_build(sc_ctx *c, double t_old, double h, const double *y_old,
                       const double *y_new, const double *f_new, double (*K)[NY],
                       sc_dense *D) {
  double yy[NY];
  int s, j, k, i, st;
  for (s = DP_NS + 1; s < DP_NX; ++s) {
    for (k = 0; k < NY; ++k) {
      double dy = 0.0;
      for (j = 0; j < s; ++j) dy += K[j][k] * DP_A[s][j];
      yy[k] = y_old[k] + dy * h;
    }
    if ((st = rhs(c, yy, K[s]))) return st;
  }
  D->t_old = t_old;
  D->h = h;
  memcpy(D->y_old, y_old, sizeof(double) * NY);
  for (k = 0; k < NY; ++k) {
    const double dy = y_new[k] - y_old[k];
    D->F[0][k] = dy;
    D->F[1][k] = h * K[0][k] - dy;
    D->F[2][k] = 2 * dy - h * (f_new[k] + K[0][k]);
    for (i = 0; i < DP_NP - 3; ++i) {
      double t = 0.0;
      for (j = 0; j < DP_NX; ++j) t += DP_D[i][j] * K[j][k];
      D->F[3 + i][k] = h * t;
    }
  }
  return 0;
}

/* scipy's select_initial_step for an error estimator of order 7. */
static int initial_step(sc_ctx *c, const sc_segment *sg, const double *y0, const double *f0,
                        double *h_out) {
  double scale[NY], y1[NY], f1[NY], diff[NY], d0, d1, d2, h0, h1, len = fabs(sg->t1 - sg->t0);
  int k, st;
  if (len == 0.0) {
    *h_out = 0.0;
    return 0;
  }
  for (k = 0; k < NY; ++k) scale[k] = sg->atol + fabs(y0[k]) * sg->rtol;
  d0 = rms(y0, scale, NY);
  d1 = rms(f0, scale, NY);
  h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  if (h0 > len) h0 = len;
  for (k = 0; k < NY; ++k) y1[k] = y0[k] + h0 * f0[k];
  if ((st = rhs(c, y1, f1))) return st;
  for (k = 0; k < NY; ++k) diff[k] = f1[k] - f0[k];
  d2 = rms(diff, scale, NY) / h0;
  if (d1 <= 1e-15 && d2 <= 1e-15) h1 = fmax(1e-6, h0 * 1e-3);
  else h1 = pow(0.01 / fmax(d1, d2), 1.0 / 8.0);
  *h_out = fmin(fmin(100 * h0, h1), fmin(len, sg->max_step));
  return 0;
}

/* The segment's steps. A call that has taken at least one step and used up its wall-clock
 * budget stops before the next step with SEG_PAUSED, its place (t, y, the step size, the
 * outputs written) in t_end, y_end, h_next and n_out; the call with `resume` goes on from
 * there: the right-hand side and the event functions at y are evaluated again (the same
 * values as the step's end gave), so the steps are those of a call that never stopped. */
static int segment(sc_ctx *c, sc_segment *sg) {
  double K[DP_NX][NY], y[NY], f[NY], y_new[NY], f_new[NY], scale[NY];
  double g_old[MAX_EVENTS], g_new[MAX_EVENTS], sc_geo_old = 0.0;
  double t, h_abs = 0.0, h, t_new, err, factor;
  const double stop_at = sg->budget > 0 ? sc_wall_time() + sg->budget : INFINITY;
  sc_dense D;
  const int n_ev = (int)sg->n_ev;
  sc_geometry *geo = sg->geo && sg->geo->mode != SC_GEO_OFF && !sg->geo->found ? sg->geo : 0;
  sc_int ie, steps = 0;
  int st, e, k, accepted, rejected, have_dense;
  if (sg->resume) {
    t = sg->t_end;
    ie = sg->n_out;
    h_abs = sg->h_next;
    memcpy(y, sg->y_end, sizeof(double) * NY);
  } else {
    t = sg->t0;
    ie = 0;
    memcpy(y, sg->y0, sizeof(double) * NY);
  }
  if (geo) { /* the contact check at the start (a resumed call: where the last one paused) */
    sc_int pair;
    const double d = sc_geo_depth(geo, y, &pair);
    if (!sg->resume && d > geo->tol) {
      sc_geo_record(geo, t, y, d, pair);
      if (geo->mode == SC_GEO_STOP) {
        memcpy(sg->y_end, y, sizeof(double) * NY);
        return SEG_GEOMETRY;
      }
      geo = 0;
    }
    sc_geo_old = geo ? geo->tol - d : 0.0;
  }
  if ((st = rhs(c, y, f))) return st;
  for (e = 0; e < n_ev; ++e) g_old[e] = event_value(c, e);
  if (!sg->resume && (st = initial_step(c, sg, y, f, &h_abs))) return st;
  while (!(t == sg->t1)) {
    const double min_step = 10 * fabs(nextafter(t, INFINITY) - t);
    sg->t_end = t; /* (where a failed step leaves it) */
    if (steps > 0 && sc_wall_time() > stop_at) {
      sg->t_end = t;
      memcpy(sg->y_end, y, sizeof(double) * NY);
      sg->h_next = h_abs;
      sg->n_out = ie;
      return SEG_PAUSED;
    }
    ++steps;
    if (h_abs > sg->max_step) h_abs = sg->max_step;
    else if (h_abs < min_step) h_abs = min_step;
    accepted = rejected = 0;
    while (!accepted) {
      if (h_abs < min_step) {
        sg->t_end = t;
        memcpy(sg->y_end, y, sizeof(double) * NY);
        return SEG_TOO_SMALL;
      }
      h = h_abs;
      t_new = t + h;
      if (t_new - sg->t1 > 0) t_new = sg->t1;
      h = t_new - t;
      h_abs = fabs(h);
      if ((st = rk_step(c, t, y, f, h, K, y_new))) return st;
      for (k = 0; k < NY; ++k) scale[k] = sg->atol + fmax(fabs(y[k]), fabs(y_new[k])) * sg->rtol;
      err = error_norm(K, h, scale);
      if (err < 1) {
        factor = err == 0 ? 10.0 : fmin(10.0, 0.9 * pow(err, -1.0 / 8.0));
        if (rejected) factor = fmin(1.0, factor);
        h_abs *= factor;
        accepted = 1;
      } else {
        h_abs *= fmax(0.2, 0.9 * pow(err, -1.0 / 8.0));
        rejected = 1;
        sg->nrejected++;
      }
    }
    sg->nsteps++;
    memcpy(f_new, K[DP_NS], sizeof(double) * NY);
    /* the event functions at the step's end: the last evaluation was there */
    for (e = 0; e < n_ev; ++e) g_new[e] = event_value(c, e);
    have_dense = 0;
    {
      int first = -1;
      double t_stop = t_new, root;
      sc_int ie0;
      sc_event_arg arg;
      for (e = 0; e < n_ev; ++e) {
        if (!(g_old[e] >= 0 && g_new[e] <= 0)) continue; /* direction -1 */
        if (!have_dense) {
          if ((st = dense_build(c, t, h, y, y_new, f_new, K, &D))) return st;
          have_dense = 1;
        }
        arg.c = c;
        arg.D = &D;
        arg.e = e;
        if ((st = sc_brentq(event_fn, &arg, t, t_new, 4 * DBL_EPSILON, 4 * DBL_EPSILON,
                            &root)))
          return st;
        if (first < 0 || root < t_stop) {
          first = e;
          t_stop = root;
        }
      }
      /* output times up to the step's end (or the event), from the dense output */
      if (ie < sg->n_eval && sg->t_eval[ie] <= t_stop && !have_dense) {
        if ((st = dense_build(c, t, h, y, y_new, f_new, K, &D))) return st;
        have_dense = 1;
      }
      ie0 = ie;
      while (ie < sg->n_eval && sg->t_eval[ie] <= t_stop) {
        dense_eval(&D, sg->t_eval[ie], sg->y_eval + ie * NY);
        ++ie;
        sg->n_out = ie;
      }
      if (geo) { /* the contact check at the outputs, then at t_stop */
        double ta = t, ga = sc_geo_old, gb = 0.0, tb = t_stop, yb[NY];
        sc_int j, pair;
        int crossed = 0;
        for (j = ie0; j < ie && !crossed; ++j) {
          gb = geo->tol - sc_geo_depth(geo, sg->y_eval + j * NY, &pair);
          if (ga >= 0 && gb < 0) crossed = 1, tb = sg->t_eval[j];
          else ta = sg->t_eval[j], ga = gb;
        }
        if (!crossed) {
          if (first >= 0) dense_eval(&D, t_stop, yb);
          else memcpy(yb, y_new, sizeof(double) * NY);
          gb = geo->tol - sc_geo_depth(geo, yb, &pair);
          crossed = ga >= 0 && gb < 0;
          sc_geo_old = gb;
        }
        if (crossed) { /* located on the dense output */
          sc_geo_arg garg;
          double d;
          if (!have_dense) {
            if ((st = dense_build(c, t, h, y, y_new, f_new, K, &D))) return st;
            have_dense = 1;
          }
          garg.geo = geo;
          garg.D = &D;
          sc_brentq(sc_geo_fn, &garg, ta, tb, 4 * DBL_EPSILON, 4 * DBL_EPSILON, &root);
          dense_eval(&D, root, yb);
          d = sc_geo_depth(geo, yb, &pair);
          sc_geo_record(geo, root, yb, d, pair);
          if (geo->mode == SC_GEO_STOP) { /* the outputs after it dropped */
            while (ie > ie0 && sg->t_eval[ie - 1] > root) --ie;
            sg->n_out = ie;
            sg->t_end = root;
            memcpy(sg->y_end, yb, sizeof(double) * NY);
            return SEG_GEOMETRY;
          }
          geo = 0; /* recorded: not looked for again */
        }
      }
      if (first >= 0) {
        sg->event = first;
        sg->t_end = t_stop;
        dense_eval(&D, t_stop, sg->y_end);
        return SEG_EVENT;
      }
    }
    for (e = 0; e < n_ev; ++e) g_old[e] = g_new[e];
    t = t_new;
    memcpy(y, y_new, sizeof(double) * NY);
    memcpy(f, f_new, sizeof(double) * NY);
  }
  sg->t_end = t;
  memcpy(sg->y_end, y, sizeof(double) * NY);
  return SEG_END;
}

/* Integrate one segment (see sc_segment), or go on with a paused one (`resume`); returns and
 * stores the status (SEG_*). */
int SNAKECG_EXPORT(core_integrate_segment)(sc_segment *sg) {
  sc_ctx c;
  int i, st;
  if (!sg->resume) {
    sg->n_out = 0;
    sg->t_end = sg->t0;
  }
  sg->event = -1;
  sg->nfev = sg->nsteps = sg->nrejected = sg->nsingular = 0;
  if (sg->n_ev < 0 || sg->n_ev > MAX_EVENTS || !(sg->t1 > sg->t0) || !(sg->rtol > 0) ||
      !(sg->atol >= 0) || !(sg->max_step > 0) || sg->contact_index < 0 ||
      sg->contact_index >= NL) {
    sg->status = SEG_BAD_INPUT;
    return SEG_BAD_INPUT;
  }
  for (i = 0; i < NY; ++i)
    if (!isfinite(sg->y0[i])) {
      sg->status = SEG_BAD_INPUT;
      return SEG_BAD_INPUT;
    }
  if (ctx_alloc(&c, sg)) {
    sg->status = SEG_MEMORY;
    return SEG_MEMORY;
  }
  st = segment(&c, sg);
  sg->nfev = c.nfev;
  sg->nsingular = c.nsingular;
  sc_work_free(&c.ws);
  sg->status = st;
  return st;
}

/* The trajectory's quantities at n states Y (n x NY, row-major) in the segment's mode: row i
 * of out (SAMPLE_WIDTH = NY + 2 NC + 6 columns) is ydot (NY), lam (NC), A V (NC), gap, s, sr,
 * norm_a_obj, norm_qdd (eqs. 30, 27, 26) and the sample's status (0, or SEG_FAILED: then the
 * rest of its row is NaN). Returns 0, or SEG_MEMORY. */
int SNAKECG_EXPORT(core_mode_samples)(sc_segment *sg, sc_int n, const double *Y, double *out) {
  const int width = NY + 2 * NC + 6;
  const double *I_obj = sg->scene + SCENE_object_mass;
  sc_ctx c;
  sc_int k;
  int i, j;
  if (ctx_alloc(&c, sg)) {
    return SEG_MEMORY;
  }
  for (k = 0; k < n; ++k) {
    double *row = out + k * width, *extra = row + NY, nq = 0.0, na;
    const double *qdd = row + NX, *a = row + NX + NS;
    const int st = rhs(&c, Y + k * NY, row);
    memcpy(extra, c.lam, sizeof(double) * NC);
    memcpy(extra + NC, c.av, sizeof(double) * NC);
    extra[2 * NC] = c.sys.gap;
    extra[2 * NC + 1] = c.sys.s;
    for (i = 0; i < NS; ++i) {
      double t = 0.0;
      for (j = 0; j < NS; ++j) t += c.sys.M[i + NS * j] * qdd[j];
      nq += qdd[i] * t;
    }
    na = I_obj[0] * a[0] * a[0] + I_obj[0] * a[1] * a[1] +
         sg->scene[SCENE_object_inertia] * a[2] * a[2];
    extra[2 * NC + 2] = na / fmax(na + nq, 1e-300);
    extra[2 * NC + 3] = na;
    extra[2 * NC + 4] = nq;
    extra[2 * NC + 5] = (double)st;
    for (i = 0; i < width - 1 && st; ++i) row[i] = NAN;
  }
  sc_work_free(&c.ws);
  return 0;
}
