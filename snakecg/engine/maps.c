/* snakecg's engine: the linear maps at rest of one configuration, for any row state, from
 * the generated contact_system with the object placed (the function the forward solve calls),
 * for the optimal-torque queries (optimal.c, wheel_states.c).
 *
 * This file is part of the runtime (not generated); like forward.c it is compiled once per
 * model into the model's shared library.
 *
 * At rest (v = 0, no external wrench) the rows' accelerations at lam = 0 are linear in tau:
 * b = A_s M_s^-1 B tau = Kq^T B tau with Kq = M_s^-1 A_s^T (eq. 18; B selects the joint
 * coordinates, the last n_a of q). With the rows H held and the others F fixed (0, or +-u_i for
 * a sliding wheel), G_HH lam_H = -(b_H + G_HF lam_F) (eq. 16) gives lam = L tau + l0 (eq. 17);
 * then w = G_c lam + b, qdd = (M_s^-1 B + Kq L) tau + Kq l0 (eq. 22), a_obj = Ka lam (eq. 24),
 * Xi = Q^T M_s Q as a form in z = (tau, 1) (eq. 28), Omega = A^T I_obj A (eq. 29) and the input
 * metric N = B^T M_s^-1 B (eq. 31). The same maps as the generated interaction_maps (to
 * rounding), from the code the forward check runs anyway. G_HH is factored by the forward
 * solve's own sc_held_forces (L D L^T in row order, no pivoting); its pivot ratio
 * min_j d_j / G_jj is interaction_maps' pivot_ratio.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
struct sc_rest_work {
  sc_work_t ws;
};

/* the work arrays of contact_system (at rest or not), or null when out of memory */
sc_rest_work *sc_rest_work_new(void) {
  const sc_work_fn fns[] = {SC_CS_WORKS};
  sc_rest_work *w = (sc_rest_work *)malloc(sizeof(sc_rest_work));
  if (w && sc_work_alloc(&w->ws, fns, SC_COUNT(fns))) {
    free(w);
    w = 0;
  }
  return w;
}

void sc_rest_work_free(sc_rest_work *w) {
  if (!w) return;
  sc_work_free(&w->ws);
  free(w);
}

/* contact_system at rest at q, the object placed, and M_s^-1 B, N. Returns 0; 1 when the
 * generated call fails; 2 when M_s is not positive definite. */
int sc_rest_system(sc_rest_work *ws, const double *scene, const double *q, sc_rest *rest) {
  static const double zero[NS + 3] = {0.0};
  sc_system sys;
  double Mc[NS * NS], e[NS];
  sc_int i, j;
  if (sc_contact_system(&ws->ws, scene, q, zero, zero, 0, zero, zero, 0, &sys)) return 1;
  memcpy(rest->M, sys.M, sizeof rest->M);
  memcpy(rest->G, sys.G, sizeof rest->G);
  memcpy(rest->Kq, sys.Kq, sizeof rest->Kq);
  memcpy(rest->Ka, sys.Ka, sizeof rest->Ka);
  memcpy(Mc, sys.M, sizeof Mc); /* symmetric: column-major is row-major */
  if (!sc_cholesky(NS, Mc, NS, 0.0)) return 2;
  for (j = 0; j < NA; ++j) {
    for (i = 0; i < NS; ++i) e[i] = (i == NS - NA + j) ? 1.0 : 0.0;
    sc_cholesky_solve(NS, Mc, NS, e);
    for (i = 0; i < NS; ++i) rest->MB[i * NA + j] = e[i];
  }
  for (i = 0; i < NA; ++i)
    for (j = 0; j < NA; ++j) rest->N[i * NA + j] = rest->MB[(NS - NA + i) * NA + j];
  return 0;
}

/* The maps of the row states `state` (solver codes: HELD, SLIDE_POS, SLIDE_NEG, ABSENT, LOST)
 * into mp; Omega too when with_omega. Returns the pivot ratio (0 when G_HH is not positive
 * definite: the maps are then not filled). */
double sc_state_maps(const sc_rest *rest, const double *scene, const signed char *state,
                     int with_omega, sc_affine_maps *mp) {
  const double *G = rest->G, *Kq = rest->Kq, *Ka = rest->Ka, *M = rest->M;
  const double *bounds = scene + SCENE_bounds;
  double b[NC], lam[NC], MQ[NS * NA1], ratio, Io[3];
  signed char unforced[NC];
  sc_int i, j, r, c;
  /* lam = l0 at tau = 0 (b = 0: the sliding wheels' forces alone), then a column per joint
   * (b_j = Kq^T e_j on the rows) with the sliding rows' forces at 0, by the forward solve's
   * own factorization of the held rows (contact.c sc_held_forces) */
  for (r = 0; r < NC; ++r) {
    b[r] = 0.0;
    unforced[r] = (state[r] == SLIDE_POS || state[r] == SLIDE_NEG) ? LOST : state[r];
  }
  ratio = sc_held_forces(state, G, b, bounds, 0, mp->l0);
  mp->pivot_ratio = ratio > 0 ? ratio : 0.0;
  if (!(ratio > 0)) return mp->pivot_ratio;
  for (j = 0; j < NA; ++j) {
    for (r = 0; r < NC; ++r) b[r] = Kq[(NS - NA + j) + NS * r];
    sc_held_forces(unforced, G, b, bounds, 0, lam);
    for (r = 0; r < NC; ++r) mp->L[r * NA + j] = lam[r];
  }
  /* w = G lam + b, qdd = M^-1 B tau + Kq lam, a_obj = Ka lam */
  for (r = 0; r < NC; ++r) {
    for (j = 0; j < NA; ++j) {
      double t = Kq[(NS - NA + j) + NS * r];
      for (c = 0; c < NC; ++c) t += G[r + NC * c] * mp->L[c * NA + j];
      mp->W[r * NA + j] = t;
    }
    mp->w0[r] = 0.0;
    for (c = 0; c < NC; ++c) mp->w0[r] += G[r + NC * c] * mp->l0[c];
  }
  for (i = 0; i < NS; ++i) {
    for (j = 0; j < NA; ++j) {
      double t = rest->MB[i * NA + j];
      for (r = 0; r < NC; ++r) t += Kq[i + NS * r] * mp->L[r * NA + j];
      mp->Q[i * NA + j] = t;
    }
    mp->q0[i] = 0.0;
    for (r = 0; r < NC; ++r) mp->q0[i] += Kq[i + NS * r] * mp->l0[r];
  }
  for (i = 0; i < 3; ++i) {
    for (j = 0; j < NA; ++j) {
      double t = 0.0;
      for (r = 0; r < NC; ++r) t += Ka[i + 3 * r] * mp->L[r * NA + j];
      mp->A[i * NA + j] = t;
    }
    mp->a0[i] = 0.0;
    for (r = 0; r < NC; ++r) mp->a0[i] += Ka[i + 3 * r] * mp->l0[r];
  }
  /* Xi_h = [Q q0]^T M_s [Q q0] (eq. 28 on z = (tau, 1)) */
  for (i = 0; i < NS; ++i)
    for (j = 0; j <= NA; ++j) {
      double t = 0.0;
      for (r = 0; r < NS; ++r) t += M[i + NS * r] * (j < NA ? mp->Q[r * NA + j] : mp->q0[r]);
      MQ[i * NA1 + j] = t;
    }
  for (i = 0; i <= NA; ++i)
    for (j = 0; j <= NA; ++j) {
      double t = 0.0;
      for (r = 0; r < NS; ++r) t += (i < NA ? mp->Q[r * NA + i] : mp->q0[r]) * MQ[r * NA1 + j];
      mp->Xih[i * NA1 + j] = t;
    }
  if (with_omega) { /* Omega = A^T I_obj A (eq. 29) */
    Io[0] = Io[1] = scene[SCENE_object_mass];
    Io[2] = scene[SCENE_object_inertia];
    for (i = 0; i < NA; ++i)
      for (j = 0; j < NA; ++j) {
        double t = 0.0;
        for (r = 0; r < 3; ++r) t += mp->A[r * NA + i] * Io[r] * mp->A[r * NA + j];
        mp->Om[i * NA + j] = t;
      }
  }
  return ratio;
}

/* The maps of one configuration and row state alone, for tests: state holds NC solver codes
 * (as doubles); out receives L, l0, W, w0, Q, q0, A, a0, Xi_h, Omega, N (row-major, in that
 * order) and the pivot ratio. Returns 0; 1 when the generated call fails; 2 when M_s is not
 * positive definite; 3 when G_HH is not; -1 when out of memory. */
int SNAKECG_EXPORT(core_state_maps)(const double *scene, const double *q, const double *state,
                                    double *out) {
  sc_rest_work *ws = sc_rest_work_new();
  sc_rest rest;
  sc_affine_maps mp;
  signed char st[NC];
  int status, r;
  double *o = out;
  memset(&mp, 0, sizeof mp);
  for (r = 0; r < NC; ++r) st[r] = (signed char)state[r];
  if (!ws) return -1;
  status = sc_rest_system(ws, scene, q, &rest);
  sc_rest_work_free(ws);
  if (status) return status;
  if (!(sc_state_maps(&rest, scene, st, 1, &mp) > 0)) status = 3;
#define SC_PUT(src, count) (memcpy(o, (src), sizeof(double) * (count)), o += (count))
  SC_PUT(mp.L, NC * NA);
  SC_PUT(mp.l0, NC);
  SC_PUT(mp.W, NC * NA);
  SC_PUT(mp.w0, NC);
  SC_PUT(mp.Q, NS * NA);
  SC_PUT(mp.q0, NS);
  SC_PUT(mp.A, 3 * NA);
  SC_PUT(mp.a0, 3);
  SC_PUT(mp.Xih, NA1 * NA1);
  SC_PUT(mp.Om, NA * NA);
  SC_PUT(rest.N, NA * NA);
#undef SC_PUT
  *o = mp.pivot_ratio;
  return status;
}
