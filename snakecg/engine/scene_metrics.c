/* snakecg's engine: the metrics of a general scene's forward (step 5 of scene_rows.c) from the
 * inertia's factor its solve already took.
 *
 * With the bodies' inertia M = L D L^T (M_s, then m, m, I per object: block diagonal, and so is
 * L; scene_tiny.c's factor), v = L^T a and g = D^-1 L^-1 f = L^T a_free (a_free = M^-1 f, the
 * motion without constraint forces), every form of the paper is a sum of squares weighted by
 * the pivots D > 0 (eqs. 26, 27 and the constraint forces' norm; Reyes & Ma 2017):
 *   ||qdd_s||^2 = qdd^T M_s qdd = sum D_i v_i^2 over the snake's n_s entries,
 *   ||a_o||^2 = a_o^T I_o a_o = sum D_i v_i^2 over object o's 3 entries,
 *   ||lambda||^2 = lam^T G lam = (a - a_free)^T M (a - a_free) = sum D_i (v_i - g_i)^2,
 *   a_free^T M a_free = sum D_i g_i^2,
 * so none of them is negative, even by rounding, and sr = sum ||a_o||^2 / (that + ||qdd_s||^2)
 * (eq. 30) stays in [0, 1]; sr is 0 where the summed norms are rounding (a system that does
 * not move): below 1e-26 a_free^T M a_free, or (below 1e-12 of it) below 1e-18 e^T M^-1 e, e
 * the forces' sum taken in absolute values, |f| + sum_j |lam_j| |A_j| entry by entry: the
 * scale of the error in a = M^-1 (f + A^T lam), where forces that cancel (a heavy object
 * held by friction against a small torque) leave it far above the free motion's. The solve
 * accepts forces to 1e-9 of their scale (TOL_ACCEPT), so accelerations below 1e-9 of that
 * scale's are not resolved: a batch's warm start (another path, another rounding) left
 * 1.3e-13 of it and read sr 0.41 where the one-sample call read 0.
 */
#include <math.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_metrics.h"

#if defined(__GNUC__)
#define METRICS_UNROLL _Pragma("GCC unroll 16")
#else
#define METRICS_UNROLL
#endif

/* The metrics from v = L^T a and g = D^-1 L^-1 f (L's dense block of t rows, unit lower, D
 * on its diagonal, and its diagonal tail; r = D^-1; n, t constants where the caller's branch
 * makes them so), entry by entry as they come: each sum in the order of the entries, and v,
 * g in registers (stored and then loaded as pairs, their loads waited on the stores). */
static inline double sums(sc_int n, sc_int t, const double *L, const double *r,
                          const double *f, const double *a, double *norms, double *obj) {
  const sc_int ns = SNAKECG_NS;
  double u[512], nq = 0.0, na = 0.0, nl = 0.0, fr = 0.0, ob = 0.0, d; /* (n: at most 512) */
  sc_int i, k;
  METRICS_UNROLL for (i = 0; i < n; ++i) {
    const double D = L[i * n + i];
    double v = a[i], x = f[i], g;
    if (i < t) {
      METRICS_UNROLL for (k = i + 1; k < t; ++k) v += L[k * n + i] * a[k];
      METRICS_UNROLL for (k = 0; k < i; ++k) x -= L[i * n + k] * u[k];
      u[i] = x;
    }
    g = x * r[i];
    if (i < ns) {
      nq += D * (v * v); /* ||qdd_s||^2 */
    } else { /* object (i - ns) / 3's ||a_o||^2, its three terms in order */
      ob = (i - ns) % 3 ? ob + D * (v * v) : D * (v * v);
      if ((i - ns) % 3 == 2) obj[(i - ns) / 3] = ob, na += ob;
    }
    d = v - g;
    nl += D * (d * d);
    fr += D * (g * g);
  }
  d = na + nq;
  norms[0] = nq;
  norms[1] = na;
  norms[2] = nl;
  norms[3] = d > 1e-26 * fr ? na / d : 0.0; /* eq. (30) */
  return fr;
}

/* e^T M^-1 e for e = |f| + sum_j |lam_j| |A_j| (entry by entry; A m x n row-major): by L's
 * unit lower block of t rows (in place), then sum (L^-1 e)_i^2 r_i. */
static double force_floor(sc_int n, sc_int t, sc_int m, const double *L, const double *r,
                          const double *f, const double *A, const double *lam) {
  double e[512], s = 0.0; /* (n: at most 512) */
  sc_int i, j, k;
  for (i = 0; i < n; ++i) e[i] = fabs(f[i]);
  for (j = 0; j < m; ++j)
    if (lam[j] != 0.0) {
      const double l = fabs(lam[j]), *aj = A + j * n;
      for (i = 0; i < n; ++i) e[i] += l * fabs(aj[i]);
    }
  for (i = 0; i < n; ++i) {
    for (k = 0; k < (i < t ? i : 0); ++k) e[i] -= L[i * n + k] * e[k];
    s += e[i] * e[i] * r[i];
  }
  return s;
}

SC_INTERNAL void sc_scene_metrics(sc_int n, sc_int no, sc_int t, const double *L,
                                  const double *r, const double *f, const double *a,
                                  sc_int m, const double *A, const double *lam, double *norms,
                                  double *obj) {
  double fr;
  (void)no; /* (n = n_s + 3 n_o) */
  if (t == SNAKECG_NS && n == SNAKECG_NS)
    fr = sums(SNAKECG_NS, SNAKECG_NS, L, r, f, a, norms, obj);
  else if (t == SNAKECG_NS && n == SNAKECG_NS + 3)
    fr = sums(SNAKECG_NS + 3, SNAKECG_NS, L, r, f, a, norms, obj);
  else fr = sums(n, t, L, r, f, a, norms, obj);
  /* (the forces' scale taken only where the motion is below 1e-6 of the free motion's, |a|_M:
   * elsewhere the floor would need forces 1e3 times the free motion's scale to reach it) */
  if (norms[3] > 0.0 && norms[0] + norms[1] <= 1e-12 * fr &&
      norms[0] + norms[1] <= TOL_ACCEPT * TOL_ACCEPT * force_floor(n, t, m, L, r, f, A, lam))
    norms[3] = 0.0;
}
