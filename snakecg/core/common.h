/* What the runtime core's C files share (snakecg/core/forward.c, integrate.c, settle.c,
 * run.c, maps.c): the sizes, the row states, the simulation's structs, the
 * generated functions' work arrays, one evaluation of the generated `contact_system` (the
 * object given or placed), the rows' velocities A V, the held rows' forces of eq. (16) and the
 * active-set rule. Included after snakecg_layout.h; everything here is static, so each file
 * gets its own copy and the library exports nothing more; a file asks for the parts that not
 * every file uses (SC_ROW_VELOCITIES, SC_NEXT_STATES), or the types alone
 * (SC_TYPES_ONLY), before including it. */
#ifndef SNAKECG_CORE_COMMON_H
#define SNAKECG_CORE_COMMON_H

#include <math.h>
#include <stdlib.h>
#include <time.h>

typedef long long int sc_int;

#ifdef SC_WALL_TIME
/* Wall-clock seconds from an arbitrary origin (POSIX's monotonic clock: the file defines
 * _POSIX_C_SOURCE before its first include; elsewhere the CPU time): the long calls of the
 * simulation pause after a budget of them, so that Python can handle a Ctrl-C. */
static double sc_wall_time(void) {
#if defined(CLOCK_MONOTONIC)
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
#else
  return (double)clock() / CLOCKS_PER_SEC;
#endif
}
#endif

/* Before a loop over one of the model's sizes (known when compiling): unroll it (GCC; other
 * compilers go on without). */
#if defined(__GNUC__) && !defined(__clang__)
#define SC_UNROLL _Pragma("GCC unroll 16")
#else
#define SC_UNROLL
#endif

/* sizes: coordinates n_s, constraint rows n_c, a body state (q, q_obj), the integrated state
 * (positions, velocities and three work integrals) */
#define NS SNAKECG_NS
#define NC SNAKECG_NC
#define NX (NS + 3)
#define NY (2 * NX + 3)

typedef int (*sc_work_fn)(sc_int *sz_arg, sc_int *sz_res, sc_int *sz_iw, sc_int *sz_w);

int SNAKECG_CS(const double **arg, double **res, sc_int *iw, double *w, int mem);
int SNAKECG_CS_WORK(sc_int *sz_arg, sc_int *sz_res, sc_int *sz_iw, sc_int *sz_w);
int SNAKECG_CR(const double **arg, double **res, sc_int *iw, double *w, int mem);
int SNAKECG_CR_WORK(sc_int *sz_arg, sc_int *sz_res, sc_int *sz_iw, sc_int *sz_w);
int SNAKECG_LJ(const double **arg, double **res, sc_int *iw, double *w, int mem);
int SNAKECG_LJ_WORK(sc_int *sz_arg, sc_int *sz_res, sc_int *sz_iw, sc_int *sz_w);

/* row states (snakecg/solver.py); SUPPORT: a bilateral row that always holds and may depend
 * on the other held rows (a spatial snake's ground rows, snakecg/spatial/analysis.py) */
enum { ABSENT = 0, HELD = 1, LOST = 2, SLIDE_POS = 3, SLIDE_NEG = 4, SUPPORT = 5 };
/* A SUPPORT row whose pivot ratio is at most this depends on the held rows before it. */
#define SC_SUPPORT_TOL 1e-10

/* The simulation's structs, shared by integrate.c, settle.c and run.c (mirrored field by
 * field in snakecg/core/segment.py). */
/* event functions (snakecg/simulate/events.py, Events.functions) */
enum { EV_SEPARATION = 0, EV_S_LOW = 1, EV_S_HIGH = 2, EV_GAP = 3, EV_BREAKAWAY = 4,
       EV_SLIDE_STOP = 5 };
/* segment status */
enum { SEG_END = 0, SEG_EVENT = 1, SEG_GEOMETRY = 2, SEG_PAUSED = 3, SEG_TOO_SMALL = -1,
       SEG_PYTHON = -2,
       SEG_MEMORY = -3, SEG_BAD_INPUT = -4 };
enum { SETTLE_DONE = 0, SETTLE_PYTHON = 1, SETTLE_MEMORY = 2 };

/* One segment: inputs, then outputs (filled by core_integrate_segment). */
typedef struct {
  /* the model and the run */
  const double *scene;   /* the scene vector (layout: SCENE_*) */
  const double *tau;     /* NA, held over the segment */
  const double *f_obj;   /* 3 */
  const double *rho;     /* 2, contact point in the object frame */
  const double *state;   /* NC row states (solver codes, as doubles) */
  const sc_int *ev_kind; /* n_ev event kinds (EV_*) */
  const sc_int *ev_row;  /* their rows */
  sc_int n_ev;
  sc_int contact_index;  /* k: the contact link, from 0 */
  double c_k, l_k;       /* the contact link's COM offset and length */
  double alpha;          /* Baumgarte rate (1/s) */
  double pivot_tol;      /* held rows dependent at or below this pivot ratio */
  double rtol, atol, max_step;
  double t0, t1;
  const double *y0;      /* NY */
  const double *t_eval;  /* n_eval increasing times in (t0, t1] */
  sc_int n_eval;
  struct sc_geometry *geo; /* the contact check (geometry.h), or null */
  double budget;         /* wall-clock seconds a call may take: after them (and at least one
                            step) it stops with SEG_PAUSED; <= 0: no limit */
  sc_int resume;         /* 1: go on with the segment a call paused (from t_end, y_end,
                            h_next and n_out, as if it had not stopped) */
  /* outputs */
  double *y_eval;        /* n_eval x NY, row-major */
  sc_int n_out;          /* output times reached */
  double t_end;          /* where the segment ended (t1 or the event) */
  double *y_end;         /* NY: the state there */
  sc_int event;          /* the event that fired (index into ev_*), -1 if none */
  sc_int nfev, nsteps, nrejected; /* of this call */
  double h_next;         /* SEG_PAUSED: the step size to go on with */
  sc_int status;         /* SEG_* */
} sc_segment;

/* One settle: inputs, then outputs (filled by core_settle). */
typedef struct {
  const double *scene;  /* the scene vector (layout: SCENE_*) */
  const double *tau;    /* NA */
  const double *f_obj;  /* 3 */
  const double *rho;    /* 2 */
  sc_int contact_index; /* k, from 0 */
  double c_k, l_k;
  double pivot_tol, rel_tol;
  sc_int max_iter;      /* active-set passes */
  const double *y;      /* NY: the state at the event */
  const double *prev;   /* NC row states of the mode before (null at the start) */
  const double *forced; /* NC: a row's forced state, or -1 */
  sc_int contact_candidate;
  /* outputs */
  double vtol;          /* 1e-8 max(1, max |V|) at y */
  double *y_out;        /* NY */
  double *state;        /* NC: the new row states */
  double *forced_out;   /* NC: the forced rows after the velocity checks (-1: free) */
  sc_int impact;        /* 1 when the contact closed with an impact */
  double impact_velocity, impact_ke, impact_de; /* gdot before, energy before, change */
  double *impact_lam;   /* NC: impulses of the contact and the ideal wheels, in row order */
  sc_int n_impact;
  sc_int n_projected;   /* rows projected in step 4 (0: none) */
  double drift;         /* their largest |A V| before the projection */
  sc_int drift_row;     /* where it is (the first such row) */
  double projection_ke, projection_de;
  double *projection_lam; /* NC: their impulses, in row order */
  sc_int status;        /* SETTLE_* */
} sc_settle;

#ifndef SC_TYPES_ONLY /* run.c: the types alone */
/* Argument and result pointer arrays and work vectors of generated functions, sized for the
 * largest of `n` of them (their `_work` functions). */
typedef struct {
  const double **arg;
  double **res;
  sc_int *iw;
  double *w;
} sc_work_t;

static void sc_work_free(sc_work_t *ws) {
  free((void *)ws->arg);
  free(ws->res);
  free(ws->iw);
  free(ws->w);
  ws->arg = 0;
  ws->res = 0;
  ws->iw = 0;
  ws->w = 0;
}

/* The entries of an array (of the work-size functions a file passes to sc_work_alloc). */
#define SC_COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* 0, or -1 when a size query or an allocation failed (then nothing is left allocated). */
static int sc_work_alloc(sc_work_t *ws, const sc_work_fn *fns, int n) {
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

/* The outputs of `contact_system`: the problem of one state before any active set. */
typedef struct {
  double M[SNAKECG_NS * SNAKECG_NS];          /* M_s (eq. 4), column-major */
  double G[SNAKECG_NC * SNAKECG_NC];          /* G_c (eq. 14) */
  double b[SNAKECG_NC];                       /* the rows' accelerations at lam = 0 (eq. 13) */
  double qdd_free[SNAKECG_NS], a_free[3];     /* eq. (12) without constraint forces */
  double Kq[SNAKECG_NS * SNAKECG_NC];         /* M_s^-1 A_s^T (eq. 18) */
  double Ka[3 * SNAKECG_NC];                  /* I_obj^-1 A_o^T (eq. 18) */
  double gap, s;
} sc_system;

/* `contact_system` at (q, v, tau, q_obj, v_obj, f_obj, rho) with the scene's constants of
 * `scene` (SCENE_* offsets); q_obj == NULL places the object at the scene's contact from q
 * (the generated function's input `placed` = 1; rho is then ignored too). When v and v_obj
 * are zero, the generated `contact_system_at_rest` (the same without the velocity terms).
 * The work arrays must fit both (SC_CS_WORKS). Its status (0 on success).
 * SC_SET_SYSTEM_ARGS(F) points the arguments and results of function F (CS or CR: the
 * indices differ) at sc_contact_system's own parameters and locals, by their names. */
#define SC_CS_WORKS SNAKECG_CS_WORK, SNAKECG_CR_WORK
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

static int sc_contact_system(sc_work_t *ws, const double *scene, const double *q,
                             const double *v, const double *tau, const double *q_obj,
                             const double *v_obj, const double *f_obj, const double *rho,
                             sc_system *out) {
  static const double zeros[3] = {0.0, 0.0, 0.0}, one = 1.0, zero = 0.0;
  int k, rest = 1;
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

#ifdef SC_ROW_VELOCITIES /* integrate.c, settle.c */
/* A V (snakecg.simulate.dynamics.Dynamics.row_velocities): the gap rate (row 0) and the
 * wheels' lateral velocities, from the generated `link_jacobians` at q (its status, 0 on
 * success). The link twists J v; the wheel row of link i is (-sin phi_i, cos phi_i,
 * wheel_offset_i) on its twist, the contact row the normal n = side (-sin phi_k, cos phi_k)
 * on the velocity of the object's contact point (rho in the object frame) relative to the
 * link's, less the sliding term side omega_k (s - c_k). */
static int sc_row_velocities(sc_work_t *ws, const double *scene, const double *rho, int k,
                             double c_k, const double *q, const double *v, const double *qo,
                             const double *vo, double s, double *av) {
  enum { ns = SNAKECG_NS, nl = SNAKECG_NL };
  const double *woff = scene + SCENE_wheel_offset;
  const double sig = scene[SCENE_side];
  double J[3 * SNAKECG_NL * SNAKECG_NS], tw[3 * SNAKECG_NL], phi = q[2], spk = 0.0, cpk = 0.0;
  double n0, n1, cs, sn, rx, ry, p0, p1;
  int i, j;
  ws->arg[LJ_IN_q] = q;
  ws->arg[LJ_IN_K] = scene + SCENE_K;
  ws->res[LJ_OUT_J] = J;
  if (SNAKECG_LJ(ws->arg, ws->res, ws->iw, ws->w, 0)) return 1;
  for (i = 0; i < 3 * nl; ++i) {
    double t = 0.0;
    for (j = 0; j < ns; ++j) t += J[i + 3 * nl * j] * v[j];
    tw[i] = t;
  }
  for (i = 0; i < nl; ++i) { /* phi_1 = theta, phi_{i+1} = phi_i + q_i */
    double sp, cp;
    if (i) phi += q[2 + i];
    sp = sin(phi);
    cp = cos(phi);
    if (i == k) {
      spk = sp;
      cpk = cp;
    }
    av[1 + i] = -sp * tw[3 * i] + cp * tw[3 * i + 1] + woff[i] * tw[3 * i + 2];
  }
  n0 = sig * -spk;
  n1 = sig * cpk;
  cs = cos(qo[2]);
  sn = sin(qo[2]);
  rx = rho[0];
  ry = rho[1];
  p0 = vo[0] - vo[2] * (sn * rx + cs * ry);
  p1 = vo[1] + vo[2] * (cs * rx - sn * ry);
  av[0] = n0 * (p0 - tw[3 * k]) + n1 * (p1 - tw[3 * k + 1]) - sig * tw[3 * k + 2] * (s - c_k);
  return 0;
}
#endif

/* Solve L D L^T x = y in place (m rows; a dropped row has dinv 0 and a zero column of L). */
static void sc_ldl_solve(int m, const double *L, const double *dinv, double *y) {
  const int nc = SNAKECG_NC;
  int i, k;
  for (i = 0; i < m; ++i) /* forward, diagonal and back substitution */
    for (k = 0; k < i; ++k) y[i] -= L[i + nc * k] * y[k];
  for (i = m - 1; i >= 0; --i) {
    y[i] *= dinv[i];
    for (k = i + 1; k < m; ++k) y[i] -= L[k + nc * i] * y[k];
  }
}

/* The held forces y (m of them) made least-norm where SUPPORT rows were dropped (drop[j]):
 * the solutions differ by the null vectors z_j = e_j - G_KK^-1 G_Kj (K: the rows kept), so
 * y <- y - Z (Z^T Z)^-1 Z^T y. */
static void sc_least_norm(int m, const int *held, const int *drop, const double *G,
                          const double *L, const double *dinv, double *y) {
  const int nc = SNAKECG_NC;
  double Z[SNAKECG_NC * SNAKECG_NC], C[SNAKECG_NC * SNAKECG_NC], c[SNAKECG_NC];
  int nd = 0, i, j, k;
  for (j = 0; j < m; ++j) {
    double *z = Z + nc * nd;
    if (!drop[j]) continue;
    for (i = 0; i < m; ++i) z[i] = drop[i] ? 0.0 : G[held[i] + nc * held[j]];
    sc_ldl_solve(m, L, dinv, z);
    for (i = 0; i < m; ++i) z[i] = -z[i];
    z[j] = 1.0;
    ++nd;
  }
  for (j = 0; j < nd; ++j) { /* C = Z^T Z (Cholesky in place), c = Z^T y */
    double t = 0.0;
    for (i = 0; i < m; ++i) t += Z[i + nc * j] * y[i];
    c[j] = t;
    for (k = 0; k <= j; ++k) {
      double s = 0.0;
      for (i = 0; i < m; ++i) s += Z[i + nc * j] * Z[i + nc * k];
      C[j + nc * k] = s;
    }
  }
  for (j = 0; j < nd; ++j) {
    double s = C[j + nc * j];
    for (k = 0; k < j; ++k) s -= C[j + nc * k] * C[j + nc * k];
    s = sqrt(s);
    C[j + nc * j] = s;
    for (i = j + 1; i < nd; ++i) {
      double t = C[i + nc * j];
      for (k = 0; k < j; ++k) t -= C[i + nc * k] * C[j + nc * k];
      C[i + nc * j] = t / s;
    }
  }
  for (j = 0; j < nd; ++j) { /* c <- C^-T C^-1 c */
    for (k = 0; k < j; ++k) c[j] -= C[j + nc * k] * c[k];
    c[j] /= C[j + nc * j];
  }
  for (j = nd - 1; j >= 0; --j) {
    for (k = j + 1; k < nd; ++k) c[j] -= C[k + nc * j] * c[k];
    c[j] /= C[j + nc * j];
  }
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
static double sc_held_forces(const signed char *state, const double *G, const double *b,
                             const double *bounds, const double *extra, double *lam) {
  const int nc = SNAKECG_NC;
  int held[SNAKECG_NC], drop[SNAKECG_NC], m = 0, dropped = 0, i, j, k;
  double L[SNAKECG_NC * SNAKECG_NC], d[SNAKECG_NC], dinv[SNAKECG_NC], y[SNAKECG_NC], ratio = 1.0;
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
  SC_UNROLL
  for (j = 0; j < m; ++j) { /* L D L^T of G_HH, no pivoting */
    double s = G[held[j] + nc * held[j]], r, ld[SNAKECG_NC];
    for (k = 0; k < j; ++k) { /* ld = row j of L D */
      ld[k] = L[j + nc * k] * d[k];
      s -= L[j + nc * k] * ld[k];
    }
    r = s / G[held[j] + nc * held[j]];
    drop[j] = state[held[j]] == SUPPORT && fabs(r) <= SC_SUPPORT_TOL;
    if (drop[j]) { /* dependent: out of the factorization */
      d[j] = dinv[j] = 0.0;
      for (i = j + 1; i < m; ++i) L[i + nc * j] = 0.0;
      dropped = 1;
      continue;
    }
    d[j] = s;
    dinv[j] = 1.0 / s; /* one division per pivot */
    if (!(r >= ratio)) ratio = r; /* NaN propagates */
    for (i = j + 1; i < m; ++i) {
      double t = G[held[i] + nc * held[j]];
      for (k = 0; k < j; ++k) t -= L[i + nc * k] * ld[k];
      L[i + nc * j] = t * dinv[j];
    }
  }
  for (i = 0; i < m; ++i) /* forward, diagonal and back substitution */
    for (k = 0; k < i; ++k) y[i] -= L[i + nc * k] * y[k];
  for (i = m - 1; i >= 0; --i) {
    y[i] *= dinv[i];
    for (k = i + 1; k < m; ++k) y[i] -= L[k + nc * i] * y[k];
  }
  if (dropped) sc_least_norm(m, held, drop, G, L, dinv, y);
  for (i = 0; i < m; ++i) lam[held[i]] = y[i];
  return ratio;
}

#ifdef SC_NEXT_STATES /* forward.c, settle.c */
/* Relative weight of the rounding term of a row's scale (snakecg.solver.ROUND_REL). */
#define SC_ROUND_REL 1e-5

/* The next row states (snakecg.solver._violations with _tolerances): returns 1 if any moved.
 * Each row is judged against its own scale (force units), s_r = max(|lam_r|, |w_r| / G_rr,
 * |b_r| / G_rr, ROUND_REL sum_j |G_rj lam_j| / G_rr) with b = w - G lam (the row's
 * acceleration at zero force): tol_lam_r = rel_tol s_r, tol_w_r = rel_tol G_rr s_r. Scaling
 * every input force scales every term: the decisions do not depend on units; and the huge
 * forces of nearly dependent rows (which cancel in the other rows) no longer widen the
 * tolerance of a row they barely move. */
static int sc_next_states(signed char *state, const double *lam, const double *w,
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
#endif
#endif

#endif
