/* snakecg's runtime core: the optimal-torque queries (maps.c, optimal.c, max_sr.c, push.c,
 * wheel_states.c).
 *
 * One call answers a batch of configurations, each by the same steps (docs/how-to/optimize.md):
 * the system at rest with the object placed (the generated contact_system at rest), the
 * all-held maps of eqs. (17), (22), (24), (28), (29), (31) (maps.c), the query's solve
 * (max_sr.c, push.c, wheel_states.c on the QP block of qp.c), the optimality certificate on the
 * original problem, the exact forward solve at the answer (forward.c's core_forward) and the
 * forward check of the answer. The query and the answers are flat double vectors laid out in
 * snakecg_layout.h (OPT_IN_*, OPT_OUT_*; snakecg/core/layout.py), read by name in Python
 * (snakecg/core/optimal.py); the codes below are mirrored there.
 *
 * Included after snakecg_layout.h. Prototypes of every function that crosses the files of the
 * query are here (none is declared in a .c file).
 */
#ifndef SNAKECG_CORE_OPTIMAL_H
#define SNAKECG_CORE_OPTIMAL_H

#include <math.h>

/* the sizes, the row states and the integer type of common.h (its types alone: the
 * generated functions are called by maps.c only, which includes common.h whole first) */
#ifndef SNAKECG_CORE_COMMON_H
#define SC_TYPES_ONLY
#include "common.h"
#undef SC_TYPES_ONLY
#endif
#include "qp.h"

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
enum {
  SC_CERT_NONE = 0,
  SC_CERT_QP = 1,
  SC_CERT_LP = 2,
  SC_CERT_QCQP = 3,
  SC_CERT_EIGEN = 4,
  SC_CERT_STATE = 5
};
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

/* maps.c */
SC_INTERNAL sc_rest_work *sc_rest_work_new(void);
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
/* push.c */
SC_INTERNAL void sc_least_slip_push(sc_optimal *o);
SC_INTERNAL void sc_strongest_push(sc_optimal *o);
/* wheel_states.c: max_sr with sliding wheels, after the all-held answer is in o->out */
SC_INTERNAL void sc_max_sr_sliding(sc_optimal *o);
/* forward.c (exported) */
int SNAKECG_EXPORT(core_forward)(sc_int n, const double *scene, const double *constants,
                                 sc_int max_iter, const double *const *in, const sc_int *stride,
                                 double *out);

#endif
