/* snakecg's engine: a general scene's run, many time steps in one call, and batches of runs
 * (snakecg/scenes/stepping.py states the scheme; scene_step.c does one step).
 *
 * From the state in the step's buffers (sc_scene_step, its rows found at x), steps of dt to
 * the run's duration, each with:
 *   1. the torque held over the step: a constant, a table of times (linear or held between
 *      samples) or the serpenoid PD law (snakecg/simulate/gaits.py: tau = kp (q_ref - q) +
 *      kd (qdot_ref - qdot), clipped), evaluated here; or the caller's law (RUN_TAU: the call
 *      returns for it and goes on when called again with the torque in the step's tau);
 *   2. the step (core_scene_step); where its end overlaps beyond the tolerance, the pairs
 *      overlapping there (core_scene_gaps, bounding circles within 2 tol) and, for each, the
 *      time along the step where its distance at x + s h V+ reaches its target (-tol / 4, or
 *      halfway from a start already within the tolerance) by Brent's method (sc_brentq, the
 *      tolerances of scipy's brentq the Python loop used: 1e-12, 1e-10); the step taken again
 *      shortened to the earliest, at most RUN_TRIES times, never shorter than h_min; where
 *      the step's solve does not converge (nearly dependent rows), or a shortened step is
 *      still too short, the step taken again with the overlaps held rather than pushed out
 *      (their offsets 0: where the rows of a jammed snake are nearly dependent, pushing an
 *      overlap out at gap / h asks for velocities of tens of m/s or for none at all; the run
 *      counts such steps), once; then, where the solve still does not converge, halved up
 *      to RETRY_HALVINGS times (as Drake's discrete solver takes substeps where its solve
 *      fails: the sets' sizes, the offsets and the velocity term weigh otherwise);
 *   3. the record: every `every`-th step and the last, a row (t, x, V, tau, acc) into the
 *      caller's buffer; an impact returns (RUN_IMPACT, for the caller's event record) unless
 *      the run only counts them (a batch).
 * A call returns at the end, for the caller's law, an impact, a full record buffer, after
 * `pause` steps (progress, Ctrl-C) or where the run stops; called again it goes on exactly
 * as if it had not returned. core_scene_run_batch runs n such runs to their ends.
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "geometry.h"
#include "scene_step.h"

#define RUN_TRIES 60 /* shortened tries of one step */
#define RETRY_HALVINGS 6 /* halvings of a step whose solve did not converge */
#define ROOT_XTOL 1e-12
#define ROOT_RTOL 1e-10
/* the torque laws (snakecg/scenes/stepping.py's LAW_*) */
enum { LAW_CONSTANT = 0, LAW_TABLE = 1, LAW_HOLD = 2, LAW_SERPENOID_PD = 3, LAW_CALLER = 4 };
/* why a call returned (stepping.py's RUN_*); PH_*: where the run stands */
enum { RUN_END = 0, RUN_TAU = 1, RUN_FULL = 2, RUN_IMPACT = 3, RUN_PAUSE = 4,
       RUN_NOT_CONVERGED = 5, RUN_IMPACT_NOT_CONVERGED = 6, RUN_REFUSED = 7,
       RUN_TOO_SHORT = 8, RUN_TRIES_OUT = 9, RUN_BAD_TAU = 10 };
enum { PH_START = 0, PH_STEP = 1, PH_TAU = 2 };

/* One run (snakecg/engine/binding.py mirrors it as SceneRunCall). */
typedef struct {
  sc_scene_step *st;      /* the step: its state, rows, torque and accumulators */
  sc_scene_state *gs;     /* the gaps' call: q (n_s), qo (3 n_o) and out (5 gcap) its own */
  sc_int gcap;            /* room for pairs' records in gs->out */
  double duration, dt, h_min;
  double tau_limit;       /* a law's torque beyond it (or not finite) stops (RUN_BAD_TAU) */
  sc_int law, nlp;        /* LAW_*, its parameters (stepping.py's law_parameters) */
  const double *lp;
  sc_int every;           /* keep every k-th step (and the last); 0: keep none */
  double *rec;            /* cap rows of 1 + 2 n + NA + ST_WIDTH */
  sc_int cap, nrec;       /* the caller empties the buffer (nrec = 0) on RUN_FULL */
  sc_int pause;           /* steps per call before RUN_PAUSE (0: none) */
  sc_int stop_at_impacts; /* 1: return RUN_IMPACT after a step with an impact */
  double *work;           /* 2 n + 5 gcap scratch */
  /* the run's state: time, steps, phase; impacts, the smallest contact gap of the steps */
  double t;
  sc_int nstep, phase, impacts;
  double min_gap;
  /* RUN_TOO_SHORT: the deepest pair at the step's end (kind, index of each, distance) */
  double bad[5];
  /* the paper's contact check (geometry.c's, the scene's one object its plate; null: none)
   * of every kept sample, from the links' cos and sin the step took: the first sample
   * (counted from the run's first, nkept the count) whose largest overlap exceeds geo_tol
   * (-1: none yet), that overlap and its pair */
  const sc_geometry *geo;
  double geo_tol;
  sc_int nkept, geo_k, geo_pair;
  double geo_depth;
} sc_scene_run;

/* A torque law (LAW_TABLE, LAW_HOLD, LAW_SERPENOID_PD with its parameters p) at t and the
 * state q, v (n_s each) into tau (NA); LAW_CONSTANT: tau left as it is. Returns 0, or
 * RUN_BAD_TAU where a torque is not finite or beyond limit. The serpenoid PD law's one
 * compiled home (snakecg/simulate/gaits.py's SerpenoidPD calls it through the binding). */
int SNAKECG_EXPORT(core_scene_law)(sc_int law, const double *p, double t, const double *q,
                                   const double *v, double limit, double *tau) {
  sc_int j, na = SNAKECG_NS - 3;
  if (law == LAW_CONSTANT) return 0;
  if (law == LAW_TABLE || law == LAW_HOLD) { /* k, times (k), torques (k x na) */
    sc_int k = (sc_int)p[0], lo = 0, hi = k, i;
    const double *ts = p + 1, *tq = p + 1 + k;
    while (lo < hi) { /* the first time > t: numpy's searchsorted(side="right") */
      sc_int mid = (lo + hi) / 2;
      if (ts[mid] <= t) lo = mid + 1;
      else hi = mid;
    }
    i = lo - 1;
    if (i < 0) i = 0;
    if (lo == 0 || i >= k - 1 || law == LAW_HOLD) {
      for (j = 0; j < na; ++j) tau[j] = tq[i * na + j];
    } else {
      double s = (t - ts[i]) / (ts[i + 1] - ts[i]);
      for (j = 0; j < na; ++j) tau[j] = (1.0 - s) * tq[i * na + j] + s * tq[(i + 1) * na + j];
    }
  } else if (law == LAW_SERPENOID_PD) {
    /* amplitude, 2 pi frequency, offset, clip (0/1); phases, kp, kd, tau_max (na each) */
    const double a = p[0], w = p[1], off = p[2], *ph = p + 4, *kp = ph + na, *kd = kp + na,
                 *tm = kd + na;
    for (j = 0; j < na; ++j) {
      double arg = w * t + ph[j];
      double u = kp[j] * ((a * sin(arg) + off) - q[3 + j]) + kd[j] * ((a * w) * cos(arg) -
                                                                       v[3 + j]);
      if (p[3] != 0.0) u = fmin(fmax(u, -tm[j]), tm[j]);
      tau[j] = u;
    }
  }
  for (j = 0; j < na; ++j)
    if (!(fabs(tau[j]) <= limit)) return RUN_BAD_TAU;
  return 0;
}

/* The run's law at t from the state in its step (LAW_CALLER: the caller wrote the torque). */
static int law_tau(const sc_scene_run *r, double t) {
  return SNAKECG_EXPORT(core_scene_law)(r->law, r->lp, t, r->st->x, r->st->V, r->tau_limit,
                                        (double *)r->st->tau);
}

/* One record row at the step's state (kept: the steps' scratch, or null), and its check. */
static void keep(sc_scene_run *r, const void *kept) {
  const sc_int n = SNAKECG_NS + 3 * (sc_int)r->st->pk[SP_NO], na = SNAKECG_NS - 3;
  double *row = r->rec + r->nrec * (1 + 2 * n + na + ST_WIDTH);
  row[0] = r->t;
  memcpy(row + 1, r->st->x, sizeof(double) * (size_t)n);
  memcpy(row + 1 + n, r->st->V, sizeof(double) * (size_t)n);
  memcpy(row + 1 + 2 * n, r->st->tau, sizeof(double) * (size_t)na);
  memcpy(row + 1 + 2 * n + na, r->st->acc, sizeof(double) * ST_WIDTH);
  r->nrec++;
  if (r->geo && r->geo_k < 0) {
    const double *cs = kept ? sc_scene_step_cs(kept, r->st->x) : 0;
    sc_int p;
    const double d = cs ? sc_geo_depth_cs(r->geo, r->st->x, cs, &p)
                        : sc_geo_depth(r->geo, r->st->x, &p);
    if (d > r->geo_tol) r->geo_k = r->nkept, r->geo_depth = d, r->geo_pair = p;
  }
  r->nkept++;
}

/* The engine's body index (links, objects, obstacles) of a pair record's kind and index. */
static sc_int body_index(const sc_scene_run *r, double kind, double index) {
  const sc_int nl = SNAKECG_NS - 2, no = (sc_int)r->st->pk[SP_NO];
  return (sc_int)index + (kind == 0.0 ? 0 : kind == 1.0 ? nl : nl + no);
}

/* The distance of bodies a, b (or every pair's, a < 0, within margin) at xs: the count of
 * records in gs->out (or < 0: core_scene_gaps' refusal). */
static int gaps_at(sc_scene_run *r, const double *xs, sc_int a, sc_int b, double margin) {
  sc_scene_state *g = r->gs;
  const sc_int no = (sc_int)r->st->pk[SP_NO];
  int found;
  memcpy((double *)g->q, xs, sizeof(double) * SNAKECG_NS);
  memcpy((double *)g->qo, xs + SNAKECG_NS, sizeof(double) * (size_t)(3 * no));
  g->pair_a = a;
  g->pair_b = b;
  g->margin = margin;
  g->ccap = r->gcap;
  found = SNAKECG_EXPORT(core_scene_gaps)(g);
  return found < 0 ? found : (found < r->gcap ? found : (int)r->gcap);
}

typedef struct { /* the distance of one pair along a refused step, less its target */
  sc_scene_run *r;
  const double *x, *Vp;
  double h, target, *xs;
  sc_int a, b;
} pair_along;

static int along_fn(void *arg, double s, double *g) {
  pair_along *p = (pair_along *)arg;
  const sc_int n = SNAKECG_NS + 3 * (sc_int)p->r->st->pk[SP_NO];
  const double sh = s * p->h;
  sc_int i;
  int found;
  for (i = 0; i < n; ++i) p->xs[i] = p->x[i] + sh * p->Vp[i];
  found = gaps_at(p->r, p->xs, p->a, p->b, 0.0);
  if (found != 1) return found < 0 ? found : -5;
  *g = p->r->gs->out[4] - p->target;
  return 0;
}

/* A refused step of length *h: the earliest time along it where a pair overlapping beyond
 * the tolerance at its end reaches its target; *h shortened to it (held: the step holds its
 * overlaps as the run's retry, none shorter for a pair that starts overlapping). Returns 0,
 * RUN_REFUSED (no pair overlaps there: the refusal is another), RUN_TOO_SHORT, or < 0. */
static int shorten(sc_scene_run *r, double *h, int held) {
  sc_scene_step *st = r->st;
  const sc_int n = SNAKECG_NS + 3 * (sc_int)st->pk[SP_NO];
  const double tol = st->tol;
  double *x0 = r->work, *xp = x0 + n, *bad = xp + n, s_hit = 1.0;
  sc_int i, k, nbad = 0;
  int found, code;
  for (i = 0; i < n; ++i) {
    x0[i] = st->x[i];
    xp[i] = st->x[i] + *h * st->Vp[i];
  }
  found = gaps_at(r, xp, -1, -1, 2.0 * tol);
  if (found < 0) return found;
  for (k = 0; k < found; ++k)
    if (r->gs->out[5 * k + 4] < -tol) memcpy(bad + 5 * nbad++, r->gs->out + 5 * k, 40);
  if (!nbad) return RUN_REFUSED;
  for (k = 0; k < nbad; ++k) {
    const double *p = bad + 5 * k;
    pair_along pa;
    double d0, target, s;
    pa.a = body_index(r, p[0], p[1]);
    pa.b = body_index(r, p[2], p[3]);
    found = gaps_at(r, x0, pa.a, pa.b, 0.0);
    if (found != 1) return found < 0 ? found : -5;
    d0 = r->gs->out[4];
    target = fmin(-0.25 * tol, 0.5 * (fmin(d0, tol) - tol));
    if (!(d0 > target) || (held && d0 < 0.0)) { /* (held for want of a push-out: no step
      keeps an overlap from deepening, every shorter one would come to halfway again) */
      s_hit = 0.0;
      break;
    }
    pa.r = r;
    pa.x = x0;
    pa.Vp = st->Vp;
    pa.h = *h;
    pa.target = target;
    pa.xs = xp;
    if ((code = sc_brentq(along_fn, &pa, 0.0, 1.0, ROOT_XTOL, ROOT_RTOL, &s))) return code;
    s_hit = fmin(s_hit, s);
  }
  *h = *h * s_hit;
  if (*h < r->h_min) {
    sc_int worst = 0;
    for (k = 1; k < nbad; ++k)
      if (bad[5 * k + 4] < bad[5 * worst + 4]) worst = k;
    memcpy(r->bad, bad + 5 * worst, 40);
    return RUN_TOO_SHORT;
  }
  return 0;
}

/* core_scene_run, its steps' scratch in *kept. */
static int run_on(sc_scene_run *r, void **kept) {
  sc_scene_step *st = r->st;
  const double eps = 1e-9 * r->dt;
  sc_int steps = 0;
  if (r->phase == PH_START) { /* the first sample (the rows at x found by the caller) */
    if (r->law != LAW_CALLER && law_tau(r, r->t)) return RUN_BAD_TAU;
    r->min_gap = st->acc[ST_MIN_GAP];
    if (r->every > 0) {
      if (r->nrec >= r->cap) return RUN_FULL;
      keep(r, *kept);
    }
    r->phase = PH_STEP;
  }
  while (r->duration - r->t > eps) { /* (rounding of the sum of the steps is no step) */
    double h = fmin(r->dt, r->duration - r->t);
    const double h0 = h;
    sc_int tries, halved = 0, held = 0; /* (held: the overlaps held once, the file's head) */
    int code = 0, status = STEP_DONE;
    if (r->phase == PH_STEP) {
      if (r->every > 0 && r->nrec >= r->cap) return RUN_FULL;
      if (r->pause > 0 && steps >= r->pause) return RUN_PAUSE;
      if (r->law == LAW_CALLER) {
        r->phase = PH_TAU;
        return RUN_TAU;
      }
      if (law_tau(r, r->t)) return RUN_BAD_TAU;
    }
    r->phase = PH_STEP;
    st->hold = 0;
    for (tries = 0; tries < RUN_TRIES; ++tries) {
      st->h = h;
      if ((code = sc_scene_step_kept(st, kept))) return code;
      status = (int)st->status;
      if (status == STEP_NOT_CONVERGED) { /* held, then halved (the file's head) */
        if (!held) {
          held = 1;
          if (!st->hold) { /* (else the step held them already: its jam, scene_step.c) */
            st->hold = 1;
            continue;
          }
        }
        st->hold = 0;
        if (halved == RETRY_HALVINGS || 0.5 * h < r->h_min) return RUN_NOT_CONVERGED;
        h *= 0.5, halved++;
        continue;
      }
      if (status == STEP_DONE || status == STEP_IMPACT_NOT_CONVERGED) break;
      code = shorten(r, &h, (int)held);
      if (code == RUN_TOO_SHORT && !held && !st->hold) {
        st->hold = held = 1, h = h0, halved = 0;
        continue;
      }
      if (code) return code;
    }
    st->hold = 0;
    st->quick = held; /* (the next step's push-out: SC_QUICK_SWEEPS, scene_step.c) */
    if (tries == RUN_TRIES) return RUN_TRIES_OUT;
    r->t += h;
    r->nstep++;
    steps++;
    if (status == STEP_IMPACT_NOT_CONVERGED) return RUN_IMPACT_NOT_CONVERGED;
    r->min_gap = fmin(r->min_gap, st->acc[ST_MIN_GAP]);
    if (r->every > 0 && (r->nstep % r->every == 0 || r->duration - r->t <= eps)) keep(r, *kept);
    if (st->acc[ST_IMPACT] != 0.0) {
      r->impacts++;
      if (r->stop_at_impacts) return RUN_IMPACT;
    }
  }
  return RUN_END;
}

/* Go on with run r: RUN_* (why it returned), or < 0 (core_scene_step's or the gaps'
 * refusal: -1 memory, -2 sizes, -3 a state not finite, -4, -5 a pair's distance). The steps
 * of one call share their scratch (made at its first step). */
int SNAKECG_EXPORT(core_scene_run)(sc_scene_run *r) {
  void *kept = 0;
  int code = run_on(r, &kept);
  sc_scene_step_kept(0, &kept);
  return code;
}

/* n runs, each to its end (a batch: no caller's law, no impacts returned, no record or a
 * buffer large enough): each run's last RUN_* (or < 0) in code[i]. Returns 0. */
int SNAKECG_EXPORT(core_scene_run_batch)(sc_scene_run *const *runs, sc_int n, sc_int *code) {
  sc_int i;
  for (i = 0; i < n; ++i) {
    int c;
    do c = SNAKECG_EXPORT(core_scene_run)(runs[i]);
    while (c == RUN_PAUSE || c == RUN_IMPACT);
    code[i] = c;
  }
  return 0;
}
