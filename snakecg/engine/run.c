/* snakecg's runtime core, part 4: a whole simulation run with a constant torque, in C.
 *
 * This file is part of the runtime (not generated), compiled once per model into the model's
 * shared library like forward.c, integrate.c and events.c.
 *
 * It runs the loop of snakecg/simulate/simulator.py (Simulator.run) for a torque that is
 * constant over the whole run, from the start's settle (done here too with sc_run.start, or
 * before by the caller): segment after segment in the mode
 * (core_integrate_segment, integrate.c), the mode's terminal events
 * (snakecg/simulate/events.py, Events.specs), at an event what Events.handle does (the rows
 * that the event fixes: a separated or lost contact, a wheel breaking away against its
 * force, sliding wheels that keep sliding; the contact candidate of a closing gap on the link)
 * and the settle (core_settle, events.c). It records the samples (the output times, both
 * sides of every event) with their mode, the modes, and the events with what Python needs to
 * describe them. The contact check (geometry.c) runs in every segment and on the state after
 * every event; with SC_GEO_STOP its first violation ends the run (RUN_GEOMETRY), its sample the
 * last. A failed evaluation or a derivative that is not finite (SEG_FAILED, SETTLE_FAILED)
 * ends the run with RUN_FAILED at R->t. What the Python loop does differently (a too small
 * step, which it reports; more samples or modes than room; an object penetrating the link
 * at the start, which it refuses) returns RUN_PYTHON: the caller then runs the whole loop in
 * Python from the start, with the same compiled segments and settles.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime (before the first include) */
#include <math.h>
#include <string.h>
#include <time.h>

#include "snakecg_layout.h"
#include "engine.h"
#define MODE_WIDTH (NC + 1)  /* a mode: its row states, then off_link */
#define EVENT_WIDTH (11 + NC) /* an event: see sc_run.events */


enum { RUN_COMPLETED = 0, RUN_STOPPED = 1, RUN_PYTHON = 2, RUN_GEOMETRY = 3, RUN_PAUSED = 4,
       RUN_FAILED = 5 };

typedef struct {
  sc_segment *sg;     /* the run's segment (tau, constants, its y0/state/ev_* arrays) */
  sc_settle *st;      /* the run's settle (its arrays) */
  double T, gtol;     /* duration; gap and link tolerance of the contact (m) */
  const double *grid; /* the output times (increasing, the last is T) */
  sc_int n_grid, max_events;
  double t;           /* in: the start (after its settle, or before it with `start`) */
  const double *y;    /* in: NY, the state there */
  sc_int off_link;    /* in: the start mode's flag (its row states in sg->state); with
                         `start`: set by the start's settle */
  double loss;        /* in: the energy removed at the start (with `start`: set there); out:
                         at the end */
  /* outputs */
  sc_int cap;         /* rows of t_out, y_out, mode_out, loss_out */
  double *t_out, *y_out, *mode_out, *loss_out;
  sc_int n_out;
  sc_int cap_modes;
  double *modes;      /* cap_modes x MODE_WIDTH */
  sc_int n_modes;
  sc_int cap_events;
  double *events;     /* cap_events x EVENT_WIDTH: t, the event's kind (EV_*) and row, the
                         modes before and after, impact (0/1), its closing velocity, the
                         kinetic energy before it and its change, the drift projected away
                         (-1: none), the impulses' count, then the impulses (NC) */
  sc_int n_events;
  sc_int stuck;       /* events in a row without progress in time (at a stop) */
  double *samples;    /* cap x (NY + 2 NC + 6): core_mode_samples of every sample in its mode */
  sc_int segments, nfev, nsteps, nsingular; /* nsingular: regularized (dependent rows) */
  double segment_cpu; /* CPU seconds inside the segment integrations */
  sc_int start;       /* in: 1 when y is the initial state, before the start's settle (done
                         here first, see start()), 0 when it is the state after it */
  double *start_out;  /* out (start): START_WIDTH, see start() */
  double budget;      /* in: wall-clock seconds a call may take; after them it stops with
                         RUN_PAUSED (within a segment, between two, or within the samples)
                         and the next call with `resume` goes on; <= 0: no limit */
  sc_int resume;      /* in/out: 0 a new run; where a paused call stopped: 1 within a
                         segment (sg->resume), 2 before a segment, 3 within the samples */
  sc_int mode, i0, n_sampled; /* where a paused call stopped (with t, off_link, stuck) */
  sc_int status;      /* RUN_* */
} sc_run;

/* sc_run.start_out: gap, s, touching, off_link; impact (0/1), its closing velocity, the
 * kinetic energy before it and its change, the impulses' count, the impulses (NC); the rows
 * projected, their drift, vtol, the drift's row, the kinetic energy before the projection and
 * its change, the impulses (NC) */
#define START_IMPACT 4
#define START_PROJECTION (9 + NC)
#define START_WIDTH (15 + 2 * NC)

static sc_int add_mode(sc_run *R, const double *state, sc_int off_link) {
  double *m;
  if (R->n_modes >= R->cap_modes) return -1;
  m = R->modes + R->n_modes * MODE_WIDTH;
  memcpy(m, state, sizeof(double) * NC);
  m[NC] = (double)off_link;
  return R->n_modes++;
}

static int add_sample(sc_run *R, double t, const double *y, sc_int mode) {
  if (R->n_out >= R->cap) return 1;
  R->t_out[R->n_out] = t;
  memcpy(R->y_out + R->n_out * NY, y, sizeof(double) * NY);
  R->mode_out[R->n_out] = (double)mode;
  R->loss_out[R->n_out] = R->loss;
  R->n_out++;
  return 0;
}

/* Events.specs: the terminal events of the mode (state, off_link) into sg; their count. */
static sc_int specs(sc_segment *sg, const double *state, sc_int off_link) {
  const double *bounds = sg->scene + SCENE_bounds;
  sc_int *kind = (sc_int *)sg->ev_kind, *row = (sc_int *)sg->ev_row, n = 0;
  int r;
  if (state[0] == HELD) {
    kind[n] = EV_SEPARATION, row[n++] = 0;
    kind[n] = EV_S_LOW, row[n++] = 0;
    kind[n] = EV_S_HIGH, row[n++] = 0;
  } else if (!off_link) {
    kind[n] = EV_GAP, row[n++] = 0;
  }
  for (r = 1; r < NC; ++r) {
    if (state[r] == HELD && isfinite(bounds[r])) kind[n] = EV_BREAKAWAY, row[n++] = r;
    else if (state[r] == SLIDE_POS || state[r] == SLIDE_NEG)
      kind[n] = EV_SLIDE_STOP, row[n++] = r;
  }
  return n;
}

/* Events.handle of the event `e` of the segment at (t_e, y_e), then the settle: the new
 * state in st->y_out, the new row states in st->state; *off_link updated. 0, or RUN_FAILED. */
static int handle(sc_run *R, sc_int e, const double *y_e, sc_int *off_link) {
  sc_segment *sg = R->sg;
  sc_settle *st = R->st;
  const sc_int kind = sg->ev_kind[e], row = sg->ev_row[e];
  double *forced = (double *)st->forced, point[NY + 2 * NC + 6];
  int r, candidate = sg->state[0] == HELD;
  sc_int stopped = -1;
  for (r = 0; r < NC; ++r) forced[r] = -1.0;
  if (kind == EV_GAP || kind == EV_BREAKAWAY) { /* lam and s there, in the mode */
    R->nfev++;
    if (SNAKECG_EXPORT(core_mode_samples)(sg, 1, y_e, point) != 0) return RUN_FAILED;
    if (point[NY + 2 * NC + 5] != 0.0) return RUN_FAILED;
  }
  if (kind == EV_SEPARATION) {
    forced[0] = LOST;
    candidate = 0;
  } else if (kind == EV_S_LOW || kind == EV_S_HIGH) {
    forced[0] = LOST;
    candidate = 0;
    *off_link = 1;
  } else if (kind == EV_GAP) {
    const double s = point[NY + 2 * NC + 1];
    if (-R->gtol <= s && s <= sg->l_k + R->gtol) candidate = 1;
    else forced[0] = LOST, *off_link = 1; /* passed the link beyond its ends (Events.handle) */
  } else if (kind == EV_BREAKAWAY) {
    forced[row] = point[NY + row] > 0 ? SLIDE_POS : SLIDE_NEG;
  } else {
    stopped = row;
  }
  for (r = 0; r < NC; ++r) /* sliding wheels that did not stop keep sliding */
    if ((sg->state[r] == SLIDE_POS || sg->state[r] == SLIDE_NEG) && forced[r] < 0 &&
        r != stopped)
      forced[r] = sg->state[r];
  memcpy((double *)st->y, y_e, sizeof(double) * NY);
  st->prev = sg->state;
  st->contact_candidate = candidate;
  if (SNAKECG_EXPORT(core_settle)(st) != SETTLE_DONE) return RUN_FAILED;
  R->nsingular += st->nsingular;
  return 0;
}

/* Simulator.run at the start, for R->y the initial state: the gap and the contact position s
 * (contact_system's, in no mode and with no torque), the contact touching (|gap| <= gtol with
 * s on the link, gtol about) or off the link, then the start's settle (Events.settle without
 * a mode before, the contact a candidate when touching) with the run's torque. Its new state
 * in y, its row states in the segment's state, *off_link set, its energy removed in R->loss;
 * what Python records of it in R->start_out. 0, RUN_FAILED, or RUN_PYTHON when the object
 * penetrates the link (Python refuses it). */
static int start(sc_run *R, double *y, sc_int *off_link) {
  sc_segment *sg = R->sg;
  sc_settle *st = R->st;
  const double *tau = sg->tau, *state = sg->state;
  double point[NY + 2 * NC + 6], zero_tau[SNAKECG_NA], zero_state[NC], *o = R->start_out;
  double gap, s, *forced = (double *)st->forced;
  int on_link, touching, r, failed;
  for (r = 0; r < SNAKECG_NA; ++r) zero_tau[r] = 0.0;
  for (r = 0; r < NC; ++r) zero_state[r] = ABSENT;
  sg->tau = zero_tau; /* CompiledSegments.gap_and_s: no torque, no row held */
  sg->state = zero_state;
  failed = SNAKECG_EXPORT(core_mode_samples)(sg, 1, y, point) != 0 ||
           point[NY + 2 * NC + 5] != 0.0;
  sg->tau = tau;
  sg->state = state;
  if (failed) return RUN_FAILED;
  gap = point[NY + 2 * NC];
  s = point[NY + 2 * NC + 1];
  on_link = -R->gtol <= s && s <= sg->l_k + R->gtol;
  if (gap < -R->gtol && on_link) return RUN_PYTHON; /* penetrating: Python refuses it */
  touching = fabs(gap) <= R->gtol && on_link;
  *off_link = !on_link && fabs(gap) <= R->gtol;
  for (r = 0; r < NC; ++r) forced[r] = -1.0;
  memcpy((double *)st->y, y, sizeof(double) * NY);
  st->prev = 0;
  st->contact_candidate = touching;
  if (SNAKECG_EXPORT(core_settle)(st) != SETTLE_DONE) return RUN_FAILED;
  R->nsingular += st->nsingular;
  memcpy(y, st->y_out, sizeof(double) * NY);
  memcpy((double *)sg->state, st->state, sizeof(double) * NC);
  memset(o, 0, sizeof(double) * START_WIDTH);
  o[0] = gap;
  o[1] = s;
  o[2] = touching;
  o[3] = (double)*off_link;
  R->loss = 0.0; /* the energy of the start's records, in their order */
  if (st->impact) {
    o[START_IMPACT] = 1.0;
    o[START_IMPACT + 1] = st->impact_velocity;
    o[START_IMPACT + 2] = st->impact_ke;
    o[START_IMPACT + 3] = st->impact_de;
    o[START_IMPACT + 4] = (double)st->n_impact;
    memcpy(o + START_IMPACT + 5, st->impact_lam, sizeof(double) * (size_t)st->n_impact);
    R->loss += -st->impact_de;
  }
  if (st->n_projected) {
    o[START_PROJECTION] = (double)st->n_projected;
    o[START_PROJECTION + 1] = st->drift;
    o[START_PROJECTION + 2] = st->vtol;
    o[START_PROJECTION + 3] = (double)st->drift_row;
    o[START_PROJECTION + 4] = st->projection_ke;
    o[START_PROJECTION + 5] = st->projection_de;
    memcpy(o + START_PROJECTION + 6, st->projection_lam,
           sizeof(double) * (size_t)st->n_projected);
    if (st->drift > st->vtol) R->loss += -st->projection_de; /* recorded: an impulse */
  }
  return 0;
}

/* The loop. With a budget, a call stops with RUN_PAUSED where it stands (its place in R and
 * the segment); the call with R->resume goes on from there. At the top of the loop the
 * state y is the last sample's. */
static int run(sc_run *R, double stop_at) {
  sc_segment *sg = R->sg;
  sc_settle *st = R->st;
  const double T = R->T, tiny = 1e-12 * (T > 1.0 ? T : 1.0);
  double t = R->t, y[NY], *state = (double *)sg->state;
  sc_int off_link = R->off_link, mode, stuck = R->stuck, i0 = R->i0, k;
  const sc_int resume = R->resume;
  int status, first = 1, failed;
  clock_t c0;
  R->resume = 0;
  if (resume) {
    mode = R->mode;
    memcpy(y, R->y_out + (R->n_out - 1) * NY, sizeof(y));
  } else {
    stuck = i0 = 0;
    memcpy(y, R->y, sizeof(y));
    if (R->start && (failed = start(R, y, &off_link))) return failed;
    if ((mode = add_mode(R, state, off_link)) < 0 || add_sample(R, t, y, mode))
      return RUN_PYTHON;
  }
  while (t < T * (1 - 1e-13)) {
    if (resume != 1 || !first) {
      if (!first && sc_wall_time() > stop_at) { /* pause before this segment */
        R->resume = 2;
        break;
      }
      /* output times after t: the grid's (its last is T, where the segment ends) */
      while (i0 < R->n_grid && !(R->grid[i0] > t)) ++i0;
      if (i0 >= R->n_grid || R->n_out + (R->n_grid - i0) + 2 > R->cap) return RUN_PYTHON;
      sg->t_eval = R->grid + i0;
      sg->n_eval = R->n_grid - i0;
      sg->y_eval = R->y_out + R->n_out * NY;
      sg->n_ev = specs(sg, state, off_link);
      memcpy((double *)sg->y0, y, sizeof(y));
      sg->t0 = t;
      sg->t1 = T;
      sg->resume = 0;
    }
    first = 0;
    sg->budget = isfinite(stop_at) ? fmax(stop_at - sc_wall_time(), 1e-9) : 0.0;
    c0 = clock();
    status = SNAKECG_EXPORT(core_integrate_segment)(sg);
    R->segment_cpu += (double)(clock() - c0) / CLOCKS_PER_SEC;
    R->nfev += sg->nfev;
    R->nsteps += sg->nsteps;
    R->nsingular += sg->nsingular;
    if (status == SEG_PAUSED) { /* the segment goes on at the next call */
      sg->resume = 1;
      R->resume = 1;
      break;
    }
    R->segments++;
    if (status == SEG_FAILED) { /* where the step that failed began */
      R->t = sg->t_end;
      return RUN_FAILED;
    }
    if (status != SEG_END && status != SEG_EVENT && status != SEG_GEOMETRY) return RUN_PYTHON;
    for (k = 0; k < sg->n_out; ++k) { /* the outputs, written in place */
      R->t_out[R->n_out] = sg->t_eval[k];
      R->mode_out[R->n_out] = (double)mode;
      R->loss_out[R->n_out] = R->loss;
      R->n_out++;
    }
    if (status == SEG_GEOMETRY) { /* the contact check's first violation ends the run */
      if (R->t_out[R->n_out - 1] < sg->t_end && add_sample(R, sg->t_end, sg->y_end, mode))
        return RUN_PYTHON;
      R->t = sg->t_end;
      return RUN_GEOMETRY;
    }
    if (status == SEG_END) {
      t = T;
      memcpy(y, R->y_out + (R->n_out - 1) * NY, sizeof(y));
      break;
    }
    { /* an event */
      const double t_e = sg->t_end;
      const sc_int e = sg->event, before = mode;
      double *ev;
      stuck = t_e - t <= tiny ? stuck + 1 : 0;
      if (R->t_out[R->n_out - 1] < t_e && add_sample(R, t_e, sg->y_end, mode)) return RUN_PYTHON;
      if (R->n_events >= R->cap_events) return RUN_PYTHON;
      if (handle(R, e, sg->y_end, &off_link)) {
        R->t = t_e;
        return RUN_FAILED;
      }
      memcpy(y, st->y_out, sizeof(y));
      memcpy(state, st->state, sizeof(double) * NC);
      if ((mode = add_mode(R, state, off_link)) < 0) return RUN_PYTHON;
      ev = R->events + R->n_events * EVENT_WIDTH;
      ev[0] = t_e;
      ev[1] = (double)sg->ev_kind[e];
      ev[2] = (double)sg->ev_row[e];
      ev[3] = (double)before;
      ev[4] = (double)mode;
      ev[5] = (double)st->impact;
      ev[6] = st->impact_velocity;
      ev[7] = st->impact_ke;
      ev[8] = st->impact_de;
      ev[9] = st->n_projected ? st->drift : -1.0;
      ev[10] = (double)(st->impact ? st->n_impact : 0);
      for (k = 0; k < NC; ++k) ev[11 + k] = k < ev[10] ? st->impact_lam[k] : 0.0;
      R->n_events++;
      if (st->impact) R->loss += -st->impact_de;
      t = t_e;
      if (add_sample(R, t, y, mode)) return RUN_PYTHON;
      if (sg->geo && sg->geo->mode != SC_GEO_OFF && !sg->geo->found) { /* the state after it */
        sc_int pair;
        const double d = sc_geo_depth(sg->geo, y, &pair);
        if (d > sg->geo->tol) {
          sc_geo_record(sg->geo, t, y, d, pair);
          if (sg->geo->mode == SC_GEO_STOP) {
            R->t = t;
            return RUN_GEOMETRY;
          }
        }
      }
      if (R->n_events >= R->max_events || stuck > 20) {
        R->t = t;
        R->stuck = stuck;
        return RUN_STOPPED;
      }
    }
  }
  R->t = t;
  if (R->resume) { /* paused: where it stands */
    R->off_link = off_link;
    R->stuck = stuck;
    R->mode = mode;
    R->i0 = i0;
    return RUN_PAUSED;
  }
  return RUN_COMPLETED;
}

/* Samples evaluated between two looks at the clock. */
#define SAMPLE_CHUNK 256

/* The trajectory's quantities at every sample from R->n_sampled on, in its mode
 * (core_mode_samples on each run of samples that share their mode, SAMPLE_CHUNK at most at
 * once): 0, 1 (failed), or RUN_PAUSED after stop_at (R->n_sampled: how far it got). */
static int samples(sc_run *R, double stop_at) {
  const int width = NY + 2 * NC + 6;
  double *state = (double *)R->sg->state;
  sc_int start = R->n_sampled, end;
  while (start < R->n_out) {
    const sc_int mode = (sc_int)R->mode_out[start];
    if (start > R->n_sampled && sc_wall_time() > stop_at) {
      R->n_sampled = start;
      return RUN_PAUSED;
    }
    for (end = start + 1;
         end < R->n_out && end - start < SAMPLE_CHUNK && (sc_int)R->mode_out[end] == mode;
         ++end) {
    }
    memcpy(state, R->modes + mode * MODE_WIDTH, sizeof(double) * NC);
    if (SNAKECG_EXPORT(core_mode_samples)(R->sg, end - start, R->y_out + start * NY,
                                          R->samples + start * width))
      return 1;
    start = end;
  }
  R->n_sampled = start;
  return 0;
}

/* Run the loop (see sc_run), then evaluate the samples; returns and stores the status
 * (RUN_*). RUN_PAUSED: call again with R->resume as it was left, nothing else changed. */
int SNAKECG_EXPORT(core_run)(sc_run *R) {
  const double stop_at = R->budget > 0 ? sc_wall_time() + R->budget : INFINITY;
  int done;
  if (R->resume == 3) { /* the loop is done (its status kept): the samples go on */
    R->resume = 0;
    done = samples(R, stop_at);
    if (done == RUN_PAUSED) R->resume = 3;
    else if (done) R->status = RUN_PYTHON;
    return done == RUN_PAUSED ? RUN_PAUSED : (int)R->status;
  }
  if (!R->resume) {
    R->n_out = R->n_modes = R->n_events = 0;
    R->segments = R->nfev = R->nsteps = R->nsingular = 0;
    R->segment_cpu = 0.0;
    R->stuck = 0;
    R->i0 = R->mode = R->n_sampled = 0;
  }
  R->status = run(R, stop_at);
  if (R->status == RUN_PAUSED || R->status == RUN_PYTHON || R->status == RUN_FAILED)
    return (int)R->status;
  done = samples(R, stop_at);
  if (done == RUN_PAUSED) {
    R->resume = 3;
    return RUN_PAUSED;
  }
  if (done) R->status = RUN_PYTHON;
  return (int)R->status;
}
