/* snakecg's engine: the primal piece's kernels apart from its body (scene_primal.c): the
 * kernels of its FMA copy alone (piece_fma: n = n_s, compiled with AVX2 and FMA; its rounding
 * is its own), then the face's rank (every copy's). Included by scene_primal.c alone, after
 * engine.h, scene_sets.h and scene_small.h. */
#ifndef SNAKECG_ENGINE_SCENE_PRIMAL_H
#define SNAKECG_ENGINE_SCENE_PRIMAL_H

#ifdef SC_SMALL_FMA

/* four doubles, loaded and stored at any double's address */
typedef double __attribute__((vector_size(32), aligned(8))) sc_pv4;

/* The Hessian d I + T T^T's lower triangle (R, n_s x n_s row-major; its upper triangle not
 * written) from T's ns columns (column j at T + j n_s): row i's entries four at a time, each
 * quad's sum over the columns in order in one register (fused multiply-adds), the quad past
 * the diagonal stored entry by entry. T's last quad of a column is read past its n_s
 * entries (into the next column or T's room: its lanes past the row are never stored). */
__attribute__((always_inline)) static inline void sc_primal_hessian(sc_int ns, const double *T,
                                                                    double *R, double d) {
  enum { N = SNAKECG_NS, Q = (SNAKECG_NS + 3) / 4 };
  sc_int i, j, q;
  SC_UNROLL for (i = 0; i < N; ++i) {
    sc_pv4 acc[Q];
    SC_UNROLL for (q = 0; q <= i / 4; ++q) acc[q] = (sc_pv4){0.0, 0.0, 0.0, 0.0};
    for (j = 0; j < ns; ++j) {
      const double *tj = T + j * N, a = tj[i];
      SC_UNROLL for (q = 0; q <= i / 4; ++q) acc[q] += a * *(const sc_pv4 *)(tj + 4 * q);
    }
    SC_UNROLL for (q = 0; q < i / 4; ++q) *(sc_pv4 *)(R + i * N + 4 * q) = acc[q];
    SC_UNROLL for (q = 0; q <= i % 4; ++q) R[i * N + 4 * (i / 4) + q] = acc[i / 4][q];
    R[i * N + i] += d;
  }
}

/* x's n_s entries from four-double registers (the last quad's lanes past n_s not stored) */
#define PV4_STORE(x, v)                                                                     \
  do {                                                                                      \
    sc_int q_, e_;                                                                          \
    SC_UNROLL for (q_ = 0; q_ < SNAKECG_NS / 4; ++q_) *(sc_pv4 *)((x) + 4 * q_) = (v)[q_];  \
    SC_UNROLL for (e_ = 4 * (SNAKECG_NS / 4); e_ < SNAKECG_NS; ++e_)                      \
      (x)[e_] = (v)[e_ / 4][e_ % 4];                                                        \
  } while (0)

/* The objective's gradient y - g_F + sum_j s_j Z_j w_j / |w_j| over the ns sliding discs
 * (Zc: their column pairs, each n_s long; ws, nws: their w and |w|; rad: their s), in four
 * registers summed disc by disc; with T (a Newton step) also T's columns
 * sqrt(s_j / |w_j|) Z_j u_j^perp (each stored four entries at a time: the last quad's
 * lanes past n_s into the next column's room, overwritten by it, or T's room). y, g_F and
 * Zc are read past their n_s entries (lanes never stored). */
__attribute__((always_inline)) static inline void sc_primal_grad(
    sc_int ns, const double *y, const double *gF, const double *Zc, const double *rad,
    const double *ws, const double *nws, double *grad, double *T) {
  enum { N = SNAKECG_NS, Q = (SNAKECG_NS + 3) / 4 };
  sc_pv4 g[Q];
  sc_int j, q;
  SC_UNROLL for (q = 0; q < Q; ++q)
    g[q] = *(const sc_pv4 *)(y + 4 * q) - *(const sc_pv4 *)(gF + 4 * q);
  for (j = 0; j < ns; ++j) {
    const double *z0 = Zc + 2 * j * N, *z1 = z0 + N, w0 = ws[2 * j] / nws[j],
                 w1 = ws[2 * j + 1] / nws[j], r0 = rad[j] * w0, r1 = rad[j] * w1;
    if (T) {
      const double cj = sqrt(rad[j] / nws[j]), a0 = cj * w1, a1 = cj * w0;
      SC_UNROLL for (q = 0; q < Q; ++q)
        *(sc_pv4 *)(T + j * N + 4 * q) = a0 * *(const sc_pv4 *)(z0 + 4 * q) -
                                         a1 * *(const sc_pv4 *)(z1 + 4 * q);
    }
    SC_UNROLL for (q = 0; q < Q; ++q)
      g[q] += r0 * *(const sc_pv4 *)(z0 + 4 * q) + r1 * *(const sc_pv4 *)(z1 + 4 * q);
  }
  PV4_STORE(grad, g);
}

/* The sliding discs' column pairs of Z gathered (Zc: 2 ns columns of n_s, from Zs: their
 * rows one run, coordinate i's at Zs + i ld) by 4 x 4 blocks transposed in registers, and
 * the start y = g_F + sum_j (Z_j lam_j) (lam: the discs' forces, one run) in four
 * registers, disc by disc. g_F and Zc are read past their n_s entries (lanes never
 * stored). */
__attribute__((always_inline)) static inline void sc_primal_start(
    sc_int ns, const double *Zs, sc_int ld, const double *lam, const double *gF,
    double *restrict Zc, double *restrict y) {
  typedef long long __attribute__((vector_size(32))) sc_pl4;
  enum { N = SNAKECG_NS, Q = (SNAKECG_NS + 3) / 4 };
  sc_pv4 g[Q];
  sc_int i, j, q;
  for (j = 0; j + 3 < 2 * ns; j += 4) {
    SC_UNROLL for (i = 0; i + 3 < N; i += 4) {
      const sc_pv4 a = *(const sc_pv4 *)(Zs + i * ld + j),
                   b = *(const sc_pv4 *)(Zs + (i + 1) * ld + j),
                   c = *(const sc_pv4 *)(Zs + (i + 2) * ld + j),
                   d = *(const sc_pv4 *)(Zs + (i + 3) * ld + j);
      const sc_pv4 ab0 = __builtin_shuffle(a, b, (sc_pl4){0, 4, 2, 6}),
                   ab1 = __builtin_shuffle(a, b, (sc_pl4){1, 5, 3, 7}),
                   cd0 = __builtin_shuffle(c, d, (sc_pl4){0, 4, 2, 6}),
                   cd1 = __builtin_shuffle(c, d, (sc_pl4){1, 5, 3, 7});
      *(sc_pv4 *)(Zc + j * N + i) = __builtin_shuffle(ab0, cd0, (sc_pl4){0, 1, 4, 5});
      *(sc_pv4 *)(Zc + (j + 1) * N + i) = __builtin_shuffle(ab1, cd1, (sc_pl4){0, 1, 4, 5});
      *(sc_pv4 *)(Zc + (j + 2) * N + i) = __builtin_shuffle(ab0, cd0, (sc_pl4){2, 3, 6, 7});
      *(sc_pv4 *)(Zc + (j + 3) * N + i) = __builtin_shuffle(ab1, cd1, (sc_pl4){2, 3, 6, 7});
    }
    SC_UNROLL for (i = 4 * (N / 4); i < N; ++i)
      SC_UNROLL for (q = 0; q < 4; ++q) Zc[(j + q) * N + i] = Zs[i * ld + j + q];
  }
  for (; j < 2 * ns; ++j)
    SC_UNROLL for (i = 0; i < N; ++i) Zc[j * N + i] = Zs[i * ld + j];
  SC_UNROLL for (q = 0; q < Q; ++q) g[q] = *(const sc_pv4 *)(gF + 4 * q);
  for (j = 0; j < ns; ++j) {
    const double *z0 = Zc + 2 * j * N, *z1 = z0 + N, l0 = lam[2 * j], l1 = lam[2 * j + 1];
    SC_UNROLL for (q = 0; q < Q; ++q)
      g[q] += l0 * *(const sc_pv4 *)(z0 + 4 * q) + l1 * *(const sc_pv4 *)(z1 + 4 * q);
  }
  PV4_STORE(y, g);
}

/* x = R^-1 z by columns (Lt: R's columns, column i at Lt + i n_s from its diagonal on; t its
 * diagonal's reciprocals), z in four registers: x_i from the entries before it, then the
 * entries after it less column i times x_i (the quad of the diagonal masked to the entries
 * past it). z and Lt are read past their n_s entries (lanes never stored). */
__attribute__((always_inline)) static inline void sc_primal_fwd(const double *Lt, const double *t,
                                                                const double *z, double *x) {
  typedef long long __attribute__((vector_size(32))) sc_pl4;
  enum { N = SNAKECG_NS, Q = (SNAKECG_NS + 3) / 4 };
  static const sc_pl4 past[4] = {{0, -1, -1, -1}, {0, 0, -1, -1}, {0, 0, 0, -1}, {0, 0, 0, 0}};
  sc_pv4 d[Q];
  sc_int i, q;
  SC_UNROLL for (q = 0; q < Q; ++q) d[q] = *(const sc_pv4 *)(z + 4 * q);
  SC_UNROLL for (i = 0; i < N; ++i) {
    const double *li = Lt + i * N, xi = d[i / 4][i % 4] * t[i];
    d[i / 4][i % 4] = xi;
    if (i % 4 < 3 && i + 1 < N)
      d[i / 4] -= (sc_pv4)((sc_pl4) * (const sc_pv4 *)(li + 4 * (i / 4)) & past[i % 4]) * xi;
    SC_UNROLL for (q = i / 4 + 1; q < Q; ++q) d[q] -= *(const sc_pv4 *)(li + 4 * q) * xi;
  }
  PV4_STORE(x, d);
}

/* a^T b - c^T e over the n_s coordinates (c NULL: a^T b), four lanes' sums then the rest */
__attribute__((always_inline)) static inline double sc_primal_dot(const double *a,
                                                                  const double *b,
                                                                  const double *c,
                                                                  const double *e) {
  sc_pv4 s = {0.0, 0.0, 0.0, 0.0};
  double r;
  sc_int q, i;
  SC_UNROLL for (q = 0; q < SNAKECG_NS / 4; ++q) {
    s += *(const sc_pv4 *)(a + 4 * q) * *(const sc_pv4 *)(b + 4 * q);
    if (c) s -= *(const sc_pv4 *)(c + 4 * q) * *(const sc_pv4 *)(e + 4 * q);
  }
  r = (s[0] + s[1]) + (s[2] + s[3]);
  SC_UNROLL for (i = 4 * (SNAKECG_NS / 4); i < SNAKECG_NS; ++i)
    r += c ? a[i] * b[i] - c[i] * e[i] : a[i] * b[i];
  return r;
}

/* sliding's w_i = Z_i^T y + c_i, |w_i| and sum s_i |w_i| (scene_primal.c's, the same
 * arguments, n = n_s): four rows' sums (two discs') in one register over the coordinates,
 * the last pair of rows in half of one. */
__attribute__((always_inline)) static inline double sc_primal_sliding(
    sc_int ld, sc_int ns, const double *s, const double *Zs, const double *cs, const double *y,
    double *restrict ws, double *restrict nws) {
  typedef double __attribute__((vector_size(16), aligned(8))) sc_pv2;
  sc_int i, j;
  double v = 0.0;
  for (j = 0; j + 3 < 2 * ns; j += 4) {
    sc_pv4 w = *(const sc_pv4 *)(cs + j);
    SC_UNROLL for (i = 0; i < SNAKECG_NS; ++i) w += *(const sc_pv4 *)(Zs + i * ld + j) * y[i];
    *(sc_pv4 *)(ws + j) = w;
  }
  if (j < 2 * ns) {
    sc_pv2 w = *(const sc_pv2 *)(cs + j);
    SC_UNROLL for (i = 0; i < SNAKECG_NS; ++i) w += *(const sc_pv2 *)(Zs + i * ld + j) * y[i];
    *(sc_pv2 *)(ws + j) = w;
  }
  for (j = 0; j < ns; ++j) {
    nws[j] = sqrt(ws[2 * j] * ws[2 * j] + ws[2 * j + 1] * ws[2 * j + 1]);
    v += s[j] * nws[j];
  }
  return v;
}

/* dy = R^-T dy (R's lower triangle, t its diagonal's reciprocals), dy in four registers:
 * row i's entries before the diagonal (its quad past them masked to zeros) times dy_i taken
 * from the entries before it. dy is read past its n_s entries (lanes never stored). */
__attribute__((always_inline)) static inline void sc_primal_back(const double *R, const double *t,
                                                                 double *dy) {
  typedef long long __attribute__((vector_size(32))) sc_pl4;
  enum { N = SNAKECG_NS, Q = (SNAKECG_NS + 3) / 4 };
  static const sc_pl4 mask[4] = {{0, 0, 0, 0}, {-1, 0, 0, 0}, {-1, -1, 0, 0}, {-1, -1, -1, 0}};
  sc_pv4 d[Q];
  sc_int i, q;
  SC_UNROLL for (q = 0; q < Q; ++q) d[q] = *(const sc_pv4 *)(dy + 4 * q);
  SC_UNROLL for (i = N - 1; i >= 0; --i) {
    const double *ri = R + i * N, di = d[i / 4][i % 4] * t[i];
    d[i / 4][i % 4] = di;
    SC_UNROLL for (q = 0; q < i / 4; ++q) d[q] -= *(const sc_pv4 *)(ri + 4 * q) * di;
    if (i % 4)
      d[i / 4] -= (sc_pv4)((sc_pl4) * (const sc_pv4 *)(ri + 4 * (i / 4)) & mask[i % 4]) * di;
  }
  PV4_STORE(dy, d);
}
#endif

/* The rank of the rows F (nf of them) by K = Z_F Z_F^T (n x n: G_FF's nonzero eigenvalues),
 * its pivots above NULL_TOL of the first (sc_min_norm_face's rule); with apply and a rank
 * below nf, their forces made the minimum-norm ones of the same Z_F lam_F: Z_F^T x,
 * K x = Z_F lam_F. Scratch: K n x n, v, x, t n each, perm n, zf n nf (the rows' columns of
 * Z gathered: K and v summed row by row of F in its order, each entry's sum as a dot
 * product over F would add it; the FMA copy's: K by sc_primal_hessian's quads). */
PRIMAL_FLAT sc_int face_rank_in(sc_problem *p, const double *Z, const sc_int *F, sc_int nf,
                                double *K, double *v, double *x, double *t, sc_int *perm,
                                double *zf, int apply, const int fused) {
  const sc_int n = fused ? SNAKECG_NS : p->n, m = p->m;
  sc_int i, j, k, rank;
  for (j = 0; j < nf; ++j)
    for (i = 0; i < n; ++i) zf[j * n + i] = Z[i * m + F[j]];
#ifdef SC_SMALL_FMA
  if (fused) {
    sc_primal_hessian(nf, zf, K, 0.0);
    for (i = 0; i < n; ++i) v[i] = 0.0;
    for (j = 0; j < nf; ++j) {
      const double *restrict zj = zf + j * n, l = p->lam[F[j]];
      for (i = 0; i < n; ++i) v[i] += zj[i] * l;
    }
  }
#endif
  for (i = 0; i < n && !fused; ++i) {
    v[i] = 0.0;
    for (k = 0; k <= i; ++k) K[i * n + k] = 0.0;
  }
  for (j = 0; j < nf && !fused; ++j) {
    const double *restrict zj = zf + j * n, l = p->lam[F[j]];
    for (i = 0; i < n; ++i) {
      double *restrict ki = K + i * n;
      const double zi = zj[i];
      v[i] += zi * l;
      for (k = 0; k <= i; ++k) ki[k] += zi * zj[k];
    }
  }
  rank = sc_psd_solve(n, K, n, v, NULL_TOL, x, t, perm);
  if (apply && rank < nf)
    for (j = 0; j < nf; ++j) {
      double s = 0.0;
      for (i = 0; i < n; ++i) s += zf[j * n + i] * x[i];
      p->lam[F[j]] = s;
    }
  return rank;
}
static sc_int face_rank(sc_problem *p, const double *Z, const sc_int *F, sc_int nf, double *K,
                        double *v, double *x, double *t, sc_int *perm, double *zf,
                        int apply) {
  return face_rank_in(p, Z, F, nf, K, v, x, t, perm, zf, apply, 0);
}
#ifdef SC_SMALL_FMA
__attribute__((target("avx2,fma"), noinline)) static sc_int face_rank_fma(
    sc_problem *p, const double *Z, const sc_int *F, sc_int nf, double *K, double *v, double *x,
    double *t, sc_int *perm, double *zf, int apply) {
  return face_rank_in(p, Z, F, nf, K, v, x, t, perm, zf, apply, 1);
}
#define FACE_RANK(...) (fused ? face_rank_fma(__VA_ARGS__) : face_rank(__VA_ARGS__))
#else
#define FACE_RANK face_rank
#endif
#endif
