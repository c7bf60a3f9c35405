/* snakecg's engine: the broad phase of a general scene's contacts. A pair of bodies goes on to
 * the closest points (scene_geometry.c's sc_shape_closest) unless their bounding circles are
 * apart by more than twice the tolerance; scene_rows.c's contact_rows asks for the bodies
 * that may touch one body, 64 at a time, as bits.
 *
 * The test is the one contact_rows made pair by pair, (dx^2 + dy^2 > far^2 with far =
 * (reach_a + reach_b + 2 tol)(1 + 1e-9)), the same operations in the same order, so that the
 * pairs that go on are the same; here two pairs an operation (SSE2, the x86-64 baseline) where
 * the compiler has it: the pegs row's 11 links among 10 pegs test 146 pairs a step.
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_broad.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

SC_INTERNAL uint64_t sc_broad_near(const double *centre, const double *reach, double tol,
                                   sc_int ia, sc_int ib0, sc_int ib1) {
  const double xa = centre[2 * ia], ya = centre[2 * ia + 1], ra = reach[ia], tol2 = 2 * tol,
               widen = 1 + 1e-9;
  uint64_t apart = 0;
  sc_int ib = ib0;
#if defined(__SSE2__)
  const __m128d vx = _mm_set1_pd(xa), vy = _mm_set1_pd(ya), vr = _mm_set1_pd(ra),
                vt = _mm_set1_pd(tol2), vw = _mm_set1_pd(widen);
  for (; ib + 1 < ib1; ib += 2) {
    const __m128d c0 = _mm_loadu_pd(centre + 2 * ib), c1 = _mm_loadu_pd(centre + 2 * ib + 2);
    const __m128d dx = _mm_sub_pd(vx, _mm_unpacklo_pd(c0, c1)),
                  dy = _mm_sub_pd(vy, _mm_unpackhi_pd(c0, c1));
    const __m128d far = _mm_mul_pd(_mm_add_pd(_mm_add_pd(vr, _mm_loadu_pd(reach + ib)), vt), vw);
    const __m128d s = _mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy));
    apart |= (uint64_t)_mm_movemask_pd(_mm_cmpgt_pd(s, _mm_mul_pd(far, far))) << (ib - ib0);
  }
#endif
  for (; ib < ib1; ++ib) {
    const double dx = xa - centre[2 * ib], dy = ya - centre[2 * ib + 1],
                 far = (ra + reach[ib] + tol2) * widen;
    apart |= (uint64_t)(dx * dx + dy * dy > far * far) << (ib - ib0);
  }
  return ~apart & (ib1 - ib0 < 64 ? ((uint64_t)1 << (ib1 - ib0)) - 1 : ~(uint64_t)0);
}
