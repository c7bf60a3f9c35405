/* snakecg's runtime core, part 5: the all-held maps of one configuration at rest, from the
 * generated contact_system with the object placed (the function the forward solve calls), for the
 * optimal-torque query of optimal.c.
 *
 * This file is part of the runtime (not generated). Like forward.c it is compiled once per
 * model into the model's shared library.
 *
 * At rest (v = 0, no external wrench) the rows' accelerations at lam = 0 are linear in tau:
 * b = A_s M_s^-1 B tau = Kq^T B tau with Kq = M_s^-1 A_s^T (eq. 18; B selects the joint
 * coordinates, the last n_a of q). With every present row held, G_HH lam_H = -b_H (eq. 16)
 * gives lam = L tau (eq. 17); then qdd = (M_s^-1 B + Kq L) tau (eq. 22), a_obj = Ka L tau
 * (eq. 24), Xi = Q^T M_s Q (eq. 28), Omega = A^T I_obj A (eq. 29) and the input metric
 * N = B^T M_s^-1 B (eq. 31). The same maps as the generated interaction_maps, to rounding,
 * from the code the forward check runs anyway (one set of generated code to bring into the
 * caches instead of two). G_HH is factored by the forward solve's sc_held_forces (LDL^T in row
 * order, no pivoting); its pivot ratio min_j d_j / G_jj is interaction_maps' pivot_ratio.
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "common.h"

#define NA SNAKECG_NA

/* The maps at q, row-major into `maps`: L (NC x NA), A (3 x NA), Xi, Omega, N (NA x NA each),
 * then the pivot ratio. Returns 0; 1 when a generated call or an allocation fails; 2 when the
 * held rows are dependent (pivot ratio at or below pivot_tol) or M_s is not positive definite;
 * 3 when a map is not finite. */
int SNAKECG_EXPORT(core_held_maps)(const double *scene, const double *q, double pivot_tol,
                                   double *maps) {
  sc_work_t ws;
  const sc_work_fn fns[] = {SC_CS_WORKS};
  sc_system sys;
  const double zero[NS] = {0.0};
  const double *present = scene + SCENE_present;
  double Mc[NS * NS], MB[NS * NA], Q[NS * NA], MQ[NS * NA];
  double Lt[NC * NA], ratio = 1.0, Io[3];
  signed char state[NC];
  double *L = maps, *A = maps + NC * NA, *Xi = A + 3 * NA, *Om = Xi + NA * NA, *N = Om + NA * NA;
  int i, j, k, r, status;
  if (sc_work_alloc(&ws, fns, SC_COUNT(fns))) return 1;
  status = sc_contact_system(&ws, scene, q, zero, zero, 0, zero, zero, 0, &sys); /* placed */
  sc_work_free(&ws);
  if (status) return 1;
  /* lam = L tau: G_HH L_H = -(Kq^T B)_H column by column, the other rows 0 (Kq column-major
   * NS x NC), by the forward solve's own factorization */
  for (r = 0; r < NC; ++r) state[r] = present[r] != 0.0 ? HELD : ABSENT;
  for (j = 0; j < NA; ++j) {
    double b[NC], lam[NC];
    for (r = 0; r < NC; ++r) b[r] = sys.Kq[(NS - NA + j) + NS * r];
    ratio = sc_held_forces(state, sys.G, b, scene + SCENE_bounds, 0, lam);
    for (r = 0; r < NC; ++r) Lt[r * NA + j] = lam[r];
  }
  maps[NC * NA + 3 * NA + 3 * NA * NA] = ratio;
  if (!(ratio > pivot_tol)) return 2;
  /* M_s^-1 B by Cholesky (lower factor, column-major in Mc) */
  for (j = 0; j < NS; ++j) {
    double s = sys.M[j + NS * j];
    for (k = 0; k < j; ++k) s -= Mc[j + NS * k] * Mc[j + NS * k];
    if (!(s > 0)) return 2;
    s = sqrt(s);
    Mc[j + NS * j] = s;
    for (i = j + 1; i < NS; ++i) {
      double t = sys.M[i + NS * j];
      for (k = 0; k < j; ++k) t -= Mc[i + NS * k] * Mc[j + NS * k];
      Mc[i + NS * j] = t / s;
    }
  }
  for (j = 0; j < NA; ++j) {
    double y[NS];
    for (i = 0; i < NS; ++i) {
      double t = (i == NS - NA + j) ? 1.0 : 0.0;
      for (k = 0; k < i; ++k) t -= Mc[i + NS * k] * y[k];
      y[i] = t / Mc[i + NS * i];
    }
    for (i = NS - 1; i >= 0; --i) {
      double t = y[i];
      for (k = i + 1; k < NS; ++k) t -= Mc[k + NS * i] * y[k];
      y[i] = t / Mc[i + NS * i];
    }
    for (i = 0; i < NS; ++i) MB[i * NA + j] = y[i];
  }
  /* the maps */
  memcpy(L, Lt, sizeof Lt);
  for (i = 0; i < NS; ++i)
    for (j = 0; j < NA; ++j) {
      double t = MB[i * NA + j];
      for (r = 0; r < NC; ++r) t += sys.Kq[i + NS * r] * Lt[r * NA + j];
      Q[i * NA + j] = t;
    }
  for (i = 0; i < 3; ++i)
    for (j = 0; j < NA; ++j) {
      double t = 0.0;
      for (r = 0; r < NC; ++r) t += sys.Ka[i + 3 * r] * Lt[r * NA + j];
      A[i * NA + j] = t;
    }
  Io[0] = Io[1] = scene[SCENE_object_mass];
  Io[2] = scene[SCENE_object_inertia];
  for (k = 0; k < NS; ++k) /* M_s Q, for Xi = Q^T (M_s Q) */
    for (j = 0; j < NA; ++j) {
      double t = 0.0;
      for (r = 0; r < NS; ++r) t += sys.M[k + NS * r] * Q[r * NA + j];
      MQ[k * NA + j] = t;
    }
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) {
      double x = 0.0, o = 0.0;
      for (k = 0; k < NS; ++k) x += Q[k * NA + i] * MQ[k * NA + j];
      for (k = 0; k < 3; ++k) o += A[k * NA + i] * Io[k] * A[k * NA + j];
      Xi[i * NA + j] = x;
      Om[i * NA + j] = o;
      N[i * NA + j] = MB[(NS - NA + i) * NA + j];
    }
  for (i = 0; i < NC * NA + 3 * NA + 3 * NA * NA; ++i)
    if (!isfinite(maps[i])) return 3;
  return 0;
}
