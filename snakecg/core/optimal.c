/* snakecg's runtime core, part 4: one optimal-torque query on one configuration
 * (snakecg/optimize/quick.py) in one call: the all-held maps (maps.c), the task, the solve,
 * the optimality certificate on the original problem (optimal.h) and the exact forward solve
 * at the answer (forward.c's core_forward).
 *
 * This file is part of the runtime (not generated). Like forward.c it is compiled once per
 * model into the model's shared library; it uses nothing of the model but the symbol prefix.
 *
 * It performs, operation for operation, what the Python path of snakecg.optimize does on plain
 * floats for the same cases, so that both give the same answers to rounding (the maps, built
 * from contact_system here and by interaction_maps there, agree to rounding, which only the
 * problem's own conditioning amplifies):
 *
 * - max_sr, every row held: the rank-one closed form of the top of the Rayleigh quotient
 *   (eqs. 28-30; snakecg/optimize/max_sr.py _rank_one), scaled onto the limits (_max_scale),
 *   and its certificate (certificate.py _eigen: the residual of Omega v = sr (Omega + Xi) v,
 *   the largest eigenvalue of Omega - sr (Omega + Xi) by cyclic Jacobi rotations, primal
 *   feasibility);
 * - least_slip_push and strongest_push with box limits only: the task as a bound on the
 *   contact force (problems.py push_target), the QP or LP posed in the scaled torque
 *   (box_push.py) and solved by the dense dual active set of Goldfarb and Idnani
 *   (active_set.py), the strongest push's tie-break QP when its LP optimum is not unique, and
 *   the KKT certificate with the duality gap (certificate.py _push_floats).
 *
 * Whatever the Python path would answer otherwise (a structural infeasibility, a closed form
 * that does not apply, the active set giving up, a certificate that needs non-negative least
 * squares) makes the call return a non-zero code: the caller then takes the Python path,
 * which words the answer. Nothing here allocates but the generated functions' work arrays
 * (maps.c, core_forward).
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "optimal.h"

/* box_push.solve_box_push: the least-slip QP (lp 0, task lam_c >= lam_lo, == when equal) or
 * the strongest-push LP (lp 1, no task) with box limits only, in y = tau / tau_max. Writes
 * tau, the binding codes (nb of them) and, for the LP, whether its optimum is unique. */
static int op_box_push(const op_call *c, const op_maps *mp, int lp, int has_lo, double lam_lo,
                       int equal, double *tau, double *bind, int *nb, int *unique) {
  int n = mp->n, R = 0, r, i, j, w, code[OP_ROWS], nact = 0, act[OP_ROWS];
  double rows[OP_ROWS * DENSE_MAX], lo[OP_ROWS], hi[OP_ROWS], H[DENSE_MAX * DENSE_MAX];
  double g[DENSE_MAX], y[DENSE_MAX], lam[OP_ROWS], big = 0.0, fs;
  const double *s = c->tau_max, *ell = ROW(mp->L, 0);
  op_qp Q;
  if (n > DENSE_MAX || 2 + mp->nw + n > OP_ROWS) return 0;
  memset(H, 0, sizeof H);
  memset(g, 0, sizeof g);
#define OP_ADD(vec, a, b, nm)                                   \
  do {                                                          \
    double rn_ = 0.0, cs_[DENSE_MAX];                           \
    for (j = 0; j < n; ++j) {                                   \
      cs_[j] = (vec)[j] * s[j];                                 \
      if (fabs(cs_[j]) > rn_) rn_ = fabs(cs_[j]);               \
    }                                                           \
    if (rn_ > 0) {                                              \
      for (j = 0; j < n; ++j) rows[R * DENSE_MAX + j] = cs_[j] / rn_; \
      lo[R] = (a) / rn_;                                        \
      hi[R] = (b) / rn_;                                        \
      code[R++] = (nm);                                         \
    }                                                           \
  } while (0)
  if (has_lo) OP_ADD(ell, lam_lo, equal ? lam_lo : INFINITY, B_TASK);
  if (!has_lo || lam_lo < 0) OP_ADD(ell, 0.0, INFINITY, B_CONTACT);
  for (w = 0; w < mp->nw; ++w) {
    double ub = c->wheel_ub[w];
    OP_ADD(ROW(mp->L, c->wheel_row[w]), -ub, ub, B_JOINT + n + w);
  }
#undef OP_ADD
  for (i = 0; i < n; ++i) {
    for (j = 0; j < n; ++j) rows[R * DENSE_MAX + j] = (i == j) ? 1.0 : 0.0;
    lo[R] = -1.0;
    hi[R] = 1.0;
    code[R++] = B_JOINT + i;
  }
  if (lp) {
    fs = 0.0;
    for (j = 0; j < n; ++j) {
      g[j] = -ell[j] * s[j];
      if (fabs(g[j]) > fs) fs = fabs(g[j]);
    }
    fs = fs > 0 ? fs : 1.0;
    for (j = 0; j < n; ++j) g[j] = g[j] / fs;
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) H[i * DENSE_MAX + j] = (i == j) ? LP_REG : 0.0;
  } else {
    double reg = 0.0;
    fs = 0.0;
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) {
        double h = 2.0 * ROW(mp->Xi, i)[j] * (s[i] * s[j]);
        H[i * DENSE_MAX + j] = h;
        if (fabs(h) > fs) fs = fabs(h);
      }
    fs = fs > 0 ? fs : 1.0;
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) H[i * DENSE_MAX + j] = H[i * DENSE_MAX + j] / fs;
    for (i = 0; i < n; ++i)
      if (fabs(H[i * DENSE_MAX + i]) > reg) reg = fabs(H[i * DENSE_MAX + i]);
    reg = HESSIAN_REG * (reg > 1e-300 ? reg : 1e-300);
    for (i = 0; i < n; ++i) H[i * DENSE_MAX + i] += reg;
    for (j = 0; j < n; ++j) g[j] = 0.0;
  }
  if (!op_dense_qp(&Q, n, H, g, R, rows, lo, hi, y, lam)) return 0;
  for (r = 0; r < R; ++r)
    if (fabs(lam[r]) > big) big = fabs(lam[r]);
  if (big > 0)
    for (r = 0; r < R; ++r)
      if (fabs(lam[r]) > 1e-7 * big) {
        double ry = op_dot(rows + r * DENSE_MAX, y, n);
        double dl = fabs(ry - lo[r]), dh = fabs(ry - hi[r]);
        if ((dl < dh ? dl : dh) <= 1e-6) act[nact++] = r;
      }
  *nb = 0;
  for (i = 0; i < nact; ++i) {
    int cd = code[act[i]], seen = 0;
    if (cd == B_TASK) continue;
    for (j = 0; j < *nb; ++j)
      if ((int)bind[j] == cd) seen = 1;
    if (!seen) bind[(*nb)++] = cd;
  }
  *unique = 0;
  if (lp && nact >= n) {
    double B[OP_ROWS * DENSE_MAX];
    for (i = 0; i < nact; ++i)
      for (j = 0; j < n; ++j) B[i * DENSE_MAX + j] = rows[act[i] * DENSE_MAX + j];
    *unique = op_rank(nact, n, B, DENSE_MAX, 1e-9) == n;
  }
  for (j = 0; j < n; ++j) tau[j] = y[j] * s[j];
  return 1;
}

/* max_sr with every row held: the rank-one closed form, the scale onto the limits, the
 * certificate of the generalized eigenproblem */
static int op_max_sr(const op_call *c, const op_maps *mp, double *out) {
  int n = mp->n, j, w, nb = 0, ncand = 0, code[OP_ROWS];
  double v[OP_MAX], cc, kc, lam, s, cand[OP_ROWS], *tau = out + O_TAU, *bind = out + O_TAU + n;
  const double *ell = ROW(mp->L, 0);
  int any = 0;
  for (j = 0; j < n; ++j)
    if (ell[j] != 0.0) any = 1;
  if (mp->k <= 0 || !any) return OP_STRUCTURE;
  if (!op_chol_solve(n, mp->Xi, OP_MAX, ell, 1e-12, v)) return OP_CLOSED_FORM;
  cc = op_dot(ell, v, n);
  if (!(cc > 0)) return OP_CLOSED_FORM;
  kc = mp->k * cc;
  lam = kc / (kc + 1.0);
  /* the largest s > 0 with s v inside every limit, and the limits that set it */
  if (c->radius > 0) {
    double qv = op_quad(mp->N, OP_MAX, v, n);
    cand[ncand] = c->radius / sqrt(qv > 1e-300 ? qv : 1e-300);
    code[ncand++] = B_ELLIPSOID;
  }
  if (c->tau_max)
    for (j = 0; j < n; ++j)
      if (fabs(v[j]) > 0) {
        cand[ncand] = c->tau_max[j] / fabs(v[j]);
        code[ncand++] = B_JOINT + j;
      }
  for (w = 0; w < mp->nw; ++w) {
    double li = op_dot(ROW(mp->L, c->wheel_row[w]), v, n);
    if (fabs(li) > 0) {
      cand[ncand] = c->wheel_ub[w] / fabs(li);
      code[ncand++] = B_JOINT + n + w;
    }
  }
  if (!ncand) return OP_CLOSED_FORM;
  s = cand[0];
  for (j = 1; j < ncand; ++j)
    if (cand[j] < s) s = cand[j];
  for (j = 0; j < ncand; ++j)
    if (cand[j] <= s * (1 + 1e-9)) bind[nb++] = code[j];
  for (j = 0; j < n; ++j) tau[j] = s * v[j];
  out[O_NB] = nb;
  out[O_EXPECTED] = lam > 0.0 ? (lam < 1.0 ? lam : 1.0) : 0.0;
  { /* the certificate (certificate._eigen) */
    double D[OP_MAX * OP_MAX], S[OP_MAX * OP_MAX], Dt[OP_MAX], Ot[OP_MAX], rr[OP_MAX];
    double den, sr, nD, top, scale;
    int i;
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) D[i * OP_MAX + j] = ROW(mp->Om, i)[j] + ROW(mp->Xi, i)[j];
    for (i = 0; i < n; ++i) {
      Dt[i] = op_dot(D + i * OP_MAX, tau, n);
      Ot[i] = op_dot(ROW(mp->Om, i), tau, n);
    }
    den = op_dot(tau, Dt, n);
    sr = den > 0 ? op_dot(tau, Ot, n) / den : 0.0;
    nD = op_frob(D, OP_MAX, n);
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) {
        double sij = ROW(mp->Om, i)[j] - sr * D[i * OP_MAX + j];
        double sji = ROW(mp->Om, j)[i] - sr * D[j * OP_MAX + i];
        S[i * n + j] = 0.5 * (sij + sji);
      }
    top = op_top_eigenvalue(n, S);
    scale = (op_frob(mp->Om, OP_MAX, n) + nD) * op_norm(tau, n);
    for (i = 0; i < n; ++i) rr[i] = Ot[i] - sr * Dt[i];
    out[O_STAT] = scale > 0 ? op_norm(rr, n) / scale : 0.0;
    out[O_PRIMAL] = op_primal(c, mp, tau);
    out[O_COMP] = 0.0;
    out[O_GAP] = (top > 0.0 ? top : 0.0) / (nD > 1e-300 ? nD : 1e-300);
  }
  return OP_OK;
}

/* the push tasks with box limits only (push.least_slip_push, push.strongest_push) */
static int op_push(const op_call *c, const op_maps *mp, double *out) {
  int n = mp->n, nb = 0, unique = 0, j, has_lo = 0, equal = 0, lp;
  double *tau = out + O_TAU, *bind = out + O_TAU + n, d[3], lam_lo = 0.0;
  const double *a = mp->a_dir, *ell = ROW(mp->L, 0);
  double na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  if (!c->tau_max || c->radius > 0) return OP_SIZE;
  if (na == 0 || mp->k <= 0) return OP_STRUCTURE;
  lp = c->kind == OP_STRONGEST;
  if (c->kind == OP_LEAST_SLIP && c->a_obj) { /* a full planar acceleration */
    double s0 = (a[0] * c->a_obj[0] + a[1] * c->a_obj[1] + a[2] * c->a_obj[2]) / (na * na);
    double e[3], an = sqrt(c->a_obj[0] * c->a_obj[0] + c->a_obj[1] * c->a_obj[1] +
                           c->a_obj[2] * c->a_obj[2]);
    for (j = 0; j < 3; ++j) e[j] = c->a_obj[j] - s0 * a[j];
    if (sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) > 1e-6 * (an > 1e-300 ? an : 1e-300))
      return OP_STRUCTURE;
    if (s0 < 0) return OP_STRUCTURE;
    has_lo = equal = 1;
    lam_lo = s0;
  } else {
    double gamma, dn;
    if (c->direction) {
      for (j = 0; j < 3; ++j) d[j] = c->direction[j];
    } else { /* the strongest push along the contact normal */
      dn = na > 1e-300 ? na : 1e-300;
      for (j = 0; j < 3; ++j) d[j] = a[j] / dn;
    }
    gamma = d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
    if (gamma <= 1e-9 * na) return OP_STRUCTURE;
    if (!lp) {
      has_lo = 1;
      lam_lo = c->a_min / gamma;
    }
    out[O_GAIN] = gamma;
  }
  out[O_TIE] = 0.0;
  if (!op_box_push(c, mp, lp, has_lo, lam_lo, equal, tau, bind, &nb, &unique))
    return OP_ACTIVE_SET;
  out[O_NB] = nb;
  if (lp) {
    double lam_max = op_dot(ell, tau, n);
    if (lam_max <= 0) return OP_NOT_POSITIVE;
    if (!unique) { /* ties: among the strongest pushes, the least snake motion */
      double t2[OP_MAX], b2[OP_ROWS];
      int nb2, u2;
      if (!op_box_push(c, mp, 0, 1, lam_max * (1 - 1e-9), 0, t2, b2, &nb2, &u2))
        return OP_ACTIVE_SET;
      for (j = 0; j < n; ++j) tau[j] = t2[j];
      out[O_TIE] = 1.0;
    }
    out[O_EXPECTED] = out[O_GAIN] * op_dot(ell, tau, n);
    if (!op_push_certificate(c, mp, tau, 0, 0.0, 0, 1, out + O_STAT)) return OP_CERTIFICATE;
  } else {
    double xt[OP_MAX];
    for (j = 0; j < n; ++j) { /* (tau Xi)_j: the column j of Xi */
      double s = 0.0;
      int i;
      for (i = 0; i < n; ++i) s += tau[i] * ROW(mp->Xi, i)[j];
      xt[j] = s;
    }
    out[O_EXPECTED] = op_dot(xt, tau, n);
    out[O_LAM_LO] = lam_lo;
    if (!op_push_certificate(c, mp, tau, 1, lam_lo, equal, 0, out + O_STAT)) return OP_CERTIFICATE;
  }
  return OP_OK;
}

/* maps.c */
int SNAKECG_EXPORT(core_held_maps)(const double *scene, const double *q, double pivot_tol,
                                   double *maps);
/* forward.c */
int SNAKECG_EXPORT(core_forward)(op_int n, const double *scene, const double *constants,
                                 op_int max_iter, const double *const *in, const op_int *stride,
                                 double *out);

int SNAKECG_EXPORT(core_optimal)(const op_call *c) {
  op_maps mp;
  int n = (int)c->n, nc = (int)c->nc, i, j, st;
  double *out = c->out, ll;
  const double *ell, *A = c->maps + SNAKECG_NC * SNAKECG_NA, *src;
  out[O_STATUS] = OP_SIZE;
  if (n != SNAKECG_NA || nc != SNAKECG_NC || n > OP_MAX || c->nw > nc) return OP_SIZE;
  /* the all-held maps at q (maps.c), row-major */
  if (SNAKECG_EXPORT(core_held_maps)(c->scene, c->q, c->pivot_tol, c->maps))
    return out[O_STATUS] = OP_MAPS;
  mp.n = n;
  mp.nc = nc;
  mp.nw = (int)c->nw;
  for (i = 0; i < nc; ++i)
    for (j = 0; j < n; ++j) ROW(mp.L, i)[j] = c->maps[i * n + j];
  src = A + 3 * n;
  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j) {
      ROW(mp.Xi, i)[j] = src[i * n + j];
      ROW(mp.Om, i)[j] = src[n * n + i * n + j];
      ROW(mp.N, i)[j] = src[2 * n * n + i * n + j];
    }
  for (i = 0; i < mp.nw; ++i)
    if (c->wheel_row[i] < 1 || c->wheel_row[i] >= nc) return OP_SIZE;
  /* a_obj = a_dir lam_c, k = ||a_dir||^2 in the object's metric (problems.configs) */
  ell = ROW(mp.L, 0);
  ll = op_dot(ell, ell, n);
  for (i = 0; i < 3; ++i) {
    double s = 0.0;
    for (j = 0; j < n; ++j) s += A[i * n + j] * ell[j];
    mp.a_dir[i] = ll > 0 ? s / ll : 0.0;
  }
  mp.k = 0.0;
  for (i = 0; i < 3; ++i) mp.k += c->Io[i] * mp.a_dir[i] * mp.a_dir[i];
  out[O_K] = mp.k;
  for (i = 0; i < 3; ++i) out[O_ADIR + i] = mp.a_dir[i];
  st = c->kind == OP_MAX_SR ? op_max_sr(c, &mp, out) : op_push(c, &mp, out);
  out[O_STATUS] = st;
  if (st != OP_OK) return st;
  out[O_QUAD] = op_quad(mp.N, OP_MAX, out + O_TAU, n);
  { /* the forward solve at the answer: q, v = 0, tau, the object placed, at rest */
    static const double zero[SNAKECG_NS] = {0.0};
    const double *in[7];
    op_int stride[7] = {0, 0, 0, 0, 0, 0, 0};
    in[IN_q] = c->q;
    in[IN_v] = zero;
    in[IN_tau] = out + O_TAU;
    in[IN_q_obj] = 0;
    in[IN_v_obj] = zero;
    in[IN_f_obj] = zero;
    in[IN_rho] = 0;
    out[O_FORWARD] = SNAKECG_EXPORT(core_forward)(1, c->scene, c->constants, c->max_iter, in,
                                                  stride, c->row);
  }
  return st;
}

/* The dense dual active set alone, for tests: min 1/2 x^T H x + g^T x s.t.
 * lo <= A x <= hi (H n x n, A R x n, row-major); 1 with x and the rows' multipliers. */
int SNAKECG_EXPORT(core_dense_qp)(op_int n, op_int R, const double *H, const double *g,
                                  const double *A, const double *lo, const double *hi, double *x,
                                  double *lam) {
  double Hd[DENSE_MAX * DENSE_MAX], Ad[OP_ROWS * DENSE_MAX];
  op_qp Q;
  int i, j;
  if (n < 1 || n > DENSE_MAX || R < 0 || R > OP_ROWS) return -1;
  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j) Hd[i * DENSE_MAX + j] = H[i * n + j];
  for (i = 0; i < R; ++i)
    for (j = 0; j < n; ++j) Ad[i * DENSE_MAX + j] = A[i * n + j];
  return op_dense_qp(&Q, (int)n, Hd, g, (int)R, Ad, lo, hi, x, lam);
}

/* The largest eigenvalue of a symmetric n x n matrix (row-major, copied), for tests. */
double SNAKECG_EXPORT(core_top_eigenvalue)(op_int n, const double *S) {
  double W[OP_MAX * OP_MAX];
  int i;
  if (n < 1 || n > OP_MAX) return NAN;
  for (i = 0; i < n * n; ++i) W[i] = S[i];
  return op_top_eigenvalue((int)n, W);
}
