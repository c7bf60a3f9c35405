/* snakecg's engine: a general scene's piece solved in the primal, in the coordinates' n
 * unknowns instead of the rows' m forces (scene_solve.c's warm start, where m > n: the pegs
 * row's 22-33 rows on 13 coordinates; where m <= n the dual is the smaller and keeps it).
 *
 * On a piece (scene_solve.c's header: every block held, zero, or sliding), the dual's
 * problem is the Lagrange dual of the primal one in the accelerations (velocities in a time
 * step) a, with y = L^T a (M = L L^T), g = L^-1 f, Z = L^-1 A^T, w = A a + c = Z^T y + c:
 *   minimise 1/2 |y - g_F|^2 + sum_{sliding disc i} s_i |w_i|
 *   subject to w_H = 0 (the held rows: contacts, stuck 2-D blocks, ideal wheels),
 * g_F = g + Z_F lam_F the free motion with the fixed forces (saturated boxes) applied, s_i
 * the disc's radius. Its Hessian I + sum_i (s_i / |w_i|) v_i v_i^T (v_i = Z_i u_i^perp, one
 * rank-one term per sliding disc) is positive definite and its equalities are the held rows
 * alone; a Newton step on y with them (Cholesky R R^T of the Hessian, the held rows'
 * multipliers by the Schur complement Y^T Y, Y = R^-1 Z_H, |H| unknowns) from the caller's
 * forces (y = g + Z lam), then chord steps on that factor (the same equations at the new
 * point, the Hessian of the first: each contracts by about the first step's size, 1e-5 of y
 * on a pegs step) while each contracts by a tenth at least, else a Newton step again; the
 * step halved while the objective rises; converged where the next step falls below rounding.
 * Then the forces lam_H the multipliers and lam_i = -s_i w_i / |w_i|, every row's w and a
 * from the last y (g + Z lam but for the next step's size, below rounding; g + Z lam itself
 * where forces are then moved): the dual's piece's forces and a, without G = Z^T Z. What it
 * does not treat it leaves (returns 0) to scene_solve.c's dual path: a sliding split
 * ellipse; held rows dependent (or nearly: pivots of Y^T Y below PRIMAL_DEP of the first); a
 * sliding disc whose sliding |w_i| falls to rounding; no convergence within PRIMAL_STEPS
 * steps. For the snake alone (n = n_s, the pegs row) the Hessian's Cholesky and q = R^-1 grad
 * are scene_small.c's factor unrolled for n_s (sc_cholesky's factor bit for bit), and the
 * piece is compiled a second time with AVX, chosen where the processor has it (no FMA: bit
 * for bit the copy without; core_scene_primal's mode 2 takes that one), and a third time with
 * AVX2 and FMA, chosen before it where the processor has both: the products fused into the
 * sums, the Hessian's factor scene_small.c's sc_small_factor_fma (by L D L^T, its
 * diagonal's reciprocals kept with its columns for the triangular solves) and its loops over the
 * coordinates scene_primal.h's kernels (the n_s coordinates four to a register: the start,
 * the gradient with T, the Hessian, the discs' w, R^-1 by L's columns, R^-T, the held rows'
 * dot products, the face's K):
 * within rounding of the others, not bit for bit (mode 3 takes the AVX copy). */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"
#include "scene_small.h"

#if defined(__GNUC__) /* (inlined where the caller makes the size a constant) */
#define PRIMAL_FLAT static inline __attribute__((always_inline))
#else
#define PRIMAL_FLAT static inline
#endif
#include "scene_primal.h" /* (its kernels) */

#define PRIMAL_STEPS 12 /* Newton and chord steps before the dual path takes over */
#define PRIMAL_DEP 1e-8 /* held rows taken as dependent below this pivot ratio (dual: 1e-10) */

/* core_scene_primal's switch (1: the warm start tries the primal piece first, the snake's
 * fastest copy; 2: the same with the plain copy; 3: with the AVX copy, which answers bit for
 * bit as the plain one) and counts
 * (tries, answers: measurement only; atomic where the compiler has GCC's builtins, as the
 * batches' threads count together) */
static int primal_on = 1;
static long primal_counts[2];
#if defined(__GNUC__)
#define PRIMAL_ADD(k, v) __atomic_fetch_add(&primal_counts[k], (v), __ATOMIC_RELAXED)
#define PRIMAL_TAKE(k) __atomic_exchange_n(&primal_counts[k], 0L, __ATOMIC_RELAXED)
#else
#define PRIMAL_ADD(k, v) (primal_counts[k] += (v))
static long primal_take(int k) {
  long v = primal_counts[k];
  primal_counts[k] = 0;
  return v;
}
#define PRIMAL_TAKE(k) primal_take(k)
#endif

/* A try counted (ok 1: answered, 0: left to the dual path; -1: none, the switch read);
 * returns the switch. */
SC_INTERNAL int sc_primal_tally(int ok) {
  if (ok >= 0) {
    PRIMAL_ADD(0, 1L);
    PRIMAL_ADD(1, ok ? 1L : 0L);
  }
  return primal_on;
}

/* The primal piece switched on (mode 1; 2: on with the snake's plain copy; 3: its AVX copy
 * without FMA) or off (0), or left (-1); counts (2 doubles, or NULL): the tries and answers
 * since the last read, then reset. Returns the previous mode. */
int SNAKECG_EXPORT(core_scene_primal)(sc_int mode, double *counts) {
  int prev = primal_on;
  if (mode >= 0 && mode <= 3) primal_on = (int)mode;
  if (counts) {
    long t = PRIMAL_TAKE(0);
    long a = PRIMAL_TAKE(1);
    counts[0] = (double)t, counts[1] = (double)a;
  }
  return prev;
}

/* Scratch (doubles) of sc_primal_piece for n coordinates and m rows. */
SC_INTERNAL sc_int sc_primal_work(sc_int n, sc_int m) {
  return 2 * n * n + 3 * n * m + m * m + 11 * n + 7 * m + 4; /* (Lt: n n + 4) */
}

/* w_i = Z_i^T y + c_i of the sliding discs' rows (Zs: their columns first, row i at Zs + i ld;
 * cg: their offsets), their norms |w_i| (nws) and the objective's nonsmooth part sum s_i |w_i|
 * (s: their radii). */
PRIMAL_FLAT double sliding(sc_int n, sc_int ld, sc_int ns, const double *s, const double *Zs,
                           const double *cg, const double *y, double *restrict ws,
                           double *restrict nws, const int fused) {
  sc_int i, j;
  double v = 0.0;
#ifdef SC_SMALL_FMA
  if (fused) return sc_primal_sliding(ld, ns, s, Zs, cg, y, ws, nws);
#endif
  for (j = 0; j + 3 < 2 * ns; j += 4) { /* (four sums at a time in registers, each over the
    coordinates in order) */
    double w0 = cg[j], w1 = cg[j + 1], w2 = cg[j + 2], w3 = cg[j + 3];
    for (i = 0; i < n; ++i) {
      const double *restrict zi = Zs + i * ld + j, yi = y[i];
      w0 += zi[0] * yi;
      w1 += zi[1] * yi;
      w2 += zi[2] * yi;
      w3 += zi[3] * yi;
    }
    ws[j] = w0, ws[j + 1] = w1, ws[j + 2] = w2, ws[j + 3] = w3;
  }
  for (; j < 2 * ns; j += 2) {
    double w0 = cg[j], w1 = cg[j + 1];
    for (i = 0; i < n; ++i) {
      const double *restrict zi = Zs + i * ld + j, yi = y[i];
      w0 += zi[0] * yi;
      w1 += zi[1] * yi;
    }
    ws[j] = w0, ws[j + 1] = w1;
  }
  for (j = 0; j < ns; ++j) {
    nws[j] = sqrt(ws[2 * j] * ws[2 * j] + ws[2 * j + 1] * ws[2 * j + 1]);
    v += s[j] * nws[j];
  }
  return v;
}

/* w = Z^T (g + Z lam) + c, every row (y: n scratch) */
PRIMAL_FLAT void every_w(sc_int n, sc_problem *p, const double *Z, const double *g,
                         const double *c, double *y) {
  const sc_int m = p->m;
  sc_int i, j;
  for (i = 0; i < n; ++i) { /* (four partial sums: four short dependent chains) */
    const double *restrict zi = Z + i * m, *restrict l = p->lam;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (j = 0; j + 3 < m; j += 4) {
      s0 += zi[j] * l[j];
      s1 += zi[j + 1] * l[j + 1];
      s2 += zi[j + 2] * l[j + 2];
      s3 += zi[j + 3] * l[j + 3];
    }
    for (; j < m; ++j) s0 += zi[j] * l[j];
    y[i] = g[i] + ((s0 + s1) + (s2 + s3));
  }
  for (j = 0; j + 3 < m; j += 4) { /* (four rows' sums at a time in registers, each over the
    coordinates in order) */
    double w0 = c ? c[j] : 0.0, w1 = c ? c[j + 1] : 0.0, w2 = c ? c[j + 2] : 0.0,
           w3 = c ? c[j + 3] : 0.0;
    for (i = 0; i < n; ++i) {
      const double *restrict zi = Z + i * m + j, yi = y[i];
      w0 += zi[0] * yi;
      w1 += zi[1] * yi;
      w2 += zi[2] * yi;
      w3 += zi[3] * yi;
    }
    p->w[j] = w0, p->w[j + 1] = w1, p->w[j + 2] = w2, p->w[j + 3] = w3;
  }
  for (; j < m; ++j) {
    double w0 = c ? c[j] : 0.0;
    for (i = 0; i < n; ++i) w0 += Z[i * m + j] * y[i];
    p->w[j] = w0;
  }
}

/* every row's w = Z^T y + c at the piece's last point y (Zc: the piece's gathered columns, the
 * ns sliding discs' pairs, then the held rows'), each summed as every_w sums it (from the
 * offset, over the coordinates in order): the sliding discs' their objective's (ws: the same
 * sums at y), the held rows' by their gathered columns, the rest (zero, fixed) from Z */
PRIMAL_FLAT void last_w(sc_int n, sc_problem *p, const double *Z, const double *Zc,
                        const double *c, const double *y, const double *ws, sc_int ns) {
  const sc_int m = p->m;
  sc_int i, k, e, js = 0, jh = 0;
  for (k = 0; k < p->nb; ++k) {
    const sc_int r = p->start[k], nk = sc_block_size(p->kind[k]);
    if (p->state[k] == S_SLIDE && p->kind[k] == K_DISC) {
      p->w[r] = ws[2 * js], p->w[r + 1] = ws[2 * js + 1];
      ++js;
      continue;
    }
    for (e = 0; e < nk; ++e) {
      double u = c ? c[r + e] : 0.0;
      if (p->state[k] == S_HELD) {
        const double *restrict zj = Zc + (2 * ns + jh++) * n;
        for (i = 0; i < n; ++i) u += zj[i] * y[i];
      } else {
        for (i = 0; i < n; ++i) u += Z[i * m + r + e] * y[i];
      }
      p->w[r + e] = u;
    }
  }
}

/* Y's columns nc (1 or 2) of held rows, Y_j = R^-1 Z_j by forward substitution (t: R's
 * diagonal's reciprocals; Zc: their gathered columns, each n long; ch: their offsets), and
 * lh_j = Y_j^T q - (Z_j^T y + c_j); the columns' chains side by side, each summed as one
 * column alone would be */
PRIMAL_FLAT void held_cols(sc_int n, const int nc, const double *R, const double *t,
                           const double *Zc, const double *ch, const double *y,
                           const double *q, double *restrict Y, double *restrict lh) {
  double u[2] = {0.0, 0.0}, t0[2], t1[2];
  sc_int i, k;
  int c;
  for (c = 0; c < nc; ++c) u[c] = -ch[c];
  for (i = 0; i < n; ++i) {
    const double *restrict ri = R + i * n;
    for (c = 0; c < nc; ++c) t0[c] = Zc[c * n + i], t1[c] = 0.0;
    for (k = 0; k + 1 < i; k += 2)
      for (c = 0; c < nc; ++c) {
        t0[c] -= ri[k] * Y[c * n + k];
        t1[c] -= ri[k + 1] * Y[c * n + k + 1];
      }
    if (k < i)
      for (c = 0; c < nc; ++c) t0[c] -= ri[k] * Y[c * n + k];
    for (c = 0; c < nc; ++c) {
      Y[c * n + i] = (t0[c] + t1[c]) * t[i];
      u[c] += Y[c * n + i] * q[i] - Zc[c * n + i] * y[i];
    }
  }
  for (c = 0; c < nc; ++c) lh[c] = u[c];
}


/* The piece of p->state (its forces' start in p->lam) solved in the primal: p->lam and p->w
 * (every row's, w = Z^T y + c, y = g + Z lam to rounding) filled. g = L^-1 f, Z = L^-1 A^T
 * (n x m, coordinate i's row at Z + i m; M = L L^T), c the rows' offsets (or NULL). Returns 1
 * when solved with unique forces, 2 with the face's minimum-norm ones (def: the held rows'
 * rank defect; work's first n: y), 0 when left to the dual path (p->lam, p->w then
 * undefined). */
PRIMAL_FLAT int piece(sc_int n, sc_problem *p, const double *Z, const double *g,
                      const double *c, double *work, sc_int *iwork, sc_int *def,
                      const int fused) {
  const sc_int m = p->m, nb = p->nb;
  double *R = work, *Y = R + n * n, *S = Y + n * (m + 3), *gF = S + m * m, *y = gF + n,
         *grad = y + n, *q = grad + n, *dy = q + n, *yt = dy + n, *t = yt + n, *lh = t + n,
         *ws = lh + m, *rad = ws + m, *wt = rad + m, *bh = wt + m, *cg = bh + m, *Zg = cg + m,
         *Zc = Zg + n * m, *nws = Zc + n * m, *Lt = nws + m;
  sc_int *hr = iwork, *sl = hr + m, *perm = sl + m, h = 0, ns = 0, i, j, k, it, rank = 0;
  double ysc, v = 0.0, dsq = 0.0, big, prev = INFINITY;
  int ok = 0, dep = 0, again = 0, fresh = 1, solved;
  sc_int nf, lds;
  const double *Zs, *cs;
  int run;
  if (!sc_piece_parts(p, n, Z, g, gF, hr, &h, sl, rad, &ns, NULL))
    return 0; /* (the piece: held rows, fixed forces, sliding discs; scene_sets.h) */
  /* the piece's columns of Z gathered (Zc, (2 ns + h) x n: the sliding discs' pairs, then
   * the held rows', each column contiguous for the loops over the coordinates; the discs'
   * rows also by coordinates for their w, Zs with row stride lds: in Z itself where they are
   * one run of rows, sl[j] = sl[0] + 2 j, the pegs row's ground, else gathered in Zg) and
   * the start y = g_F + Z (lam_S, lam_H) at the caller's forces, column by column */
  for (j = 1, run = ns > 0; j < ns && run; ++j) run = sl[j] == sl[0] + 2 * j;
  if (run && c) cs = c + sl[0]; /* (the discs' offsets: in c where one run, else gathered) */
  else
    for (j = 0, cs = cg; j < 2 * ns; ++j) cg[j] = c ? c[sl[j / 2] + j % 2] : 0.0;
  for (j = 0; j < h; ++j) cg[2 * ns + j] = c ? c[hr[j]] : 0.0;
#ifdef SC_SMALL_FMA
  if (fused && run) sc_primal_start(ns, Z + sl[0], m, p->lam + sl[0], gF, Zc, y);
#endif
  for (i = 0; i < n && !(fused && run); ++i) y[i] = gF[i];
  for (j = 0; j < ns && !(fused && run); ++j) {
    double *restrict z0 = Zc + 2 * j * n, *restrict z1 = z0 + n, *restrict yy = y;
    const double *zr = Z + sl[j], l0 = p->lam[sl[j]], l1 = p->lam[sl[j] + 1];
    for (i = 0; i < n; ++i) z0[i] = zr[i * m], z1[i] = zr[i * m + 1];
    for (i = 0; i < n; ++i) yy[i] += z0[i] * l0 + z1[i] * l1;
  }
  for (j = 0; j < h; ++j) {
    double *restrict zj = Zc + (2 * ns + j) * n, *restrict yy = y;
    const double *zr = Z + hr[j], l = p->lam[hr[j]];
    for (i = 0; i < n; ++i) zj[i] = zr[i * m];
    for (i = 0; i < n; ++i) yy[i] += zj[i] * l;
  }
  if (run) {
    Zs = Z + sl[0];
    lds = m;
  } else {
    for (i = 0; i < n; ++i)
      for (j = 0; j < 2 * ns; ++j) Zg[i * 2 * ns + j] = Zc[j * n + i];
    Zs = Zg;
    lds = 2 * ns;
  }
  ysc = sqrt(p->fscale * p->wscale);
  for (it = 0; it < PRIMAL_STEPS; ++it) {
    double step = 0.0, tstep = 1.0, ymax = ysc;
    int feasible = it > 0;
    if (it == 0) { /* (the objective: its nonsmooth part v, |y - g_F|^2 dsq; then the accepted
      point's, kept) */
      v = sliding(n, lds, ns, rad, Zs, cs, y, ws, nws, fused);
      for (i = 0, dsq = 0.0; i < n; ++i) dsq += (y[i] - gF[i]) * (y[i] - gF[i]);
    }
    /* the gradient y - g_F + sum s_j Z_j u_j and (fresh) the Hessian I + T T^T (T's column j:
     * sqrt(s_j / |w_j|) v_j, contiguous in Y's room) */
#ifdef SC_SMALL_FMA
    if (fused) { /* (the FMA copy: the gradient, T's columns, its kernels) */
      for (j = 0; j < ns; ++j)
        if (!(nws[j] > TOL_ACCEPT * p->wscale)) return 0;
      sc_primal_grad(ns, y, gF, Zc, rad, ws, nws, grad, fresh ? Y : NULL);
      if (fresh) sc_primal_hessian(ns, Y, R, 1.0);
    }
#endif
    for (i = 0; i < n && !fused; ++i) grad[i] = y[i] - gF[i];
    for (j = 0; j < ns && !fresh && !fused; ++j) { /* (a chord step: the gradient alone) */
      double w0 = ws[2 * j], w1 = ws[2 * j + 1], nw = nws[j], r0, r1;
      const double *restrict z0 = Zc + 2 * j * n, *restrict z1 = z0 + n;
      double *restrict gr = grad;
      if (!(nw > TOL_ACCEPT * p->wscale)) return 0;
      r0 = rad[j] * (w0 / nw);
      r1 = rad[j] * (w1 / nw);
      for (i = 0; i < n; ++i) gr[i] += z0[i] * r0 + z1[i] * r1;
    }
    for (j = 0; j < ns && fresh && !fused; ++j) {
      double w0 = ws[2 * j], w1 = ws[2 * j + 1], nw = nws[j], cj, r0, r1;
      const double *restrict z0 = Zc + 2 * j * n, *restrict z1 = z0 + n;
      double *restrict tj = Y + j * n, *restrict gr = grad;
      if (!(nw > TOL_ACCEPT * p->wscale)) return 0; /* sliding at rounding's speed */
      w0 /= nw;
      w1 /= nw;
      cj = sqrt(rad[j] / nw);
      r0 = rad[j] * w0;
      r1 = rad[j] * w1;
      for (i = 0; i < n; ++i) {
        tj[i] = cj * (w1 * z0[i] - w0 * z1[i]); /* Z_j u^perp (up to sign) */
        gr[i] += z0[i] * r0 + z1[i] * r1;
      }
    }
    for (j = ns * n; fresh && !fused && j < ((ns + 3) / 4) * 4 * n; ++j) Y[j] = 0.0;
    for (i = 0; i < n && fresh && !fused; ++i) { /* R's row i: the terms four columns of T at a time
      (its contiguous part vectorised) */
      double *restrict ri = R + i * n;
      for (k = 0; k <= i; ++k) ri[k] = 0.0;
      for (j = 0; j < ns; j += 4) { /* (T's columns past ns: zeros) */
        const double *restrict t0 = Y + j * n, *restrict t1 = t0 + n, *restrict t2 = t1 + n,
                     *restrict t3 = t2 + n;
        const double a0 = t0[i], a1 = t1[i], a2 = t2[i], a3 = t3[i];
        for (k = 0; k <= i; ++k) ri[k] += (a0 * t0[k] + a1 * t1[k]) + (a2 * t2[k] + a3 * t3[k]);
      }
      ri[i] += 1.0;
    }
    solved = 0;
    if (fresh) { /* (the snake alone: scene_small.c's factor unrolled for n_s, q with it) */
#ifdef SC_FIXED
      if (n == SNAKECG_NS) {
        for (i = 0, big = 0.0; i < n; ++i) big = sc_max(big, R[i * n + i]);
#ifdef SC_SMALL_FMA
        if (fused) { /* (the FMA copy: the factor's reciprocals kept as t) */
          if (!sc_small_factor_fma(R, grad, 1e-14 * big, R, q, t, Lt)) return 0;
        } else
#endif
        if (!sc_small_factor(R, grad, 1e-14 * big, R, q)) return 0;
        solved = 1;
      } else
#endif
      if (!sc_cholesky(n, R, n, 1e-14)) return 0;
      for (i = 0; i < n && !(fused && solved); ++i)
        t[i] = 1.0 / R[i * n + i]; /* (multiplied: no division chain) */
    }
    /* q = R^-1 grad; Y = R^-1 Z_H (column j, held row j's, at Y + j n; a chord step: the
     * last), lh = Y^T q - w_H (w_H = Z_H^T y + c_H), S = Y^T Y factored */
#ifdef SC_SMALL_FMA
    if (fused && !fresh) sc_primal_fwd(Lt, t, grad, q); /* (the FMA copy: by L's columns) */
#endif
    for (i = 0; i < n && !solved && !fused; ++i) {
      const double *restrict ri = R + i * n;
      double s0 = grad[i], s1 = 0.0;
      for (k = 0; k + 1 < i; k += 2) {
        s0 -= ri[k] * q[k];
        s1 -= ri[k + 1] * q[k + 1];
      }
      if (k < i) s0 -= ri[k] * q[k];
      q[i] = (s0 + s1) * t[i];
    }
    for (j = 0; j < h && (!fresh || fused); ++j) {
      const double *restrict yj = Y + j * n, *restrict zj = Zc + (2 * ns + j) * n;
      double u = -cg[2 * ns + j];
#ifdef SC_SMALL_FMA
      if (fresh) { /* (the FMA copy: Y's column by L's columns, S's row) */
        sc_primal_fwd(Lt, t, zj, Y + j * n);
        for (k = 0; k <= j; ++k) S[j * h + k] = sc_primal_dot(yj, Y + k * n, NULL, NULL);
      }
      if (fused) {
        lh[j] = u + sc_primal_dot(yj, q, zj, y);
        continue;
      }
#endif
      for (i = 0; i < n; ++i) u += yj[i] * q[i] - zj[i] * y[i];
      lh[j] = u;
    }
    for (j = 0; j + 1 < h && fresh && !fused; j += 2) { /* (two columns side by side) */
      held_cols(n, 2, R, t, Zc + (2 * ns + j) * n, cg + 2 * ns + j, y, q, Y + j * n, lh + j);
      for (k = 0; k <= j; ++k) S[j * h + k] = sc_dot(Y + j * n, Y + k * n, n);
      for (k = 0; k <= j + 1; ++k) S[(j + 1) * h + k] = sc_dot(Y + (j + 1) * n, Y + k * n, n);
    }
    for (; j < h && fresh && !fused; ++j) {
      held_cols(n, 1, R, t, Zc + (2 * ns + j) * n, cg + 2 * ns + j, y, q, Y + j * n, lh + j);
      for (k = 0; k <= j; ++k) S[j * h + k] = sc_dot(Y + j * n, Y + k * n, n);
    }
    if (h > 0) {
      for (j = 0; j < h; ++j) bh[j] = lh[j];
      if (fresh) rank = sc_psd_solve(h, S, h, bh, PRIMAL_DEP, lh, wt, perm); /* (basic) */
      else sc_psd_resolve(h, S, h, rank, perm, 1, bh, lh, wt);
    }
    /* dy = R^-T (Y lam_H - q) */
    for (i = 0; i < n; ++i) dy[i] = -q[i];
    for (j = 0; j < h; ++j) {
      const double *restrict yj = Y + j * n, l = lh[j];
      for (i = 0; i < n; ++i) dy[i] += yj[i] * l;
    }
#ifdef SC_SMALL_FMA
    if (fused) sc_primal_back(R, t, dy);
#endif
    for (i = n - 1; i >= 0 && !fused; --i) { /* (by R's rows: contiguous, vectorised) */
      const double *restrict ri = R + i * n;
      double *restrict d = dy, di = dy[i] * t[i];
      d[i] = di;
      for (k = 0; k < i; ++k) d[k] -= ri[k] * di;
    }
    for (i = 0; i < n; ++i) {
      step = sc_max(step, fabs(dy[i]));
      ymax = sc_max(ymax, fabs(y[i]));
    }
    step /= ymax;
    if (!(step <= 1e-15)) { /* the step, halved while the objective rises (from a feasible
      point: the first step also brings the held rows to w_H = 0) */
      double v0 = v, d0 = dsq, d1 = 0.0, vt, *swap;
      for (;;) {
        for (i = 0; i < n; ++i) yt[i] = y[i] + tstep * dy[i];
        d1 = 0.0;
        for (i = 0; i < n; ++i) d1 += (yt[i] - gF[i]) * (yt[i] - gF[i]);
        vt = sliding(n, lds, ns, rad, Zs, cs, yt, ws, nws, fused);
        big = 1e-14 * (fabs(0.5 * d0 + v0) + p->fscale * p->wscale);
        if (!feasible || 0.5 * d1 + vt <= 0.5 * d0 + v0 + big || tstep < 1e-3) break;
        tstep *= 0.5;
      }
      if (tstep < 1e-3) return 0;
      swap = y, y = yt, yt = swap;
      v = vt;
      dsq = d1;
    }
    /* converged where the next step falls below rounding: after a Newton step quadratic in
     * this full one (its constant from the last two, at least 1), after a chord step this
     * one times its rate from the last two (at least this one; none after a halved step):
     * y and (the Newton pair) lam_H to rounding */
    if (tstep == 1.0 &&
        step * (fresh ? step * sc_max(1.0, it > 0 ? step / (prev * prev) : 1.0)
                      : sc_max(isfinite(prev) ? step / prev : 1.0, step)) <= 1e-16) {
      ok = 1;
      break;
    }
    if (it >= 1 && !(step <= 1e-4)) return 0; /* not yet quadratic after two steps (a time
      step's second is 1e-13 to 1e-5 of y): a start too far for the primal to pay (a forward
      neighbour's on the indeterminate scene took 4-10 steps), the dual path's */
    /* the next step a chord step on this factor (the Hessian, Y and Y^T Y's) where this step
     * was full and, if a chord step, contracted by a tenth at least; else a Newton step */
    fresh = !(tstep == 1.0 && (fresh || step <= 0.1 * prev));
    prev = tstep == 1.0 ? step : INFINITY;
  }
  if (!ok) return 0;
  /* the forces: held, the multipliers; sliding discs, -s w / |w| at the last point */
  for (j = 0; j < h; ++j) p->lam[hr[j]] = lh[j];
  for (j = 0; j < ns; ++j) {
    double w0 = ws[2 * j], w1 = ws[2 * j + 1], nw = nws[j];
    if (!(nw > TOL_ACCEPT * p->wscale)) return 0;
    p->lam[sl[j]] = -rad[j] * w0 / nw;
    p->lam[sl[j] + 1] = -rad[j] * w1 / nw;
  }
  *def = h - rank;
  last_w(n, p, Z, Zc, c, y, ws, ns); /* (y: g + Z lam to the step's rounding) */
  /* the face: the held rows and every block's without acceleration (sliding at rounding's
   * speed, an open contact closing at none); where its rows are dependent, its forces the
   * minimum-norm ones (sc_min_norm_face's), kept where they are in their sets */
  for (k = 0, nf = h; k < nb; ++k)
    if (p->state[k] != S_HELD && sc_still(p, k))
      for (i = 0; i < sc_block_size(p->kind[k]); ++i) hr[nf++] = p->start[k] + i;
  if (rank < h && nf > h && FACE_RANK(p, Z, hr, h, R, q, dy, t, perm, Y, 0) != rank)
    return 0; /* (the held rows' rank: the dual's, to the pivots') */
  if (rank < h || nf > h) {
    sc_int rf = FACE_RANK(p, Z, hr, nf, R, q, dy, t, perm, Y, 1);
    if (nf == h && rf != rank) return 0;
    if (rf < nf) {
      dep = 1;
      for (k = 0; k < nb; ++k)
        if ((p->state[k] == S_HELD || sc_still(p, k)) &&
            !sc_in_set(p, k, p->lam + p->start[k], 1e-13, 1))
          return 0;
    }
  }
  for (k = 0; k < nb; ++k) /* a contact's force below zero by rounding: zero (the dual's) */
    if (p->kind[k] == K_UNILATERAL && p->lam[p->start[k]] < 0) {
      if (!(p->lam[p->start[k]] >= -TOL_ACCEPT * p->fscale)) return 0;
      p->lam[p->start[k]] = 0.0;
      again = 1;
    }
  if (again || dep) every_w(n, p, Z, g, c, y);
  memcpy(work, y, sizeof(double) * (size_t)n); /* (y, for the accelerations) */
  return 1 + dep;
}

#if defined(__x86_64__) && !defined(__clang__) && __GNUC__ >= 6 && !defined(SC_NO_AVX)
#define PRIMAL_AVX 1
/* the snake's copy with AVX where the processor has it (no FMA: each lane's operations the
 * same, bit for bit) */
__attribute__((target("avx"), noinline)) static int piece_avx(sc_problem *p, const double *Z,
                                                              const double *g, const double *c,
                                                              double *work, sc_int *iwork,
                                                              sc_int *def) {
  return piece(SNAKECG_NS, p, Z, g, c, work, iwork, def, 0);
}
#ifdef SC_SMALL_FMA
/* the snake's copy with AVX2 and FMA where the processor has both: the compiler fuses the
 * products into the sums (the default contraction of GNU C) and the Hessian's factor is
 * sc_small_factor_fma's (reciprocals): within rounding of the copies without, not bit for bit */
__attribute__((target("avx2,fma"), noinline)) static int piece_fma(sc_problem *p,
                                                                   const double *Z,
                                                                   const double *g,
                                                                   const double *c,
                                                                   double *work, sc_int *iwork,
                                                                   sc_int *def) {
  return piece(SNAKECG_NS, p, Z, g, c, work, iwork, def, 1);
}
#endif
#endif

/* sc_primal_piece's body, compiled apart for the snake alone (n = SNAKECG_NS coordinates, no
 * object: the pegs row's 13) with the size a constant: its loops unrolled, no remainders */
SC_INTERNAL int sc_primal_piece(sc_problem *p, const double *Z, const double *g,
                                const double *c, double *work, sc_int *iwork, sc_int *def) {
#ifdef PRIMAL_AVX
#ifdef SC_SMALL_FMA
  if (p->n == SNAKECG_NS && primal_on == 1 && __builtin_cpu_supports("avx2") &&
      __builtin_cpu_supports("fma"))
    return piece_fma(p, Z, g, c, work, iwork, def);
#endif
  if (p->n == SNAKECG_NS && primal_on != 2 && __builtin_cpu_supports("avx"))
    return piece_avx(p, Z, g, c, work, iwork, def);
#endif
  if (p->n == SNAKECG_NS) return piece(SNAKECG_NS, p, Z, g, c, work, iwork, def, 0);
  return piece(p->n, p, Z, g, c, work, iwork, def, 0);
}
