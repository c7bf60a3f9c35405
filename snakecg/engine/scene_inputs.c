/* snakecg's engine: a general scene's batch inputs checked before any work (scene_rows.c's
 * forward refuses a call with a sample not finite, with a force beyond FORCE_LIMIT or with its
 * base beyond POSITION_SPAN scene sizes, and names the first). Every entry is tested by its
 * bits, a row of contiguous samples as one run of integer operations (no branch per entry;
 * vectorized), and only where one may be bad are the samples scanned one by one. */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_inputs.h"

/* the torques' and the objects' wrenches' bound (snakecg.engine.rules.FORCE_LIMIT, the
 * paper's path's too): the norms are quadratic in the forces, beyond it they overflow */
#define FORCE_LIMIT 1e150
enum { EXP_INF = 2047, EXP_FORCE = 1023 + 498 }; /* exponent fields: not finite; 2^498,
  below FORCE_LIMIT (2^498 < 1e150 < 2^499): an entry from it on is checked one by one */

/* 1 where every entry of n rows of w values (stride apart; 0: one row) has an exponent field
 * below top: (its exponent) + 2048 - top carries into bit 63 exactly where it is not; the
 * sums' bits gathered by or (top EXP_INF: every entry finite). */
static int below_rows(const double *x, sc_int n, sc_int stride, sc_int w, uint64_t top) {
  const uint64_t e = 0x7ff0000000000000ull, k = (2048 - top) << 52;
  uint64_t bad = 0, u;
  sc_int i, j;
  if (stride == w) w *= n, n = n > 0; /* contiguous rows: one run */
  else if (stride == 0) n = n > 0;
  for (i = 0; i < n; ++i, x += stride)
    for (j = 0; j < w; ++j) {
      memcpy(&u, x + j, sizeof u);
      bad |= (u & e) + k;
    }
  return !(bad >> 63);
}

/* 1 where the base positions (q's first two entries) of n rows are within lim */
static int near_rows(const double *q, sc_int n, sc_int sq, double lim) {
  sc_int i, far = 0;
  if (sq == 0) n = n > 0;
  for (i = 0; i < n; ++i, q += sq) far |= !(fabs(q[0]) <= lim) | !(fabs(q[1]) <= lim);
  return !far;
}

SC_INTERNAL sc_int sc_inputs_bad(sc_int n, const double *q, sc_int sq, const double *tau,
                                 sc_int st, const double *fo, sc_int sf, sc_int no3,
                                 double qlim) {
  sc_int i, j;
  if (below_rows(q, n, sq, SNAKECG_NS, EXP_INF) && near_rows(q, n, sq, qlim) &&
      below_rows(tau, n, st, SNAKECG_NA, EXP_FORCE) && below_rows(fo, n, sf, no3, EXP_FORCE))
    return -1;
  for (i = 0; i < n; ++i) { /* the first sample with one bad (NaN fails every comparison) */
    int ok = fabs(q[i * sq]) <= qlim && fabs(q[i * sq + 1]) <= qlim;
    for (j = 0; j < SNAKECG_NS; ++j) ok &= isfinite(q[i * sq + j]) != 0;
    for (j = 0; j < SNAKECG_NA; ++j) ok &= fabs(tau[i * st + j]) <= FORCE_LIMIT;
    for (j = 0; j < no3; ++j) ok &= fabs(fo[i * sf + j]) <= FORCE_LIMIT;
    if (!ok) return i;
  }
  return -1;
}
