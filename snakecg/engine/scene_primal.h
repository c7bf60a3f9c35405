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
#endif
