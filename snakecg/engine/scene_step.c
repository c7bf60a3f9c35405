/* snakecg's engine: one time step of a general scene (snakecg/scenes/stepping.py states the
 * scheme: velocity-level steps on the exact solve, Stewart & Trinkle 1996, Anitescu & Potra
 * 1997), in one call.
 *
 * From (x, V) (x = (q, q_obj), V = (v, v_obj)) and the rows found at x (scene_rows.c's
 * sc_scene_state_rows, kept in the caller's buffers from the step before), a step of length h:
 *   1. the bias forces h_s(q, v) (the generated `bias_forces_cs`, from the links' cos and sin
 *      that the rows at x took, scene_rows.h; else `bias_forces`), the generalized force
 *      fgen = B tau - h_s + E f_obj and f = M V + h fgen;
 *   2. the exact solve (scene_tiny.c's tiny path, else scene_solve.c's general one past it;
 *      with contact friction scene_friction.c's on the tangent rows too) with the friction
 *      sets' sizes times h and the contacts' offsets gap / h (none within GAP_BAND of the
 *      tolerance): V+, its active set started from the last step's pieces (consecutive steps
 *      almost always have the same; they are kept at the step's end, 6.);
 *   3. x+ = x + h V+ and the rows there; a pair overlapping beyond the tolerance refuses the
 *      step (STEP_OVERLAP, V+ kept for the caller's root finding, nothing else changed);
 *   4. the step's work: the torques' h tau . v+, the ground's dissipation -lam . (A V+), the
 *      contacts' work and impulse, the sliding sets' impulse against their velocity (the
 *      cosine), the solve's largest residuals;
 *   5. an inelastic impact where a contact new at x+ closes faster than impact_speed: the same
 *      solve with h = 0 (no friction impulse at the ground, whose forces are finite; ideal
 *      wheels take impulses; a contact's friction impulse within mu times its normal
 *      impulse, Coulomb's law on the velocities after) on A V >= 0; its kinetic energy loss;
 *   6. x, V and the rows replaced by the step's end; its kinetic energy, smallest contact gap
 *      and contact count.
 * h = 0: the rows at x alone (the run's start).
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_rows.h"
#include "scene_solve.h"
#include "scene_step.h"
#include "scene_tiny.h"

/* the run's accumulators and the last step's figures (ST_*, snakecg/scenes/run_record.py's),
 * a step's status (STEP_*, or SS_OVERLAP, SS_MORE, SS_FAILED: the rows at the end refused):
 * engine.h */
enum { SOLVE_INFO = 8 }; /* the solve's certificate: status, dependent, primal, dual, compl.. */
#define SC_STEP_SWEEPS 200000 /* snakecg.scenes.solve.MAX_SWEEPS */
/* a step after one whose overlaps were held for want of a converged push-out (quick) tries
 * the push-out with these sweeps at most: where its rows are the same, it fails again */
#define SC_QUICK_SWEEPS 5000
/* a contact's gap within this of the tolerance from zero takes no offset: what a step's
 * gap stabilisation leaves (second order, ~1e-11 m) would else ask dependent contacts (a
 * snake jammed among pegs) for offsets that no velocity meets, above the solve's acceptance */
#define GAP_BAND 1e-3
/* a push-out that gives the state more kinetic energy than its free motion's by more than this
 * times the energy of pushing each overlap out alone is a jam (its rows nearly dependent:
 * velocities of tens of m/s for 1e-5 m); the step holds its overlaps instead */
#define JAM_RATIO 1e4

/* One call's arguments (sc_scene_step of engine.h; snakecg/engine/binding.py mirrors them as
 * SceneStep): pk the packed scene; tol, h, impact_speed: contact tolerance (m), step (s),
 * closing speed (m/s); tau (NA), fo (3 n_o) held over the step; x, V (n each) the state,
 * replaced by the step's end when accepted; ccap, mcap room for contacts and rows; M, A, par,
 * out, kind, start the rows at x (sc_scene_state_rows' outputs); M1 .. start1
 * scratch: the rows at the step's end, swapped with M .. start (the pointers) where the step
 * is accepted; Vp (n) the step's V+ (before an impact); lam, info
 * (mcap, SOLVE_INFO) the step's solve, ilam, iinfo the impact's; acc (ST_WIDTH); status
 * STEP_* or SS_*; from (6 mcap + 2, or NULL: every solve from scratch), nfrom: the last
 * accepted step's pieces on the rows at x (3 per block: state, forces / h; its blocks' count;
 * 0: none), the run's own; then at from + 3 mcap that step's own forces (the pieces' before
 * their extrapolation, keep_pieces), from[6 mcap] their blocks' count and from[6 mcap + 1]
 * that step's h; hold: 1 for a step that holds the overlaps (offsets 0, not gap / h: the run's
 * retry where pushing them out asks for what no velocity gives, scene_run.c); quick: 1 after a
 * step that the run held so (SC_QUICK_SWEEPS). */

static double quad(sc_int n, const double *M, const double *v) {
  double s = 0.0;
  sc_int i, j;
  for (i = 0; i < n; ++i) {
    double t = 0.0;
    for (j = 0; j < n; ++j) t += M[i * n + j] * v[j];
    s += v[i] * t;
  }
  return s;
}

/* t = M V (n x n row-major): each t_k summed over j in order, as quad's; for the snake alone
 * (n = n_s) and the snake with one object (n = n_s + 3, the paper's push), sizes known when
 * compiling, two rows at a time (GCC's vector types), the same sums bit for bit. */
#if defined(__GNUC__)
typedef double __attribute__((vector_size(16))) mv_v2;
static inline __attribute__((always_inline)) void mv_fixed(const sc_int N, const double *M,
                                                           const double *V, double *t) {
  sc_int i, j;
  SC_UNROLL for (i = 0; i + 1 < N; i += 2) {
    mv_v2 s = {0.0, 0.0};
    SC_UNROLL for (j = 0; j < N; ++j) s += (mv_v2){M[i * N + j], M[(i + 1) * N + j]} * V[j];
    t[i] = s[0], t[i + 1] = s[1];
  }
  for (; i < N; ++i) { /* (an odd n: the last row) */
    double s = 0.0;
    SC_UNROLL for (j = 0; j < N; ++j) s += M[i * N + j] * V[j];
    t[i] = s;
  }
}
#endif

static void mv_sums(sc_int n, const double *M, const double *V, double *t) {
  sc_int i, j;
#if defined(__GNUC__)
  if (n == SNAKECG_NS) {
    mv_fixed(SNAKECG_NS, M, V, t);
    return;
  }
  if (n == SNAKECG_NS + 3) {
    mv_fixed(SNAKECG_NS + 3, M, V, t);
    return;
  }
#endif
  for (i = 0; i < n; ++i) {
    double s = 0.0;
    for (j = 0; j < n; ++j) s += M[i * n + j] * V[j];
    t[i] = s;
  }
}

/* The solve of the rows in c's buffers at force f, the sets' sizes times h, the contacts'
 * offsets gap / h (h = 0: none), from the last step's pieces where c keeps them (h > 0):
 * a (n), lam, info, the blocks' states (scratch + 5 mcap). Returns core_scene_solve_s's
 * code. */
static int solve(sc_scene_step *c, sc_int n, double h, const double *f, double *scratch,
                 double *a, double *lam, double *info) {
  sc_int m = (sc_int)c->out[RO_M], nb = (sc_int)c->out[RO_NB], nc = (sc_int)c->out[RO_NC];
  double *rec = c->out + RO_POSE + 3 * (sc_int)c->pk[SP_NO], unique;
  double *par = scratch, *off = par + 3 * c->mcap, *w = off + c->mcap, *st = w + c->mcap,
         *from = st + c->mcap; /* the pieces' forces (kept per second) times h */
  sc_int b, k;
  /* from the last step's pieces (an impact from scratch: measured as cheap, 1 pass after 4
   * sweeps, against 2.3 passes from the step's pieces) */
  const int warm = c->from && c->nfrom == nb && h > 0;
  const sc_int sweeps = c->quick && !c->hold && h > 0 ? SC_QUICK_SWEEPS : SC_STEP_SWEEPS;
  for (b = 0; b < nb; ++b) { /* (times 1.0 where not sized: the same number) */
    const sc_int kd = c->kind[b];
    const double s = kd == K_BOX || kd == K_DISC || kd == K_SPLIT ? h : 1.0, *q = c->par + 3 * b;
    par[3 * b] = q[0] * s, par[3 * b + 1] = q[1] * s, par[3 * b + 2] = q[2] * s;
  }
  for (k = 0; k < m; ++k) off[k] = 0.0;
  for (k = 0; h > 0 && k < nc; ++k) { /* (a gap within GAP_BAND of zero: none; held: an
    overlap is not pushed out) */
    double g = rec[CR_W * k + 10];
    off[c->start[k]] = fabs(g) > GAP_BAND * c->tol && !(c->hold && g < 0) ? g / h : 0.0;
  }
  if (warm) {
    const double *restrict fr = c->from;
    double *restrict to = from;
    for (b = 0; b < nb; ++b) {
      to[3 * b] = fr[3 * b];
      to[3 * b + 1] = fr[3 * b + 1] * h;
      to[3 * b + 2] = fr[3 * b + 2] * h;
    }
  }
  /* (with contact friction: scene_friction.c's solve on the tangent rows after the m rows,
   * an impact's too: its friction impulses within mu times its normal impulses) */
  if (c->pk[SP_FRICTION] == 0) { /* (the convex solve: the tiny path first, as
    core_scene_solve_s; the wrappers' sizes and scratch only where it declines) */
    if (sc_tiny_solve(n, m, nb, c->M, f, c->A, off, c->kind, c->start, par, warm ? from : NULL,
                      lam, a, w, st, info))
      return 0;
    return sc_scene_solve_one(n, m, nb, c->M, f, c->A, off, c->kind, c->start, par,
                              sweeps, warm ? from : NULL, lam, a, w, st, info, 0, 0);
  }
  return sc_friction_solve(n, m, nb, nc, c->M, f, c->A, off, c->kind, c->start, par,
                           c->A + m * n, rec, sweeps, warm ? from : NULL, lam, a, w,
                           st, info, &unique);
}

/* y := L^-1 y (sc_ldl_factor's unit lower L, n x n); returns y^T D^-1 y, that is the form
 * y^T M^-1 y of the y given */
static double inverse_form(sc_int n, const double *L, const double *dinv, double *y) {
  double s = 0.0;
  sc_int i, k;
  for (i = 0; i < n; ++i) {
    for (k = 0; k < i; ++k) y[i] -= L[i + n * k] * y[k];
    s += y[i] * y[i] * dinv[i];
  }
  return s;
}

/* Whether the step's V+ (c->Vp) from f = M V* pushes its overlaps out as a jam does
 * (JAM_RATIO): mv = M V, w (n n + 4 n) scratch, off the solve's offsets (< 0: an overlap
 * pushed out). */
static int jammed(const sc_scene_step *c, sc_int n, const double *f, const double *mv,
                  const double *off, double *w) {
  const sc_int nc = (sc_int)c->out[RO_NC];
  const double ke = 0.5 * quad(n, c->M, c->Vp);
  double *L = w, *d = L + n * n, *dinv = d + n, *y = dinv + n, alone = 0.0, below = 0.0;
  sc_int k;
  for (k = 0; k < nc && !(off[c->start[k]] < 0.0); ++k) continue;
  if (k == nc) return 0; /* (nothing pushed out) */
  for (k = 0; k < n; ++k) below += c->V[k] * (f[k] - 0.5 * mv[k]);
  if (!(ke > below)) return 0; /* (below the free motion's 1/2 f^T M^-1 f = below + h^2 / 2
    g^T M^-1 g, g the generalized force: no energy above it, most steps, no factor) */
  if (!(sc_ldl_factor(n, c->M, n, NULL, L, n, d, dinv, NULL, 0.0, y) > 0.0)) return 0;
  for (k = 0; k < nc; ++k) { /* 1/2 off_k^2 / (a_k M^-1 a_k^T), each overlap alone */
    const double o = off[c->start[k]];
    if (!(o < 0.0)) continue;
    memcpy(y, c->A + c->start[k] * n, sizeof(double) * (size_t)n);
    alone += 0.5 * o * o / inverse_form(n, L, dinv, y);
  }
  memcpy(y, f, sizeof(double) * (size_t)n); /* the free motion's 1/2 f^T M^-1 f */
  return ke - 0.5 * inverse_form(n, L, dinv, y) > JAM_RATIO * alone;
}

/* The step's pieces (the solve's states st and impulses lam on the rows at x) as the start of
 * the next step's solve on the rows at its end (c->from, 3 per block: state, forces lam / h):
 * the ground's blocks are the same; a contact is the one of the same bodies, the same count
 * of that pair's contacts before it, else new: held at zero force. Where the step before had
 * the same length and, on a block, the same state, its forces extrapolated linearly from that
 * step's (kept at c->from + 3 mcap; not after an impact, nor with contact friction, whose
 * fixed point starts otherwise), 2 lam - lam_before: the next step's exact solve starts nearer
 * its answer (its first Newton step on the pegs row 5.7e-5 -> 2.6e-6 of y, median), the same
 * answer. d: 3 mcap scratch. */
static void keep_pieces(sc_scene_step *c, sc_int no, const double *st, double *d, int impact) {
  const sc_int nc0 = (sc_int)c->out[RO_NC], nc1 = (sc_int)c->out1[RO_NC],
               nb1 = (sc_int)c->out1[RO_NB], mc = c->mcap;
  const double *r0 = c->out + RO_POSE + 3 * no, *r1 = c->out1 + RO_POSE + 3 * no, h = c->h;
  const double *lam = c->lam;
  const sc_int *start = c->start, *kind1 = c->kind1;
  double *last = c->from + 3 * mc; /* (the step before's forces on the rows at x) */
  sc_int k, j, i;
  const int ex = !impact && c->pk[SP_FRICTION] == 0 && last[3 * mc] == c->out[RO_NB] &&
                 last[3 * mc + 1] == h;
  for (k = 0; k < nb1; ++k) {
    double *s = c->from + 3 * k;
    sc_int old = -1;
    if (k < nc1) {
      const double *a = r1 + CR_W * k;
      sc_int before = 0;
      for (i = 0; i < k; ++i) before += r1[CR_W * i] == a[0] && r1[CR_W * i + 1] == a[1] &&
                                        r1[CR_W * i + 2] == a[2] && r1[CR_W * i + 3] == a[3];
      for (j = 0; j < nc0 && old < 0; ++j) {
        const double *b = r0 + CR_W * j;
        if (b[0] == a[0] && b[1] == a[1] && b[2] == a[2] && b[3] == a[3] && before-- == 0)
          old = j;
      }
    } else {
      old = nc0 + k - nc1;
    }
    s[0] = old < 0 ? (double)S_HELD : st[old];
    s[1] = s[2] = 0.0;
    for (i = 0, j = old < 0 ? 0 : sc_block_size(kind1[k]); i < j; ++i)
      s[1 + i] = lam[start[old] + i] / h;
    d[3 * k] = s[0], d[3 * k + 1] = s[1], d[3 * k + 2] = s[2]; /* (this step's own) */
    for (i = 0; ex && old >= 0 && last[3 * old] == s[0] && i < j; ++i)
      s[1 + i] += s[1 + i] - last[3 * old + 1 + i];
  }
  memcpy(last, d, sizeof(double) * (size_t)(3 * nb1));
  last[3 * mc] = impact ? 0.0 : (double)nb1; /* (after an impact: none extrapolated from these) */
  last[3 * mc + 1] = h;
  c->nfrom = nb1;
}

/* The step's work (4.) from the rows at x, the impulses lam and V+; the rows' velocities A V+
 * from the solve's w = A V+ + off (every row's, off its offsets: solve's). */
static void step_work(sc_scene_step *c, const double *Vp, const double *ws, const double *off,
                      int held) {
  const sc_int nb = (sc_int)c->out[RO_NB] + (c->pk[SP_FRICTION] != 0) * (sc_int)c->out[RO_NC];
  double *acc = c->acc, impulse = 0.0, cmin = 2.0, t = 0.0;
  sc_int b, r, j;
  for (j = 3; j < SNAKECG_NS; ++j) t += c->tau[j - 3] * Vp[j];
  acc[ST_WORK_TAU] += c->h * t;
  for (b = 0; b < nb; ++b) {
    sc_int kd = c->kind[b], size = sc_block_size(kd);
    double w[2] = {0.0, 0.0}, sp = 0.0, ln = 0.0, dot = 0.0;
    for (r = 0; r < size; ++r) {
      const double l = c->lam[c->start[b] + r];
      w[r] = ws[c->start[b] + r] - off[c->start[b] + r];
      if (kd == K_BOX || kd == K_DISC || kd == K_SPLIT) acc[ST_FRICTION] -= l * w[r];
      if (kd == K_UNILATERAL) {
        acc[ST_CONTACT_WORK] += l * w[r];
        impulse += l;
      }
      sp += w[r] * w[r];
      ln += l * l;
      dot += l * w[r];
    }
    if (kd != K_DISC && kd != K_BOX) continue; /* (the cosine: a friction set's alone) */
    sp = sqrt(sp);
    ln = sqrt(ln);
    if (sp > 1e-9 && ln > 0 && -dot / (sp * ln) < cmin) cmin = -dot / (sp * ln);
  }
  acc[ST_CONTACT_IMPULSE] = impulse;
  if (cmin <= 1.0) /* kinetic friction against the sliding: 1 */
    acc[ST_SLIDING_COS] = acc[ST_SLIDING_COS] < 0 ? cmin : fmin(acc[ST_SLIDING_COS], cmin);
  for (j = 0; j < 3; ++j)
    acc[ST_PRIMAL + j] = fmax(acc[ST_PRIMAL + j], c->info[2 + j]);
  acc[ST_STEPS] += 1.0;
  acc[ST_HELD] += held;
}

/* The contact k of rows `out` is one at rows `old` too (the same bodies). */
static int held_before(const double *old, const double *out, sc_int no, sc_int k) {
  const double *a = out + RO_POSE + 3 * no + CR_W * k, *r = old + RO_POSE + 3 * no;
  sc_int j, nc = (sc_int)old[RO_NC];
  for (j = 0; j < nc; ++j, r += CR_W)
    if (r[0] == a[0] && r[1] == a[1] && r[2] == a[2] && r[3] == a[3]) return 1;
  return 0;
}

/* The kinetic energy, smallest contact gap and contact count of the state in c; mv (3 n): M V
 * (quad's sums, the next step's M V in f: the same M and V unless the caller moved x or V),
 * then the x and V it belongs to. */
static void figures(sc_scene_step *c, sc_int n, double *mv) {
  const sc_int no = (sc_int)c->pk[SP_NO], nc = (sc_int)c->out[RO_NC];
  double g = INFINITY, s = 0.0;
  sc_int k;
  for (k = 0; k < nc; ++k) g = fmin(g, c->out[RO_POSE + 3 * no + CR_W * k + 10]);
  mv_sums(n, c->M, c->V, mv); /* (quad's sums) */
  for (k = 0; k < n; ++k) s += c->V[k] * mv[k];
  memcpy(mv + n, c->x, sizeof(double) * (size_t)n);
  memcpy(mv + 2 * n, c->V, sizeof(double) * (size_t)n);
  c->acc[ST_KE] = 0.5 * s;
  c->acc[ST_MIN_GAP] = g;
  c->acc[ST_NC] = (double)nc;
}

/* A run's scratch of its steps, kept from one to the next (sc_scene_step_kept): the bias
 * forces' work, the step's doubles (then 3 n: figures' M V and its x and V; n_s + 2 n_l: the
 * last rows' q and their links' cos and sin), the rows' scratch (scene_rows.c's). */
typedef struct { sc_work_t ws; double *d, *qcs; void *rows; } step_keep;

/* The links' cos and sin of the last rows (at x, status 0) with their q, into qcs. */
static void rows_cs(const step_keep *k, const double *x, double *qcs) {
  memcpy(qcs, x, sizeof(double) * SNAKECG_NS);
  memcpy(qcs + SNAKECG_NS, sc_scene_rows_cs(k->rows), sizeof(double) * 2 * SNAKECG_NL);
}

/* The links' cos and sin at x where the last rows of the steps keeping their scratch in keep
 * were taken at x's q, else null: scene_step.h. */
SC_INTERNAL const double *sc_scene_step_cs(const void *keep, const double *x) {
  const step_keep *k = (const step_keep *)keep;
  if (!k || !k->qcs || memcmp(k->qcs, x, sizeof(double) * SNAKECG_NS)) return 0;
  return k->qcs + SNAKECG_NS;
}

static void keep_free(step_keep *k) {
  if (!k) return;
  sc_work_free(&k->ws);
  free(k->d);
  free(k->rows);
  free(k);
}

/* One step (or, h = 0, the rows at x): c->status says how it ended. Returns 0, -1 out of
 * memory, -2 on sizes out of range, -3 on a state not finite. */
int SNAKECG_EXPORT(core_scene_step)(sc_scene_step *c) {
  void *keep = 0;
  int code = sc_scene_step_kept(c, &keep);
  keep_free((step_keep *)keep);
  return code;
}

/* core_scene_step with its scratch kept in *keep (null at a run's first step; the same c's
 * sizes at every call), for the next step; c null: *keep freed. */
SC_INTERNAL int sc_scene_step_kept(sc_scene_step *c, void **keep) {
  const double *pk = c ? c->pk : 0;
  const sc_int no = c ? (sc_int)pk[SP_NO] : 0, n = SNAKECG_NS + 3 * no, mc = c ? c->mcap : 0;
  const sc_work_fn fns[] = {SNAKECG_BF_WORK, SNAKECG_BC_WORK};
  const sc_int nd = 7 * n + SNAKECG_NS + 9 * mc + 8 + n * n + 4 * n; /* (then the rows' q and
    cs) */
  step_keep *kp = (step_keep *)*keep;
  double *d, *f, *fgen, *hb, *xp, *scratch, *mv, *qcs;
  int bc, held = c ? c->hold != 0 : 0;
  sc_int i, j, k, nc1;
  int code;
  if (!c) {
    keep_free(kp);
    *keep = 0;
    return 0;
  }
  if (!kp) { /* (freed by the caller, whole or in part) */
    if (!(*keep = kp = (step_keep *)calloc(1, sizeof(step_keep)))) return -1;
    if (sc_work_alloc(&kp->ws, fns, SC_COUNT(fns))) return -1;
    kp->d = (double *)malloc(sizeof(double) * (size_t)(nd + SNAKECG_NS + 2 * SNAKECG_NL));
    if (!kp->d) return -1;
    for (i = 0; i < n; ++i) kp->d[nd - 2 * n + i] = NAN;
    for (i = 0; i < SNAKECG_NS; ++i) kp->d[nd + i] = NAN;
  }
  mv = kp->d + nd - 3 * n; /* (M V, x, V: none yet) */
  qcs = kp->qcs = kp->d + nd; /* (the rows' q, cs: none yet) */
  c->acc[ST_IMPACT] = 0.0;
  c->acc[ST_LOSS] = 0.0;
  if (!(c->h > 0)) {
    c->nfrom = 0; /* no pieces yet */
    if (c->from) c->from[6 * mc] = 0.0;
    code = sc_scene_state_rows(pk, c->x, c->x + SNAKECG_NS, c->tol, c->ccap, mc, c->out, c->M,
                               c->A, c->par, c->kind, c->start, &kp->rows);
    if (code < 0) return code;
    c->status = code;
    if (code == 0) figures(c, n, mv), rows_cs(kp, c->x, qcs);
    return 0;
  }
  { /* (x - x is 0 where x is finite, NaN where not: one test for the 2 n numbers) */
    const double *restrict x = c->x, *restrict V = c->V;
    double z = 0.0;
    for (i = 0; i < n; ++i) z += (x[i] - x[i]) + (V[i] - V[i]);
    if (z != 0.0) return -3;
  }
  d = kp->d;
  f = d;
  fgen = f + n;
  xp = fgen + n;
  hb = xp + n;
  scratch = hb + SNAKECG_NS; /* 9 mcap: the solve's sizes, offsets, w, states, start; then
    n n + 4 n: jammed's */
  /* 1.: from the links' cos and sin where the rows at x took them (the same sums, rounding) */
  bc = memcmp(qcs, c->x, sizeof(double) * SNAKECG_NS) == 0;
  kp->ws.arg[bc ? BC_IN_q : BF_IN_q] = c->x;
  kp->ws.arg[bc ? BC_IN_v : BF_IN_v] = c->V;
  kp->ws.arg[bc ? BC_IN_K : BF_IN_K] = pk + (sc_int)pk[SP_K];
  if (bc) kp->ws.arg[BC_IN_cs] = qcs + SNAKECG_NS;
  kp->ws.res[bc ? BC_OUT_h : BF_OUT_h] = hb;
  if (bc ? SNAKECG_BC(kp->ws.arg, kp->ws.res, kp->ws.iw, kp->ws.w, 0)
         : SNAKECG_BF(kp->ws.arg, kp->ws.res, kp->ws.iw, kp->ws.w, 0)) {
    c->status = SS_FAILED;
    return 0;
  }
  for (i = 0; i < 3; ++i) fgen[i] = 0.0 - hb[i];
  for (i = 3; i < SNAKECG_NS; ++i) fgen[i] = (0.0 + c->tau[i - 3]) - hb[i];
  for (i = SNAKECG_NS; i < n; ++i) fgen[i] = c->fo[i - SNAKECG_NS];
  if (memcmp(mv + n, c->x, sizeof(double) * (size_t)n) ||
      memcmp(mv + 2 * n, c->V, sizeof(double) * (size_t)n)) { /* (else the last figures') */
    mv_sums(n, c->M, c->V, mv);
    memcpy(mv + n, c->x, sizeof(double) * (size_t)n);
    memcpy(mv + 2 * n, c->V, sizeof(double) * (size_t)n);
  }
  {
    const double h = c->h, *restrict m = mv, *restrict g = fgen;
    double *restrict fo = f;
    for (i = 0; i < n; ++i) fo[i] = m[i] + h * g[i];
  }
  code = solve(c, n, c->h, f, scratch, c->Vp, c->lam, c->info); /* 2. */
  if (!code && c->info[0] == 0.0 && !c->hold &&
      jammed(c, n, f, mv, scratch + 3 * mc, scratch + 9 * mc)) { /* held instead */
    c->hold = held = 1; /* (kept: the run's retries of this step hold them too) */
    code = solve(c, n, c->h, f, scratch, c->Vp, c->lam, c->info);
  }
  if (code || c->info[0] != 0.0) {
    c->status = STEP_NOT_CONVERGED;
    return code == -1 ? -1 : 0;
  }
  { /* 3. */
    const double h = c->h, *restrict x = c->x, *restrict vp = c->Vp;
    double *restrict y = xp;
    for (i = 0; i < n; ++i) y[i] = x[i] + h * vp[i];
  }
  code = sc_scene_state_rows(pk, xp, xp + SNAKECG_NS, c->tol, c->ccap, mc, c->out1, c->M1,
                             c->A1, c->par1, c->kind1, c->start1, &kp->rows);
  if (code != 0) {
    c->status = code > 0 ? code : c->status;
    return code < 0 ? code : 0;
  }
  step_work(c, c->Vp, scratch + 4 * mc, scratch + 3 * mc, held); /* 4. */
  nc1 = (sc_int)c->out1[RO_NC];
  {
    int impact = 0; /* 5.: a new contact closing */
    for (k = 0; k < nc1 && !impact; ++k) {
      double vn = 0.0;
      if (held_before(c->out, c->out1, no, k)) continue;
      for (j = 0; j < n; ++j) vn += c->A1[c->start1[k] * n + j] * c->Vp[j];
      impact = vn < -c->impact_speed;
    }
    if (c->from) keep_pieces(c, no, scratch + 5 * mc, scratch + 6 * mc, impact);
    memcpy(c->x, xp, sizeof(double) * (size_t)n); /* 6. */
    rows_cs(kp, c->x, qcs);
    memcpy(c->V, c->Vp, sizeof(double) * (size_t)n);
    { /* the rows at the end become the rows at x: the buffers swapped, not copied (the
      caller finds the current ones by their addresses in c) */
      double *t;
      sc_int *u;
      t = c->out, c->out = c->out1, c->out1 = t;
      t = c->M, c->M = c->M1, c->M1 = t;
      t = c->A, c->A = c->A1, c->A1 = t;
      t = c->par, c->par = c->par1, c->par1 = t;
      u = c->kind, c->kind = c->kind1, c->kind1 = u;
      u = c->start, c->start = c->start1, c->start1 = u;
    }
    c->status = STEP_DONE;
    if (impact) {
      double *v1 = fgen, e0 = quad(n, c->M, c->V);
      for (i = 0; i < n; ++i) {
        double t = 0.0;
        for (j = 0; j < n; ++j) t += c->M[i * n + j] * c->V[j];
        f[i] = t;
      }
      code = solve(c, n, 0.0, f, scratch, v1, c->ilam, c->iinfo);
      if (code || c->iinfo[0] != 0.0) {
        c->status = STEP_IMPACT_NOT_CONVERGED;
      } else {
        c->acc[ST_IMPACT] = 1.0;
        c->acc[ST_LOSS] = 0.5 * (e0 - quad(n, c->M, v1));
        c->acc[ST_IMPACT_LOSS] += c->acc[ST_LOSS];
        memcpy(c->V, v1, sizeof(double) * (size_t)n);
      }
    }
  }
  figures(c, n, mv);
  return code == -1 ? -1 : 0;
}
