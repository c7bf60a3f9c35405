/* snakecg's engine: the broad phase of a general scene's contacts. A pair of bodies goes on to
 * the closest points (scene_geometry.c's sc_shape_closest) unless their bounding circles are
 * apart by more than twice the tolerance; scene_rows.c's contact_rows takes, once per
 * configuration, every moving body's bodies that may touch it as words of bits.
 *
 * The test is the one contact_rows made pair by pair, (dx^2 + dy^2 > far^2 with far =
 * (reach_a + reach_b + 2 tol)(1 + 1e-9)), the same operations in the same order (dx as
 * x_b - x_a: its square is the same), so that the pairs that go on are the same; here on the
 * circles laid out by coordinate (scene_broad.h), four pairs an operation (AVX) where the
 * processor has it, else two (SSE2, the x86-64 baseline; the pads after the last body, and
 * beyond 64 bodies the pairs from a multiple of the width on to the first wanted, tested and
 * dropped): the pegs row's 11 links among 10 pegs test 155 pairs a step, the paper's scene 7
 * a sample, all in one call.
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_broad.h"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

/* The bits of bodies [first, hi) apart from body ia's circle (its vx, vy, vr in every lane)
 * into apart, W pairs an operation (V: W doubles, unaligned; BITS(s, f2): the lanes where
 * s > f2 as bits); the bodies from first and the pads after them, bits beyond 63 dropped. */
#define SC_BROAD_RUN(V, W, BITS, first, hi)                                                 \
  for (ib = (first); ib < (hi); ib += (W)) {                                                \
    const V dx = *(const V *)(centre + ib) - vx, dy = *(const V *)(centre + pad + ib) - vy; \
    const V far = ((vr + *(const V *)(reach + ib)) + vt) * vw;                              \
    apart |= (uint64_t)(BITS(dx * dx + dy * dy, far * far)) << (ib & 63);                   \
  }
/* The bits of [lo, hi) not apart (NaN: not apart). */
#define SC_BROAD_NEAR(lo, hi, w)                                                            \
  ((lo) >= (hi) ? 0                                                                         \
                : ~apart & (~(uint64_t)0 << ((lo)&63)) & (~(uint64_t)0 >> (64 - ((hi)-64 * (w)))))
/* The masks of bodies ia < na against the bodies after them, for one instruction set (one
 * word: at most 64 bodies, the loop over words left out, the bodies from ib0 on). */
#define SC_BROAD_MASKS(V, W, BITS)                                                          \
  const sc_int nw = sc_broad_words(nbody), pad = sc_broad_pad(nbody);                      \
  const double tol2 = 2 * tol, widen = SC_BROAD_WIDEN;                                      \
  const V vt = tol2 - (V){0}, vw = widen - (V){0};                                          \
  sc_int ia, w, ib;                                                                         \
  for (ia = 0; ia < na; ++ia) {                                                             \
    const sc_int ib0 = ia + 1 + (ia + 1 < nl); /* (not the next link: its neighbour) */     \
    const V vx = centre[ia] - (V){0}, vy = centre[pad + ia] - (V){0},                      \
            vr = reach[ia] - (V){0};                                                        \
    uint64_t apart = 0;                                                                     \
    if (nw == 1) { /* (from ib0 on) */                                                      \
      SC_BROAD_RUN(V, W, BITS, ib0, nbody)                                                  \
      near[ia] = SC_BROAD_NEAR(ib0, nbody, 0);                                              \
      continue;                                                                             \
    }                                                                                       \
    for (w = 0; w < nw; ++w) {                                                              \
      const sc_int lo = 64 * w > ib0 ? 64 * w : ib0,                                        \
                   hi = 64 * w + 64 < nbody ? 64 * w + 64 : nbody;                          \
      apart = 0; /* (from a multiple of W: the word's bits) */                              \
      SC_BROAD_RUN(V, W, BITS, lo & ~(sc_int)((W) - 1), hi)                                 \
      near[ia * nw + w] = SC_BROAD_NEAR(lo, hi, w);                                         \
    }                                                                                       \
  }

#if defined(__SSE2__)
typedef double __attribute__((vector_size(16), aligned(8))) sc_b2;
#define SC_BITS2(s, f) _mm_movemask_pd(_mm_cmpgt_pd((__m128d)(s), (__m128d)(f)))
#if defined(__x86_64__) && !defined(__clang__) && __GNUC__ >= 6 && !defined(SC_NO_AVX)
#define SC_BROAD_AVX 1
typedef double __attribute__((vector_size(32), aligned(8))) sc_b4;
#define SC_BITS4(s, f) _mm256_movemask_pd(_mm256_cmp_pd((__m256d)(s), (__m256d)(f), _CMP_GT_OQ))
__attribute__((target("avx"), noinline)) static void masks_avx(
    const double *centre, const double *reach, double tol, sc_int na, sc_int nl, sc_int nbody,
    uint64_t *near) {
  SC_BROAD_MASKS(sc_b4, 4, SC_BITS4)
}
#endif
#else
typedef double sc_b1; /* (one pair at a time: the same operations) */
#define SC_BITS1(s, f) ((s) > (f))
#endif

SC_INTERNAL void sc_broad_masks(const double *centre, const double *reach, double tol,
                                sc_int na, sc_int nl, sc_int nbody, uint64_t *near) {
#if defined(SC_BROAD_AVX)
  if (__builtin_cpu_supports("avx")) {
    masks_avx(centre, reach, tol, na, nl, nbody, near);
    return;
  }
#endif
#if defined(__SSE2__)
  SC_BROAD_MASKS(sc_b2, 2, SC_BITS2)
#else
  SC_BROAD_MASKS(sc_b1, 1, SC_BITS1)
#endif
}

SC_INTERNAL sc_int sc_broad_pairs(const double *reach, double tol, sc_int na, sc_int nl,
                                  sc_int nbody, unsigned char (*pair)[2], double *far2) {
  const double tol2 = 2 * tol, widen = SC_BROAD_WIDEN;
  sc_int ia, ib, k = 0;
  for (ia = 0; ia < na; ++ia)
    for (ib = ia + 1 + (ia + 1 < nl); ib < nbody; ++ib, ++k) {
      const double far = ((reach[ia] + reach[ib]) + tol2) * widen;
      pair[k][0] = (unsigned char)ia, pair[k][1] = (unsigned char)ib;
      far2[k] = far * far;
    }
  return k;
}
