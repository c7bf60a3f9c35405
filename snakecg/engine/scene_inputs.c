/* snakecg's engine: a general scene's batch inputs checked before any work (scene_rows.c's
 * forward refuses a call with a sample not finite and names the first). Every entry is tested
 * by its bits, a row of contiguous samples as one run of integer operations (no branch per
 * entry; vectorized), and only where one is not finite are the samples scanned one by one. */
#include <stdint.h>
#include <string.h>
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_inputs.h"

/* 1 where every entry of n rows of w values (stride apart; 0: one row) is finite: an entry's
 * exponent bits are all set exactly where it is infinite or NaN, and then (its exponent) +
 * 2^52 carries into bit 63; the sums' bits gathered by or. */
static int finite_rows(const double *x, sc_int n, sc_int stride, sc_int w) {
  const uint64_t e = 0x7ff0000000000000ull, one = 0x0010000000000000ull;
  uint64_t bad = 0, u;
  sc_int i, j;
  if (stride == w) w *= n, n = n > 0; /* contiguous rows: one run */
  else if (stride == 0) n = n > 0;
  for (i = 0; i < n; ++i, x += stride)
    for (j = 0; j < w; ++j) {
      memcpy(&u, x + j, sizeof u);
      bad |= (u & e) + one;
    }
  return !(bad >> 63);
}

SC_INTERNAL sc_int sc_inputs_bad(sc_int n, const double *q, sc_int sq, const double *tau,
                                 sc_int st, const double *fo, sc_int sf, sc_int no3) {
  sc_int i, j;
  if (finite_rows(q, n, sq, SNAKECG_NS) && finite_rows(tau, n, st, SNAKECG_NA) &&
      finite_rows(fo, n, sf, no3))
    return -1;
  for (i = 0; i < n; ++i) { /* the first sample with one not finite */
    int ok = 1;
    for (j = 0; j < SNAKECG_NS; ++j) ok &= isfinite(q[i * sq + j]) != 0;
    for (j = 0; j < SNAKECG_NA; ++j) ok &= isfinite(tau[i * st + j]) != 0;
    for (j = 0; j < no3; ++j) ok &= isfinite(fo[i * sf + j]) != 0;
    if (!ok) return i;
  }
  return -1;
}
