/* snakecg's engine: the primal piece's kernels for its FMA copy alone (scene_primal.c's
 * piece_fma: n = n_s, compiled with AVX2 and FMA; its rounding is its own). Included by
 * scene_primal.c after engine.h and scene_small.h, where SC_SMALL_FMA is defined. */
#ifndef SNAKECG_ENGINE_SCENE_PRIMAL_H
#define SNAKECG_ENGINE_SCENE_PRIMAL_H

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
