/* snakecg's engine: the exact solve of a general scene at one sample (and a batch).
 *
 * This file is part of the runtime (not generated) and knows no robot: it takes, per sample,
 * the inertia I of every body (snake coordinates and 3 per object: eq. 12), the applied
 * generalized force f (B tau + external wrenches, eq. 12), the constraint rows A (eqs. 8-10:
 * contact normals, wheel lateral rows, ground friction rows) and their blocks' sets:
 *
 *   FREE        one row, lam free (an ideal wheel: bilateral, unbounded)
 *   UNILATERAL  one row, lam >= 0 (a contact: the paper's assumption 2, frictionless)
 *   BOX         one row, |lam| <= p0 (a wheel's lateral force bounded by mu m g)
 *   DISC        two rows, |lam| <= p0 (isotropic Coulomb at a COM, radius mu m g)
 *   SPLIT       two rows (along, across the link): a split ellipse, semi-axis p0 backward
 *               (lam_t <= 0, resisting forward sliding), p1 forward (lam_t >= 0, resisting
 *               backward sliding), p2 across (anisotropic Coulomb)
 *
 * Gauss's principle with the sets' support functions has the dual
 *     min_lam 1/2 lam^T G lam + b^T lam  over lam in K = K_1 x ... x K_nb,
 * G = A I^-1 A^T (eq. 14), b = A I^-1 f + c (eq. 16 at rest, c = 0): the accelerations
 * a = I^-1 (f + A^T lam) (eq. 18) are unique; the forces are unique when G is regular. With
 * I = L L^T, G = Z^T Z and b = Z^T L^-1 f + c for Z = L^-1 A^T (built once per sample). The
 * solve is an active set on the pieces (held/stick, zero, sliding):
 *   1. the piece's equations solved to rounding (scene_piece.c's sc_polish): w = 0 on held
 *      rows and no acceleration along the boundary on sliding blocks, lam fixed on zero rows
 *      and saturated boxes; the held rows' forces eliminated (G_HH factored once by diagonal
 *      pivoting, dependent rows dropped), Newton on one angle per sliding 2-D block;
 *   2. the KKT conditions checked on the result (scene_kkt.c); a violated piece is switched
 *      (a primal-dual active-set step) and step 1 repeated (step 1's Newton left early where a
 *      block will certainly be switched: its breach beyond three times its last step's change);
 *   3. the pieces start from the caller's where given (core_scene_solve_s: a time step's,
 *      the last step's pieces: that piece first solved in the primal, scene_primal.c, without
 *      G, and kept where its KKT conditions hold; else a few passes), then from the held
 *      guess (every block held) where the rows are at most the coordinates; else, or when
 *      that fails within a few passes, from block Gauss-Seidel sweeps (each block minimised
 *      exactly: a clamp, or a 2-D trust-region problem whose secular equation is solved to
 *      rounding), read after five sweeps and tried where they read otherwise than at the last
 *      try, every failed try doubling the sweeps to the next reading (or once they converged;
 *      where w settled, a row that accelerates reads zero or sliding whatever its force);
 *      once BARRIER_SWEEPS sweeps solved no piece, the pieces read from the dual's log-barrier
 *      path (scene_barrier.c: an interior point, which does not drift along a statically
 *      indeterminate face's null space as the sweeps' forces do; its point, put onto those
 *      pieces, kept as a near miss, or within the acceptance as an answer whose forces lie
 *      inside the face's sets, where no piece solves); every RESCUE_SWEEPS sweeps without a
 *      solved piece, the reading solved from Z itself, one switch a pass (scene_rescue.c:
 *      nearly dependent held rows).
 * The certificate (KKT residuals, relative to the sample's force and acceleration scales) is
 * returned with every sample. Where the held rows' equations are dependent (statically
 * indeterminate), the flag is set and the held forces are the minimum-norm ones on the face
 * inside their sets (scene_sets.c's sc_min_norm_face; the accelerations the new forces' where
 * nearly dependent rows taken as dependent move them, by 5e-10 of their scale at most, and
 * the KKT conditions hold); else the face's basic solution stays and the flag says so (2). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_block.h"
#include "scene_diag.h"
#include "scene_sets.h"
#include "scene_rescue.h"
#include "scene_barrier.h"
#include "scene_kkt.h"
#include "scene_tiny.h"
#include "scene_solve.h"

enum { ST_SOLVED = 0, ST_NOT_CONVERGED = 1, ST_SINGULAR_MASS = 2, ST_BAD_INPUT = 3 }; /* status */

#define TRY_PASSES 6 /* from pieces read before the sweeps converged */
#define CHUNK 5 /* sweeps before the first reading of the pieces */
#define READ_SLIDE 0.15 /* 2-D block read sliding within this of its boundary mid-sweeps */
/* the sweeps' w taken as settled once they converged or, at the margin's readings (after two
 * failed tries), after this many sweeps: a row accelerating beyond TOL_ACCEPT then reads zero
 * or sliding (sc_read_states; nearly dependent rows' forces drift while w has settled) */
#define READ_W_SWEEPS 200
#define BARRIER_SWEEPS 150 /* sweeps unsolved before the barrier path is read (once) */
/* every RESCUE_SWEEPS sweeps unsolved (RESCUE_TRIES times at most): from Z (scene_rescue.c) */
#define RESCUE_SWEEPS 1000
#define RESCUE_TRIES 16

/* Nearly dependent held rows: where Z's rows are delta from dependent, G_HH's pivot is
 * delta^2 and below DEP_TOL (delta up to 1e-5) the piece takes them as dependent; the face's
 * basic forces may then leave their sets, and its rows accelerate, by about delta of their
 * scales, which for delta above 1e-9 is beyond the acceptance (G, the rows' squares, does not
 * resolve them further); just above it, kept, they are solved only to 1e-16 / delta^2. Such a
 * piece whose KKT residuals (res) are above the acceptance but none above NEAR_MISS is a near
 * miss: with rows dropped, its forces are first moved along the face's null space into their
 * sets; the best near miss (least residual, at most NEAR_OK) is kept and answered (dependent
 * flag 3, its certificate above 1e-9) where no piece is accepted after NEAR_SWEEPS sweeps.
 * The barrier path's point put onto its pieces is kept alike, whatever its residual: within
 * the acceptance it is then an answer (its forces inside the face's sets, not basic). */
#define NEAR_MISS 1e-6
#define NEAR_OK 1e-7
#define NEAR_SWEEPS 2000
typedef struct {
  double *lam, *state, res; /* (m forces, nb states; res: the largest residual, INF: none) */
} sc_near;

static double near_miss(sc_problem *p, double *res) {
  const double e = (sc_kkt(p, res, 0), sc_max(res[0], sc_max(res[1], res[2])));
  return e > TOL_ACCEPT && e <= NEAR_MISS ? e : 0.0;
}

/* A near miss of piece p (its largest residual e) kept in nm where it is the best so far. */
static void keep_near(sc_near *nm, const sc_problem *p, double e) {
  sc_int k;
  if (!(e <= NEAR_OK && e < nm->res)) return;
  nm->res = e;
  memcpy(nm->lam, p->lam, sizeof(double) * (size_t)p->m);
  for (k = 0; k < p->nb; ++k) nm->state[k] = (double)p->state[k];
}

/* Active-set passes from the states in p: the piece's equations solved (polish), the KKT
 * conditions checked and the violated pieces switched, at most max_pass times. Returns 1 when
 * a piece's solution satisfies them (res: its residuals), else 0. kept: w = G lam + b on entry.
 * fkp: the minimum-norm choice's kept null space (or NULL). */
static int active_set(sc_problem *p, const double *Z, sc_near *nm, sc_int max_pass,
                      double *work, sc_int *iwork, sc_int *passes, sc_int *defect, double *res,
                      int kept, sc_face_keep *fkp) {
  sc_int pass;
  int early = 1, stopped;
  double e;
  for (pass = 0; pass < max_pass; ++pass, kept = 1) { /* (each pass leaves w = G lam + b) */
    ++*passes;
    stopped = early;
    *defect = sc_polish(p, work, iwork, kept, &stopped);
    if (!stopped && (e = near_miss(p, res)) > 0) {
      if (*defect > 0 && res[0] > TOL_ACCEPT && res[1] <= TOL_ACCEPT && res[2] <= TOL_ACCEPT &&
          sc_min_norm_face(p, Z, work, 1e-10, 0.0, fkp) == 1) { /* (the accelerations moved
        by 1e-10 of their scale at most) */
        sc_update_w(p);
        e = near_miss(p, res);
      }
      if (e > 0) keep_near(nm, p, e);
    }
    if (!sc_kkt(p, res, 1)) {
      if (!stopped) return res[0] <= TOL_ACCEPT && res[1] <= TOL_ACCEPT && res[2] <= TOL_ACCEPT;
      early = 0; /* (stopped early, yet nothing to switch: solved to rounding next) */
    }
  }
  return 0;
}

/* The scales: forces (what would stop the rows' accelerations, and the sets' sizes),
 * accelerations; from G's diagonal (dg[i * stride]) and b. */
static void scales(sc_problem *p, const double *dg, sc_int stride, const double *b) {
  double fs = 0.0, ws = 0.0, ps = 0.0;
  sc_int i;
  for (i = 0; i < p->m; ++i) { /* (branches: as selects, a chain through fs, slower) */
    const double d = dg[i * stride];
    if (d > 0 && fabs(b[i]) / d > fs) fs = fabs(b[i]) / d;
    if (fabs(b[i]) > ws) ws = fabs(b[i]);
  }
  for (i = 0; i < 3 * p->nb; ++i) { /* the sets' finite sizes: the largest apart, then fs's */
    const double v = fabs(p->par[i]);
    ps = v > ps && v <= DBL_MAX ? v : ps;
  }
  if (ps > fs) fs = ps;
  for (i = 0; i < p->m; ++i) {
    double g = dg[i * stride] * fs;
    if (g > ws) ws = g;
  }
  p->fscale = fs > 0 ? fs : 1.0;
  p->wscale = ws > 0 ? ws : 1.0;
}

/* p's scales replaced by the forces' own where the sets are far above them (scene_sets.h's
 * sc_tight_scales: 1, the answer then checked again at these). */
static int tight_scales(sc_problem *p, const double *dg, sc_int stride, const double *b) {
  double fs, ws;
  if (!sc_tight_scales(p->m, dg, stride, b, p->lam, p->fscale, &fs, &ws)) return 0;
  p->fscale = fs;
  p->wscale = ws > 0 ? ws : p->wscale;
  return 1;
}

/* The pieces and forces from the caller's (3 per block: the code of state_out, -1 none: held;
 * the forces: a sliding 2-D block's angle, the held rows' start, which dependent held rows
 * keep: the basic solution near the last one, inside the sets). */
static void start_from(sc_problem *p, const double *from) {
  sc_int i, k;
  for (i = 0; i < p->m; ++i) p->lam[i] = 0.0;
  for (k = 0; k < p->nb; ++k) {
    const double *q = p->par + 3 * k, *s = from + 3 * k;
    const sc_int kind = p->kind[k], r = p->start[k], code = (sc_int)s[0],
                 nk = sc_block_size(kind);
    int zero = sc_zero_set(p, k);
    p->gamma[k] = 0.0;
    p->state[k] = zero || (code == S_ZERO && kind != K_FREE) ? S_ZERO : S_HELD;
    if (zero || p->state[k] == S_ZERO) continue;
    for (i = 0; i < nk; ++i) p->lam[r + i] = s[1 + i];
    if (code < S_SLIDE || kind < K_BOX) continue;
    if (kind == K_BOX) p->lam[r] = code == 4 ? -q[0] : q[0];
    else if (s[1] == 0.0 && s[2] == 0.0) continue;
    p->state[k] = S_SLIDE;
  }
}

/* The warm start's piece solved in the primal (scene_primal.c), kept where the KKT conditions
 * hold and, on a dependent face, its forces are the minimum-norm ones (not where the dual would
 * next open a contact at zero force). G's diagonal and b summed as G's own loop does (the same
 * scales; dg: m scratch). 1 when kept (dep: the flag, defect: the held rows' rank defect). */
static int primal_start(sc_problem *p, const double *Z, const double *g, const double *c,
                        const double *from, double *dg, double *work, sc_int *iwork,
                        double *res, sc_int *defect, int *dep) {
  const sc_int n = p->n, m = p->m;
  sc_int j, k, h = 0;
  int ok, r;
  double *restrict d = dg, *restrict e = p->b;
  start_from(p, from);
  for (k = 0; k < p->nb; ++k)
    if (p->state[k] == S_HELD) h += sc_block_size(p->kind[k]);
  if (2 * h > n) return 0; /* (more held rows: the forces left the sets on every try) */
  sc_diag_b(n, m, Z, g, d, e); /* (scene_diag.c) */
  for (j = 0; c && j < m; ++j) e[j] += c[j];
  scales(p, dg, 1, p->b);
  r = sc_primal_piece(p, Z, g, c, work, iwork, defect);
  ok = r > 0 && !sc_kkt(p, res, 1) && res[0] <= TOL_ACCEPT && res[1] <= TOL_ACCEPT &&
       res[2] <= TOL_ACCEPT;
  if (ok && tight_scales(p, dg, 1, p->b)) /* (else the dual's path, checked there too) */
    ok = !sc_kkt(p, res, 0) && res[0] <= TOL_ACCEPT && res[1] <= TOL_ACCEPT &&
         res[2] <= TOL_ACCEPT;
  for (k = 0; k < p->nb && ok && r == 2; ++k) /* (the dual's next choice: a contact opened) */
    if (p->kind[k] == K_UNILATERAL && p->state[k] == S_HELD &&
        p->lam[p->start[k]] <= 1e-12 * p->fscale)
      ok = 0;
  *dep = ok ? r - 1 : 0;
  sc_primal_tally(ok);
  return ok;
}

/* a := L^-T a for the snake alone (n = t = n_s, L dense): the general loop's operations in
 * its order, unrolled in registers (no loop of a few elements a row: the divisions alone). */
static inline __attribute__((always_inline)) void back_ns(const double *L, double *a) {
  enum { N = SNAKECG_NS };
  double x[N];
  sc_int i, k;
  SC_UNROLL for (i = 0; i < N; ++i) x[i] = a[i];
  SC_UNROLL for (i = N - 1; i >= 0; --i) {
    const double ai = x[i] / L[i * N + i];
    x[i] = ai;
    SC_UNROLL for (k = 0; k < i; ++k) x[k] -= L[i * N + k] * ai;
  }
  SC_UNROLL for (i = 0; i < N; ++i) a[i] = x[i];
}

/* The room of a sample's scratch after its fixed arrays (scene_solve_work's): the passes', the
 * primal piece's and scene_sets.c's minimum-norm forces inside the sets. */
static sc_int rest_size(sc_int n, sc_int m, sc_int nb) {
  const sc_int u = m + nb;
  return (u * u + 3 * u + 2 * m * m + 3 * m + 16) + sc_primal_work(n, m) +
         (2 * m * m + 12 * m + n * n + 3 * n);
}

/* One sample. M (n x n), f (n), A (m x n) row-major; out: lam (m), a (n), w (m), state (nb),
 * info (INFO_WIDTH). Scratch: work and iwork sized by scene_solve_work. */
static void solve_sample(sc_int n, sc_int m, sc_int nb, const double *M, const double *f,
                         const double *A, const double *c, const sc_int *kind, const sc_int *start,
                         const double *par, sc_int max_sweeps, const double *from,
                         double *lam, double *a, double *w, double *state_out, double *info,
                         double *work, sc_int *iwork, int tiny, sc_solve_keep *kp) {
  double *L = work, *Z = L + n * n, *G = Z + n * m, *b = G + m * m, *gam = b + m,
         *keep = gam + nb, *zero = keep + m, *rest = zero + m, res[3] = {NAN, NAN, NAN};
  sc_int i, j, k, t, total_sweeps = 0, passes = 0, defect = 0, chunk = CHUNK;
  sc_int *state = iwork, *iw2 = iwork + nb, *prev = iw2 + 3 * (m + nb);
  const double *acc = lam; /* the forces the accelerations are taken from (eq. 18) */
  sc_problem p;
  sc_tr2d prep[2 * PREP_BLOCKS]; /* (the sweeps' blocks' H parts: taken at their first sweep) */
  sc_near near;
  sc_face_keep *fkp = NULL; /* (the minimum-norm choice's null space, kept with G) */
  int dep = 0, ok = 0, primal = 0, reread = 0, fails = 0, nearly = 0, rescued = 0, zw = 0,
      barred = 0, interior = 0;
  if (tiny && sc_tiny_solve(n, m, nb, M, f, A, c, kind, start, par, from, lam, a, w, state_out,
                            info))
    return; /* (a tiny problem of one-row blocks: scene_tiny.c, the same steps compiled) */
  memset(info, 0, sizeof(double) * INFO_WIDTH);
  if (!sc_inertia_factor(n, M, f, 1e-14, L, a, &t)) { /* (scene_small.c: g = L^-1 f in a) */
    info[INFO_STATUS] = ST_SINGULAR_MASS;
    for (i = 0; i < m; ++i) lam[i] = w[i] = NAN;
    for (i = 0; i < n; ++i) a[i] = NAN;
    return;
  }
  if (kp) Z = kp->Z, G = kp->G; /* (a batch's samples at one configuration: held) */
  if (kp && kp->face.face) fkp = &kp->face;
  p.pk = kp ? kp->pieces : NULL;
  if (!kp || kp->ok < 1) sc_scene_z(n, m, t, L, A, Z); /* Z = L^-1 A^T (scene_small.c) */
  if (kp && kp->ok < 1) kp->ok = 1;
  near.lam = rest + rest_size(n, m, nb), near.state = near.lam + m, near.res = INFINITY;
  p.n = n; p.m = m; p.nb = nb; p.kind = kind; p.start = start; p.par = par;
  p.G = G; p.b = b; p.lam = lam; p.w = w; p.gamma = gam; p.state = state;
  if (from && m > n && sc_primal_tally(-1)) /* the warm start's piece, first in the primal
    where its n unknowns are fewer than the dual's m */
    ok = primal = primal_start(&p, Z, a, c, from, keep, rest, iw2, res, &defect, &dep);
  if (primal) { passes = 1; goto answered; }
  if (fkp && kp->ok != 2) fkp->nf = -1; /* (G found again: the null space and the pieces */
  if (p.pk && kp->ok != 2) sc_piece_forget(p.pk); /* kept go) */
  sc_scene_gram(n, m, Z, a, c, kp && kp->ok == 2 ? NULL : G, b, zero); /* G = Z^T Z, b =
    Z^T g + c (G held: b alone) */
  if (kp) kp->ok = 2;
  scales(&p, G, m + 1, b);
  for (i = 0; i < m; ++i) lam[i] = 0.0;
  for (k = 0; k < nb; ++k) gam[k] = 0.0;
  if (m == 0) {
    ok = 1;
    res[0] = res[1] = res[2] = 0.0;
  }
  if (!ok && from) { /* the active set from the caller's pieces (start_from) */
    start_from(&p, from);
    ok = active_set(&p, Z, &near, FROM_PASSES, rest, iw2, &passes, &defect, res, 0, fkp);
    if (!ok) { /* else today's order from zero forces */
      for (i = 0; i < m; ++i) lam[i] = 0.0;
      for (k = 0; k < nb; ++k) gam[k] = 0.0;
    }
  }
  if (!ok && m <= n) { /* the active set from the held guess: every block held (or its set
    zero); not where more rows than coordinates make the held forces' basic solution arbitrary */
    for (k = 0; k < nb; ++k) state[k] = sc_zero_set(&p, k) ? S_ZERO : S_HELD;
    ok = active_set(&p, Z, &near, GUESS_PASSES, rest, iw2, &passes, &defect, res, 0, fkp);
    if (!ok) /* else the sweeps from zero forces */
      for (i = 0; i < m; ++i) lam[i] = 0.0;
  }
  /* block Gauss-Seidel sweeps in chunks, the pieces read after each and tried where they
   * read otherwise than at the last try (from a copy: the sweeps go on from their own point;
   * every failed try doubles the chunk, up to 16 times CHUNK), or when the sweeps converged
   * (then they go on from the pieces' point, inside the polyhedral sets). Against the margin's
   * tries wandering (their passes switch many blocks at once): on the second failed one, the
   * same point read with 1e-6 and tried, and every later reading so (fails: those tries) */
  for (k = 0; k < nb; ++k) prev[k] = -1;
  while (!ok && total_sweeps < max_sweeps &&
         !(near.res <= NEAR_OK && total_sweeps >= NEAR_SWEEPS)) { /* (a near miss: below) */
    int same = 1;
    sc_int s = reread ? chunk : sc_block_sweeps(&p, chunk, 1e-12, total_sweeps == 0, prep);
    if (!reread) total_sweeps += s;
    if (!barred && !reread && total_sweeps >= BARRIER_SWEEPS) { /* once: read from the
      dual's barrier path instead (scene_barrier.c), else the sweeps go on from their point */
      memcpy(keep, lam, sizeof(double) * (size_t)m);
      barred = sc_barrier(&p, Z, rest, prev + 3 * nb) > 0 ? (sc_update_w(&p), 2) : 1;
      if (barred == 2) { /* its pieces, its point put onto them (kept: a near miss, or within
        the acceptance an answer, where no piece solves) */
        sc_read_states(&p, 1e-6, 1e-6, 0.0);
        sc_barrier_onto(&p);
        sc_update_w(&p);
        keep_near(&near, &p, (sc_kkt(&p, res, 0), sc_max(res[0], sc_max(res[1], res[2]))));
        if ((ok = active_set(&p, Z, &near, 20, rest, iw2, &passes, &defect, res, 1, fkp))) break;
      }
      memcpy(lam, keep, sizeof(double) * (size_t)m);
      sc_update_w(&p);
    }
    sc_read_states(&p, 1e-6, s < chunk || fails >= 2 ? 1e-6 : READ_SLIDE,
                   s < chunk || (fails >= 2 && total_sweeps >= READ_W_SWEEPS) ? TOL_ACCEPT :
                   0.0); /* (converged: 1e-6, and from w where it settled) */
    for (k = 0; k < nb; ++k)
      if (state[k] != prev[k]) same = 0;
    if (rescued < RESCUE_TRIES && s == chunk && total_sweeps >= RESCUE_SWEEPS * (rescued + 1)) {
      sc_int *read = prev + nb; /* (a long run's reading from Z; else the sweeps go on) */
      ++rescued;
      memcpy(keep, lam, sizeof(double) * (size_t)m);
      memcpy(read, state, sizeof(sc_int) * (size_t)nb);
      if ((ok = zw = sc_rescue(&p, Z, a, c, rest, iw2, read + nb, &passes, &defect, res, sc_kkt)))
        break;
      memcpy(lam, keep, sizeof(double) * (size_t)m);
      memcpy(state, read, sizeof(sc_int) * (size_t)nb);
      sc_update_w(&p); /* (w of that lam again: a try's passes take it as kept) */
    }
    if (same && s == chunk) { /* (a re-read as the margin's: as after its failed try) */
      if (reread && chunk < 16 * CHUNK) chunk *= 2;
      reread = 0;
      continue;
    }
    reread = 0;
    memcpy(prev, state, sizeof(sc_int) * (size_t)nb);
    memcpy(keep, lam, sizeof(double) * (size_t)m);
    ok = active_set(&p, Z, &near, s < chunk ? 20 : TRY_PASSES, rest, iw2, &passes, &defect,
                    res, 1, fkp);
    if (!ok && s == chunk) {
      memcpy(lam, keep, sizeof(double) * (size_t)m);
      if ((reread = ++fails == 2)) sc_update_w(&p); /* (w of this lam, for the reading) */
      else if (chunk < 16 * CHUNK) chunk *= 2;
    }
    else if (!ok)
      for (k = 0; k < nb; ++k) {
        sc_int r = start[k];
        if (kind[k] == K_UNILATERAL && lam[r] < 0) lam[r] = 0;
        if (kind[k] == K_BOX) lam[r] = fmax(-par[3 * k], fmin(par[3 * k], lam[r]));
      }
  }
  if (!ok && near.res <= NEAR_OK) { /* the best near miss (above): answered, flag 3; the
    barrier's point within the acceptance: an answer (its face's minimum-norm forces below) */
    memcpy(lam, near.lam, sizeof(double) * (size_t)m);
    for (k = 0; k < nb; ++k) state[k] = (sc_int)near.state[k];
    sc_update_w(&p);
    sc_kkt(&p, res, 0);
    ok = 1;
    if (near.res > TOL_ACCEPT) nearly = 1, dep = 3;
    else interior = 1; /* (forces inside the face's sets: not a basic solution) */
  }
  if (ok && !nearly && tight_scales(&p, G, m + 1, b)) { /* the sets far above the forces:
    the answer checked at the forces' scales, switched and solved again where it breaks them
    (the first answer kept, at the first scales, where that does not solve) */
    const double f0 = p.fscale, w0 = p.wscale, r0[3] = {res[0], res[1], res[2]};
    const sc_int d0 = defect;
    memcpy(keep, lam, sizeof(double) * (size_t)m);
    memcpy(prev, state, sizeof(sc_int) * (size_t)nb);
    if (sc_kkt(&p, res, 0), !(fmax(res[0], fmax(res[1], res[2])) <= TOL_ACCEPT) &&
        !active_set(&p, Z, &near, TRY_PASSES, rest, iw2, &passes, &defect, res, 1, fkp)) {
      memcpy(lam, keep, sizeof(double) * (size_t)m);
      memcpy(state, prev, sizeof(sc_int) * (size_t)nb);
      p.fscale = f0, p.wscale = w0, defect = d0;
      memcpy(res, r0, sizeof(r0));
      sc_update_w(&p);
    }
  }
  if (ok) { /* (w and res: the last pass's, of this lam, until lam moves; once it may have
    moved, both are taken again at the end, and until then only a pass's w is read) */
    int degenerate = (defect > 0 || interior) && !nearly, moved = 0; /* (a near miss: its
      forces, flag 3) */
    for (k = 0; k < nb && !degenerate && !nearly; ++k)
      if (state[k] != S_HELD && sc_still(&p, k)) degenerate = 1;
    if (degenerate) { /* (a from the face's basic forces: the minimum-norm choice's rounding
      would reach a system that does not move; from the new forces where nearly dependent rows
      taken as dependent move it, by 5e-10 of its scale at most, and the KKT conditions hold) */
      memcpy(keep, lam, sizeof(double) * (size_t)m);
      if ((dep = sc_min_norm_face(&p, Z, rest, 1e-13, 5e-10, fkp)) == 3) {
        if (zw) sc_rescue_w(&p, Z, a, c, rest); else sc_update_w(&p);
        if (sc_kkt(&p, res, 0), !(fmax(res[0], fmax(res[1], res[2])) <= TOL_ACCEPT))
          memcpy(lam, keep, sizeof(double) * (size_t)m), dep = 2;
      }
      acc = dep == 3 ? lam : keep, dep = dep == 3 ? 1 : dep, moved = 1;
      /* a held contact the choice leaves without force and acceleration reads open (both
       * pieces hold; the open one starts a batch's next sample with fewer dependent rows) */
      for (k = 0; k < nb && dep == 1; ++k)
        if (kind[k] == K_UNILATERAL && state[k] == S_HELD &&
            lam[start[k]] <= 1e-12 * p.fscale && sc_still(&p, k))
          state[k] = S_ZERO;
    }
    int clip = 0; /* a contact's force below zero by rounding: zero (before: zero, prev) */
    for (k = 0; k < nb; ++k)
      if (kind[k] == K_UNILATERAL && (lam[start[k]] < 0 || acc[start[k]] < 0)) {
        if (!clip++)
          memcpy(zero, lam, sizeof(double) * (size_t)m), memcpy(prev, state, sizeof(sc_int) * nb);
        lam[start[k]] = fmax(lam[start[k]], 0.0);
        if (acc == keep) keep[start[k]] = fmax(keep[start[k]], 0.0);
        moved = 1;
      }
    for (j = 0; j < 2 && moved; ++j) { /* (w from Z where the rescue solved: G's rounding
      times its large forces) */
      if (zw) sc_rescue_w(&p, Z, a, c, rest); else sc_update_w(&p);
      if (sc_kkt(&p, res, 0), !clip || fmax(res[0], fmax(res[1], res[2])) <= TOL_ACCEPT) break;
      for (k = 0, clip = 0; k < nb; ++k) /* not rounding (a held face's dependent rows): those
        contacts opened and the piece solved again, else the answer before the clip (its
        negative forces within the acceptance) */
        if (kind[k] == K_UNILATERAL && state[k] == S_HELD && zero[start[k]] < 0) state[k] = S_ZERO;
      if (active_set(&p, Z, &near, TRY_PASSES, rest, iw2, &passes, &defect, res, 1, fkp))
        dep = defect > 0 ? 2 : 0, acc = lam, moved = 0;
      else memcpy(lam, zero, sizeof(double) * (size_t)m), memcpy(state, prev, sizeof(sc_int) * nb);
    }
  }
answered:
  if (ok && !(fmax(res[0], fmax(res[1], res[2])) <= TOL_ACCEPT)) /* the answer's own residuals
    decide what it is: above the acceptance a near miss (flag 3), above NEAR_OK none */
    fmax(res[0], fmax(res[1], res[2])) <= NEAR_OK ? (void)(dep = 3) : (void)(ok = 0);
  info[INFO_STATUS] = ok ? ST_SOLVED : ST_NOT_CONVERGED;
  info[INFO_DEPENDENT] = (double)dep;
  info[INFO_PRIMAL] = res[0];
  info[INFO_DUAL] = res[1];
  info[INFO_COMPL] = res[2];
  info[INFO_SWEEPS] = (double)total_sweeps;
  info[INFO_PASSES] = (double)passes;
  info[INFO_RANK_DEFECT] = (double)defect;
  if (ok) /* on the set's boundary without sliding: stick at the limit */
    for (k = 0; k < nb; ++k)
      if (state[k] == S_SLIDE) {
        sc_int r = start[k], nk = sc_block_size(kind[k]);
        double e = 0.0;
        for (i = 0; i < nk; ++i) e = sc_max(e, fabs(w[r + i]));
        if (e <= TOL_ACCEPT * p.wscale) state[k] = S_HELD;
      }
  for (k = 0; k < nb; ++k) {
    double code = (double)state[k];
    if (state[k] == S_SLIDE && kind[k] == K_BOX) code = lam[start[k]] > 0 ? 3.0 : 4.0;
    state_out[k] = code;
  }
  /* eq. (18): a = M^-1 (f + A^T lam) = L^-T (g + Z lam) */
  for (j = k = 0; j < m && !primal; ++j) /* (the rows with a force listed once: iw2 is free
    by now; the primal's g + Z lam at the start of rest) */
    if (acc[j] != 0.0 && isfinite(acc[j])) iw2[k++] = j;
  for (i = 0; i < n; ++i) { /* (summed in a register: a and Z may alias for the compiler) */
    const double *zi = Z + i * m;
    double t = primal ? rest[i] : a[i];
    for (j = 0; j < k; ++j) t += zi[iw2[j]] * acc[iw2[j]];
    a[i] = t;
  }
  if (n == SNAKECG_NS && t == SNAKECG_NS) back_ns(L, a);
  else
    for (i = n - 1; i >= 0; --i) { /* (by L's rows, contiguous: vectorised; its rows from t
      on are their diagonal) */
      const double ai = a[i] / L[i * n + i], *restrict li = L + i * n;
      double *restrict ak = a;
      a[i] = ai;
      for (k = 0; k < (i < t ? i : 0); ++k) ak[k] -= li[k] * ai;
    }
  if (!ok) {
    for (i = 0; i < n; ++i) a[i] = NAN;
    for (i = 0; i < m; ++i) lam[i] = NAN;
  }
}

/* Scratch sizes (doubles, sc_ints) for n coordinates, m rows, nb blocks. */
void SNAKECG_EXPORT(core_scene_solve_work)(sc_int n, sc_int m, sc_int nb, sc_int *nd, sc_int *ni) {
  *nd = n * n + n * m + m * m + m + nb + 2 * m + rest_size(n, m, nb) + (m + nb); /* (the
        last: the near miss kept) */
  *ni = 3 * nb + 4 * (m + nb) + 16 + n; /* (prev's 3 nb: the rescue's reading and switches
    among them; past them, the barrier's n) */
}

/* A batch of samples of equal sizes n; sample s has m[s] rows and nb[s] blocks (padded to
 * mmax, nbmax in the arrays). Inputs per sample at s * (n n), s * n, s * (mmax n),
 * s * mmax (the rows' offsets c, or NULL: none), s * nbmax, s * 3 nbmax. Outputs: lam, w
 * (mmax), a (n), state (nbmax), info (INFO_WIDTH). Returns 0, -1 when out of memory, -2
 * when a size is out of range. */
int SNAKECG_EXPORT(core_scene_solve_b)(sc_int ns, sc_int n, sc_int mmax, sc_int nbmax,
                                       const sc_int *m, const sc_int *nb, const double *M,
                                       const double *f, const double *A, const double *c,
                                       const sc_int *kind, const sc_int *start,
                                       const double *par, sc_int max_sweeps, double *lam,
                                       double *a, double *w, double *state, double *info) {
  sc_int nd, ni, s;
  double *work;
  sc_int *iwork;
  if (n < 1 || n > 512 || mmax < 0 || mmax > 500 || nbmax < 0 || nbmax > mmax) return -2;
  SNAKECG_EXPORT(core_scene_solve_work)(n, mmax, nbmax, &nd, &ni);
  work = (double *)malloc(sizeof(double) * (size_t)nd);
  iwork = (sc_int *)malloc(sizeof(sc_int) * (size_t)ni);
  if (!work || !iwork) {
    free(work);
    free(iwork);
    return -1;
  }
  for (s = 0; s < ns; ++s) {
    if (m[s] < 0 || m[s] > mmax || nb[s] < 0 || nb[s] > nbmax) {
      free(work);
      free(iwork);
      return -2;
    }
    solve_sample(n, m[s], nb[s], M + s * n * n, f + s * n, A + s * mmax * n,
                 c ? c + s * mmax : NULL, kind + s * nbmax, start + s * nbmax,
                 par + s * 3 * nbmax, max_sweeps, NULL, lam + s * mmax, a + s * n,
                 w + s * mmax, state + s * nbmax, info + s * INFO_WIDTH, work, iwork, 1, 0);
  }
  free(work);
  free(iwork);
  return 0;
}

/* One sample of core_scene_solve_b (offsets c), its active set tried first from the pieces
 * `from` (3 per block; NULL: none). Returns 0, -1 out of memory, -2 sizes out of range. */
int SNAKECG_EXPORT(core_scene_solve_s)(sc_int n, sc_int m, sc_int nb, const double *M,
                                       const double *f, const double *A, const double *c,
                                       const sc_int *kind, const sc_int *start,
                                       const double *par, sc_int max_sweeps,
                                       const double *from, double *lam, double *a, double *w,
                                       double *state, double *info) {
  return sc_scene_solve_one(n, m, nb, M, f, A, c, kind, start, par, max_sweeps, from, lam, a, w,
                            state, info, 1, 0);
}

SC_INTERNAL int sc_scene_solve_one(sc_int n, sc_int m, sc_int nb, const double *M,
                                   const double *f, const double *A, const double *c,
                                   const sc_int *kind, const sc_int *start, const double *par,
                                   sc_int max_sweeps, const double *from, double *lam,
                                   double *a, double *w, double *state, double *info,
                                   int tiny, sc_solve_keep *kp) {
  sc_int nd, ni, iws[256];
  double *work, ws[10240]; /* (scratch on the stack up to 80 KB, no allocation: a time step's
    problems, 13 coordinates and up to 33 rows on the pegs row, are 8,000-10,000 doubles) */
  sc_int *iwork;
  if (n < 1 || n > 512 || m < 0 || m > 500 || nb < 0 || nb > m) return -2;
  SNAKECG_EXPORT(core_scene_solve_work)(n, m, nb, &nd, &ni);
  work = nd <= 10240 ? ws : (double *)malloc(sizeof(double) * (size_t)nd);
  iwork = ni <= 256 ? iws : (sc_int *)malloc(sizeof(sc_int) * (size_t)ni);
  if (work && iwork)
    solve_sample(n, m, nb, M, f, A, c, kind, start, par, max_sweeps, from, lam, a, w, state,
                 info, work, iwork, tiny, kp);
  if (work != ws) free(work);
  if (iwork != iws) free(iwork);
  return work && iwork ? 0 : -1;
}

/* core_scene_solve_b with no offsets (w = A a): the solve at rest. */
int SNAKECG_EXPORT(core_scene_solve)(sc_int ns, sc_int n, sc_int mmax, sc_int nbmax,
    const sc_int *m, const sc_int *nb, const double *M, const double *f, const double *A,
    const sc_int *kind, const sc_int *start, const double *par, sc_int max_sweeps,
    double *lam, double *a, double *w, double *state, double *info) {
  return SNAKECG_EXPORT(core_scene_solve_b)(ns, n, mmax, nbmax, m, nb, M, f, A, NULL, kind,
                                            start, par, max_sweeps, lam, a, w, state, info);
}
