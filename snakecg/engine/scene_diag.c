/* snakecg's engine: the general solve's G diagonal and b = Z^T g at a warm start (scene_solve.c's
 * primal start: the force and acceleration scales before the primal piece), summed as
 * scene_small.c's Gram loop sums them, compiled for the snake's size and for any. */
#include <stddef.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_diag.h"

#if defined(__GNUC__)
#define SOLVE_FLAT static inline __attribute__((always_inline))
#else
#define SOLVE_FLAT static inline
#endif

/* G's diagonal d and Z^T g (e) as G's own loop sums them (scene_small.c's gram: the
 * coordinates four at a time, the last n mod 4 one short group: bit for bit the same). */
SOLVE_FLAT void diag_b(sc_int n, sc_int m, const double *Z, const double *g,
                       double *restrict d, double *restrict e) {
  const sc_int n4 = n - n % 4;
  sc_int i, j;
  if (n4 == 0)
    for (j = 0; j < m; ++j) d[j] = e[j] = 0.0;
  else { /* (the first four: 0.0 + their sums, as when added to zeros, without the zeros) */
    const double *restrict z0 = Z, *restrict z1 = z0 + m, *restrict z2 = z1 + m,
                 *restrict z3 = z2 + m;
    const double a0 = g[0], a1 = g[1], a2 = g[2], a3 = g[3];
    for (j = 0; j < m; ++j) {
      d[j] = 0.0 + ((z0[j] * z0[j] + z1[j] * z1[j]) + (z2[j] * z2[j] + z3[j] * z3[j]));
      e[j] = 0.0 + ((z0[j] * a0 + z1[j] * a1) + (z2[j] * a2 + z3[j] * a3));
    }
  }
  for (i = 4; i < n4; i += 4) {
    const double *restrict z0 = Z + i * m, *restrict z1 = z0 + m, *restrict z2 = z1 + m,
                 *restrict z3 = z2 + m;
    const double a0 = g[i], a1 = g[i + 1], a2 = g[i + 2], a3 = g[i + 3];
    for (j = 0; j < m; ++j) {
      d[j] += (z0[j] * z0[j] + z1[j] * z1[j]) + (z2[j] * z2[j] + z3[j] * z3[j]);
      e[j] += (z0[j] * a0 + z1[j] * a1) + (z2[j] * a2 + z3[j] * a3);
    }
  }
  if (n - n4 == 1) {
    const double *restrict z0 = Z + n4 * m;
    const double a0 = g[n4];
    for (j = 0; j < m; ++j) {
      d[j] += z0[j] * z0[j];
      e[j] += z0[j] * a0;
    }
  } else if (n - n4 == 2) {
    const double *restrict z0 = Z + n4 * m, *restrict z1 = z0 + m;
    const double a0 = g[n4], a1 = g[n4 + 1];
    for (j = 0; j < m; ++j) {
      d[j] += z0[j] * z0[j] + z1[j] * z1[j];
      e[j] += z0[j] * a0 + z1[j] * a1;
    }
  } else if (n - n4 == 3) {
    const double *restrict z0 = Z + n4 * m, *restrict z1 = z0 + m, *restrict z2 = z1 + m;
    const double a0 = g[n4], a1 = g[n4 + 1], a2 = g[n4 + 2];
    for (j = 0; j < m; ++j) {
      d[j] += (z0[j] * z0[j] + z1[j] * z1[j]) + z2[j] * z2[j];
      e[j] += (z0[j] * a0 + z1[j] * a1) + z2[j] * a2;
    }
  }
}

/* d = G's diagonal, e = Z^T g (Z: n x m row-major), G's own sums; the snake's size a constant
 * (its loops unrolled). (A copy with AVX, four doubles wide, measured slower by the clock:
 * 180.3-181.1 against 181.2-182.9 simulated s per CPU s, 4 pairs, load 3.5.) */
SC_INTERNAL void sc_diag_b(sc_int n, sc_int m, const double *Z, const double *g, double *d,
                           double *e) {
  if (n == SNAKECG_NS) diag_b(SNAKECG_NS, m, Z, g, d, e);
  else diag_b(n, m, Z, g, d, e);
}
