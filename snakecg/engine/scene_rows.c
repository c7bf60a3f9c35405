/* snakecg's engine: the forward solve of a general scene at rest, per sample, in one call for a
 * batch: contacts found from geometry, the constraint rows, the exact solve, the metrics.
 *
 * Per sample (eqs. 7-30 of Reyes & Ma 2017, on any set of constraints):
 *   1. the link poses, the link Jacobians J_i (twist of link i's COM = J_i qdot, eq. 3), M_s
 *      (eq. 4) and the links' cos and sin: the generated function `scene_kinematics`;
 *   2. the objects placed (a pose, or touching a link on its side at an offset), every body's
 *      shape (scene_geometry.c); a broad phase of bounding circles, then the closest points of
 *      every pair that may touch (links with objects and obstacles, links that are not
 *      neighbours, objects with objects and obstacles); a pair that overlaps beyond the
 *      tolerance stops the sample (status OVERLAP, the pair and its depth reported); one
 *      unilateral row n . (v_B - v_A) >= 0 per contact within the tolerance, at the two surface
 *      points fixed on their bodies, and where the pair has Coulomb friction a tangent row;
 *   3. the ground's blocks (a table packed once per model: wheels, ideal wheels, Coulomb,
 *      anisotropic Coulomb per link; an object's Coulomb friction with the ground);
 *   4. the exact solve of scene_solve.c (core_scene_solve_s; a tiny problem straight to
 *      scene_tiny.c; with contact friction scene_friction.c's) on the full inertia (M_s, then
 *      m, m, I per object) and force (B tau, the objects' wrenches), in a batch from the last
 *      sample's pieces (frictionless);
 *   5. the metrics (scene_metrics.c, from the inertia's factor): ||qdd_s||^2 = qdd^T M_s qdd
 *      (eq. 26), ||a_o||^2 = a_o^T I_o a_o (eq. 27) per object and summed,
 *      ||lambda||^2 = lam^T G lam = (a - a_free)^T M (a - a_free), and sr (eq. 30; 0 where the
 *      summed norms are rounding, a system that does not move: scene_metrics.c). A sample not
 *      solved has NaN metrics and its status says why.
 * The scene, outputs and details (rows, forces, row accelerations, block states) are laid out
 * as snakecg/scenes/packing.py writes and reads them (SP_*, SO_*, the records' widths below).
 * Steps 1-3 alone at a simulation's state (the objects at given poses, the run's tolerance):
 * core_scene_rows (and sc_scene_state_rows, scene_step.c's); the pairs' signed distances,
 * overlapping or not, for the root finding of a contact's onset: core_scene_gaps.
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_rows.h"
#include "scene_work.h"
#include "scene_broad.h"
#include "scene_metrics.h"
#include "scene_tiny.h"
#include "scene_inputs.h"

/* the packed scene (SP_*, LINK_W, OBJ_W, OBS_W): engine.h */
enum { GB_W = 8 };    /* type (GB_*), body, wheel offset, par (3), block kind (K_*) */
enum { GB_WHEEL = 0, GB_COULOMB = 1, GB_SPLIT = 2, GB_OBJECT = 3 };
/* one sample's outputs: the solve's info (scene_solve.c's INFO_* order), then these */
enum { SO_INFO = 0, SO_NC = 8, SO_NORM_QDD, SO_NORM_A, SO_NORM_L, SO_SR, SO_OVERLAP,
       SO_SOLUTIONS = SO_OVERLAP + 6, SO_QDD };
/* a contact's record (CR_W, engine.h): body a (kind, index), b, point a (2), b (2), normal
 * (2), gap, force, state, the pair's mu, tangent force and state; a sample's status (SS_*,
 * engine.h) after scene_solve.c's 0 solved, 1 not converged, 2 singular mass (5, more contacts
 * than the solve takes, is the caller's; 8: the answer overflowed) */
enum { BODY_LINK = 0, BODY_OBJECT = 1, BODY_OBSTACLE = 2 };
/* Gauss-Seidel sweeps allowed per sample (snakecg.scenes.solve.MAX_SWEEPS) */
#define SC_SCENE_SWEEPS 200000
/* a warm start's passes beyond which it gained nothing (10-joint scene: cold ~5 sweeps, 2.5-3
 * passes, a pass ~3 sweeps' time; one falling back: +4); 1-row blocks, m <= n: beyond one */
#define SC_GAIN_PASSES 2


/* The bodies placed at the link poses P (the objects at qo, or by the scene): the parts that
 * do not move once per call. */
static void place(sc_scene_work *sw, const double *P, const double *qo, int given) {
  sc_scene_place(sw->pk, P, qo, (sw->placed ? 0 : 1) | 2 * given, sw->cs, sw->shape, sw->pose,
                 sw->centre, sw->reach);
  sw->placed = 1;
}

/* An object's part of a contact's D = J_b - J_a (sign 1: b's, -1: a's) at its point p, in
 * object o's columns (x: 1, 0, y_o - p_y; y: 0, 1, p_x - x_o) times sign, added to zero. */
static void object_part(const sc_scene_work *sw, sc_int o, const double *p, double sign,
                        const double *nrm, double *row, double *Dx, double *Dy) {
  const double *ps = sw->pose + 3 * o, n0 = nrm[0], n1 = nrm[1]; /* (scalars: no stack pairs) */
  const double x0 = 0.0 + sign, x2 = 0.0 + sign * -(p[1] - ps[1]), y1 = 0.0 + sign,
               y2 = 0.0 + sign * (p[0] - ps[0]);
  const sc_int col = SNAKECG_NS + 3 * o;
  row[col] = n0 * x0 + n1 * 0.0;
  row[col + 1] = n0 * 0.0 + n1 * y1;
  row[col + 2] = n0 * x2 + n1 * y2;
  if (Dx) Dx[col] = x0, Dx[col + 1] = 0.0, Dx[col + 2] = x2;
  if (Dx) Dy[col] = 0.0, Dy[col + 1] = y1, Dy[col + 2] = y2;
}

/* A contact's row n . D (n entries), D = J_b - J_a at its points (p_b on body b, p_a on a; on
 * a link from its twist's column J_i, x: J_x - r_y J_w, y: J_y + r_x J_w, r from its COM; on
 * an object object_part) summed from zero, b's then a's; where Dx is not null, D's two rows
 * into Dx, Dy (a friction row's). ib > ia: a link b has a link a. */
static void contact_row(const sc_scene_work *sw, sc_int ia, sc_int ib, const sc_touch *t,
                        const double *P, double *row, double *Dx, double *Dy) {
  const sc_int n = sw->n, ns = SNAKECG_NS, nl = SNAKECG_NL, step = 3 * SNAKECG_NL;
  const double n0 = t->n[0], n1 = t->n[1], zero = n0 * 0.0 + n1 * 0.0;
  const double *Ja = sw->J + 3 * ia, *Jb = sw->J + 3 * ib;
  const double ra0 = ia < nl ? t->a[0] - P[3 * ia] : 0.0,
               ra1 = ia < nl ? t->a[1] - P[3 * ia + 1] : 0.0,
               rb0 = ib < nl ? t->b[0] - P[3 * ib] : 0.0,
               rb1 = ib < nl ? t->b[1] - P[3 * ib + 1] : 0.0;
  sc_int j;
  if (ib < nl) /* two links */
    for (j = 0; j < ns; ++j, Ja += step, Jb += step) {
      const double x = (0.0 + (Jb[0] + -rb1 * Jb[2])) - (Ja[0] + -ra1 * Ja[2]),
                   y = (0.0 + (Jb[1] + rb0 * Jb[2])) - (Ja[1] + ra0 * Ja[2]);
      row[j] = n0 * x + n1 * y;
      if (Dx) Dx[j] = x, Dy[j] = y;
    }
  else if (ia < nl) /* a link and an object or obstacle */
    for (j = 0; j < ns; ++j, Ja += step) {
      const double x = 0.0 - (Ja[0] + -ra1 * Ja[2]), y = 0.0 - (Ja[1] + ra0 * Ja[2]);
      row[j] = n0 * x + n1 * y;
      if (Dx) Dx[j] = x, Dy[j] = y;
    }
  for (j = ia < nl ? ns : 0; j < n; ++j) { /* the objects' columns (and a's, an object's) */
    row[j] = zero;
    if (Dx) Dx[j] = Dy[j] = 0.0;
  }
  if (ib >= nl && ib < nl + sw->no) object_part(sw, ib - nl, t->b, 1.0, t->n, row, Dx, Dy);
  if (ia >= nl) object_part(sw, ia - nl, t->a, -1.0, t->n, row, Dx, Dy);
}

static sc_int body_kind(const sc_scene_work *sw, sc_int b, sc_int *index) {
  if (b < SNAKECG_NL) { *index = b; return BODY_LINK; }
  if (b < SNAKECG_NL + sw->no) { *index = b - SNAKECG_NL; return BODY_OBJECT; }
  *index = b - SNAKECG_NL - sw->no;
  return BODY_OBSTACLE;
}

/* The contacts of the pair (ia, ib) that may touch: their rows into sw->A from row *nc on,
 * their records (CR_W each, every field) into recs, *nc counting them; returns 0, or SS_*
 * (overlap: the pair, depth, tolerance in over). */
static int contact_pair(sc_scene_work *sw, sc_int ia, sc_int ib, const double *P,
                        double *recs, double *over, sc_int cap, sc_int *ncp) {
  const double tol = sw->tol;
  const sc_int n = sw->n;
  sc_int k, j, kk, nc = *ncp;
  int count;
  sc_touch t[SC_TOUCH_MAX];
  const double d = sc_shape_closest(sw->shape + ia, sw->shape + ib, sw->pk[SP_SIZE], tol, tol,
                                    t, &count);
  if (d < -tol) {
    double *o = over, idx;
    o[0] = (double)body_kind(sw, ia, &k), o[1] = (double)k;
    idx = (double)body_kind(sw, ib, &k);
    o[2] = idx, o[3] = (double)k, o[4] = -d, o[5] = tol;
    return SS_OVERLAP;
  }
  if (d > tol) return 0;
  for (k = 0; k < count; ++k) {
    double *Dx = sw->T ? sw->D : 0, *Dy = sw->D + n, *rec;
    if (nc >= cap) return SS_MORE;
    contact_row(sw, ia, ib, t + k, P, sw->A + nc * n, Dx, Dy);
    rec = recs + CR_W * nc;
    rec[0] = (double)body_kind(sw, ia, &kk), rec[1] = (double)kk;
    rec[2] = (double)body_kind(sw, ib, &kk), rec[3] = (double)kk;
    for (j = 0; j < 2; ++j) {
      rec[4 + j] = t[k].a[j];
      rec[6 + j] = t[k].b[j];
      rec[8 + j] = t[k].n[j];
    }
    rec[10] = d;
    rec[11] = rec[12] = rec[13] = rec[14] = rec[15] = 0.0; /* (the solve's, friction's) */
    sw->kind[nc] = K_UNILATERAL;
    sw->start[nc] = nc;
    sw->par[3 * nc] = sw->par[3 * nc + 1] = sw->par[3 * nc + 2] = 0.0;
    if (sw->T) sc_friction_row(sw->pk, ia, ib, t[k].n, Dx, Dy, n, sw->T + nc * n, rec);
    *ncp = ++nc;
  }
  return 0;
}

/* The contacts' rows of one configuration into sw->A (rows 0..), their records (CR_W each)
 * into recs, their count into *nc (the records written where it stops); returns 0, or SS_*
 * (overlap: the pair, depth, tolerance in over).
 * The pairs in order (ia, then ib), those whose bounding circles are not apart (scene_broad.h):
 * with few bodies from the table of the pairs, else from every moving body's masks at once. */
static int contact_rows(sc_scene_work *sw, const double *P, double *recs, double *over,
                        sc_int cap, sc_int *nc) {
  const double tol = sw->tol;
  const sc_int nl = SNAKECG_NL, nbody = sw->nbody, nw = sc_broad_words(nbody),
               na = nl + sw->no;
  const uint64_t *near = sw->near; /* (locals: the records' stores may alias sw's fields) */
  sc_int ia, ib, iw, k, np;
  int code;
  uint64_t bits;
  *nc = 0;
  if (nbody <= SC_BROAD_FEW) { /* the pairs' table (made at the first call or tolerance) */
    const double *centre = sw->centre, *far2 = sw->far2;
    const unsigned char(*pair)[2] = (const unsigned char(*)[2])sw->pair;
    const sc_int pad = sc_broad_pad(nbody);
    if (!(sw->ftol == tol)) /* (NaN at first) */
      sw->npair = sc_broad_pairs(sw->reach, tol, na, nl, nbody, sw->pair, sw->far2),
      sw->ftol = tol;
    for (k = 0, np = sw->npair; k < np; ++k)
      if (sc_broad_near(centre, pad, pair[k], far2[k]) &&
          (code = contact_pair(sw, pair[k][0], pair[k][1], P, recs, over, cap, nc)))
        return code;
    return 0;
  }
  sc_broad_masks(sw->centre, sw->reach, tol, na, nl, nbody, sw->near);
  for (iw = 0; iw < na * nw; ++iw) /* (body ia's words in turn: one loop, most words 0) */
    for (bits = near[iw]; bits;) {
      ia = nw == 1 ? iw : iw / nw;
      ib = sc_broad_pop(&bits, 64 * (nw == 1 ? 0 : iw % nw));
      if ((code = contact_pair(sw, ia, ib, P, recs, over, cap, nc))) return code;
    }
  return 0;
}

/* The ground's blocks after the contacts' nc rows; returns the rows used. Where kept (the
 * forward's last rows were for the same nc, and nothing has written them since), only what
 * the configuration moves is written: the blocks' kinds, starts and parameters, the rows'
 * zeros in the objects' columns and an object's rows are as they were left. */
static sc_int ground_rows(sc_scene_work *sw, sc_int nc, int kept) {
  const double *gb = sw->pk + (sc_int)sw->pk[SP_GROUND];
  const sc_int n = sw->n;
  sc_int g, r = nc, j;
  for (g = 0; g < sw->ng; ++g, gb += GB_W) {
    sc_int b = (sc_int)gb[1], type = (sc_int)gb[0], bk = nc + g;
    double *r0 = sw->A + r * n, *r1 = r0 + n;
    if (!kept) {
      sw->kind[bk] = (sc_int)gb[6];
      sw->start[bk] = r;
      sw->par[3 * bk] = gb[3];
      sw->par[3 * bk + 1] = gb[4];
      sw->par[3 * bk + 2] = gb[5];
      for (j = SNAKECG_NS; type != GB_OBJECT && j < n; j += 3) { /* the objects' columns, */
        r0[j] = r0[j + 1] = r0[j + 2] = 0.0; /* not set below (three at a time: no memset) */
        if (type != GB_WHEEL) r1[j] = r1[j + 1] = r1[j + 2] = 0.0;
      }
      if (type == GB_OBJECT) {
        for (j = 0; j < n; ++j) r0[j] = r1[j] = 0.0;
        r0[SNAKECG_NS + 3 * b] = 1.0;
        r1[SNAKECG_NS + 3 * b + 1] = 1.0;
      }
    }
    if (type == GB_OBJECT) {
      r += 2;
      continue;
    }
    { /* (one loop per type: the same entries) */
      const double c = sw->cs[2 * b], s = sw->cs[2 * b + 1], off = gb[2];
      const double *J = sw->J + 3 * b;
      if (type == GB_WHEEL)
        for (j = 0; j < SNAKECG_NS; ++j, J += 3 * SNAKECG_NL)
          r0[j] = -s * J[0] + c * J[1] + off * J[2];
      else if (type == GB_COULOMB)
        for (j = 0; j < SNAKECG_NS; ++j, J += 3 * SNAKECG_NL) r0[j] = J[0], r1[j] = J[1];
      else
        for (j = 0; j < SNAKECG_NS; ++j, J += 3 * SNAKECG_NL) {
          r0[j] = c * J[0] + s * J[1];
          r1[j] = -s * J[0] + c * J[1];
        }
    }
    r += type == GB_WHEEL ? 1 : 2;
  }
  return r;
}

/* The link poses (sw->P), Jacobians (sw->J) and, where mass, M_s (sw->Ms) and the links' cos
 * and sin (sw->cs, place's `given`) at q: the generated functions' status (0 on success). */
static int kinematics(sc_scene_work *sw, const double *q, int mass) {
  sc_work_t *ws = &sw->ws;
  const double *K = sw->pk + (sc_int)sw->pk[SP_K];
  if (mass) { /* the four in one generated function: the joints' sines taken once */
    ws->arg[SK_IN_q] = q, ws->arg[SK_IN_K] = K;
    ws->res[SK_OUT_poses] = sw->P, ws->res[SK_OUT_J] = sw->J;
    ws->res[SK_OUT_M] = sw->Ms, ws->res[SK_OUT_cs] = sw->cs;
    return SNAKECG_SK(ws->arg, ws->res, ws->iw, ws->w, 0) != 0;
  }
  ws->arg[LP_IN_q] = q, ws->arg[LP_IN_K] = K, ws->res[LP_OUT_poses] = sw->P;
  if (SNAKECG_LP(ws->arg, ws->res, ws->iw, ws->w, 0)) return 1;
  ws->arg[LJ_IN_q] = q, ws->arg[LJ_IN_K] = K, ws->res[LJ_OUT_J] = sw->J;
  return SNAKECG_LJ(ws->arg, ws->res, ws->iw, ws->w, 0) != 0;
}

/* M_s (the generated column-major) into M's first n_s rows and columns (n x n, row-major): its
 * columns as rows, M_s symmetric entry for entry (derive/kinematics.py mirrors each entry). */
static void snake_block(const double *Ms, double *M, sc_int n) {
  sc_int i;
  if (n == SNAKECG_NS) memcpy(M, Ms, sizeof(double) * SNAKECG_NS * SNAKECG_NS); /* (one copy) */
  for (i = 0; n > SNAKECG_NS && i < SNAKECG_NS; ++i)
    memcpy(M + i * n, Ms + SNAKECG_NS * i, sizeof(double) * SNAKECG_NS);
}

/* The bodies' full inertia (M_s; m, m, I per object), n x n row-major, into M. */
static void full_inertia(const sc_scene_work *sw, double *M) {
  const sc_int n = sw->n, ns = SNAKECG_NS;
  sc_int o;
  if (n > ns) memset(M, 0, sizeof(double) * (size_t)(n * n)); /* (else every entry set below) */
  snake_block(sw->Ms, M, n);
  for (o = 0; o < sw->no; ++o) {
    const double *obj = sw->pk + (sc_int)sw->pk[SP_OBJECTS] + OBJ_W * o;
    sc_int c = ns + 3 * o;
    M[c * n + c] = M[(c + 1) * n + c + 1] = obj[4];
    M[(c + 2) * n + c + 2] = obj[5];
  }
}

/* One sample: out (its row), and where A is not null its details (rows, forces, row
 * accelerations, block states; mcap rows each). Where warm, the solve starts from the last
 * sample's pieces if its blocks are the same (contacts: of the same bodies, in order). */
static void scene_sample(sc_scene_work *sw, const double *q, const double *tau,
                         const double *fo, sc_int max_sweeps, double *out, double *A,
                         double *lam, double *w, double *state, int warm) {
  const sc_int n = sw->n, ns = SNAKECG_NS, width = SO_QDD + ns + 7 * sw->no + 3 * sw->ng;
  static const double zeros[SO_QDD]; /* (copied: a few moves; a memset of it is a string op) */
  sc_int nc, m, nb, i, j, o, t = -1, pnb = sw->pnb, code;
  double *P = sw->P, *rec = out + SO_QDD + ns + 7 * sw->no + 3 * sw->ng, *a = out + SO_QDD;
  const int same = sw->qnc >= 0 && !memcmp(q, sw->pq, sizeof(double) * (size_t)ns);
  int kept = same; /* (the last sample's rows, records and the solve's Z and G reused) */
  sw->pnb = -1; /* (until this sample is solved) */
  memcpy(out, zeros, sizeof(zeros)); /* (the row's rest written below) */
  if (!same) { /* (else the last sample's q: its poses, rows, records and inertia, kept) */
    sw->qnc = -1, sw->sk.ok = 0;
    if (kinematics(sw, q, 1)) goto failed;
    place(sw, P, 0, 1);
  } else if (!sw->qbuf && !(sw->qbuf = (double *)malloc(sizeof(double) * (size_t)(
             sw->mcap * (n + sw->mcap))))) /* (the solve's Z and G: at the first repeat) */
    kept = 0; /* (out of memory: the rows found again, nothing held for the solve) */
  else
    sw->sk.Z = sw->qbuf, sw->sk.G = sw->qbuf + sw->mcap * n;
  for (o = 0; o < sw->no; ++o)
    for (j = 0; j < 3; ++j) out[SO_QDD + ns + 4 * sw->no + 3 * o + j] = sw->pose[3 * o + j];
  if (kept) /* (the records' solve fields: written again below) */
    memcpy(rec, sw->qrec, sizeof(double) * (size_t)(CR_W * (nc = sw->qnc))), code = 0;
  else if (!(code = contact_rows(sw, P, rec, out + SO_OVERLAP, sw->ccap, &nc))) {
    sw->qnc = nc, sw->pq = q, sw->qrec = rec;
    if (sw->qown) { /* (one-sample calls: copies, the caller's buffer being the next's) */
      memcpy(sw->qown, q, sizeof(double) * (size_t)ns);
      memcpy(sw->qown + ns, rec, sizeof(double) * (size_t)(CR_W * nc));
      sw->pq = sw->qown, sw->qrec = sw->qown + ns;
    }
  }
  /* the records' room after those written zeroed, whatever the caller's buffer held */
  memset(rec + CR_W * nc, 0, sizeof(double) * (size_t)(CR_W * (sw->ccap - nc)));
  if (code) { /* (the rows found before it stand where the ground's were: not kept) */
    sw->gnc = -1;
    out[SO_INFO] = (double)code;
    for (i = SO_NORM_QDD; i <= SO_SR; ++i) out[i] = NAN;
    for (i = SO_QDD; i < width; ++i) out[i] = NAN; /* no contacts, no ground blocks */
    return;
  }
  m = ground_rows(sw, nc, sw->gnc == nc); /* (the solves write no row, block or parameter */
  sw->gnc = nc, nb = nc + sw->ng; /* before m and nb: those after them, contact friction's) */
  snake_block(sw->Ms, sw->M, n); /* M_s into the inertia (the objects' part is the call's) */
  sw->f[0] = sw->f[1] = sw->f[2] = 0.0; /* the force: B tau, the objects' wrenches */
  for (i = 3; i < ns; ++i) sw->f[i] = tau[i - 3];
  for (i = 0; i < 3 * sw->no; ++i) sw->f[ns + i] = fo[i];
  for (i = 0; i < nb; ++i) sw->st[i] = 0.0;
  warm = warm && pnb == nb && !(sw->cool > 0 && sw->cool--); /* (backing off: cold) */
  for (i = 0; warm && i < nc * CR_W; i += CR_W)
    for (j = 0; j < 4; ++j) warm &= rec[i + j] == sw->prec[i + j]; /* the same bodies */
  /* the solve (a tiny problem straight to scene_tiny.c, which hands back the inertia's factor
   * whether it answers or not; else sc_scene_solve_one, core_scene_solve_s's, or with contact
   * friction scene_friction.c) */
  if (!sw->T && sc_tiny_forward(n, m, nb, sw->M, sw->f, sw->A, sw->kind, sw->start, sw->par,
                                warm ? sw->prev : 0, sw->lam, a, sw->w, sw->st, out + SO_INFO,
                                sw->L, sw->g, &t))
    ;
  else if (!sw->T) /* (the Z and G of the same q's samples held: sk, once allocated) */
    sc_scene_solve_one(n, m, nb, sw->M, sw->f, sw->A, NULL, sw->kind, sw->start, sw->par,
                       max_sweeps, warm ? sw->prev : 0, sw->lam, a, sw->w, sw->st,
                       out + SO_INFO, 1, kept ? &sw->sk : 0);
  else
    sc_friction_solve(n, m, nb, nc, sw->M, sw->f, sw->A, NULL, sw->kind, sw->start, sw->par,
                      sw->T, rec, max_sweeps, warm ? sw->prev : 0, sw->lam, a, sw->w, sw->st,
                      out + SO_INFO, out + SO_SOLUTIONS);
  /* the metrics (scene_metrics.c) by the inertia's factor (the tiny path's, whichever path
   * solved: the metrics do not depend on it) */
  if (out[SO_INFO] == 0.0 && t < 0 && !sc_tiny_inertia(n, sw->M, sw->f, sw->L, sw->g, &t))
    out[SO_INFO] = 2.0; /* (a singular mass matrix, as the solve says it) */
  if (out[SO_INFO] == 0.0)
    sc_scene_metrics(n, sw->no, t, sw->L, sw->g, sw->f, a, m, sw->A, sw->lam, out + SO_NORM_QDD,
                     a + n);
  for (i = SO_NORM_QDD; out[SO_INFO] == 0.0 && i <= SO_SR; ++i) /* (an overflow: forces or
    masses beyond double precision's range, which the KKT residuals' fmax passes by; a value
    of a not finite makes ||lambda||^2's sum over every entry so, and a is taken from lam) */
    if (!isfinite(out[i])) out[SO_INFO] = SS_OVERFLOW;
  if (out[SO_INFO] != 0.0)
    for (i = SO_NORM_QDD; i <= SO_SR; ++i) out[i] = NAN;
  for (i = 0; out[SO_INFO] != 0.0 && i < n + sw->no; ++i) a[i] = NAN; /* (qdd, a_o, ||a_o||^2) */
  out[SO_NC] = (double)nc;
  if (warm) { /* a start that gained nothing (it fell back to sweeps, or took more than
    SC_GAIN_PASSES; 1-row blocks, m <= n: one): the next 1, 2 .. 128 cold; a gain halves it */
    j = out[SO_INFO + 5] == 0.0 && out[SO_INFO + 6] <= (m == nb && m <= n ? 1 : SC_GAIN_PASSES);
    sw->backoff = j ? sw->backoff / 2 : sw->backoff ? 2 * sw->backoff : 1;
    if (sw->backoff > 128) sw->backoff = 128;
    sw->cool = j ? 0 : sw->backoff;
  }
  /* the pieces: the next sample's start; a contact's force and state (its one row: row i) */
  for (i = 0; i < nc; ++i) {
    double *s = sw->prev + 3 * i;
    s[0] = sw->st[i], s[1] = sw->lam[i], s[2] = 0.0;
    rec[CR_W * i + 11] = s[1], rec[CR_W * i + 12] = s[0];
  }
  for (; i < nb; ++i) { /* a ground block's forces and state (a 2-D block: two rows) */
    sc_int r = sw->start[i];
    double *s = sw->prev + 3 * i, *g = rec - 3 * sw->ng + 3 * (i - nc);
    s[0] = sw->st[i], s[1] = sw->lam[r];
    s[2] = (i + 1 < nb ? sw->start[i + 1] : m) - r == 2 ? sw->lam[r + 1] : 0.0;
    g[0] = s[1]; g[1] = s[2]; g[2] = s[0];
  }
  sw->pnb = out[SO_INFO] == 0.0 ? nb : -1, sw->prec = rec; /* the next sample's start */
  if (A) {
    memcpy(A, sw->A, sizeof(double) * (size_t)(m * n));
    memcpy(lam, sw->lam, sizeof(double) * (size_t)m);
    memcpy(w, sw->w, sizeof(double) * (size_t)m);
    memcpy(state, sw->st, sizeof(double) * (size_t)nb);
  }
  return;
failed: /* a generated function refused */
  memset(rec, 0, sizeof(double) * CR_W * sw->ccap);
  out[SO_INFO] = SS_FAILED;
  for (i = SO_NORM_QDD; i < width; ++i) out[i] = NAN;
}

/* The forward solve of n samples of a general scene packed in pk: sample i's q, tau, f_obj at
 * q + i sq, tau + i st, fo + i sf (stride 0 broadcasts); its outputs at out + i width
 * (width = SO_QDD + n_s + 7 n_o + 3 n_g + CR_W ccap); where A is not null, its details at
 * A + i mcap n, lam, w, state + i mcap. At most ccap contacts a sample (a sample with more:
 * status SS_MORE, for the caller to redo with a larger ccap; every column of a row written,
 * zeros after its contacts). The solves start from the last sample's pieces where its
 * blocks are the same, but at every chunk-th sample of the call (chunk < 2: all cold; a
 * caller splitting a batch on multiples of chunk gets the same answers whatever the split)
 * and for 1, 2, 4 .. 128 samples after starts that gained nothing. Returns 0, -1 out of
 * memory, -2 on sizes out of range, -(3 + i) when an input of sample i is refused
 * (scene_inputs.c: not finite, a force beyond 1e150, the base beyond POSITION_SPAN sizes). */
static int forward(const double *pk, sc_int n, const double *q, sc_int sq, const double *tau,
                   sc_int st, const double *fo, sc_int sf, sc_int ccap, sc_int mcap,
                   double *out, double *A, double *lam, double *w, double *state, sc_int chunk,
                   void **keep) {
  sc_scene_work local, *sw = &local;
  sc_int i, left, width, mg = (sc_int)pk[SP_MG] + (pk[SP_FRICTION] != 0) * ccap; /* (tangents) */
  if (ccap < 0 || mcap < ccap + mg || mcap > 500 || SNAKECG_NS + 3 * pk[SP_NO] > 512)
    return -2;
  /* inputs first: a sample that is not finite refuses the call (scene_inputs.c) */
  if ((i = sc_inputs_bad(n, q, sq, tau, st, fo, sf, 3 * (sc_int)pk[SP_NO],
                         POSITION_SPAN * pk[SP_SIZE])) >= 0)
    return (int)(-3 - (i < 2000000000 ? i : 2000000000));
  if (keep && *keep) { /* (as made below: cold, the last call's rows kept for its q) */
    sw = (sc_scene_work *)*keep, sw->pnb = -1;
    if (!sw->qown) sw->qnc = -1; /* (no copy of that q: nothing kept) */
  } else if (sc_scene_work_alloc(sw, pk, ccap, mcap, 1))
    return -1;
  else if (full_inertia(sw, sw->M), keep) { /* the objects' part (M_s: per sample) */
    *keep = sw = (sc_scene_work *)memcpy(sw->base, sw, sizeof(*sw));
    sw->qown = (double *)malloc(sizeof(double) * (size_t)(SNAKECG_NS + CR_W * ccap)); /*
      (null, out of memory: the rows found again at every call) */
  }
  width = SO_QDD + SNAKECG_NS + 7 * sw->no + 3 * sw->ng + CR_W * ccap;
  for (i = 0, left = 0; i < n; ++i, --left) { /* cold at every chunk-th sample of the call */
    if (left == 0) left = chunk > 1 ? chunk : 1, sw->cool = sw->backoff = 0; /* (no division) */
    scene_sample(sw, q + i * sq, tau + i * st, fo + i * sf, SC_SCENE_SWEEPS, out + i * width,
                 A ? A + i * mcap * sw->n : 0, A ? lam + i * mcap : 0, A ? w + i * mcap : 0,
                 A ? state + i * mcap : 0, chunk > 1 && left != chunk);
  }
  if (!keep) sc_scene_work_free(sw);
  return 0;
}

int SNAKECG_EXPORT(core_scene_forward)(const double *pk, sc_int n, const double *q, sc_int sq,
                                       const double *tau, sc_int st, const double *fo,
                                       sc_int sf, sc_int ccap, sc_int mcap, double *out,
                                       double *A, double *lam, double *w, double *state,
                                       sc_int chunk) {
  return forward(pk, n, q, sq, tau, st, fo, sf, ccap, mcap, out, A, lam, w, state, chunk, 0);
}

/* core_scene_forward with its arguments in one struct: the one-sample calls pass a single
 * pointer (a foreign call's cost grows with its argument count; snakecg/engine/binding.py
 * mirrors it as SceneCall). keep (null at first): the scratch made at the first call and
 * reused by the next ones (the same pk, ccap, mcap; the fixed bodies placed, the objects'
 * inertia set; a call at the last call's q, bit for bit, keeps its rows, Z and G as a batch's
 * samples at one q do: the same answers); a call with n = 0 frees it. */
typedef struct {
  const double *pk; sc_int n; const double *q; sc_int sq;
  const double *tau; sc_int st; const double *fo; sc_int sf, ccap, mcap;
  double *out, *A, *lam, *w, *state; sc_int chunk; void *keep;
} sc_scene_call;

int SNAKECG_EXPORT(core_scene_forward_call)(sc_scene_call *c) {
  if (c->n == 0) { /* (the kept scratch freed) */
    if (c->keep) sc_scene_work_free((sc_scene_work *)c->keep);
    c->keep = 0;
    return 0;
  }
  return forward(c->pk, c->n, c->q, c->sq, c->tau, c->st, c->fo, c->sf, c->ccap, c->mcap,
                 c->out, c->A, c->lam, c->w, c->state, c->chunk, &c->keep);
}

/* ---- the rows at a simulation's state (snakecg/scenes/stepping.py; maps at rest) ---- */
/* The arguments of core_scene_rows and core_scene_gaps: sc_scene_state of engine.h
 * (snakecg/engine/binding.py mirrors them as SceneStateCall): pk the packed scene; q (n_s);
 * qo the objects' poses (3 n_o, or null: placed by the scene from q); tol (rows: the contact
 * tolerance, m; <= 0: the scene's); margin (gaps: the pairs whose bounding circles are within
 * it, m); ccap, mcap (rows: room for contacts and rows, mcap >= ccap + ground rows; gaps: for
 * records); pair_a, pair_b (gaps: this pair of bodies alone, -1: every pair); out (rows: RO_*,
 * then the contacts, CR_W each; gaps: 5 per pair); M (rows: the bodies' inertia, n x n
 * row-major, or null); A (mcap x n), par (3 per block), kind, start: the rows' blocks. */
/* A state's scratch (where keep is not null: made at the first call into *keep, the caller's
 * to free, then reused; the same pk, ccap, mcap every call); its rows (A not null) go straight
 * into A, par, kind, start. */
static int state_work(sc_scene_work **sw, const double *pk, const double *q, const double *qo,
                      double tol, sc_int ccap, sc_int mcap, double *A, double *par,
                      sc_int *kind, sc_int *start, void **keep) {
  sc_int j, no3 = 3 * (sc_int)pk[SP_NO], fr = pk[SP_FRICTION] != 0; /* (tangent rows) */
  int ok = 1;
  if (ccap < 0 || mcap < (1 + fr) * ccap + pk[SP_MG] || mcap > 500 || SNAKECG_NS + no3 > 512)
    return -2;
  for (j = 0; j < SNAKECG_NS; ++j) ok &= isfinite(q[j]) != 0;
  for (j = 0; qo && j < no3; ++j) ok &= isfinite(qo[j]) != 0;
  if (!ok) return -3;
  if (keep && *keep) *sw = (sc_scene_work *)*keep; /* (its fixed bodies placed already) */
  else if (sc_scene_work_alloc(*sw, pk, ccap, mcap, A == 0)) return -1;
  else if (keep) *keep = *sw = (sc_scene_work *)memcpy((*sw)->base, *sw, sizeof(**sw));
  if (A) (*sw)->A = A, (*sw)->par = par, (*sw)->kind = kind, (*sw)->start = start;
  (*sw)->tol = tol > 0 ? tol : pk[SP_TOL];
  return 0;
}

/* The contacts, rows and blocks of one state (q, the objects at qo): the rows of the
 * forward's step 2 and 3 (contacts first, one unilateral row each, then the ground's
 * blocks; with contact friction the contacts' tangent rows after them, m + k contact k's),
 * and where c->M is not null the bodies' inertia. A pair overlapping beyond the
 * tolerance: status SS_OVERLAP and its record; more than ccap contacts: SS_MORE. Returns
 * 0, -1 out of memory, -2 on sizes out of range, -3 on an input not finite. */
int SNAKECG_EXPORT(core_scene_rows)(const sc_scene_state *c) {
  int code = sc_scene_state_rows(c->pk, c->q, c->qo, c->tol, c->ccap, c->mcap, c->out, c->M,
                                 c->A, c->par, c->kind, c->start, 0);
  return code < 0 ? code : 0;
}

SC_INTERNAL int sc_scene_state_rows(const double *pk, const double *q, const double *qo,
                                    double tol, sc_int ccap, sc_int mcap, double *out,
                                    double *M, double *A, double *par, sc_int *kind,
                                    sc_int *start, void **keep) {
  sc_scene_work local, *sw = &local;
  sc_int nc, m, i, code = state_work(&sw, pk, q, qo, tol, ccap, mcap, A, par, kind, start, keep);
  if (code) return (int)code;
  for (i = 0; i < RO_POSE + 3 * sw->no; ++i) out[i] = 0.0;
  code = kinematics(sw, q, M != 0) ? SS_FAILED : 0;
  if (!code) {
    place(sw, sw->P, qo, M != 0);
    for (i = 0; i < 3 * sw->no; ++i) out[RO_POSE + i] = sw->pose[i];
    code = contact_rows(sw, sw->P, out + RO_POSE + 3 * sw->no, out + RO_OVERLAP, sw->ccap, &nc);
  }
  if (!code) {
    m = ground_rows(sw, nc, 0);
    out[RO_NC] = (double)nc;
    out[RO_M] = (double)m;
    out[RO_NB] = (double)(nc + sw->ng);
    if (sw->T) memcpy(A + m * sw->n, sw->T, sizeof(double) * (size_t)(nc * sw->n)); /* (T) */
    if (M) full_inertia(sw, M);
  }
  out[RO_STATUS] = (double)code;
  if (!keep) sc_scene_work_free(sw);
  return (int)code;
}

SC_INTERNAL const double *sc_scene_rows_cs(const void *keep) { /* scene_rows.h */
  return ((const sc_scene_work *)keep)->cs;
}
/* The signed distance of every pair of bodies that can touch (the pairs of contact_rows)
 * whose bounding circles are within c->margin at one state, or of the pair (pair_a, pair_b)
 * alone (body indices: links, objects, obstacles), overlapping or not: records (body a kind,
 * index, body b kind, index, distance) into out, at most c->ccap. Returns their count (the
 * pairs found, beyond ccap not written), -1 out of memory, -2 on sizes, -3 on an input not
 * finite, -4 where a generated function refused. */
int SNAKECG_EXPORT(core_scene_gaps)(const sc_scene_state *c) {
  sc_scene_work sw, *swp = &sw; /* (no keep: swp stays &sw) */
  sc_int ia, ib, k, found = 0,
         code = state_work(&swp, c->pk, c->q, c->qo, 0.0, 0, (sc_int)c->pk[SP_MG], 0, 0, 0, 0, 0);
  if (code) return (int)code;
  if (kinematics(&sw, c->q, 0)) {
    sc_scene_work_free(&sw);
    return -4;
  }
  place(&sw, sw.P, c->qo, 0);
  for (ia = 0; ia < SNAKECG_NL + sw.no; ++ia)
    for (ib = ia + 1; ib < sw.nbody; ++ib) {
      const double *cx = sw.centre, *cy = sw.centre + sc_broad_pad(sw.nbody);
      sc_touch t[SC_TOUCH_MAX];
      double d, *rec;
      int count;
      if (ib < SNAKECG_NL && ib - ia < 2) continue; /* neighbouring links */
      if (c->pair_a >= 0 && !(ia == c->pair_a && ib == c->pair_b)) continue;
      if (c->pair_a < 0 &&
          hypot(cx[ia] - cx[ib], cy[ia] - cy[ib]) > sw.reach[ia] + sw.reach[ib] + c->margin)
        continue;
      d = sc_shape_closest(sw.shape + ia, sw.shape + ib, c->pk[SP_SIZE], sw.tol, INFINITY, t,
                           &count);
      if (found < c->ccap) {
        rec = c->out + 5 * found;
        rec[0] = (double)body_kind(&sw, ia, &k), rec[1] = (double)k;
        rec[2] = (double)body_kind(&sw, ib, &k), rec[3] = (double)k, rec[4] = d;
      }
      ++found;
    }
  sc_scene_work_free(&sw);
  return (int)found;
}
