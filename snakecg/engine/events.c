/* snakecg's runtime core, part 3: what a simulation does at an event (or at its start), in C.
 *
 * This file is part of the runtime (not generated), compiled once per model into the model's
 * shared library like forward.c and integrate.c, with the header `snakecg_layout.h`.
 *
 * It computes what snakecg/simulate/events.py's Events.settle computes with the generated
 * functions called from Python (the reference; the two are held together by the tests):
 *   1. the rows' velocities A V and the tolerance vtol = 1e-8 max(1, max |V|);
 *   2. a contact that closes with a normal velocity (gdot < -vtol) takes a plastic impact:
 *      the positions projected onto g = 0 (up to three Newton steps along I^-1 A_c^T), then
 *      the velocities projected onto A_R V = 0 for the contact and the ideal wheels, the
 *      impulse Lam_R = -G_RR^-1 (A V)_R conserving momentum, the energy 1/2 Lam^T G_RR Lam
 *      lost; a contact that is moving apart (gdot > vtol) or not a candidate is lost;
 *   3. bounded wheels not sticking before (or after an impact) with a lateral velocity beyond
 *      vtol slide, against it;
 *   4. the remaining present rows (the candidates) projected the same way (their drift);
 *   5. the new active set: the primal-dual iteration of snakecg/solver.py (and forward.c) over
 *      the candidates at the acceleration level (eqs. 13, 14, 16), the forced rows fixed
 *      (a sliding wheel at its bound, a lost contact at zero force), then enumeration when
 *      it has not settled in max_iter passes (rows.c's sc_decide_states).
 * Dependent rows (pivot ratio at most pivot_tol) in a projection or a decision get rows.c's
 * Tikhonov term (least-norm impulses and forces; counted in nsingular). A failed evaluation
 * returns SETTLE_FAILED and writes nothing that the caller keeps.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
/* G, Q = [Kq; Ka], gap, s and A V at y. */
static int maps(sc_work_t *ws, const sc_settle *st, const double *y, sc_system *sys,
                double *av) {
  const double *q = y, *qo = y + NS, *v = y + NX, *vo = y + NX + NS;
  if (sc_contact_system(ws, st->scene, q, v, st->tau, qo, vo, st->f_obj, st->rho, sys))
    return 1;
  return sc_row_velocities(ws, st->scene, st->rho, (int)st->contact_index, st->c_k, q, v, qo,
                           vo, sys->s, av);
}

/* The kinetic energy of y with M_s of sys (Dynamics.kinetic_energy). */
static double kinetic_energy(const sc_settle *st, const sc_system *sys, const double *y) {
  const double *v = y + NX, *vo = y + NX + NS, m = st->scene[SCENE_object_mass];
  double e = 0.0;
  int i, j;
  for (j = 0; j < NS; ++j) {
    double t = 0.0;
    for (i = 0; i < NS; ++i) t += v[i] * sys->M[i + NS * j];
    e += t * v[j];
  }
  return 0.5 * e + 0.5 * (vo[0] * (m * vo[0]) + vo[1] * (m * vo[1]) +
                          vo[2] * (st->scene[SCENE_object_inertia] * vo[2]));
}

/* The constants of rows.c's rules that the settle uses. */
static sc_constants constants(const sc_settle *st) {
  sc_constants k;
  memset(&k, 0, sizeof(k));
  k.pivot_tol = st->pivot_tol;
  k.rel_tol = st->rel_tol;
  k.regularization = st->regularization;
  return k;
}

/* Dynamics.project: y projected (positions onto g = 0 first when `positions` and the contact
 * is among the m `rows`), the impulses Lam (m) and the kinetic-energy change: LU of G_RR, or
 * where the rows are dependent the least-norm impulses of the Tikhonov rule. 0, or 1. */
static int project(sc_work_t *ws, sc_settle *st, double *y, const int *rows, int m,
                   int positions, double *Lam, double *dE) {
  const sc_constants k = constants(st);
  sc_system sys;
  double av[NC], GF[NC * NC], lam[NC];
  signed char state[NC];
  sc_int piv[NC];
  int i, j, it, singular;
  if (positions && m > 0 && rows[0] == 0) {
    for (it = 0; it < 3; ++it) {
      if (maps(ws, st, y, &sys, av)) return 1;
      if (fabs(sys.gap) <= 1e-15 * fmax(1.0, st->l_k)) break;
      for (i = 0; i < NS; ++i) y[i] -= sys.Kq[i] * (sys.gap / sys.G[0]);
      for (i = 0; i < 3; ++i) y[NS + i] -= sys.Ka[i] * (sys.gap / sys.G[0]);
    }
  }
  if (maps(ws, st, y, &sys, av)) return 1;
  *dE = 0.0;
  if (m == 0) return 0;
  for (i = 0; i < NC; ++i) state[i] = ABSENT;
  for (i = 0; i < m; ++i) {
    for (j = 0; j < m; ++j) GF[i * m + j] = sys.G[rows[i] + NC * rows[j]];
    Lam[i] = av[rows[i]];
    state[rows[i]] = HELD;
  }
  memcpy(sys.b, av, sizeof(av)); /* G_RR Lam = -(A V)_R: the held rows' forces with b = A V */
  sc_delassus_state(&sys, &k, state, st->scene + SCENE_bounds, 0, lam, 0, &singular);
  if (!singular && sc_lu_factor(m, GF, m, piv)) { /* linalg.h: P A = L U */
    sc_lu_solve(m, GF, m, piv, Lam);
    for (i = 0; i < m; ++i) Lam[i] = -Lam[i];
  } else {
    for (i = 0; i < m; ++i) Lam[i] = lam[rows[i]];
    st->nsingular++;
  }
  for (i = 0; i < NS; ++i) {
    double t = 0.0;
    for (j = 0; j < m; ++j) t += sys.Kq[i + NS * rows[j]] * Lam[j];
    y[NX + i] += t;
  }
  for (i = 0; i < 3; ++i) {
    double t = 0.0;
    for (j = 0; j < m; ++j) t += sys.Ka[i + 3 * rows[j]] * Lam[j];
    y[NX + NS + i] += t;
  }
  {
    double e = 0.0;
    for (i = 0; i < m; ++i) {
      double t = 0.0;
      for (j = 0; j < m; ++j) t += sys.G[rows[i] + NC * rows[j]] * Lam[j];
      e += Lam[i] * t;
    }
    *dE = -0.5 * e;
  }
  return 0;
}

/* Events.decide: the active set over the candidates, the forced rows fixed (rows.c's
 * iteration, then enumeration; Tikhonov where the held rows are dependent). 0, or 1. */
static int decide(sc_work_t *ws, sc_settle *st, const double *y, const signed char *forced,
                  const double *bounds, const double *present, signed char *state) {
  const sc_constants k = constants(st);
  sc_system sys;
  double free[NC];
  int r, any = 0, singular;
  for (r = 0; r < NC; ++r) {
    state[r] = forced[r] >= 0 ? forced[r] : present[r] != 0.0 ? HELD : ABSENT;
    free[r] = forced[r] < 0 && present[r] != 0.0;
    if (free[r] != 0.0) any = 1;
  }
  if (!any) return 0;
  if (sc_contact_system(ws, st->scene, y, y + NX, st->tau, y + NS, y + NX + NS, st->f_obj,
                        st->rho, &sys))
    return 1;
  sc_decide_states(&sys, &k, bounds, free, (long)st->max_iter, state, &singular);
  st->nsingular += singular;
  return 0;
}

static int settle(sc_work_t *ws, sc_settle *st) {
  const double *bounds = st->scene + SCENE_bounds, *present = st->scene + SCENE_present;
  sc_system sys;
  double y[NY], av[NC], vtol = 0.0, lam[NC], dE;
  signed char forced[NC], held_before[NC], state[NC];
  int rows[NC], m, r, impact = 0, contact_in;
  memcpy(y, st->y, sizeof(y));
  for (r = 0; r < NC; ++r) {
    forced[r] = (signed char)(st->forced[r] >= 0 ? st->forced[r] : -1);
    held_before[r] = st->prev != 0 && st->prev[r] == HELD;
  }
  if (maps(ws, st, y, &sys, av)) return SETTLE_FAILED;
  for (r = 0; r < NX; ++r)
    if (fabs(y[NX + r]) > vtol) vtol = fabs(y[NX + r]);
  vtol = 1e-8 * fmax(1.0, vtol);
  st->vtol = vtol;
  contact_in = st->contact_candidate && forced[0] < 0;
  if (contact_in && !held_before[0] && av[0] < -vtol) { /* plastic impact */
    m = 0;
    rows[m++] = 0;
    for (r = 1; r < NC; ++r)
      if (present[r] != 0.0 && !isfinite(bounds[r])) rows[m++] = r;
    st->impact_velocity = av[0];
    st->impact_ke = kinetic_energy(st, &sys, y);
    if (project(ws, st, y, rows, m, 1, lam, &dE)) return SETTLE_FAILED;
    memcpy(st->impact_lam, lam, sizeof(double) * (size_t)m);
    st->n_impact = m;
    st->impact_de = dE;
    st->impact = impact = 1;
    if (maps(ws, st, y, &sys, av)) return SETTLE_FAILED;
  } else if (contact_in && !held_before[0] && av[0] > vtol) {
    forced[0] = LOST; /* already moving apart */
  } else if (!contact_in && forced[0] < 0) {
    forced[0] = LOST;
  }
  for (r = 1; r < NC; ++r) { /* bounded wheels that slide */
    if (!(present[r] != 0.0 && isfinite(bounds[r]))) continue;
    if (forced[r] >= 0 || (held_before[r] && !impact)) continue;
    if (fabs(av[r]) > vtol) forced[r] = av[r] < 0 ? SLIDE_POS : SLIDE_NEG;
  }
  m = 0;
  for (r = 0; r < NC; ++r)
    if (present[r] != 0.0 && forced[r] < 0) rows[m++] = r;
  if (m) { /* the candidates' drift */
    st->drift = -1.0;
    for (r = 0; r < m; ++r)
      if (fabs(av[rows[r]]) > st->drift) {
        st->drift = fabs(av[rows[r]]);
        st->drift_row = rows[r];
      }
    st->projection_ke = kinetic_energy(st, &sys, y);
    if (project(ws, st, y, rows, m, rows[0] == 0, lam, &dE)) return SETTLE_FAILED;
    memcpy(st->projection_lam, lam, sizeof(double) * (size_t)m);
    st->projection_de = dE;
  }
  st->n_projected = m;
  if (decide(ws, st, y, forced, bounds, present, state)) return SETTLE_FAILED;
  for (r = 0; r < NY; ++r) st->y_out[r] = y[r];
  for (r = 0; r < NC; ++r) {
    st->state[r] = (double)state[r];
    st->forced_out[r] = (double)forced[r];
  }
  return SETTLE_DONE;
}

/* Settle one event (see sc_settle); returns and stores the status (SETTLE_*). */
int SNAKECG_EXPORT(core_settle)(sc_settle *st) {
  const sc_work_fn fns[] = {SC_CS_WORKS, SNAKECG_LJ_WORK};
  sc_work_t ws;
  int status;
  st->impact = st->n_impact = st->n_projected = st->nsingular = 0;
  st->drift = 0.0;
  st->drift_row = -1;
  if (sc_work_alloc(&ws, fns, SC_COUNT(fns))) {
    st->status = SETTLE_MEMORY;
    return SETTLE_MEMORY;
  }
  status = settle(&ws, st);
  sc_work_free(&ws);
  st->status = status;
  return status;
}

/* The root of fn between xa and xb to xtol + rtol |root| (the integrator locates its events
 * with it, 4 eps each; a general scene's run its contacts' onsets, scene_run.c):
 * scipy.optimize.brentq (scipy/optimize/Zeros/brentq.c) on fn over [xa, xb]. */
int sc_brentq(sc_root_fn fn, void *arg, double xa, double xb, double xtol, double rtol,
              double *root) {
  double xpre = xa, xcur = xb, xblk = 0.0, fpre, fcur, fblk = 0.0, spre = 0.0, scur = 0.0;
  double sbis, delta, stry, dpre, dblk;
  int i, st;
  if ((st = fn(arg, xpre, &fpre))) return st;
  if ((st = fn(arg, xcur, &fcur))) return st;
  *root = xpre;
  if (fpre == 0) return 0;
  *root = xcur;
  if (fcur == 0) return 0;
  if (signbit(fpre) == signbit(fcur)) return 0; /* not bracketed: solve_ivp would raise */
  for (i = 0; i < 100; ++i) {
    if (fpre != 0 && fcur != 0 && signbit(fpre) != signbit(fcur)) {
      xblk = xpre;
      fblk = fpre;
      spre = scur = xcur - xpre;
    }
    if (fabs(fblk) < fabs(fcur)) {
      xpre = xcur;
      xcur = xblk;
      xblk = xpre;
      fpre = fcur;
      fcur = fblk;
      fblk = fpre;
    }
    delta = (xtol + rtol * fabs(xcur)) / 2;
    sbis = (xblk - xcur) / 2;
    if (fcur == 0 || fabs(sbis) < delta) break;
    if (fabs(spre) > delta && fabs(fcur) < fabs(fpre)) {
      if (xpre == xblk) { /* interpolate */
        stry = -fcur * (xcur - xpre) / (fcur - fpre);
      } else { /* extrapolate */
        dpre = (fpre - fcur) / (xpre - xcur);
        dblk = (fblk - fcur) / (xblk - xcur);
        stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre));
      }
      if (2 * fabs(stry) < fmin(fabs(spre), 3 * fabs(sbis) - delta)) {
        spre = scur;
        scur = stry;
      } else {
        spre = sbis;
        scur = sbis;
      }
    } else {
      spre = sbis;
      scur = sbis;
    }
    xpre = xcur;
    fpre = fcur;
    if (fabs(scur) > delta) xcur += scur;
    else xcur += (sbis > 0 ? delta : -delta);
    if ((st = fn(arg, xcur, &fcur))) return st;
  }
  *root = xcur;
  return 0;
}
