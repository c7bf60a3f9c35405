/* snakecg's engine: the broad phase of a general scene's contacts (scene_broad.c), used by
 * scene_rows.c's contact_rows. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_BROAD_H
#define SNAKECG_ENGINE_SCENE_BROAD_H

#include <stdint.h>

/* The words of bits per body of sc_broad_masks: one per 64 bodies. */
static inline sc_int sc_broad_words(sc_int nbody) { return (nbody + 63) / 64; }
/* The bounding circles' room per coordinate: 4 more than nbody, rounded up to a multiple of 4
 * (the pads after the last body are read, their bits dropped: any number, not left unset). */
static inline sc_int sc_broad_pad(sc_int nbody) { return (nbody + 7) & ~(sc_int)3; }

/* For every body ia < na, the bodies ib > ia (neighbouring links, ib = ia + 1 < nl, skipped)
 * that may touch it: their bounding circles are not apart by more than twice the tolerance,
 * (reach_a + reach_b + 2 tol)(1 + 1e-9) (a distance that is NaN is not apart). The circles:
 * centre the bodies' x, then from centre + sc_broad_pad(nbody) their y, reach their radii
 * (sc_broad_pad(nbody) each); body ib is bit ib % 64 of near[ia sc_broad_words(nbody) +
 * ib / 64]. */
SC_INTERNAL void sc_broad_masks(const double *centre, const double *reach, double tol,
                                sc_int na, sc_int nl, sc_int nbody, uint64_t *near);

/* The bodies up to which contact_rows tests the pairs one by one from a table made once
 * (sc_broad_pairs), without the masks: the paper's scene (4 links, a disc) tests 7 pairs a
 * sample, fewer operations than one call of sc_broad_masks, and its scalar loads read the
 * circles just stored by scalar stores (a vector load of them waits for the stores). */
/* a pair's far widened by this factor (both tests: the masks and the pairs' table) */
#define SC_BROAD_WIDEN (1 + 1e-9)

enum { SC_BROAD_FEW = 8, SC_BROAD_PAIRS = SC_BROAD_FEW * (SC_BROAD_FEW - 1) / 2 };

/* With nbody <= SC_BROAD_FEW, the pairs of sc_broad_masks in its order (ia < na, then ib)
 * into pair, and the square of each pair's far, (reach_a + reach_b + 2 tol)(1 + 1e-9), the
 * same operations, into far2: body ib's circle is apart from ia's where dx^2 + dy^2 > far2
 * (dx, dy as x_b - x_a: the same answer as the masks', NaN not apart). Their count. */
SC_INTERNAL sc_int sc_broad_pairs(const double *reach, double tol, sc_int na, sc_int nl,
                                  sc_int nbody, unsigned char (*pair)[2], double *far2);
/* A pair of that table (its bodies, its far2) not apart: the circles' centres at centre (the
 * bodies' x, then from centre + pad their y). */
static inline int sc_broad_near(const double *centre, sc_int pad, const unsigned char *pair,
                                double far2) {
  const double dx = centre[pair[1]] - centre[pair[0]],
               dy = centre[pad + pair[1]] - centre[pad + pair[0]];
  return !(dx * dx + dy * dy > far2);
}

/* The lowest body of a word of bits (not zero) at base, the bit cleared. */
static inline sc_int sc_broad_pop(uint64_t *bits, sc_int base) {
  sc_int k;
#if defined(__GNUC__)
  k = (sc_int)__builtin_ctzll(*bits);
#else
  for (k = 0; !((*bits >> k) & 1u); ++k) continue;
#endif
  *bits &= *bits - 1;
  return base + k;
}
#endif
