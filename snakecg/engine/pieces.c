/* snakecg's runtime core, part 4: the affine maps and the conditions of the pieces of the
 * bounded-wheel map (the exact bounded-wheel extremes, snakecg/pieces.py `piece`).
 *
 * This file is part of the runtime (not generated). Like forward.c it is compiled once per
 * model into the model's shared library; it uses nothing of the model but the symbol prefix.
 *
 * With bounded wheels the contact/wheel solution is affine in the (whitened) torque u on each
 * state's polyhedron (eqs. 12-25 with the sliding wheels' fixed forces +-mu m_i g): for the
 * held rows H, G_HH lam_H = -(Bt_H u + (G lam_f)_H), the other rows' forces fixed (lam_f: the
 * bound, signed, for a sliding wheel; 0 for a lost contact). So per (configuration, state)
 * pair: lam = Lam u + lam0, w = G lam + Bt u (the rows' accelerations), qdd = Q0 u + Kq lam,
 * a_obj = A0 u + Ka lam, and the state's conditions a . u + b >= 0, in snakecg/pieces.py's
 * order: a held contact keeps lam_c >= 0 (across: lost), a lost one w_c >= 0 (across: held);
 * a held bounded wheel |lam_r| <= bound (across: sliding + / -), a sliding one a velocity of
 * its sign (across: held). Each condition is scaled to a largest coefficient of 1; unused
 * slots are 0 . u + 1 >= 0 after the used ones.
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"


/* row states (snakecg/solver.py) */
enum { SC_PIECE_ABSENT = 0, SC_PIECE_HELD = 1, SC_PIECE_LOST = 2, SC_PIECE_SLIDE_POS = 3, SC_PIECE_SLIDE_NEG = 4 };

/* one condition into slot `*k` of the pair: coefficients a (stride `sa`, times `sign`), the
 * constant b; scaled to a largest coefficient of 1 */
static void sc_piece_add(double *cond, sc_int *flip, sc_int *row, int *k, int na, const double *a,
                   int sa, double sign, double b, int to, int r) {
  double *c = cond + (*k) * (na + 1), scale = 0.0;
  int i;
  for (i = 0; i < na; ++i) c[i] = sign * a[i * sa];
  c[na] = b;
  for (i = 0; i <= na; ++i)
    if (fabs(c[i]) > scale) scale = fabs(c[i]);
  if (scale > 0)
    for (i = 0; i <= na; ++i) c[i] /= scale;
  flip[*k] = to;
  row[*k] = r;
  ++*k;
}

/* For pairs p < P (configuration cfg[p], row states states[p]):
 *   per configuration: G (nc, nc), Bt (nc, na), Q0 (ns, na), A0 (3, na), Kq (ns, nc),
 *   Ka (3, nc); bounds (nc), +inf where a row is unbounded;
 *   out per pair: Lam (nc, na), lam0 (nc), W (nc, na), w0 (nc), Q (ns, na), q0 (ns),
 *   Aa (3, na), a0 (3), cond (mfull, na + 1), flip (mfull, the state across, -1 unused),
 *   row (mfull).
 * Returns the largest number of used conditions of a pair, -1 when a size is not positive or
 * mfull is too small, -2 - p when pair p's held rows are singular. */
sc_int SNAKECG_EXPORT(core_pieces)(sc_int P, sc_int na_, sc_int nc_, sc_int ns_, sc_int mfull,
                                   const sc_int *cfg, const signed char *states,
                                   const double *bounds, const double *G, const double *Bt,
                                   const double *Q0, const double *A0, const double *Kq,
                                   const double *Ka, double *Lam, double *lam0, double *W,
                                   double *w0, double *Q, double *q0, double *Aa, double *a0,
                                   double *cond, sc_int *flip, sc_int *row) {
  const int na = (int)na_, nc = (int)nc_, ns = (int)ns_, D = na > nc ? na : nc;
  int mmax = 0, r;
  sc_int p;
  if (na < 1 || nc < 1 || ns < 1) return -1;
  {
    int need = 2;
    for (r = 1; r < nc; ++r)
      if (isfinite(bounds[r])) need += 4;
    if (mfull < need) return -1;
  }
  for (p = 0; p < P; ++p) {
    const sc_int n = cfg[p];
    const signed char *st = states + p * nc;
    const double *Gp = G + n * nc * nc, *Bp = Bt + n * nc * na, *Kqp = Kq + n * ns * nc;
    const double *Kap = Ka + n * 3 * nc;
    double *L = Lam + p * nc * na, *l0 = lam0 + p * nc, *Wp = W + p * nc * na;
    double *w0p = w0 + p * nc, *Qp = Q + p * ns * na, *q0p = q0 + p * ns;
    double *Ap = Aa + p * 3 * na, *a0p = a0 + p * 3;
    double *cp = cond + p * mfull * (na + 1);
    sc_int *fp = flip + p * mfull, *rp = row + p * mfull;
    double lf[D], M[D * D], X[D * (D + 1)]; /* D = max(na, nc): any size */
    int H[D], nh = 0, i, j, l, k = 0;
    /* the fixed forces and the held rows */
    for (r = 0; r < nc; ++r) {
      double ub = isfinite(bounds[r]) ? bounds[r] : 0.0;
      lf[r] = st[r] == SC_PIECE_SLIDE_POS ? ub : (st[r] == SC_PIECE_SLIDE_NEG ? -ub : 0.0);
      if (st[r] == SC_PIECE_HELD) H[nh++] = r;
    }
    /* G_HH X = -[Bt_H, (G lf)_H] by Gaussian elimination with partial pivoting */
    for (i = 0; i < nh; ++i) {
      double glf = 0.0;
      for (j = 0; j < nh; ++j) M[i * nh + j] = Gp[H[i] * nc + H[j]];
      for (l = 0; l < na; ++l) X[i * (na + 1) + l] = -Bp[H[i] * na + l];
      for (j = 0; j < nc; ++j) glf += Gp[H[i] * nc + j] * lf[j];
      X[i * (na + 1) + na] = -glf;
    }
    for (j = 0; j < nh; ++j) {
      int piv = j;
      double best = fabs(M[j * nh + j]);
      for (i = j + 1; i < nh; ++i)
        if (fabs(M[i * nh + j]) > best) {
          best = fabs(M[i * nh + j]);
          piv = i;
        }
      if (!(best > 0)) return -2 - p;
      if (piv != j) {
        for (l = 0; l < nh; ++l) {
          double t = M[j * nh + l];
          M[j * nh + l] = M[piv * nh + l];
          M[piv * nh + l] = t;
        }
        for (l = 0; l <= na; ++l) {
          double t = X[j * (na + 1) + l];
          X[j * (na + 1) + l] = X[piv * (na + 1) + l];
          X[piv * (na + 1) + l] = t;
        }
      }
      for (i = j + 1; i < nh; ++i) {
        double f = M[i * nh + j] / M[j * nh + j];
        if (f == 0.0) continue;
        for (l = j; l < nh; ++l) M[i * nh + l] -= f * M[j * nh + l];
        for (l = 0; l <= na; ++l) X[i * (na + 1) + l] -= f * X[j * (na + 1) + l];
      }
    }
    for (j = nh - 1; j >= 0; --j) {
      for (l = 0; l <= na; ++l) {
        double s = X[j * (na + 1) + l];
        for (i = j + 1; i < nh; ++i) s -= M[j * nh + i] * X[i * (na + 1) + l];
        X[j * (na + 1) + l] = s / M[j * nh + j];
      }
    }
    /* lam = Lam u + lam0 */
    memset(L, 0, sizeof(double) * (size_t)(nc * na));
    for (r = 0; r < nc; ++r) l0[r] = lf[r];
    for (i = 0; i < nh; ++i) {
      for (l = 0; l < na; ++l) L[H[i] * na + l] = X[i * (na + 1) + l];
      l0[H[i]] = X[i * (na + 1) + na] + lf[H[i]];
    }
    /* w = W u + w0, qdd = Q u + q0, a_obj = Aa u + a0 */
    for (r = 0; r < nc; ++r) {
      double s0 = 0.0;
      for (l = 0; l < na; ++l) {
        double s = Bp[r * na + l];
        for (j = 0; j < nc; ++j) s += Gp[r * nc + j] * L[j * na + l];
        Wp[r * na + l] = s;
      }
      for (j = 0; j < nc; ++j) s0 += Gp[r * nc + j] * l0[j];
      w0p[r] = s0;
    }
    for (i = 0; i < ns + 3; ++i) {
      const double *K = i < ns ? Kqp + i * nc : Kap + (i - ns) * nc;
      const double *B0 = i < ns ? Q0 + n * ns * na + i * na : A0 + n * 3 * na + (i - ns) * na;
      double *out = i < ns ? Qp + i * na : Ap + (i - ns) * na;
      double s0 = 0.0;
      for (l = 0; l < na; ++l) {
        double s = B0[l];
        for (j = 0; j < nc; ++j) s += K[j] * L[j * na + l];
        out[l] = s;
      }
      for (j = 0; j < nc; ++j) s0 += K[j] * l0[j];
      if (i < ns) q0p[i] = s0;
      else a0p[i - ns] = s0;
    }
    /* the conditions, in snakecg/pieces.py's order */
    if (st[0] == SC_PIECE_HELD) sc_piece_add(cp, fp, rp, &k, na, L, 1, 1.0, l0[0], SC_PIECE_LOST, 0);
    if (st[0] == SC_PIECE_LOST) sc_piece_add(cp, fp, rp, &k, na, Wp, 1, 1.0, w0p[0], SC_PIECE_HELD, 0);
    for (r = 1; r < nc; ++r) {
      if (!isfinite(bounds[r])) continue;
      if (st[r] == SC_PIECE_HELD) {
        sc_piece_add(cp, fp, rp, &k, na, L + r * na, 1, -1.0, -l0[r] + bounds[r], SC_PIECE_SLIDE_POS, r);
        sc_piece_add(cp, fp, rp, &k, na, L + r * na, 1, 1.0, l0[r] + bounds[r], SC_PIECE_SLIDE_NEG, r);
      }
      if (st[r] == SC_PIECE_SLIDE_POS)
        sc_piece_add(cp, fp, rp, &k, na, Wp + r * na, 1, -1.0, -w0p[r], SC_PIECE_HELD, r);
      if (st[r] == SC_PIECE_SLIDE_NEG)
        sc_piece_add(cp, fp, rp, &k, na, Wp + r * na, 1, 1.0, w0p[r], SC_PIECE_HELD, r);
    }
    if (k > mmax) mmax = k;
    for (; k < mfull; ++k) { /* unused: 0 . u + 1 >= 0 */
      double *c = cp + k * (na + 1);
      for (l = 0; l < na; ++l) c[l] = 0.0;
      c[na] = 1.0;
      fp[k] = -1;
      rp[k] = 0;
    }
  }
  return mmax;
}
