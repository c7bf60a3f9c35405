/* snakecg's engine: a Coulomb family of forces at a contact-friction solution (scene_family.c),
 * for scene_friction.c. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_FAMILY_H
#define SNAKECG_ENGINE_SCENE_FAMILY_H

/* A solution of the contact-friction solve: its mt rows (m the convex solve's, then the nt
 * contacts' tangent rows), nb blocks (contact k's normal block k, row rn[k]; its tangent row
 * m + k), the sets (kind, start, par), the contacts' coefficients mu, G = A M^-1 A^T (mt x mt),
 * the rows' accelerations w, the forces' scale F and the
 * accelerations' W. */
typedef struct {
  sc_int mt, nb, nt, m;
  const sc_int *kind, *start, *rn;
  const double *par, *mu, *G, *w;
  double F, W;
} sc_family;

/* The rank defect of Coulomb's piece at the forces lam (0: they are the only ones with these
 * accelerations; -1: out of memory). Where it is positive, the family's minimum-norm member
 * replaces lam with *chosen 1; *chosen 0 where it was not found (lam stays). */
SC_INTERNAL sc_int sc_coulomb_family(const sc_family *c, double *lam, int *chosen);
#endif
