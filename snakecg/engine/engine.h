/* snakecg's engine: the one header of the compiled library's types and prototypes.
 *
 * Every C file of the engine includes the model's snakecg_layout.h (its sizes, the generated
 * functions' symbols, the offsets of the scene vector and of the query and answer vectors;
 * written from the model's manifest by snakecg/engine/layout.py), then this header. Every
 * function that crosses files is declared here, with the file that defines it; nothing else
 * declares a function of another file. The small dense linear algebra is linalg.h's.
 *
 *   contact.c       the per-state system (contact_system), the held rows' forces of eq. (16),
 *                   the active-set rule, work arrays (with forward.c alone in a spatial scene)
 *   forward.c       the forward solve of a batch (exported: core_forward)
 *   rows.c          its rare samples: Tikhonov, enumeration, the rows factored directly
 *   integrate.c     a segment between events: DOP853, dense output, event location (exported)
 *   events.c        at an event: impacts, projections, the new active set (core_settle)
 *   run.c           a whole simulation: segments and events in one call (exported: core_run)
 *   geometry.c      the contact check of a simulation (overlap depths), the rows' velocities
 *   maps.c          the system at rest and the affine maps of one row state
 *   qp.c            dense QPs and the ellipsoid constraint (the dual active set)
 *   certificate.c   non-negative least squares and the KKT certificate of a point
 *   optimal.c       the optimal-torque queries of a batch (exported: core_optimal)
 *   max_sr.c, push.c, wheel_states.c   the queries' solves
 *   pieces.c, sphere.c                 the exact extremes' pieces and faces (exported)
 *   scene_sets.c, _piece.c, _primal.c, _small.c, _tiny.c, _solve.c   the exact solve
 *   scene_place.c, _geometry.c, _broad.c, _rows.c, _step.c, _run.c   placement, contacts
 *                   (their broad phase), rows, forward, a time step, whole runs and batches
 *   scene_friction.c  Coulomb friction at a general scene's contacts (tangent rows, its solve)
 *
 * One prefix (sc_), one integer type (sc_int). The library exports the model's prefixed entry
 * points only (SNAKECG_EXPORT); the engine's own functions across its files are hidden
 * (SC_INTERNAL). */
#ifndef SNAKECG_ENGINE_H
#define SNAKECG_ENGINE_H
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
typedef long long int sc_int; /* the engine's one integer type (CasADi's casadi_int) */
#if defined(__GNUC__)
#define SC_INTERNAL __attribute__((visibility("hidden")))
#else
#define SC_INTERNAL
#endif
/* Before a loop over one of the model's sizes (known when compiling): unroll it (GCC). */
#if defined(__GNUC__) && !defined(__clang__)
#define SC_UNROLL _Pragma("GCC unroll 16")
#else
#define SC_UNROLL
#endif
#include "linalg.h"
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
#ifdef SNAKECG_LP /* a planar model's link poses, kinematics with M_s, bias forces (scene_*.c) */
int SNAKECG_LP(const double **arg, double **res, sc_int *iw, double *w, int mem);
int SNAKECG_LP_WORK(sc_int *sz_arg, sc_int *sz_res, sc_int *sz_iw, sc_int *sz_w);
int SNAKECG_SK(const double **arg, double **res, sc_int *iw, double *w, int mem);
int SNAKECG_SK_WORK(sc_int *sz_arg, sc_int *sz_res, sc_int *sz_iw, sc_int *sz_w);
int SNAKECG_BF(const double **arg, double **res, sc_int *iw, double *w, int mem);
int SNAKECG_BF_WORK(sc_int *sz_arg, sc_int *sz_res, sc_int *sz_iw, sc_int *sz_w);
#endif
/* row states (snakecg/solver.py); SUPPORT: a bilateral row held always that may depend on the
 * held rows (a spatial snake's ground rows, snakecg/spatial/analysis.py) */
enum { ABSENT = 0, HELD = 1, LOST = 2, SLIDE_POS = 3, SLIDE_NEG = 4, SUPPORT = 5 };
/* The simulation's structs (integrate.c, events.c, run.c; mirrored field by field in
 * snakecg/engine/binding.py). Event functions (Events.functions of events.py): */
enum { EV_SEPARATION = 0, EV_S_LOW = 1, EV_S_HIGH = 2, EV_GAP = 3, EV_BREAKAWAY = 4,
       EV_SLIDE_STOP = 5 };
/* segment and settle status; *_FAILED: an evaluation failed or a derivative is not finite */
enum { SEG_END = 0, SEG_EVENT = 1, SEG_GEOMETRY = 2, SEG_PAUSED = 3, SEG_TOO_SMALL = -1,
       SEG_FAILED = -2, SEG_MEMORY = -3, SEG_BAD_INPUT = -4 };
enum { SETTLE_DONE = 0, SETTLE_FAILED = 1, SETTLE_MEMORY = 2 };
/* One segment: inputs, then outputs (filled by core_integrate_segment). */
typedef struct { /* the model and the run */
  const double *scene;   /* the scene vector (layout: SCENE_*) */
  const double *tau, *f_obj, *rho; /* NA, held; 3; 2: the contact point in the object's frame */
  const double *state;   /* NC row states (solver codes, as doubles) */
  const sc_int *ev_kind, *ev_row; /* n_ev event kinds (EV_*), their rows */
  sc_int n_ev;
  sc_int contact_index;  /* k: the contact link, from 0 */
  double c_k, l_k;       /* its COM offset and length */
  double alpha;          /* Baumgarte rate (1/s) */
  double pivot_tol, regularization; /* held rows dependent at this pivot ratio: Tikhonov */
  double rtol, atol, max_step, t0, t1;
  const double *y0, *t_eval; /* NY; n_eval increasing times in (t0, t1] */
  sc_int n_eval;
  struct sc_geometry *geo; /* the contact check (geometry.c), or null */
  double budget;         /* wall seconds a call may take (then SEG_PAUSED; <= 0: none) */
  sc_int resume;         /* 1: go on with a paused segment (t_end, y_end, h_next, n_out) */
  /* outputs */
  double *y_eval;        /* n_eval x NY, row-major */
  sc_int n_out;          /* output times reached */
  double t_end;          /* where the segment ended (t1 or the event) */
  double *y_end;         /* NY: the state there */
  sc_int event;          /* the event that fired (index into ev_*), -1 if none */
  sc_int nfev, nsteps, nrejected, nsingular; /* of this call (nsingular: regularized) */
  double h_next;         /* SEG_PAUSED: the step size to go on with */
  sc_int status;         /* SEG_* */
} sc_segment;
/* One settle: inputs, then outputs (filled by core_settle). */
typedef struct {
  const double *scene;  /* the scene vector (layout: SCENE_*) */
  const double *tau, *f_obj, *rho; /* NA, 3, 2 */
  sc_int contact_index; /* k, from 0 */
  double c_k, l_k;
  double pivot_tol, rel_tol, regularization; /* as sc_segment's; the decisions' tolerance */
  sc_int max_iter;      /* active-set passes (then enumeration) */
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
  double projection_ke, projection_de, *projection_lam; /* their impulses (NC, row order) */
  sc_int nsingular;     /* projections and decisions whose held rows were dependent */
  sc_int status;        /* SETTLE_* */
} sc_settle;
/* ---- contact.c: the per-state system and its complementarity solve ---- */
/* Wall-clock seconds (monotonic): the long calls pause after a budget, for Ctrl-C. */
SC_INTERNAL double sc_wall_time(void);
/* Argument and result arrays and work vectors of generated functions (the largest of n). */
typedef struct {
  const double **arg;
  double **res;
  sc_int *iw;
  double *w;
} sc_work_t;
SC_INTERNAL void sc_work_free(sc_work_t *ws);
#define SC_COUNT(a) ((int)(sizeof(a) / sizeof((a)[0]))) /* the entries of an array */
/* 0, or -1 when a size query or an allocation failed (then nothing is left allocated). */
SC_INTERNAL int sc_work_alloc(sc_work_t *ws, const sc_work_fn *fns, int n);
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
/* `contact_system` at (q, v, tau, q_obj, v_obj, f_obj, rho), the scene's constants `scene`;
 * q_obj NULL places the object from q (rho ignored); `contact_system_at_rest` when v, v_obj
 * are zero. The work arrays must fit both (SC_CS_WORKS). Its status (0 on success). */
#define SC_CS_WORKS SNAKECG_CS_WORK, SNAKECG_CR_WORK
SC_INTERNAL int sc_contact_system(sc_work_t *ws, const double *scene, const double *q,
                                  const double *v, const double *tau, const double *q_obj,
                                  const double *v_obj, const double *f_obj, const double *rho,
                                  sc_system *out);
/* geometry.c: A V (snakecg.simulate.dynamics.Dynamics.row_velocities): the gap rate (row 0) and the
 * wheels' lateral velocities, from the generated `link_jacobians` at q (its status, 0 on
 * success). The link twists J v; the wheel row of link i is (-sin phi_i, cos phi_i,
 * wheel_offset_i) on its twist, the contact row the normal n = side (-sin phi_k, cos phi_k)
 * on the velocity of the object's contact point (rho in the object frame) relative to the
 * link's, less the sliding term side omega_k (s - c_k). */
SC_INTERNAL int sc_row_velocities(sc_work_t *ws, const double *scene, const double *rho, int k,
                                  double c_k, const double *q, const double *v,
                                  const double *qo, const double *vo, double s, double *av);
/* The solver's constants (snakecg.engine.CONSTANTS, in this order): pivot ratios of dependent,
 * of weak held rows, the decisions' tolerance, M's singular ratio, the checks' rounding, the
 * force limit, the ratio of rows dependent even factored directly, the Tikhonov weight. */
typedef struct {
  double pivot_tol, weak, rel_tol, mass_tol, sane_tol, force_limit, row_tol, regularization;
} sc_constants;
/* rows.c: a sample the fast path does not answer exactly, by the reference rules; its status
 * the reason's code. sys null when its evaluation failed; mass: M's pivot ratio. */
SC_INTERNAL void sc_forward_edge(const sc_system *sys, const double *scene,
                                 const sc_constants *c, long max_iter, int at_rest,
                                 double mass, double *out);
/* rows.c: lam (w = G lam + b unless null) of `state` by sc_held_forces (with `extra`), the
 * Tikhonov term where the held rows are dependent (*singular = 1); the pivot ratio. */
SC_INTERNAL double sc_delassus_state(const sc_system *sys, const sc_constants *c,
                                     const signed char *state, const double *u,
                                     const double *extra, double *lam, double *w,
                                     int *singular);
/* rows.c: the active set of the rows free[r] != 0 (the others keep theirs) at an event. */
SC_INTERNAL double sc_decide_states(const sc_system *sys, const sc_constants *c,
                                    const double *u, const double *free, long max_iter,
                                    signed char *state, int *singular);
/* The constraint forces for row states `state` (eq. 16): lam_F fixed (0, or +-bound for a
 * sliding wheel), lam_H solving G_HH lam_H = -(b_H + G_HF lam_F) - extra_H by LDL^T in row
 * order (the masked factorization of the generated `constrained_dynamics`); `extra` (may be
 * null) adds to the right-hand side per row (the simulator's Baumgarte terms); a dependent
 * SUPPORT row is dropped and the forces made least-norm. Returns the pivot ratio
 * min_j d_j / G_jj over the held rows not dropped (1 when none holds). */
SC_INTERNAL double sc_held_forces(const signed char *state, const double *G, const double *b,
                                  const double *bounds, const double *extra, double *lam);
/* The next row states (snakecg.solver._violations with _tolerances): returns 1 if any moved.
 * Each row is judged against its own scale (the rule in contact.c), so the decisions do not
 * depend on units, nor on the huge forces of nearly dependent rows. */
SC_INTERNAL int sc_next_states(signed char *state, const double *lam, const double *w,
                               const double *G, const double *bounds, double rel_tol);
/* ---- events.c: locating an event ---- */
/* A function of time whose root is sought (its value in *g): 0, or SEG_FAILED. */
typedef int (*sc_root_fn)(void *arg, double t, double *g);
/* The root of fn on [xa, xb] to xtol + rtol |root| (scipy.optimize.brentq's method, events.c)
 * in *root: 0, or fn's status. */
SC_INTERNAL int sc_brentq(sc_root_fn fn, void *arg, double xa, double xb, double xtol,
                          double rtol, double *root);
/* ---- geometry.c: the contact check of a simulation ---- */
/* The check of a run (mirrored in snakecg/engine/binding.py): inputs, then outputs. */
enum { SC_GEO_OFF = 0, SC_GEO_STOP = 1, SC_GEO_RECORD = 2 };
struct sc_geometry {
  sc_int mode;          /* SC_GEO_STOP: the first violation ends the segment (SEG_GEOMETRY);
                           SC_GEO_RECORD: it is recorded and the segment goes on */
  double tol;           /* the overlap allowed (m) */
  double half;          /* the plate's half side (m) */
  double radius;        /* the links' radius (m; 0: segments) */
  const double *length; /* SC_GEO_NL link lengths (joint to joint) */
  double com1;          /* link 1's COM from its rear end */
  /* outputs: the first violation (found = 1 once there is one; not looked for again) */
  sc_int found;
  double t, depth;      /* when the overlap first exceeds tol (located on the dense output) */
  sc_int pair;          /* the deepest pair there */
  double *y;            /* NY: the state there */
};
typedef struct sc_geometry sc_geometry;
/* The deepest overlap (m) of every pair at state y, its pair in *pair (geometry.c). */
SC_INTERNAL double sc_geo_depth(const sc_geometry *g, const double *y, sc_int *pair);
/* Record the first violation of the check (once). */
SC_INTERNAL void sc_geo_record(sc_geometry *g, double t, const double *y, double depth,
                               sc_int pair);
/* ---- qp.c: dense convex QPs, the ellipsoid constraint, non-negative least squares
 * and the KKT certificate (qp.c). Building blocks that know nothing of snakes: problems of a
 * few dozen variables and rows, solved exactly on their active set.
 *
 *   sc_qp_solve          min 1/2 x^T H x + g^T x  s.t.  lo <= A x <= hi, H positive definite:
 *                        the dual active-set method of Goldfarb & Idnani (1983), then the
 *                        optimum of its final active set solved directly (one KKT system)
 *   sc_qcqp_ellipsoid    the same plus x^T N x <= rho2 (N > 0, H >= 0), through the
 *                        ellipsoid's multiplier mu: x(mu) minimises 1/2 x^T (H + mu N) x +
 *                        g^T x over the linear rows and 1/sqrt(x(mu)^T N x(mu)) = 1/sqrt(rho2)
 *                        by Newton's method per piece of constant active set (bracketed)
 *   sc_nnls              min ||C y - d|| s.t. y >= 0 (Lawson & Hanson 1974, ch. 23)
 *   sc_kkt_certificate   the KKT residuals of a point of a QP or QCQP (primal, stationarity
 *                        by least-squares multipliers, dual signs, complementarity, the gap)
 *
 * Matrices are row-major (element (i, j) of an m x n matrix at [i * n + j]). Nothing is
 * allocated but the workspace of sc_qp_work_alloc, which serves every problem up to its sizes.
 */
/* A dense QP: min 1/2 x^T H x + g^T x s.t. lo_r <= a_r . x <= hi_r for r < m (a_r the rows of
 * A; -INFINITY / INFINITY for a missing side; lo_r == hi_r an equality). */
typedef struct {
  sc_int n, m;
  const double *H; /* n x n, symmetric */
  const double *g; /* n */
  const double *A; /* m x n */
  const double *lo, *hi;
} sc_qp;
/* A solution: x, the rows' signed multipliers (H x + g = sum_r lam_r a_r, lam_r >= 0 on an
 * active lower side, <= 0 on an active upper side, 0 on an inactive row), the active rows,
 * the counts of work done. */
typedef struct {
  double *x;      /* n */
  double *lam;    /* m */
  sc_int *active; /* n_active rows (at most n), in the order they entered */
  sc_int n_active;
  sc_int iterations; /* active-set changes (sc_qp_solve); QP solves (sc_qcqp_ellipsoid) */
  sc_int newton;     /* sc_qcqp_ellipsoid: Newton steps on the secular equation */
  double mu;         /* sc_qcqp_ellipsoid: the ellipsoid's multiplier (0: not active) */
} sc_qp_solution;
/* a problem's and a solution's fields at once */
SC_INTERNAL void sc_qp_define(sc_qp *qp, sc_int n, sc_int m, const double *H, const double *g,
                              const double *A, const double *lo, const double *hi);
SC_INTERNAL void sc_qp_solution_define(sc_qp_solution *s, double *x, double *lam, sc_int *active);
enum {
  SC_QP_OPTIMAL = 0,
  SC_QP_INFEASIBLE = 1,  /* the linear rows have no common point */
  SC_QP_NOT_CONVEX = 2,  /* H is not numerically positive definite */
  SC_QP_ITERATIONS = 3,  /* no convergence within the iteration limit */
  SC_QP_EMPTY = 4,       /* sc_qcqp_ellipsoid: no point of the rows inside the ellipsoid */
  SC_QP_SIZE = 5         /* larger than the workspace */
};
/* Scratch space for problems of up to n_max variables and m_max rows: allocated
 * (sc_qp_work_alloc), or the caller's arrays of SC_QP_WORK_DOUBLES and SC_QP_WORK_INTS
 * entries (sc_qp_work_init; a model's fixed sizes on the stack: no allocation per call). */
typedef struct {
  sc_int n_max, m_max;
  double *d;
  sc_int *i;
} sc_qp_work;
#define SC_QP_WORK_DOUBLES(n, m)                                                         \
  (6 * (n) * (n) + 10 * (n) + 4 * (m) + 6 + 5 * (n) * (n) + 12 * (n) +                  \
   7 * (n) * (2 * (m) + 2) + 14 * (2 * (m) + 2) + (2 * (m) + 2) * (2 * (m) + 2) +       \
   2 * (n) * (n) + 12 * (n) + 4 * (m) + 64)
#define SC_QP_WORK_INTS(n, m) (4 * (m) + 4 + 4 * (n) + 2 + 4 * (n) + 9 * (2 * (m) + 2) + 64)
/* doubles and sc_ints of each region, as carved by the function that uses it */
#define SC_QP_GI_D(n, m) (6 * (n) * (n) + 10 * (n) + 2 + 2 * (2 * (m) + 2))
#define SC_QP_GI_I(n, m) (2 * (2 * (m) + 2) + 2 * (n) + 2 * (n) + 2)
#define SC_QP_QC_D(n, m) (5 * (n) * (n) + 12 * (n))
#define SC_QP_QC_I(n, m) (2 * (n) + 2 * (n))
#define SC_QP_CE_K(n, m) (2 * (m) + 2)
#define SC_QP_CE_D(n, m)                                                        \
  (7 * (n) * SC_QP_CE_K(n, m) + 14 * SC_QP_CE_K(n, m) +                         \
   SC_QP_CE_K(n, m) * SC_QP_CE_K(n, m) + 2 * (n) * (n) + 12 * (n) + 4 * (m))
#define SC_QP_CE_I(n, m) (9 * SC_QP_CE_K(n, m))
/* the three regions of the workspace: the active-set solver, the secular equation, the
 * certificate (each may call the one before it) */
static inline double *sc_qp_gi_d(const sc_qp_work *w) { return w->d; }
static inline sc_int *sc_qp_gi_i(const sc_qp_work *w) { return w->i; }
static inline double *sc_qp_qc_d(const sc_qp_work *w) {
  return w->d + SC_QP_GI_D(w->n_max, w->m_max);
}
static inline sc_int *sc_qp_qc_i(const sc_qp_work *w) {
  return w->i + SC_QP_GI_I(w->n_max, w->m_max);
}
static inline double *sc_qp_ce_d(const sc_qp_work *w) {
  return w->d + SC_QP_GI_D(w->n_max, w->m_max) + SC_QP_QC_D(w->n_max, w->m_max);
}
static inline sc_int *sc_qp_ce_i(const sc_qp_work *w) {
  return w->i + SC_QP_GI_I(w->n_max, w->m_max) + SC_QP_QC_I(w->n_max, w->m_max);
}
/* Relative violation below which a row counts as satisfied (sc_qp_solve). */
#define SC_QP_FEAS_TOL 1e-12
SC_INTERNAL int sc_qp_work_alloc(sc_qp_work *w, sc_int n_max, sc_int m_max);
SC_INTERNAL void sc_qp_work_init(sc_qp_work *w, sc_int n_max, sc_int m_max, double *d,
                                 sc_int *i);
SC_INTERNAL void sc_qp_work_free(sc_qp_work *w);
SC_INTERNAL int sc_qp_solve(const sc_qp *qp, sc_qp_work *w, sc_qp_solution *sol);
SC_INTERNAL int sc_qcqp_ellipsoid(const sc_qp *qp, const double *N, double rho2, double mu0,
                                  sc_qp_work *w, sc_qp_solution *sol);
SC_INTERNAL int sc_nnls(sc_int n, sc_int k, const double *C, const double *d, double *y,
                        double *work, sc_int *iwork);
/* The certificate of a point x of min 1/2 x^T H x + c^T x (H null: linear) s.t.
 * lo <= G x <= hi (m rows) and, when Q is not null, x^T Q x <= r2. The constraints whose
 * relative slack is at most `active` are taken as active, their multipliers recomputed from the
 * stationarity condition (the normal equations of the unit-scaled active columns, or
 * non-negative least squares when their signs bind or they are dependent); `values` receives
 * stationarity, primal feasibility, complementarity and (convex only, else NaN) the duality
 * gap f(x) - d(lam), each relative (docs/how-to/optimize.md), and the multipliers of the rows
 * (lam, m: signed as in sc_qp_solution) and of Q (*mu), when those pointers are not null. */
SC_INTERNAL void sc_kkt_certificate(sc_int n, const double *x, const double *H, const double *c,
                                    sc_int m, const double *G, const double *lo,
                                    const double *hi, const double *Q, double r2, int convex,
                                    double active, double stationarity_tol, double *values,
                                    double *lam, double *mu, sc_qp_work *w);
/* ---- the optimal-torque queries (maps.c, optimal.c, max_sr.c, push.c, wheel_states.c).
 * One call answers a batch of configurations, each by the same steps (docs/how-to/optimize.md):
 * the system at rest with the object placed (the generated contact_system at rest), the
 * all-held maps of eqs. (17), (22), (24), (28), (29), (31) (maps.c), the query's solve
 * (max_sr.c, push.c, wheel_states.c on the QP block of qp.c), the optimality certificate on the
 * original problem, the exact forward solve at the answer (forward.c's core_forward) and the
 * forward check of the answer. The query and the answers are flat double vectors laid out in
 * snakecg_layout.h (OPT_IN_*, OPT_OUT_*; snakecg/engine/layout.py), read by name in Python
 * (snakecg/engine/binding.py); the codes below are mirrored there. */
#define NA SNAKECG_NA
#define NA1 (SNAKECG_NA + 1)
/* rows of the largest QP posed here: z = (tau, t) with the contact force, every wheel's two
 * sides, both sides of every joint's box, t >= 0 */
#define SC_ROWS_MAX (2 * SNAKECG_NC + 2 * SNAKECG_NA + 4)
/* query kinds (OPT_IN_kind) */
enum { SC_MAX_SR = 0, SC_LEAST_SLIP_PUSH = 1, SC_STRONGEST_PUSH = 2 };
/* statuses (OPT_OUT_status) */
enum { SC_OPTIMAL = 0, SC_INFEASIBLE = 1, SC_FAILED = 2 };
/* reasons (OPT_OUT_reason), with what OPT_OUT_detail holds */
enum {
  SC_REASON_NONE = 0,
  SC_REASON_SINGULAR = 1,        /* dependent held rows: the maps are not defined */
  SC_REASON_NO_PUSH = 2,         /* no torque accelerates the object */
  SC_REASON_OFF_NORMAL = 3,      /* a_obj off the contact normal: normal (2), a_dir (3) */
  SC_REASON_AGAINST_NORMAL = 4,  /* a_obj against the normal: normal (2) */
  SC_REASON_DIRECTION = 5,       /* d . n <= 0: normal (2) */
  SC_REASON_OUT_OF_REACH = 6,    /* least slip: wanted, at most (both in m/s^2) */
  SC_REASON_NO_STRONG_PUSH = 7,  /* strongest push: the limits allow none */
  SC_REASON_SOLVER = 8,          /* the solver failed: its status (SC_QP_*) */
  SC_REASON_WITHIN_REACH = 9,    /* the solver failed although the task is within reach */
  SC_REASON_CERTIFICATE = 10,    /* the certificate fails (residuals in OPT_OUT_*) */
  SC_REASON_FORWARD_CHECK = 11,  /* the forward check disagrees: OPT_OUT_check */
  SC_REASON_NOT_FINITE = 12,     /* the answer is not a finite torque within the force limit:
                                  * its largest |tau_j|; the caller solves the forward at 0
                                  * and puts its row's status second */
  SC_REASON_NO_ANSWER = 13,      /* the forward solve at the answer has none: its row's
                                  * status (the reason's code, snakecg/rows.py) */
  SC_REASON_UNANSWERABLE = 14    /* the system at rest is not usable in float64 (M_s not
                                  * positive definite, a map not finite): as NOT_FINITE */
};
/* forward checks (OPT_OUT_check), with OPT_OUT_check_detail */
enum {
  SC_CHECK_PASSED = 0,
  SC_CHECK_PENDING = -1,     /* the forward row needs the reference path first */
  SC_CHECK_TAU_MAX = 1,      /* joint (from 0), |tau_j|, tau_max_j */
  SC_CHECK_ELLIPSOID = 2,    /* tau^T N tau, radius^2 */
  SC_CHECK_SEPARATES = 3,
  SC_CHECK_SLIDES = 4,       /* link, its state */
  SC_CHECK_OBJECTIVE = 5,    /* from the forward solve, from the optimiser */
  SC_CHECK_A_OBJ = 6,        /* ||a_obj - wanted|| */
  SC_CHECK_A_MIN = 7         /* d . a_obj, a_min */
};
/* certificate kinds (OPT_OUT_certificate) */
enum { SC_CERT_NONE = 0, SC_CERT_QP = 1, SC_CERT_LP = 2, SC_CERT_QCQP = 3, SC_CERT_EIGEN = 4,
       SC_CERT_STATE = 5 };
/* binding codes (OPT_OUT_binding): then 3 + j for joint j (from 0), 3 + NA + i - 1 for the
 * wheel of link i (from 1) */
enum { SC_BIND_CONTACT = 0, SC_BIND_ELLIPSOID = 1, SC_BIND_NORMAL = 2, SC_BIND_JOINT = 3 };
#define SC_BIND_WHEEL(i) (SC_BIND_JOINT + NA + (i) - 1)
/* the methods used (OPT_OUT_method, bit flags) */
enum {
  SC_METHOD_RANK_ONE = 1,      /* max_sr: the rank-one closed form */
  SC_METHOD_EIGEN = 2,         /* max_sr: the generalized eigenproblem by Jacobi rotations */
  SC_METHOD_QP = 4,            /* a QP by the dual active set */
  SC_METHOD_LP = 8,            /* an LP by the dual active set */
  SC_METHOD_SECULAR = 16,      /* the ellipsoid's multiplier */
  SC_METHOD_CLOSED_ELLIPSOID = 32, /* the strongest push on the ellipsoid alone */
  SC_METHOD_TIE_BREAK = 64,    /* the least-slip tie-break of a degenerate LP */
  SC_METHOD_DIAGNOSIS = 128,   /* the strongest push that diagnoses an infeasible task */
  SC_METHOD_STATES = 256,      /* max_sr: the sliding wheel states */
  SC_METHOD_SCALE = 512        /* t-scale search of a state cut by the ellipsoid */
};
/* The system at rest at one configuration, the object placed: from the generated
 * contact_system (column-major as it writes them) M_s (eq. 4), G_c (eq. 14), Kq = M_s^-1 A_s^T
 * and Ka = I_obj^-1 A_o^T (eq. 18); then M_s^-1 B and the input metric N = B^T M_s^-1 B
 * (eq. 31), row-major (B selects the joints). */
typedef struct {
  double M[NS * NS], G[NC * NC], Kq[NS * NC], Ka[3 * NC];
  double MB[NS * NA];
  double N[NA * NA];
} sc_rest;
/* the generated functions' work arrays (maps.c) */
typedef struct sc_rest_work sc_rest_work;
/* The affine maps of one row state at rest: lam = L tau + l0 (eq. 17), w = W tau + w0 (the
 * rows' accelerations), qdd = Q tau + q0 (eq. 22), a_obj = A tau + a0 (eq. 24), Xi of eq. (28)
 * as a form in z = (tau, 1), Omega of eq. (29) in tau (the held state's: no offset), all
 * row-major; the held rows' pivot ratio (min_j d_j / G_jj of G_HH = L D L^T in row order). */
typedef struct {
  double L[NC * NA], l0[NC];
  double W[NC * NA], w0[NC];
  double Q[NS * NA], q0[NS];
  double A[3 * NA], a0[3];
  double Xih[NA1 * NA1];
  double Om[NA * NA];
  double pivot_ratio;
} sc_affine_maps;
/* One call: the model, the query and the workspaces, then the configuration at hand. */
typedef struct {
  const double *scene;        /* the scene vector (SCENE_*) */
  const double *fw_constants; /* core_forward's constants */
  sc_int max_iter;            /* core_forward's active-set passes */
  const double *in;           /* the query (OPT_IN_*) */
  sc_rest_work *ws;           /* the generated functions' work arrays */
  sc_qp_work qw;              /* the QP block's */
  /* the query */
  int kind, any_slide;
  double radius, r2;          /* r2 = 0: no ellipsoid */
  const double *tau_max;      /* null: no box */
  const double *direction;    /* null: none given */
  const double *a_obj;        /* null: none given */
  double a_min;               /* NaN: none given */
  int slide[NC];              /* rows allowed to slide (max_sr) */
  /* the model's bounded wheels: rows and bounds backed off by the friction margin */
  int nw, wheel_row[NC];
  double wheel_ub[NC];
  /* the configuration */
  const double *q;
  sc_rest rest;
  sc_affine_maps held;
  double a_dir[3], k;         /* a_obj = a_dir lam_c; k = a_dir^T I_obj a_dir */
  double widths[NA];          /* the region's bounding box (the variables' scale) */
  double *out;                /* this configuration's answer (OPT_OUT_*) */
} sc_optimal;
/* a field of the configuration's answer (OPT_OUT_*), and setting one */
#define SC_OUT(o, f) ((o)->out + OPT_OUT_##f)
#define SC_SET(o, f, v) ((o)->out[OPT_OUT_##f] = (v))
SC_INTERNAL sc_rest_work *sc_rest_work_new(void); /* maps.c */
SC_INTERNAL void sc_rest_work_free(sc_rest_work *ws);
SC_INTERNAL int sc_rest_system(sc_rest_work *ws, const double *scene, const double *q,
                               sc_rest *rest);
SC_INTERNAL double sc_state_maps(const sc_rest *rest, const double *scene,
                                 const signed char *state, int with_omega, sc_affine_maps *mp);
/* optimal.c: what the kinds share */
SC_INTERNAL void sc_optimal_bind(sc_optimal *o, int code);
SC_INTERNAL int sc_optimal_forward(sc_optimal *o, const double *tau, double *row);
SC_INTERNAL void sc_optimal_certify(sc_optimal *o, int kind, const double *values, int resolved);
SC_INTERNAL int sc_optimal_certified(const sc_optimal *o);
SC_INTERNAL void sc_optimal_status(sc_optimal *o, int status, int reason);
SC_INTERNAL void sc_optimal_if_certified(sc_optimal *o);
SC_INTERNAL void sc_optimal_count(sc_optimal *o, const sc_qp_solution *s, int qcqp);
/* max_sr.c: max_sr with every row held (then the sliding states when allowed) */
SC_INTERNAL void sc_max_sr(sc_optimal *o);
SC_INTERNAL void sc_least_slip_push(sc_optimal *o); /* push.c */
SC_INTERNAL void sc_strongest_push(sc_optimal *o);
/* wheel_states.c: max_sr with sliding wheels, after the all-held answer is in o->out */
SC_INTERNAL void sc_max_sr_sliding(sc_optimal *o);
/* ---- the exported entry points (the model's prefix; bound in snakecg/engine/binding.py) ---- */
int SNAKECG_EXPORT(core_forward)(sc_int n, const double *scene, const double *constants,
                                 sc_int max_iter, const double *const *in, const sc_int *stride,
                                 double *out); /* forward.c */
int SNAKECG_EXPORT(core_integrate_segment)(sc_segment *sg); /* integrate.c */
int SNAKECG_EXPORT(core_mode_samples)(sc_segment *sg, sc_int n, const double *Y, double *out);
int SNAKECG_EXPORT(core_settle)(sc_settle *st); /* events.c */
/* geometry.c: the contact check at n states Y (n x NY, row-major) */
int SNAKECG_EXPORT(core_contact_depth)(const sc_geometry *g, sc_int n, const double *Y,
                                      double *depth, double *pair);
/* ---- the general-scene solve (scene_sets.c, _piece.c, _primal.c, _small.c, _solve.c) ---- */
enum { K_FREE = 0, K_UNILATERAL = 1, K_BOX = 2, K_DISC = 3, K_SPLIT = 4 };
typedef struct {
  sc_int n, m, nb;
  const sc_int *kind, *start;
  const double *par; /* nb x 3 */
  double *G, *b, *lam, *w, *gamma;
  sc_int *state;
  double fscale, wscale; struct sc_piece_keep *pk; /* (pk: scene_piece.c's kept, or NULL) */
} sc_problem;
static inline sc_int sc_block_size(sc_int kind) { return kind >= K_DISC ? 2 : 1; }
enum { S_HELD = 0, S_ZERO = 1, S_SLIDE = 2 }; /* a block's state */
#define TOL_ACCEPT 1e-9 /* a row's acceleration is zero within this of its scale */
#define NULL_TOL 1e-13 /* G_FF's pivots at most this of the first: no acceleration */
SC_INTERNAL int sc_in_set(const sc_problem *p, sc_int k, double *l, double tol, int clip);
/* sc_min_norm_face's null space and dual point kept for the next choice on the same G */
typedef struct { sc_int *face; double *v, *mu; sc_int nf, nn, cap; int has_mu; } sc_face_keep;
SC_INTERNAL int sc_min_norm_face(sc_problem *p, const double *Z, double *work, double eps,
                                 double loose, sc_face_keep *fkp);
SC_INTERNAL void sc_on_boundary(const sc_problem *, sc_int, const double *u, double *l, double *T);
SC_INTERNAL void sc_direction_of(const sc_problem *p, sc_int k, const double *l, double *u);
SC_INTERNAL void sc_update_w(sc_problem *p); /* scene_piece.c: w = G lam + b; a piece */
SC_INTERNAL sc_int sc_polish(sc_problem *p, double *work, sc_int *iwork, int kept, int *early);
SC_INTERNAL int sc_primal_piece(sc_problem *p, const double *Z, const double *g, const double *c,
  double *work, sc_int *iwork, sc_int *def); SC_INTERNAL sc_int sc_primal_work(sc_int n, sc_int m);
SC_INTERNAL int sc_primal_tally(int ok); int SNAKECG_EXPORT(core_scene_primal)(sc_int, double *);
SC_INTERNAL int sc_inertia_factor(sc_int n, const double *M, const double *f, double rel,
  double *L, double *a, sc_int *t_out); /* scene_small.c: L = chol(M), a = L^-1 f, Z, G, b */
SC_INTERNAL void sc_scene_z(sc_int n, sc_int m, sc_int t, const double *L, const double *A,
  double *Z); SC_INTERNAL void sc_scene_gram(sc_int n, sc_int m, const double *Z,
  const double *g, const double *c, double *G, double *b, double *zero);
int SNAKECG_EXPORT(core_scene_solve_b)(sc_int ns, sc_int n, sc_int mmax, sc_int nbmax,
  const sc_int *m, const sc_int *nb, const double *M, const double *f, const double *A,
  const double *c, const sc_int *kind, const sc_int *start, const double *par,
  sc_int max_sweeps, double *lam, double *a, double *w, double *state, double *info);
int SNAKECG_EXPORT(core_scene_solve_s)(sc_int n, sc_int m, sc_int nb, const double *M,
  const double *f, const double *A, const double *c, const sc_int *kind, const sc_int *start,
  const double *par, sc_int max_sweeps, const double *from, double *lam, double *a, double *w,
  double *state, double *info); /* one sample, from the pieces `from` (3 per block) */
/* ---- a general scene's shapes (scene_place.c), contacts (scene_geometry.c), rows (scene_rows.c) -
 * The packed scene's header and records' widths (their fields: snakecg/scenes/packing.py). */
enum { SP_NO = 0, SP_NOB, SP_RADIUS, SP_TOL, SP_SIZE, SP_NG, SP_MG, SP_LINKS, SP_OBJECTS,
       SP_OBSTACLES, SP_GROUND, SP_K, SP_MU, SP_MUC, SP_FRICTION, SP_HEAD = 16, LINK_W = 2,
       OBJ_W = 12, OBS_W = 14 };
enum { SC_SEGMENT = 0, SC_POINT = 1, SC_POLYGON = 2, SC_HALFPLANE = 3 };
#define SC_TOUCH_MAX 64 /* candidate point pairs of two shapes (4 x 4 edges, 4 each) */
/* a core (np points; a half-plane's point and normal into the free side) and a radius; a
 * contact's surface points and its unit normal from a to b */
typedef struct { int kind, np; double p[4][2], radius, normal[2]; } sc_shape;
typedef struct { double a[2], b[2], n[2]; } sc_touch;
SC_INTERNAL void sc_shape_centroid(const sc_shape *s, double *c);
SC_INTERNAL double sc_shape_closest(const sc_shape *A, const sc_shape *B, double scale,
                                    double merge, double beyond, sc_touch *out, int *count);
SC_INTERNAL void sc_scene_place(const double *pk, const double *P, const double *qo, int how,
                                double *cs, sc_shape *shape, double *pose, double *centre,
                                double *reach);
/* A state's rows (scene_rows.c's, for scene_step.c): RO_*, poses (3 n_o), contacts (CR_W) */
enum { RO_STATUS = 0, RO_NC, RO_M, RO_NB, RO_OVERLAP, RO_POSE = RO_OVERLAP + 6, CR_W = 16 };
enum { SS_OVERLAP = 3, SS_MORE = 4, SS_FAILED = 6, SS_OVERFLOW = 8 };
/* scene_friction.c: a contact's tangent row (t = (-n_y, n_x) on D = J_b - J_a), the pair's
 * coefficient into its record; the solve with Coulomb friction at the contacts (the file) */
SC_INTERNAL void sc_friction_row(const double *pk, sc_int ia, sc_int ib, const double *nrm,
  const double *Dx, const double *Dy, sc_int n, double *row, double *rec);
SC_INTERNAL int sc_friction_solve(sc_int n, sc_int m, sc_int nb, sc_int nc, const double *M,
  const double *f, double *A, double *c, sc_int *kind, sc_int *start, double *par,
  const double *T, double *rec, sc_int sweeps, const double *from, double *lam, double *a,
  double *w, double *st, double *info, double *solutions);
SC_INTERNAL int sc_scene_state_rows(const double *pk, const double *q, const double *qo,
                                    double tol, sc_int ccap, sc_int mcap, double *out,
                                    double *M, double *A, double *par, sc_int *kind,
                                    sc_int *start, void **keep);
/* core_scene_rows' and core_scene_gaps' arguments (binding.py's SceneStateCall; fields:
 * scene_rows.c); core_scene_step's (SceneStep; fields, ST_* and STEP_*: scene_step.c) */
typedef struct { const double *pk, *q, *qo; double tol, margin; sc_int ccap, mcap, pair_a,
  pair_b; double *out, *M, *A, *par; sc_int *kind, *start; } sc_scene_state;
int SNAKECG_EXPORT(core_scene_gaps)(const sc_scene_state *c);
enum { ST_WORK_TAU = 0, ST_FRICTION, ST_IMPACT_LOSS, ST_CONTACT_WORK, ST_CONTACT_IMPULSE,
       ST_SLIDING_COS, ST_PRIMAL, ST_DUAL, ST_COMPL, ST_STEPS, ST_IMPACT, ST_LOSS, ST_KE,
       ST_MIN_GAP, ST_NC, ST_HELD, ST_WIDTH };
enum { STEP_DONE = 0, STEP_NOT_CONVERGED = 1, STEP_IMPACT_NOT_CONVERGED = 2 };
typedef struct { const double *pk; double tol, h, impact_speed; const double *tau, *fo;
  double *x, *V; sc_int ccap, mcap; double *M, *A, *par, *out; sc_int *kind, *start;
  double *M1, *A1, *par1, *out1; sc_int *kind1, *start1;
  double *Vp, *lam, *info, *ilam, *iinfo, *acc; sc_int status; double *from; sc_int nfrom,
  hold, quick; } sc_scene_step;
int SNAKECG_EXPORT(core_scene_step)(sc_scene_step *c);
SC_INTERNAL int sc_scene_step_kept(sc_scene_step *c, void **keep); /* c null: frees *keep */
#endif
