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
 * (eq. 30) stays in [0, 1]; sr is 0 where the summed norms are rounding of the free motion's
 * (below 1e-26 a_free^T M a_free: a system that does not move).
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

/* v = L^T a and g = D^-1 L^-1 f for L's dense block of t rows (unit lower, D on its diagonal)
 * and its diagonal tail, r = D^-1 (n, t constants where the caller's branch makes them so) */
static inline void forms(sc_int n, sc_int t, const double *L, const double *r, const double *f,
                         const double *a, double *v, double *g) {
  double u[512];
  sc_int i, k;
  METRICS_UNROLL for (i = 0; i < t; ++i) {
    double s = a[i], x = f[i];
    METRICS_UNROLL for (k = i + 1; k < t; ++k) s += L[k * n + i] * a[k];
    METRICS_UNROLL for (k = 0; k < i; ++k) x -= L[i * n + k] * u[k];
    v[i] = s;
    u[i] = x;
    g[i] = x * r[i];
  }
  METRICS_UNROLL for (i = t; i < n; ++i) {
    v[i] = a[i];
    g[i] = f[i] * r[i];
  }
}

SC_INTERNAL void sc_scene_metrics(sc_int n, sc_int no, sc_int t, const double *L,
                                  const double *r, const double *f, const double *a,
                                  double *norms, double *obj) {
  const sc_int ns = SNAKECG_NS;
  double v[512], g[512], nq = 0.0, na = 0.0, nl = 0.0, fr = 0.0, d; /* (n: at most 512) */
  sc_int i, o;
  if (t == ns && n == ns) forms(SNAKECG_NS, SNAKECG_NS, L, r, f, a, v, g);
  else if (t == ns && n == ns + 3) forms(SNAKECG_NS + 3, SNAKECG_NS, L, r, f, a, v, g);
  else forms(n, t, L, r, f, a, v, g);
  for (i = 0; i < ns; ++i) nq += L[i * n + i] * (v[i] * v[i]);
  for (o = 0; o < no; ++o) {
    const double *u = v + ns + 3 * o, *D = L + (ns + 3 * o) * (n + 1);
    obj[o] = D[0] * (u[0] * u[0]) + D[n + 1] * (u[1] * u[1]) + D[2 * n + 2] * (u[2] * u[2]);
    na += obj[o];
  }
  for (i = 0; i < n; ++i) {
    d = v[i] - g[i];
    nl += L[i * n + i] * (d * d);
    fr += L[i * n + i] * (g[i] * g[i]);
  }
  d = na + nq;
  norms[0] = nq;
  norms[1] = na;
  norms[2] = nl;
  norms[3] = d > 1e-26 * fr ? na / d : 0.0; /* eq. (30) */
}
