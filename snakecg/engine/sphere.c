/* snakecg's runtime core, part 3: the KKT points of a quadratic on the unit sphere cut by the
 * faces of a piece (the exact bounded-wheel extremes, snakecg/sphere_kkt.py).
 *
 * This file is part of the runtime (not generated). Like forward.c it is compiled once per
 * model into the model's shared library; it uses nothing of the model but the symbol prefix.
 *
 * A face is the sphere cut by some of a piece's conditions held at equality, itself a smaller
 * sphere u = u0 + Z y, |y| = r (Z: na x k, orthonormal columns). On it the stationary points
 * of h(u) = u^T A u + 2 g^T u + c solve (A_r - mu I) y = -g_r, |y| = r, with A_r = Z^T A Z and
 * g_r = Z^T (A u0 + g). In the eigenbasis of A_r (A_r = V diag(e) V^T, gv = V^T g_r) that is
 * the secular equation
 *     phi(mu) = sum_i gv_i^2 / (e_i - mu)^2 - r^2 = 0,    y = -sum_i gv_i / (e_i - mu) V_i,
 * whose roots are bracketed exactly: one left of the smallest pole, one right of the largest,
 * and between two poles none, one (a double root) or two on either side of the minimum of
 * the convex phi there (phi' increases from -inf to +inf). Each is found by Newton's method
 * safeguarded by bisection inside its bracket, to the rounding level. Where gv_i vanishes the
 * "hard case" adds y = y_p +- t V_i (y_p the least-norm solution orthogonal to V_i, |y| = r). NumPy's path (snakecg.sphere_kkt.quadratic_candidates)
 * finds the same points as the real eigenvalues of the 2k x 2k linearization of Gander, Golub
 * and von Matt (1989).
 *
 * Every candidate is mapped back to u, evaluated and checked against the piece's conditions
 * cond_j . (u, 1) >= -feas_tol; per face the best feasible maximum and minimum (first in the
 * candidates' order wins a tie) and the largest and smallest value over all candidates (the
 * extremes over the whole face sphere, feasible or not) come back.
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"


/* largest na (and face dimension k) handled here; larger ones stay on NumPy's path */
/* the most stationary points of a face of dimension k */
#define SC_SPHERE_CAND(k) (4 * (k) + 2)

/* Functions with the signs and zeros of phi (which = 0) and phi' (which = 1), nearly linear
 * near the poles so that Newton's method converges in a few steps, and their slopes:
 *   which 0: 1/r - S^(-1/2), S = sum_j W_j / (P_j - mu)^2 (phi = S - r^2);
 *   which 1: L^(-1/3) - R^(-1/3), L = sum_{P_j < mu} W_j / (mu - P_j)^3 and R the same over
 *            the poles right of mu (phi' = 2 (R - L); used between two poles). */
static double sc_sphere_eval(int which, int J, const double *P, const double *W, double r, double mu,
                      double *slope) {
  int j;
  if (!which) {
    double S = 0.0, dS = 0.0, si;
    for (j = 0; j < J; ++j) {
      double inv = 1.0 / (P[j] - mu), w2 = W[j] * inv * inv;
      S += w2;
      dS += 2.0 * w2 * inv;
    }
    si = 1.0 / sqrt(S);
    *slope = 0.5 * si * si * si * dS;
    return 1.0 / r - si;
  } else {
    double L = 0.0, dL = 0.0, R = 0.0, dR = 0.0, l3, r3;
    for (j = 0; j < J; ++j) {
      double d = mu - P[j], inv = 1.0 / fabs(d), w3 = W[j] * inv * inv * inv;
      if (d > 0) {
        L += w3;
        dL += w3 * inv;
      } else {
        R += w3;
        dR += w3 * inv;
      }
    }
    l3 = 1.0 / cbrt(L);
    r3 = 1.0 / cbrt(R);
    *slope = l3 * dL / L + r3 * dR / R;
    return l3 - r3;
  }
}

/* The zero of an increasing (sign +1) or decreasing (-1) function (which: 0 phi, 1 phi') on
 * (lo, hi) from x0 (the midpoint if outside): Newton steps kept inside the bracket, bisection
 * where a step leaves it or stalls (rtsafe), to the rounding level. */
static double sc_sphere_root(int which, int sign, int J, const double *P, const double *W, double r,
                      double lo, double hi, double x0, double atol) {
  const double lo0 = lo, hi0 = hi;
  double x = (x0 > lo && x0 < hi) ? x0 : 0.5 * (lo + hi), dx_old = hi - lo;
  int it;
#ifdef SC_SPHERE_COUNT
  ++sc_sphere_calls;
#endif
  for (it = 0; it < 100; ++it) {
    double slope, f = sc_sphere_eval(which, J, P, W, r, x, &slope), step, xn;
#ifdef SC_SPHERE_COUNT
    ++sc_sphere_iters;
#endif
    if (f == 0.0) return x;
    if (sign * f > 0) hi = x;
    else lo = x;
    step = f / slope;
    xn = x - step;
    /* Newton's correction below 1e-8 of the distance to the bracket's ends (the poles: the
     * point's sensitivity): the next one (quadratic convergence) is below the rounding */
    if (fabs(step) <= 1e-8 * (x - lo0 < hi0 - x ? x - lo0 : hi0 - x) + atol)
      return (xn > lo && xn < hi) ? xn : x;
    if (!(xn > lo && xn < hi) || fabs(2.0 * step) > fabs(dx_old)) {
      xn = 0.5 * (lo + hi);
      dx_old = 0.5 * (hi - lo);
    } else {
      dx_old = step;
    }
    if (hi - lo <= 4e-16 * fabs(xn) + atol) return xn;
    x = xn;
  }
  return x;
}

/* y scaled to |y| = r (r e_0 where y = 0) */
static void sc_sphere_to_sphere(int k, double *y, double r) {
  double ny = 0.0;
  int l;
  for (l = 0; l < k; ++l) ny += y[l] * y[l];
  ny = sqrt(ny);
  if (ny > 0) {
    for (l = 0; l < k; ++l) y[l] *= r / ny;
  } else {
    for (l = 0; l < k; ++l) y[l] = 0.0;
    y[0] = r;
  }
}

/* y = -sum_i gv_i / (e_i - mu) V_i, scaled to |y| = r */
static void sc_sphere_point(int k, const double *e, const double *gv, const double *V, double mu,
                     double tiny, double r, double *y) {
  int i, l;
  for (l = 0; l < k; ++l) y[l] = 0.0;
  for (i = 0; i < k; ++i) {
    double den = e[i] - mu, a;
    if (fabs(den) < tiny) den = tiny;
    a = -gv[i] / den;
    for (l = 0; l < k; ++l) y[l] += a * V[l * k + i];
  }
  sc_sphere_to_sphere(k, y, r);
}

/* The stationary points y (n x k, returned count) of y^T Ar y + 2 gr^T y on |y| = r, with
 * Ar = V diag(e) V^T (e ascending). */
static int sc_sphere_candidates(int k, const double *e, const double *V, const double *gr, double r,
                         double *Y) {
  double gv[k], P[k], W[k];
  double emax = 0.0, gmax = 0.0, escale, tiny, near, r_safe = r > 1e-100 ? r : 1e-100;
  double r2 = r_safe * r_safe, wsum = 0.0, atol;
  int i, j, l, n = 0, J = 0;
  if (k == 1) {
    Y[0] = r;
    Y[1] = -r;
    return 2;
  }
  for (i = 0; i < k; ++i) {
    double s = 0.0;
    for (l = 0; l < k; ++l) s += V[l * k + i] * gr[l];
    gv[i] = s;
    if (fabs(e[i]) > emax) emax = fabs(e[i]);
    if (fabs(gr[i]) > gmax) gmax = fabs(gr[i]);
  }
  escale = emax + gmax / r_safe + 1e-300;
  tiny = 1e-13 * escale;
  near = 1e-7 * escale;
  atol = 2e-16 * escale;
  /* poles: the eigenvalues with a weight, equal ones (within tiny) merged */
  for (i = 0; i < k; ++i) {
    double w = gv[i] * gv[i];
    if (J > 0 && e[i] - P[J - 1] <= tiny) {
      W[J - 1] += w;
    } else {
      P[J] = e[i];
      W[J] = w;
      ++J;
    }
  }
  for (i = 0, j = 0; i < J; ++i) /* weights too small to separate roots from their pole */
    if (sqrt(W[i]) > tiny * r_safe) {
      P[j] = P[i];
      W[j] = W[i];
      wsum += W[i];
      ++j;
    }
  J = j;
  if (J > 0) {
    double s = 2.0 * sqrt(wsum) / r_safe; /* phi < 0 at P_0 - s and P_J-1 + s, strictly */
    /* first guesses: the root of the nearest pole's term alone */
    double mu = sc_sphere_root(0, 1, J, P, W, r_safe, P[0] - s, P[0], P[0] - sqrt(W[0]) / r_safe, atol);
    sc_sphere_point(k, e, gv, V, mu, tiny, r, Y + k * n++);
    for (j = 0; j + 1 < J; ++j) {
      /* phi >= W_j / x^2 + W_j+1 / (d - x)^2 - r^2 >= max(8 sqrt(W_j W_j+1), W_j, W_j+1) / d^2
       * - r^2 between the two poles (x = mu - P_j, d = P_j+1 - P_j): no root where positive */
      double d = P[j + 1] - P[j], lb = 8.0 * sqrt(W[j] * W[j + 1]), slope, m, f;
      if (W[j] > lb) lb = W[j];
      if (W[j + 1] > lb) lb = W[j + 1];
      if (lb > 1.0000001 * r2 * d * d) continue;
      m = sc_sphere_root(1, 1, J, P, W, r_safe, P[j], P[j + 1], 0.5 * (P[j] + P[j + 1]), atol);
      f = sc_sphere_eval(0, J, P, W, r_safe, m, &slope);
      if (f < 0) {
        mu = sc_sphere_root(0, -1, J, P, W, r_safe, P[j], m, P[j] + sqrt(W[j]) / r_safe, atol);
        sc_sphere_point(k, e, gv, V, mu, tiny, r, Y + k * n++);
        mu = sc_sphere_root(0, 1, J, P, W, r_safe, m, P[j + 1], P[j + 1] - sqrt(W[j + 1]) / r_safe,
                     atol);
        sc_sphere_point(k, e, gv, V, mu, tiny, r, Y + k * n++);
      } else if (f <= 1e-10 / r_safe) { /* a double root (within rounding) */
        sc_sphere_point(k, e, gv, V, m, tiny, r, Y + k * n++);
      }
    }
    mu = sc_sphere_root(0, -1, J, P, W, r_safe, P[J - 1], P[J - 1] + s,
                 P[J - 1] + sqrt(W[J - 1]) / r_safe, atol);
    sc_sphere_point(k, e, gv, V, mu, tiny, r, Y + k * n++);
  }
  /* the hard case: mu an eigenvalue e_i whose gv_i vanishes (to within the roots' spread) */
  for (i = 0; i < k; ++i) {
    double yp[k], t, s2 = 0.0;
    int sgn;
    if (fabs(gv[i]) > near * r_safe) continue;
    for (l = 0; l < k; ++l) yp[l] = 0.0;
    for (j = 0; j < k; ++j) {
      double den = e[j] - e[i], a;
      if (j == i || fabs(den) <= tiny) continue;
      a = -gv[j] / den;
      for (l = 0; l < k; ++l) yp[l] += a * V[l * k + j];
    }
    for (l = 0; l < k; ++l) s2 += yp[l] * yp[l];
    t = sqrt(r * r - s2 > 0 ? r * r - s2 : 0.0);
    for (sgn = 1; sgn >= -1; sgn -= 2) {
      double *y = Y + k * n++;
      for (l = 0; l < k; ++l) y[l] = yp[l] + sgn * t * V[l * k + i];
      sc_sphere_to_sphere(k, y, r);
    }
  }
  return n;
}

/* For faces f < F of pairs pair[f]: the extremes of h over the KKT candidates.
 *   u0 (F, na), Z (F, na, k) or NULL for the whole sphere (Z = I, k = na, u0 = 0), r (F);
 *   A (P, na, na), g (P, na), c (P), cond (P, m, na + 1) per pair;
 *   skip_hi, skip_lo (F) or NULL: a face whose bounds (f(u0) +- 2 |g_r| r + the extreme
 *        eigenvalues of A_r times r^2, padded by 1e-12 of their terms) stay within
 *        [skip_lo, skip_hi] is not searched: vmax/vmin -inf/+inf, vhi/vlo those bounds;
 *   out: vmax/umax, vmin/umin (feasible candidates; -inf/+inf where none),
 *        vhi/vlo (all candidates).
 * Returns 0, or -1 when na or k is not positive or k > na (nothing written). */
int SNAKECG_EXPORT(core_sphere_faces)(sc_int F, sc_int na_, sc_int k_, sc_int m_,
                                      const sc_int *pair, const double *u0, const double *Z,
                                      const double *r, const double *A, const double *g,
                                      const double *c, const double *cond, double feas_tol,
                                      const double *skip_hi, const double *skip_lo,
                                      double *vmax, double *umax, double *vmin, double *umin,
                                      double *vhi, double *vlo) {
  int na = (int)na_, k = (int)k_, m = (int)m_;
  sc_int f;
  if (na < 1 || k < 1 || k > na) return -1;
  for (f = 0; f < F; ++f) {
    const sc_int p = pair[f];
    const double *Ap = A + p * na * na, *gp = g + p * na, *cp = cond + p * m * (na + 1);
    const double *Zf = Z ? Z + f * na * k : 0, *u0f = Z ? u0 + f * na : 0;
    const double rf = Z ? r[f] : 1.0;
    double Ar[na * na], gr[na], h[na], AZ[na * na]; /* k <= na: any size */
    double e[na], V[na * na], Y[SC_SPHERE_CAND(na) * na], u[na];
    double bmax = -INFINITY, bmin = INFINITY, hi = -INFINITY, lo = INFINITY;
    int i, j, l, nc, ci, imax = -1, imin = -1;
    /* h = A u0 + g, gr = Z^T h, Ar = Z^T A Z */
    for (i = 0; i < na; ++i) {
      double s = gp[i];
      if (Z)
        for (j = 0; j < na; ++j) s += Ap[i * na + j] * u0f[j];
      h[i] = s;
    }
    if (Z) {
      for (i = 0; i < na; ++i)
        for (l = 0; l < k; ++l) {
          double s = 0.0;
          for (j = 0; j < na; ++j) s += Ap[i * na + j] * Zf[j * k + l];
          AZ[i * k + l] = s;
        }
      for (l = 0; l < k; ++l) {
        double s = 0.0;
        for (i = 0; i < na; ++i) s += Zf[i * k + l] * h[i];
        gr[l] = s;
        for (j = 0; j < k; ++j) {
          double t = 0.0;
          for (i = 0; i < na; ++i) t += Zf[i * k + l] * AZ[i * k + j];
          Ar[l * k + j] = t;
        }
      }
      for (l = 0; l < k; ++l) /* symmetric part */
        for (j = l + 1; j < k; ++j) Ar[l * k + j] = Ar[j * k + l] =
            0.5 * (Ar[l * k + j] + Ar[j * k + l]);
    } else {
      for (i = 0; i < na; ++i) {
        gr[i] = h[i];
        for (j = 0; j < na; ++j) Ar[i * na + j] = 0.5 * (Ap[i * na + j] + Ap[j * na + i]);
      }
    }
    {
      /* the value at u0 and the bounds f(u0) +- 2 |gr| r + e_max/min r^2 on the face: where
       * they cannot beat skip_hi/skip_lo, no candidate is sought */
      double f0 = c[p], ng = 0.0, bh, bl, pad;
      for (i = 0; i < na; ++i) {
        double s = Z ? u0f[i] : 0.0, t = 0.0;
        for (j = 0; j < na; ++j) t += Ap[i * na + j] * (Z ? u0f[j] : 0.0);
        f0 += s * t + 2.0 * gp[i] * s;
      }
      if (k == 1) {
        e[0] = Ar[0];
        V[0] = 1.0;
      } else {
        sc_eigen_symmetric(k, Ar, k, e, V, k); /* linalg.h */
      }
      for (l = 0; l < k; ++l) ng += gr[l] * gr[l];
      ng = 2.0 * sqrt(ng) * rf;
      bh = f0 + ng + e[k - 1] * rf * rf;
      bl = f0 - ng + e[0] * rf * rf;
      pad = 1e-12 * (fabs(f0) + ng + (fabs(e[0]) + fabs(e[k - 1])) * rf * rf);
      if (skip_hi && bh + pad <= skip_hi[f] && bl - pad >= skip_lo[f]) {
        vmax[f] = -INFINITY;
        vmin[f] = INFINITY;
        vhi[f] = bh + pad;
        vlo[f] = bl - pad;
        memset(umax + f * na, 0, sizeof(double) * (size_t)na);
        memset(umin + f * na, 0, sizeof(double) * (size_t)na);
        continue;
      }
    }
    nc = sc_sphere_candidates(k, e, V, gr, rf, Y);
    for (ci = 0; ci < nc; ++ci) {
      const double *y = Y + ci * k;
      double v = c[p], au;
      int ok = 1;
      for (i = 0; i < na; ++i) {
        double s = Z ? u0f[i] : 0.0;
        if (Z)
          for (l = 0; l < k; ++l) s += Zf[i * k + l] * y[l];
        else
          s = y[i];
        u[i] = s;
      }
      for (i = 0; i < na; ++i) {
        au = 0.0;
        for (j = 0; j < na; ++j) au += Ap[i * na + j] * u[j];
        v += u[i] * au + 2.0 * gp[i] * u[i];
      }
      for (j = 0; j < m && ok; ++j) {
        const double *cj = cp + j * (na + 1);
        double s = cj[na];
        for (i = 0; i < na; ++i) s += cj[i] * u[i];
        ok = s >= -feas_tol;
      }
      if (v > hi) hi = v;
      if (v < lo) lo = v;
      if (ok && v > bmax) {
        bmax = v;
        imax = ci;
        memcpy(umax + f * na, u, sizeof(double) * (size_t)na);
      }
      if (ok && v < bmin) {
        bmin = v;
        imin = ci;
        memcpy(umin + f * na, u, sizeof(double) * (size_t)na);
      }
    }
    if (imax < 0) memset(umax + f * na, 0, sizeof(double) * (size_t)na);
    if (imin < 0) memset(umin + f * na, 0, sizeof(double) * (size_t)na);
    vmax[f] = bmax;
    vmin[f] = bmin;
    vhi[f] = hi;
    vlo[f] = lo;
  }
  return 0;
}

/* The faces of |S| = s conditions that meet the sphere, for every pair and every combination
 * (combos, ncombo x s slot numbers) of the pair's used conditions (used, P x m):
 * the sphere cut by a_j . u + b_j = 0 (j in S) is u = u0 + Z y, |y| = r with a^T = Q R
 * (Householder), u0 = Q_1 x where R^T x = -b, Z = Q_2 and r^2 = 1 - |u0|^2; a face is kept
 * where the rows are independent (|R_jj| > 1e-12) and r^2 >= 0. Writes the kept faces'
 * pair, combination index, u0 (F, na), Z (F, na, na - s) and r, in the order of pairs then
 * combinations (NumPy's order); returns their count F (at most P * ncombo), -1 when s is
 * not in [1, na). */
sc_int SNAKECG_EXPORT(core_sphere_cut)(sc_int P, sc_int na_, sc_int m_, sc_int s_, sc_int ncombo,
                                       const sc_int *combos, const double *cond,
                                       const unsigned char *used, sc_int *pair_out,
                                       sc_int *combo_out, double *u0, double *Z, double *r) {
  int na = (int)na_, m = (int)m_, s = (int)s_, k = na - s;
  sc_int p, ci, F = 0;
  if (s < 1 || s >= na) return -1;
  for (p = 0; p < P; ++p) {
    const double *cp = cond + p * m * (na + 1);
    for (ci = 0; ci < ncombo; ++ci) {
      const sc_int *sl = combos + ci * s;
      double Q[na * na], R[na * na], x[na], rr = 1.0;
      int i, j, l, ok = 1;
      for (j = 0; j < s; ++j) ok &= used[p * m + sl[j]] != 0;
      if (!ok) continue;
      for (i = 0; i < na; ++i) {
        for (j = 0; j < na; ++j) Q[i * na + j] = (i == j) ? 1.0 : 0.0;
        for (j = 0; j < s; ++j) R[i * s + j] = cp[sl[j] * (na + 1) + i];
      }
      for (j = 0; j < s && ok; ++j) { /* Householder on column j, rows j.. */
        double nx = 0.0, alpha, v[na], vv = 0.0;
        for (i = j; i < na; ++i) nx += R[i * s + j] * R[i * s + j];
        nx = sqrt(nx);
        alpha = R[j * s + j] >= 0 ? -nx : nx;
        for (i = 0; i < na; ++i) v[i] = (i < j) ? 0.0 : R[i * s + j];
        v[j] -= alpha;
        for (i = j; i < na; ++i) vv += v[i] * v[i];
        if (vv > 0) {
          for (l = j; l < s; ++l) { /* R <- H R */
            double d = 0.0;
            for (i = j; i < na; ++i) d += v[i] * R[i * s + l];
            d *= 2.0 / vv;
            for (i = j; i < na; ++i) R[i * s + l] -= d * v[i];
          }
          for (i = 0; i < na; ++i) { /* Q <- Q H */
            double d = 0.0;
            for (l = j; l < na; ++l) d += Q[i * na + l] * v[l];
            d *= 2.0 / vv;
            for (l = j; l < na; ++l) Q[i * na + l] -= d * v[l];
          }
        }
        ok = fabs(R[j * s + j]) > 1e-12;
      }
      if (!ok) continue;
      for (j = 0; j < s; ++j) { /* R^T x = -b, forward substitution */
        double t = -cp[sl[j] * (na + 1) + na];
        for (l = 0; l < j; ++l) t -= R[l * s + j] * x[l];
        x[j] = t / R[j * s + j];
      }
      for (i = 0; i < na; ++i) {
        double t = 0.0;
        for (j = 0; j < s; ++j) t += Q[i * na + j] * x[j];
        u0[F * na + i] = t;
        rr -= t * t;
      }
      if (!(rr >= 0)) continue;
      for (i = 0; i < na; ++i)
        for (l = 0; l < k; ++l) Z[(F * na + i) * k + l] = Q[i * na + s + l];
      r[F] = sqrt(rr);
      pair_out[F] = p;
      combo_out[F] = ci;
      ++F;
    }
  }
  return F;
}

/* Whether each face meets its piece: one of the two stationary points of direction . u on
 * the face's sphere (u0 +- r Z Z^T d / |Z^T d|; u0 +- r Z for k = 1) satisfies every
 * condition of the pair within feas_tol (snakecg.sphere_kkt.linear_candidates). */
int SNAKECG_EXPORT(core_sphere_meets)(sc_int F, sc_int na_, sc_int k_, sc_int m_,
                                      const sc_int *pair, const double *u0, const double *Z,
                                      const double *r, const double *cond,
                                      const double *direction, double feas_tol,
                                      unsigned char *meets) {
  int na = (int)na_, k = (int)k_, m = (int)m_;
  sc_int f;
  if (na < 1 || k < 1 || k > na) return -1;
  for (f = 0; f < F; ++f) {
    const double *Zf = Z + f * na * k, *cp = cond + pair[f] * m * (na + 1);
    double gz[k], ng = 0.0;
    int i, l, j, sgn, hit = 0;
    if (k == 1) {
      gz[0] = 1.0;
    } else {
      for (l = 0; l < k; ++l) {
        double t = 0.0;
        for (i = 0; i < na; ++i) t += Zf[i * k + l] * direction[i];
        gz[l] = t;
        ng += t * t;
      }
      ng = sqrt(ng);
      for (l = 0; l < k; ++l) gz[l] = ng > 1e-14 ? gz[l] / ng : (l == 0 ? 1.0 : 0.0);
    }
    for (sgn = 1; sgn >= -1 && !hit; sgn -= 2) {
      double u[na];
      int ok = 1;
      for (i = 0; i < na; ++i) {
        double t = 0.0;
        for (l = 0; l < k; ++l) t += Zf[i * k + l] * gz[l];
        u[i] = u0[f * na + i] + sgn * r[f] * t;
      }
      for (j = 0; j < m && ok; ++j) {
        const double *cj = cp + j * (na + 1);
        double t = cj[na];
        for (i = 0; i < na; ++i) t += cj[i] * u[i];
        ok = t >= -feas_tol;
      }
      hit = ok;
    }
    meets[f] = (unsigned char)hit;
  }
  return 0;
}
