/* snakecg's engine: the broad phase of a general scene's contacts (scene_broad.c), used by
 * scene_rows.c's contact_rows. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_BROAD_H
#define SNAKECG_ENGINE_SCENE_BROAD_H

#include <stdint.h>

/* Bit k set: body ib = ib0 + k (ib0 <= ib < ib1 <= ib0 + 64) may touch body ia: their
 * bounding circles (centre, reach: 2 and 1 per body) are not apart by more than twice the
 * tolerance, (reach_a + reach_b + 2 tol)(1 + 1e-9) (a distance that is NaN is not apart). */
SC_INTERNAL uint64_t sc_broad_near(const double *centre, const double *reach, double tol,
                                   sc_int ia, sc_int ib0, sc_int ib1);

/* The bodies ib > ia that may touch ia, in order, 64 at a time (neighbouring links skipped):
 * sc_broad_first, then sc_broad_next until it returns -1. */
typedef struct { uint64_t near; sc_int base, next; } sc_broad;

static inline void sc_broad_first(sc_broad *it, sc_int ia, sc_int nl) {
  it->near = 0;
  it->base = it->next = ia + 1 + (ia + 1 < nl); /* (not the next link: its neighbour) */
}

static inline sc_int sc_broad_next(sc_broad *it, const double *centre, const double *reach,
                                   double tol, sc_int ia, sc_int nbody) {
  sc_int k;
  while (!it->near) {
    if (it->next >= nbody) return -1;
    it->base = it->next;
    it->next = it->base + 64 < nbody ? it->base + 64 : nbody;
    it->near = sc_broad_near(centre, reach, tol, ia, it->base, it->next);
  }
#if defined(__GNUC__)
  k = (sc_int)__builtin_ctzll(it->near);
#else
  for (k = 0; !((it->near >> k) & 1u); ++k) continue;
#endif
  it->near &= it->near - 1;
  return it->base + k;
}
#endif
