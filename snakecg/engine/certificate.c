/* snakecg's engine: non-negative least squares and the KKT certificate of a point of a QP or
 * QCQP (prototypes and method notes in engine.h; the QP solves in qp.c).
 *
 * This file is part of the runtime (not generated); it knows nothing of the model and is
 * compiled into every model's library beside the other engine files.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"

/* ---------------------------------------------------------------------------------------
 * Non-negative least squares, min ||C y - d|| s.t. y >= 0 (C n x k row-major), by the active
 * set method of Lawson & Hanson ("Solving Least Squares Problems", 1974, ch. 23): the passive
 * set grows by the variable of largest positive dual w = C^T (d - C y); each unconstrained
 * least-squares solve on the passive set (Householder QR) that leaves the positive orthant is
 * cut back by interpolation. work: 4 k + n k + 2 n doubles; iwork: 3 k. Returns the number of
 * iterations, or -1 when not converged. */
int sc_nnls(sc_int n, sc_int k, const double *C, const double *d, double *y, double *work,
            sc_int *iwork) {
  double *wd = work, *s = wd + k, *qx = s + k, *qn = qx + k, *Ap = qn + k, *bp = Ap + n * k,
         *res = bp + n;
  sc_int *passive = iwork, *col = passive + k, *perm = col + k, it, i, j, np, maxit = 3 * k + 10;
  double cmax = 0.0, tol;
  for (j = 0; j < k; ++j) {
    y[j] = 0.0;
    passive[j] = 0;
  }
  for (i = 0; i < n * k; ++i)
    if (fabs(C[i]) > cmax) cmax = fabs(C[i]);
  tol = 10.0 * 2.220446049250313e-16 * cmax * (sc_norm(d, n) + 1e-300) * (double)(n > k ? n : k);
  for (it = 0; it < maxit; ++it) {
    sc_int jmax = -1;
    double wmax = tol;
    for (i = 0; i < n; ++i) { /* the dual w = C^T (d - C y) */
      double t = d[i];
      for (j = 0; j < k; ++j) t -= C[i * k + j] * y[j];
      res[i] = t;
    }
    for (j = 0; j < k; ++j) {
      double t = 0.0;
      for (i = 0; i < n; ++i) t += C[i * k + j] * res[i];
      wd[j] = t;
      if (!passive[j] && t > wmax) {
        wmax = t;
        jmax = j;
      }
    }
    if (jmax < 0) return (int)it;
    passive[jmax] = 1;
    for (;;) {
      double alpha = INFINITY;
      np = 0;
      for (j = 0; j < k; ++j)
        if (passive[j]) col[np++] = j;
      for (i = 0; i < n; ++i) {
        for (j = 0; j < np; ++j) Ap[i * np + j] = C[i * k + col[j]];
        bp[i] = d[i];
      }
      for (j = 0; j < k; ++j) s[j] = 0.0;
      sc_qr_least_squares(n, np, Ap, np, bp, 1e-13, qx, qn, perm);
      for (j = 0; j < np; ++j) s[col[j]] = qx[j];
      for (j = 0; j < np; ++j) {
        sc_int c = col[j];
        if (s[c] <= 0.0) {
          double a = y[c] / (y[c] - s[c]);
          if (a < alpha) alpha = a;
        }
      }
      if (alpha == INFINITY) { /* the passive solution is positive: take it */
        for (j = 0; j < k; ++j) y[j] = s[j];
        break;
      }
      for (j = 0; j < k; ++j) {
        y[j] += alpha * (s[j] - y[j]);
        if (passive[j] && y[j] <= 0.0) {
          passive[j] = 0;
          y[j] = 0.0;
        }
      }
    }
  }
  return -1;
}

/* ---------------------------------------------------------------------------------------
 * The KKT certificate (engine.h). Constraint "sizes" follow the row: |G| |x| + |bound| for a row,
 * |x| |Q| |x| + |r2| for the quadric; the gradient's size is ||H|| ||x|| + ||c||. The
 * duality gap of a convex problem at multipliers lam: with L(y) = f(y) - sum_i lam_i s_i(y)
 * (the quadric's slack r2 - y^T Q y among the s_i), L is quadratic with Hessian
 * K = H + 2 mu Q, so the dual function is d(lam) = L(x) - 1/2 r^T K^+ r with r = grad L(x),
 * and the gap f(x) - d(lam) is sum_i lam_i s_i(x) + 1/2 r^T K^+ r: every term small at a KKT
 * point (evaluating L at a computed minimiser instead would lose the gap to K's
 * conditioning). */
void sc_kkt_certificate(sc_int n, const double *x, const double *H, const double *c, sc_int m,
                        const double *G, const double *lo, const double *hi, const double *Q,
                        double r2, int convex, double active, double stationarity_tol,
                        double *values, double *lam_rows, double *mu_out, sc_qp_work *w) {
  const sc_int kmax = SC_QP_CE_K(w->n_max, w->m_max);
  double *D = sc_qp_ce_d(w), *Hx = D, *grad = Hx + n, *res = grad + n, *qx = res + n, *yv = qx + n,
         *ew = yv + n, *slo = ew + n, *shi = slo + m, *rs = shi + m, *gx = rs + m,
         *cols = gx + m, *Cn = cols + n * kmax, *big = Cn + n * kmax, *slack = big + 2 * n * kmax,
         *norms = slack + kmax, *lam = norms + kmax, *lsq = lam + kmax, *M = lsq + 2 * kmax,
         *E = M + kmax * kmax, *V = E + n * n, *nw = V + n * n; /* nnls: 8 kmax + 2 n kmax + 2 n */
  sc_int *I = sc_qp_ce_i(w), *freec = I, *origin = freec + kmax, *piv = origin + kmax,
         *iw = piv + kmax; /* nnls: 6 kmax */
  sc_int i, j, k = 0, qcol = -1;
  double f, fscale, ref, primal = 0.0, resid, size, comp = 0.0, stat, gnorm, mu = 0.0;
  for (i = 0; i < n; ++i) Hx[i] = H ? sc_dot(H + i * n, x, n) : 0.0;
  f = 0.5 * sc_dot(x, Hx, n) + sc_dot(c, x, n);
  for (i = 0; i < n; ++i) grad[i] = Hx[i] + c[i];
  /* primal feasibility and the active rows: lower sides first, then upper, then Q */
  for (i = 0; i < m; ++i) {
    const double *g = G + i * n;
    double b = 0.0, v;
    gx[i] = sc_dot(g, x, n);
    if (isfinite(lo[i]) && fabs(lo[i]) > b) b = fabs(lo[i]);
    if (isfinite(hi[i]) && fabs(hi[i]) > b) b = fabs(hi[i]);
    rs[i] = b;
    for (j = 0; j < n; ++j) rs[i] += fabs(g[j]) * fabs(x[j]);
    if (!(rs[i] > 0)) rs[i] = 1.0;
    slo[i] = isfinite(lo[i]) ? gx[i] - lo[i] : INFINITY;
    shi[i] = isfinite(hi[i]) ? hi[i] - gx[i] : INFINITY;
    v = -slo[i] > -shi[i] ? -slo[i] : -shi[i];
    if (v / rs[i] > primal) primal = v / rs[i];
  }
  for (i = 0; i < m; ++i) /* the lower sides (an equality: one free column) */
    if (slo[i] <= active * rs[i]) {
      int eq = shi[i] <= active * rs[i] && lo[i] == hi[i];
      for (j = 0; j < n; ++j) cols[j * kmax + k] = G[i * n + j];
      slack[k] = eq ? 0.0 : slo[i];
      freec[k] = eq;
      origin[k++] = i;
    }
  for (i = 0; i < m; ++i)
    if (shi[i] <= active * rs[i] && !(slo[i] <= active * rs[i] && lo[i] == hi[i])) {
      for (j = 0; j < n; ++j) cols[j * kmax + k] = -G[i * n + j];
      slack[k] = shi[i];
      freec[k] = 0;
      origin[k++] = -2 - i; /* the upper side of row i */
    }
  if (Q) {
    double qs = r2 >= 0 ? r2 : -r2, qv;
    for (i = 0; i < n; ++i) {
      qx[i] = sc_dot(Q + i * n, x, n);
      for (j = 0; j < n; ++j) qs += fabs(x[i]) * fabs(Q[i * n + j]) * fabs(x[j]);
    }
    if (!(qs > 0)) qs = 1.0;
    qv = sc_dot(x, qx, n) - r2;
    if ((qv > 0 ? qv : 0.0) / qs > primal) primal = qv / qs;
    if (-qv <= active * qs) {
      qcol = k;
      for (j = 0; j < n; ++j) cols[j * kmax + k] = -2.0 * qx[j];
      slack[k] = -qv;
      freec[k] = 0;
      origin[k++] = -1;
    }
  }
  {
    double a = fabs(f), b = fabs(sc_dot(grad, x, n));
    fscale = a > b ? a : b;
    if (!(fscale > 1e-300)) fscale = 1e-300;
  }
  ref = (H ? sc_frobenius(n, n, H, n) * sc_norm(x, n) : 0.0) + sc_norm(c, n);
  gnorm = sc_norm(grad, n);
  if (k) {
    int ok = 1;
    double fit = 0.0, tol = gnorm > ref ? gnorm : ref;
    if (!(tol > 1e-300)) tol = 1e-300;
    for (j = 0; j < k; ++j) { /* unit columns */
      double s = 0.0;
      for (i = 0; i < n; ++i) s += cols[i * kmax + j] * cols[i * kmax + j];
      norms[j] = s > 0 ? sqrt(s) : 1.0;
      for (i = 0; i < n; ++i) Cn[i * kmax + j] = cols[i * kmax + j] / norms[j];
    }
    /* the normal equations (a handful of unit columns) */
    for (i = 0; i < k; ++i) {
      for (j = 0; j < k; ++j) {
        double s = 0.0;
        sc_int l;
        for (l = 0; l < n; ++l) s += Cn[l * kmax + i] * Cn[l * kmax + j];
        M[i * k + j] = s;
      }
      {
        double s = 0.0;
        sc_int l;
        for (l = 0; l < n; ++l) s += Cn[l * kmax + i] * grad[l];
        lam[i] = s;
      }
    }
    if (!sc_lu_factor(k, M, k, piv)) ok = 0;
    if (ok) {
      sc_lu_solve(k, M, k, piv, lam);
      for (j = 0; j < k; ++j)
        if (!isfinite(lam[j]) || (!freec[j] && lam[j] < 0)) ok = 0;
    }
    if (ok) {
      for (i = 0; i < n; ++i) {
        double s = -grad[i];
        for (j = 0; j < k; ++j) s += Cn[i * kmax + j] * lam[j];
        fit += s * s;
      }
      ok = sqrt(fit) <= 0.1 * stationarity_tol * tol;
    }
    if (!ok) { /* signs bind or the columns are dependent: non-negative least squares, a free
                * multiplier as the difference of two */
      sc_int kk = k, l;
      for (j = 0; j < k; ++j)
        if (freec[j]) ++kk;
      for (i = 0; i < n; ++i) {
        l = k;
        for (j = 0; j < k; ++j) {
          big[i * kk + j] = Cn[i * kmax + j];
          if (freec[j]) big[i * kk + l++] = -Cn[i * kmax + j];
        }
      }
      sc_nnls(n, kk, big, grad, lsq, nw, iw);
      l = k;
      for (j = 0; j < k; ++j) {
        lam[j] = lsq[j];
        if (freec[j]) lam[j] -= lsq[l++];
      }
    }
    size = gnorm;
    {
      double s = 0.0;
      for (j = 0; j < k; ++j) {
        lam[j] /= norms[j];
        s += fabs(lam[j]) * norms[j];
      }
      if (s > size) size = s;
    }
    for (i = 0; i < n; ++i) {
      double s = -grad[i];
      for (j = 0; j < k; ++j) s += cols[i * kmax + j] * lam[j];
      res[i] = s;
    }
    resid = sc_norm(res, n);
  } else {
    for (i = 0; i < n; ++i) res[i] = -grad[i];
    resid = gnorm;
    size = 0.0;
  }
  {
    double dd = size > ref ? size : ref;
    if (!(dd > 1e-300)) dd = 1e-300;
    stat = resid > 0 ? resid / dd : 0.0;
  }
  for (j = 0; j < k; ++j) comp += fabs(lam[j]) * fabs(slack[j]);
  if (qcol >= 0) mu = lam[qcol];
  values[0] = stat;
  values[1] = primal;
  values[2] = k ? comp / fscale : 0.0;
  values[3] = NAN;
  if (convex) { /* 1/2 r^T K^+ r, r = grad - C lam, K = H + 2 mu Q, K^+ from its eigenvalues */
    double corr = 0.0, top = 0.0;
    int any = 0;
    for (i = 0; i < n; ++i) {
      yv[i] = -res[i];
      if (yv[i] != 0.0) any = 1;
      for (j = 0; j < n; ++j)
        E[i * n + j] = (H ? H[i * n + j] : 0.0) + (Q ? 2.0 * mu * Q[i * n + j] : 0.0);
    }
    if (any) {
      int nonzero = 0;
      for (i = 0; i < n * n; ++i)
        if (E[i] != 0.0) nonzero = 1;
      if (nonzero) {
        sc_eigen_symmetric(n, E, n, ew, V, n);
        for (i = 0; i < n; ++i)
          if (fabs(ew[i]) > top) top = fabs(ew[i]);
        for (j = 0; j < n; ++j)
          if (fabs(ew[j]) > 1e-12 * top) {
            double s = 0.0;
            for (i = 0; i < n; ++i) s += V[i * n + j] * yv[i];
            corr += 0.5 * s * s / ew[j];
          }
      }
    }
    values[3] = (k ? comp + corr : corr) / fscale;
  }
  if (lam_rows) {
    for (i = 0; i < m; ++i) lam_rows[i] = 0.0;
    for (j = 0; j < k; ++j) {
      if (origin[j] >= 0) lam_rows[origin[j]] += lam[j];
      else if (origin[j] <= -2) lam_rows[-2 - origin[j]] -= lam[j];
    }
  }
  if (mu_out) *mu_out = mu;
}
