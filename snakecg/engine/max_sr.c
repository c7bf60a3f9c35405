/* snakecg's engine: max_sr with every constraint row held (engine.h, docs/how-to/optimize.md).
 *
 * This file is part of the runtime (not generated), compiled once per model into the model's
 * shared library.
 *
 * With every row held, sr is the generalized Rayleigh quotient of (Omega, Omega + Xi)
 * (eqs. 28-30), homogeneous of degree 0: its top eigenvector, signed so that the contact pushes
 * (lam_c >= 0), maximises it over any region star-shaped about 0 (the ellipsoid, the box, the
 * friction polytope of sticking wheels), and is returned at the largest magnitude that keeps
 * every limit. One frictionless point contact makes Omega = k l l^T (a_obj = a_dir lam_c), so
 * the top is the closed form sr = k c / (k c + 1) at v = Xi^-1 l, c = l^T Xi^-1 l; where Xi is
 * not safely definite (torques that move nothing), the eigenproblem restricted to the range of
 * Omega + Xi by Jacobi rotations. The certificate: the residual of Omega v = sr (Omega + Xi) v
 * and the top eigenvalue of Omega - sr (Omega + Xi) (non-positive exactly at the maximum).
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
/* the largest s > 0 with s v inside every limit, the limits that set it bound (in the order
 * ellipsoid, joints, wheels) */
static double scale_onto_limits(sc_optimal *o, const double *v) {
  double cand[1 + NA + NC], s = INFINITY;
  int code[1 + NA + NC], nc = 0, j, w;
  if (o->r2 > 0) {
    double qv = sc_quad(NA, o->rest.N, NA, v);
    cand[nc] = o->radius / sqrt(qv > 1e-300 ? qv : 1e-300);
    code[nc++] = SC_BIND_ELLIPSOID;
  }
  if (o->tau_max)
    for (j = 0; j < NA; ++j)
      if (fabs(v[j]) > 0) {
        cand[nc] = o->tau_max[j] / fabs(v[j]);
        code[nc++] = SC_BIND_JOINT + j;
      }
  for (w = 0; w < o->nw; ++w) {
    double li = sc_dot(o->held.L + o->wheel_row[w] * NA, v, NA);
    if (fabs(li) > 0) {
      cand[nc] = o->wheel_ub[w] / fabs(li);
      code[nc++] = SC_BIND_WHEEL(o->wheel_row[w]);
    }
  }
  for (j = 0; j < nc; ++j)
    if (cand[j] < s) s = cand[j];
  for (j = 0; j < nc; ++j)
    if (cand[j] <= s * (1 + 1e-9)) sc_optimal_bind(o, code[j]);
  return s;
}

/* the top generalized eigenpair of (Om, D), D positive semidefinite, restricted to the range of
 * D (directions outside it move nothing: sr is 0/0 there): D = V diag(w) V^T, Vr the columns
 * with w_j > 1e-12 max w scaled by w_j^-1/2, then the top eigenpair of Vr^T Om Vr. */
static double top_rayleigh(const double *Om, const double *D, double *v) {
  double E[NA * NA], V[NA * NA], w[NA], Vr[NA * NA], C[NA * NA], U[NA * NA], lw[NA], top;
  int i, j, l, r = 0, keep[NA];
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) E[i * NA + j] = 0.5 * (D[i * NA + j] + D[j * NA + i]);
  sc_eigen_symmetric(NA, E, NA, w, V, NA);
  top = w[NA - 1] > 1e-300 ? w[NA - 1] : 1e-300;
  for (j = 0; j < NA; ++j)
    if (w[j] > 1e-12 * top) keep[r++] = j;
  for (i = 0; i < NA; ++i)
    for (j = 0; j < r; ++j) Vr[i * NA + j] = V[i * NA + keep[j]] / sqrt(w[keep[j]]);
  for (i = 0; i < r; ++i)
    for (j = 0; j < r; ++j) {
      double s = 0.0;
      for (l = 0; l < NA; ++l) {
        double t = 0.0;
        int m;
        for (m = 0; m < NA; ++m) t += Om[l * NA + m] * Vr[m * NA + j];
        s += Vr[l * NA + i] * t;
      }
      C[i * NA + j] = s;
    }
  for (i = 0; i < r; ++i) /* symmetric part */
    for (j = 0; j < i; ++j) {
      double h = 0.5 * (C[i * NA + j] + C[j * NA + i]);
      C[i * NA + j] = h;
      C[j * NA + i] = h;
    }
  if (!r) {
    for (i = 0; i < NA; ++i) v[i] = 0.0;
    return 0.0;
  }
  sc_eigen_symmetric(r, C, NA, lw, U, NA);
  for (i = 0; i < NA; ++i) {
    double s = 0.0;
    for (j = 0; j < r; ++j) s += Vr[i * NA + j] * U[j * NA + r - 1];
    v[i] = s;
  }
  return lw[r - 1];
}

/* largest relative violation at tau of the all-held limits (wheels within their backed-off
 * bounds, the box, the contact kept, the ellipsoid), each relative to its row's size */
static double held_violation(const sc_optimal *o, const double *tau) {
  const double *ell = o->held.L;
  double worst = 0.0, at[NA], g;
  int j, w;
  for (j = 0; j < NA; ++j) at[j] = fabs(tau[j]);
  for (w = 0; w < o->nw; ++w) {
    const double *row = o->held.L + o->wheel_row[w] * NA;
    double ub = o->wheel_ub[w];
    g = fabs(sc_dot(row, tau, NA));
    if (g > ub) {
      double rs = ub, v;
      for (j = 0; j < NA; ++j) rs += fabs(row[j]) * at[j];
      v = (g - ub) / (rs > 0 ? rs : 1.0);
      if (v > worst) worst = v;
    }
  }
  if (o->tau_max)
    for (j = 0; j < NA; ++j) {
      double t = at[j], m = o->tau_max[j];
      if (t > m && (t - m) / (t + m) > worst) worst = (t - m) / (t + m);
    }
  g = sc_dot(ell, tau, NA);
  if (g < 0) {
    double rs = 0.0, v;
    for (j = 0; j < NA; ++j) rs += fabs(ell[j]) * at[j];
    v = -g / (rs > 0 ? rs : 1.0);
    if (v > worst) worst = v;
  }
  if (o->r2 > 0) {
    double e = sc_quad(NA, o->rest.N, NA, tau);
    if (e > o->r2) {
      double qs = o->r2, v;
      int i;
      for (i = 0; i < NA; ++i)
        for (j = 0; j < NA; ++j) qs += at[i] * fabs(o->rest.N[i * NA + j]) * at[j];
      v = (e - o->r2) / (qs > 0 ? qs : 1.0);
      if (v > worst) worst = v;
    }
  }
  return worst;
}

/* tau maximises the Rayleigh quotient of eqs. (28)-(30) iff Omega - sr(tau) D is negative
 * semidefinite (D = Omega + Xi): its largest eigenvalue relative to ||D|| is the gap, the
 * residual of Omega tau = sr D tau the stationarity; plus primal feasibility */
static void eigen_certificate(sc_optimal *o, const double *tau, int resolved) {
  double D[NA * NA], S[NA * NA], Dt[NA], Ot[NA], rr[NA], w[NA], values[4], den, sr, nD, top,
      scale;
  const double *Om = o->held.Om;
  int i, j;
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) D[i * NA + j] = Om[i * NA + j] + o->held.Xih[i * NA1 + j];
  sc_matvec(NA, NA, D, NA, tau, Dt);
  sc_matvec(NA, NA, Om, NA, tau, Ot);
  den = sc_dot(tau, Dt, NA);
  sr = den > 0 ? sc_dot(tau, Ot, NA) / den : 0.0;
  nD = sc_frobenius(NA, NA, D, NA);
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j)
      S[i * NA + j] = 0.5 * ((Om[i * NA + j] - sr * D[i * NA + j]) +
                             (Om[j * NA + i] - sr * D[j * NA + i]));
  sc_eigen_symmetric(NA, S, NA, w, 0, NA);
  top = w[NA - 1];
  scale = (sc_frobenius(NA, NA, Om, NA) + nD) * sc_norm(tau, NA);
  for (i = 0; i < NA; ++i) rr[i] = Ot[i] - sr * Dt[i];
  values[0] = scale > 0 ? sc_norm(rr, NA) / scale : 0.0;
  values[1] = held_violation(o, tau);
  values[2] = 0.0;
  values[3] = (top > 0.0 ? top : 0.0) / (nD > 1e-300 ? nD : 1e-300);
  sc_optimal_certify(o, SC_CERT_EIGEN, values, resolved);
}

/* the answer of the eigenproblem, the closed form first (unless `general`) */
static void max_sr_direction(sc_optimal *o, int general) {
  double Xi[NA * NA], D[NA * NA], v[NA], *tau = SC_OUT(o, tau), lam, s;
  const double *ell = o->held.L;
  int i, j, closed = 0;
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) {
      Xi[i * NA + j] = o->held.Xih[i * NA1 + j];
      D[i * NA + j] = Xi[i * NA + j] + o->held.Om[i * NA + j];
    }
  if (!general && sc_cholesky(NA, Xi, NA, 1e-12)) { /* the rank-one closed form */
    double c;
    memcpy(v, ell, sizeof v);
    sc_cholesky_solve(NA, Xi, NA, v);
    c = sc_dot(ell, v, NA);
    if (c > 0) {
      double kc = o->k * c;
      lam = kc / (kc + 1.0);
      closed = 1;
    }
  }
  if (!closed) {
    lam = top_rayleigh(o->held.Om, D, v);
    if (sc_dot(ell, v, NA) < 0)
      for (i = 0; i < NA; ++i) v[i] = -v[i];
  }
  SC_SET(o, method, closed ? SC_METHOD_RANK_ONE : SC_METHOD_EIGEN);
  SC_SET(o, n_binding, 0);
  s = scale_onto_limits(o, v);
  for (i = 0; i < NA; ++i) tau[i] = s * v[i];
  SC_SET(o, expected, lam > 0.0 ? (lam < 1.0 ? lam : 1.0) : 0.0);
}

void sc_max_sr(sc_optimal *o) {
  const double *ell = o->held.L;
  int j, any = 0;
  for (j = 0; j < NA; ++j) any |= ell[j] != 0.0;
  if (!(o->k > 0) || !any) {
    sc_optimal_status(o, SC_INFEASIBLE, SC_REASON_NO_PUSH);
    sc_optimal_bind(o, SC_BIND_CONTACT);
    SC_SET(o, method, SC_METHOD_EIGEN);
    return;
  }
  max_sr_direction(o, 0);
  eigen_certificate(o, SC_OUT(o, tau), 0);
  if (!sc_optimal_certified(o) && ((int)o->out[OPT_OUT_method] & SC_METHOD_RANK_ONE)) {
    max_sr_direction(o, 1); /* the general eigenproblem instead of the closed form */
    eigen_certificate(o, SC_OUT(o, tau), 1);
  }
  sc_optimal_if_certified(o);
  if (o->any_slide && sc_optimal_certified(o)) sc_max_sr_sliding(o);
}

