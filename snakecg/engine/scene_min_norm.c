/* snakecg's engine: the minimum-norm forces of a statically indeterminate face of the
 * general-scene solve (scene_solve.c, scene_rescue.c) and of a Coulomb family of forces
 * (scene_family.c): the null space of the face's rows, the forces' interval along one null
 * direction, and the minimum-norm forces inside the sets (their dual's semismooth Newton).
 */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "scene_sets.h"

/* The nn vectors V + t n (length n each) orthonormalized in place: Gram-Schmidt, twice. */
static void orthonormalize(sc_int n, sc_int nn, double *V) {
  sc_int i, t, u;
  for (t = 0; t < nn; ++t) {
    int pass;
    double nrm = 0.0;
    for (pass = 0; pass < 2; ++pass)
      for (u = 0; u < t; ++u) {
        double d = 0.0;
        for (i = 0; i < n; ++i) d += V[u * n + i] * V[t * n + i];
        for (i = 0; i < n; ++i) V[t * n + i] -= d * V[u * n + i];
      }
    for (i = 0; i < n; ++i) nrm += V[t * n + i] * V[t * n + i];
    nrm = sqrt(nrm);
    for (i = 0; i < n; ++i) V[t * n + i] /= nrm;
  }
}

/* An orthonormal basis of the null space of the positive semidefinite n x n A (row-major, its
 * lower triangle read and overwritten): the pivoted L D L^T of sc_psd_solve stopped at pivots
 * of at most tol of the first (NULL_TOL on a face), the null vectors P [-L11^-T L21^T; I]
 * orthonormalized (Gram-Schmidt, twice). Basis vector t at V + t * n (contiguous); returns
 * their number.
 * Work: 2 n doubles, n sc_ints in perm. */
static sc_int null_space(sc_int n, double *A, double *V, double *work, sc_int *perm,
                         double tol) {
  double *b = work, *x = work + n;
  sc_int i, j, t, rank, nn;
  for (i = 0; i < n; ++i) b[i] = 0.0;
  rank = sc_psd_solve(n, A, n, b, tol, x, work + n, perm);
  nn = n - rank;
  for (t = 0; t < nn; ++t) {
    sc_int jj = rank + t;
    double *y = x;
    for (i = 0; i < n; ++i) y[i] = 0.0;
    y[jj] = 1.0;
    for (i = rank - 1; i >= 0; --i) { /* L11^T y1 = -L21^T e_jj */
      double sum = -A[jj * n + i];
      for (j = i + 1; j < rank; ++j) sum -= A[j * n + i] * y[j];
      y[i] = sum;
    }
    for (i = 0; i < n; ++i) V[t * n + perm[i]] = y[i];
  }
  orthonormalize(n, nn, V);
  return nn;
}

/* x (2 rows) projected onto the ray s (1, c), s > 0 (x . (1, c) > 0 given): pl = s (1, c),
 * its tangent row c times its normal one (the tie to rounding); D = e e^T with e = (1, c) / |.|,
 * so I - D = u u^T with u = (-c, 1) / |.| into cap[2], cap[3] (project's return 2). */
static int onto_ray(const double *x, double c, double *pl, double *cap) {
  const double e2 = 1.0 + c * c, s = (x[0] + c * x[1]) / e2, h = 1.0 / sqrt(e2);
  pl[0] = s;
  pl[1] = c * s;
  cap[0] = cap[1] = 0.0;
  cap[2] = -c * h;
  cap[3] = h;
  return 2;
}

/* The projection of x onto block k's set (a contact's half-line, a box, a disc, a split
 * ellipse whose halves have extent, a Coulomb cone or ray of scene_family.c; FREE: x) into
 * pl, and the part of the Newton capacitance of min_norm_in_sets that the block adds (cap,
 * nk x nk, row-major: W^-1 - I for the projection's derivative D = I - W, zero where D = 0).
 * Returns 1 where x is outside the set (D is not I: the block enters the capacitance with
 * its rows), 2 where D projects onto one direction of the block's plane (a cone's edge, a
 * ray): I - D = u u^T has one direction u, in cap[2], cap[3] (unit), W = 1 along it (cap[0]
 * 0), and the block enters the capacitance with u alone (W^-1 would not exist on its rows);
 * 0 where x is inside (D = I). */
static int project(const sc_problem *p, sc_int k, const double *x, double *pl, double *cap) {
  const double *q = p->par + 3 * k;
  double r, s;
  switch (p->kind[k]) {
    case K_CONE: /* |x_t| <= mu x_n: inside; in the polar cone (x_n + mu |x_t| <= 0): 0;
      else onto the edge e = (1, +-mu) / |.| on x_t's side */
      if (fabs(x[1]) <= q[0] * x[0]) break;
      if (x[0] + q[0] * fabs(x[1]) <= 0) {
        pl[0] = pl[1] = 0.0;
        cap[0] = cap[1] = cap[2] = cap[3] = 0.0;
        return 1;
      }
      return onto_ray(x, x[1] < 0 ? -q[0] : q[0], pl, cap);
    case K_RAY: /* lam = s (1, c), s >= 0: onto it, or 0 where x points away from it */
      if (x[0] + q[0] * x[1] <= 0) {
        pl[0] = pl[1] = 0.0;
        cap[0] = cap[1] = cap[2] = cap[3] = 0.0;
        return 1;
      }
      return onto_ray(x, q[0], pl, cap);
    case K_UNILATERAL:
      pl[0] = x[0] > 0 ? x[0] : 0.0;
      cap[0] = 0.0;
      return !(x[0] >= 0);
    case K_BOX:
      pl[0] = fmax(-q[0], fmin(q[0], x[0]));
      cap[0] = 0.0;
      return !(fabs(x[0]) <= q[0]);
    case K_DISC:
      r = sqrt(x[0] * x[0] + x[1] * x[1]);
      if (r <= q[0]) break;
      if (!(q[0] > 0)) { /* the set {0}: D = 0 */
        pl[0] = pl[1] = 0.0;
        cap[0] = cap[1] = cap[2] = cap[3] = 0.0;
        return 1;
      }
      /* D = (rho / r)(I - u u^T): along u W = 1, across 1 - rho / r, so W^-1 - I is
       * t t^T rho / (r - rho) with t = (-u1, u0) */
      pl[0] = q[0] * x[0] / r;
      pl[1] = q[0] * x[1] / r;
      s = q[0] / (r - q[0]) / (r * r);
      cap[0] = s * x[1] * x[1];
      cap[1] = cap[2] = -s * x[0] * x[1];
      cap[3] = s * x[0] * x[0];
      return 1;
    case K_SPLIT: { /* the half that x points into (projecting keeps the signs): the
      ellipse's point p_i = b_i x_i, b_i = a_i^2 / (a_i^2 + g), g >= 0 the root of
      sum x_i^2 a_i^2 / (a_i^2 + g)^2 = 1 (decreasing and convex in g: Newton from 0 rises
      to it); D = B - B n n^T B / (n^T B n) with the normal n = P p (D n = 0) */
      const double a0 = x[0] < 0 ? q[0] : q[1], a1 = q[2], e0 = a0 * a0, e1 = a1 * a1;
      double g = 0.0, b0, b1, n0, n1, bn0, bn1, nbn, d00, d01, d11, w00, w01, w11, det;
      int it;
      if ((x[0] / a0) * (x[0] / a0) + (x[1] / a1) * (x[1] / a1) <= 1.0) break;
      for (it = 0; it < 100; ++it) {
        const double c0 = x[0] * a0 / (e0 + g), c1 = x[1] * a1 / (e1 + g),
                     h = c0 * c0 + c1 * c1 - 1.0,
                     dh = -2.0 * (c0 * c0 / (e0 + g) + c1 * c1 / (e1 + g)), step = -h / dh;
        g += step;
        if (!(step > 1e-16 * g)) break;
      }
      b0 = e0 / (e0 + g);
      b1 = e1 / (e1 + g);
      pl[0] = b0 * x[0];
      pl[1] = b1 * x[1];
      n0 = pl[0] / e0;
      n1 = pl[1] / e1;
      bn0 = b0 * n0;
      bn1 = b1 * n1;
      nbn = n0 * bn0 + n1 * bn1;
      d00 = b0 - bn0 * bn0 / nbn;
      d01 = -bn0 * bn1 / nbn;
      d11 = b1 - bn1 * bn1 / nbn;
      w00 = 1.0 - d00; /* W = I - D, cap = W^-1 - I */
      w01 = -d01;
      w11 = 1.0 - d11;
      det = w00 * w11 - w01 * w01;
      cap[0] = w11 / det - 1.0;
      cap[1] = cap[2] = -w01 / det;
      cap[3] = w00 / det - 1.0;
      return 1;
    }
    default: break;
  }
  pl[0] = x[0];
  if (sc_block_size(p->kind[k]) == 2) pl[1] = x[1];
  return 0;
}

/* The null vectors V (nn, orthonormal, V + t nf) of the face's rows F0 refined against Z_F
 * itself: G_FF's null vectors carry G's rounding, which forces moved far along them bring into
 * the accelerations. Each v less its part in the range of Z_F^T (Z_F^T x with
 * Z_F Z_F^T x = Z_F v: any solution gives the same Z_F^T x), then orthonormalized again.
 * Work: n^2 + 3 n doubles. */
static void refine_null(const sc_problem *p, const double *Z, sc_int nf, const sc_int *F0,
                        double *V, sc_int nn, double *work) {
  const sc_int n = p->n, m = p->m;
  double *Gz = work, *zr = Gz + n * n, *zx = zr + n, *zw = zx + n;
  sc_int perm[512], i, j, t, rz = 0;
  for (i = 0; i < n; ++i)
    for (j = 0; j <= i; ++j) {
      double c = 0.0;
      for (t = 0; t < nf; ++t) c += Z[i * m + F0[t]] * Z[j * m + F0[t]];
      Gz[i * n + j] = c;
    }
  for (t = 0; t < nn; ++t) {
    double *v = V + t * nf;
    for (i = 0; i < n; ++i) {
      double c = 0.0;
      for (j = 0; j < nf; ++j) c += Z[i * m + F0[j]] * v[j];
      zr[i] = c;
    }
    if (t == 0)
      rz = sc_psd_solve(n, Gz, n, zr, 1e-14, zx, zw, perm);
    else
      sc_psd_resolve(n, Gz, n, rz, perm, 1, zr, zx, zw);
    for (j = 0; j < nf; ++j) {
      double c = 0.0;
      for (i = 0; i < n; ++i) c += Z[i * m + F0[j]] * zx[i];
      v[j] -= c;
    }
  }
  orthonormalize(nf, nn, V);
}

/* The minimum-norm forces inside the sets on a face whose unconstrained minimum-norm forces l0
 * (nf rows, fk: their blocks) leave them: min 1/2 |lam|^2 over lam in K with lam - l0 in the
 * null space V (nn orthonormal vectors, V + t nf; l0 orthogonal to it). Its dual over mu in
 * V's orthogonal complement, concave and once differentiable,
 *     d(mu) = mu . (l0 - Pi(mu)) + 1/2 |Pi(mu)|^2,   Pi: the projection onto K (blockwise),
 * has the gradient (I - V V^T)(l0 - Pi(mu)) = -F, and lam = Pi(mu*) at its maximiser. A
 * semismooth Newton solves F = 0: the Newton matrix (I - V V^T) D on the complement, D the
 * projection's derivative, I - D = S W S^T nonzero on the few blocks outside their sets only
 * (S selecting their rows, W their blocks; on a cone's edge or a ray, S the one direction
 * across it in the block's plane, W = 1), so the step comes from a capacitance matrix of
 * those rows alone (Woodbury):
 *     delta = -F - (I - V V^T) S C^-1 S^T F,   C = (W^-1 - I) + V_S V_S^T,
 * C by the pivoted L D L^T (its dependent rows dropped), the step
 * halved while d does not rise. Where the Newton matrix is singular along F (a step that no
 * longer moves it), the steps are damped from then on (Levenberg-Marquardt: the matrix plus
 * tau I, tau = |F| / scale, which adds tau W^-1 to C and divides delta by 1 + tau).
 * Returns 1 with the forces in lam (nf) once |F| is at rounding (1e-14 of the scale, or
 * MN_FLOOR where the steps stall or run out), 0 when not (a split ellipse with a half of no
 * extent, not projected here; or no progress). fkp (or NULL): where it holds a dual point on
 * this face, the Newton starts there (its part in V's complement) instead of at l0, the last
 * choice's answer being near (a fixed point's next inner solve; 8.5 steps a choice on the
 * 10-joint scene from l0); it keeps its own point where it succeeds. best (nf doubles, or
 * NULL): where the Newton stops short, the forces of its best iterate are taken where its |F|
 * is at most MN_FLOOR of the scale (a Coulomb family's choice: its last steps may jump off a
 * floor of 1e-13 of the scale that the line search, flat there, takes).
 * Work: 2 nf^2 + 12 nf doubles. */
/* min_norm_in_sets' Newton steps at most: damped, they may creep at first (on 10-joint
 * faces at ordinary configurations: 62 and 186 steps, then quadratic) */
#define MN_ITERATIONS 200
/* |F| taken as found where the Newton stalls or runs out of steps (1e-14 of the scale
 * otherwise): its floor was 3e-14 to 4.4e-13 of the scale on convex 10-joint faces (F is up
 * to 15 projections of 30 rows), up to 2.8e-12 on contact friction's inner faces (a third
 * of the 6- and 10-joint families' samples that kept a basic solution at 1e-12); the
 * choice's accelerations are then checked to 1e-13 as always, or taken from the new forces
 * where they move by 5e-10 at most and the KKT conditions hold (sc_min_norm_face's loose) */
#define MN_FLOOR 1e-11
static int min_norm_in_sets(const sc_problem *p, sc_int nf, const sc_int *fk, const double *l0,
                            const double *V, sc_int nn, double *lam, double *work,
                            sc_face_keep *fkp, double *best) {
  double *mu = work, *pi = mu + nf, *F = pi + nf, *del = F + nf, *tr = del + nf,
         *cap = tr + nf, *C = cap + 4 * nf, *VS = C + nf * nf, *x = VS + nf * nn, *y = x + nf,
         *sw = y + nf;
  sc_int S[512], perm[512], cs[512], ct[512], ns = 0, it, i, j, t, stalls = 0;
  const double *U[512]; /* (a capacitance row's direction in its block's plane, or NULL: the
    row S itself) */
  double scale = p->fscale, dv = 0.0, fprev = INFINITY, bfn = INFINITY;
  for (i = 0; i < nf; i += sc_block_size(p->kind[fk[i]])) { /* (a split ellipse with a
    half of no extent: not projected here) */
    const double *q = p->par + 3 * fk[i];
    if (p->kind[fk[i]] == K_SPLIT && !(q[0] > 0 && q[1] > 0 && q[2] > 0)) return 0;
  }
  for (i = 0; i < nf; ++i)
    if (fabs(l0[i]) > scale) scale = fabs(l0[i]);
  if (fkp && fkp->has_mu) { /* from the last choice's point on this face: its part in V's
    complement (the dual's domain) */
    memcpy(mu, fkp->mu, sizeof(double) * (size_t)nf);
    for (t = 0; t < nn; ++t) {
      double c = 0.0;
      for (i = 0; i < nf; ++i) c += V[t * nf + i] * mu[i];
      for (i = 0; i < nf; ++i) mu[i] -= c * V[t * nf + i];
    }
  } else
    memcpy(mu, l0, sizeof(double) * (size_t)nf);
  if (fkp) fkp->has_mu = 0; /* (kept again where this choice succeeds) */
  for (it = 0;; ++it) {
    double fn = 0.0, slope = 0.0, st = 1.0;
    sc_int ls;
    if (it == 0) { /* (later iterates: the accepted trial's, below) */
      ns = 0;
      for (i = 0; i < nf; i += sc_block_size(p->kind[fk[i]]))
        if ((ct[ns] = project(p, fk[i], mu + i, pi + i, cap + 4 * ns))) {
          cs[ns] = i; /* (the block's first row; cap + 4 its entries; ct: rows or one
            direction) */
          ns++;
        }
      dv = 0.0;
      for (i = 0; i < nf; ++i) dv += mu[i] * (l0[i] - pi[i]) + 0.5 * pi[i] * pi[i];
    }
    for (i = 0; i < nf; ++i) F[i] = pi[i] - l0[i];
    for (t = 0; t < nn; ++t) { /* F = (I - V V^T)(Pi - l0) */
      double c = 0.0;
      for (i = 0; i < nf; ++i) c += V[t * nf + i] * F[i];
      for (i = 0; i < nf; ++i) F[i] -= c * V[t * nf + i];
    }
    for (i = 0; i < nf; ++i) fn = fmax(fn, fabs(F[i]));
    if (best && fn < bfn) /* (the best iterate's forces, where the caller keeps them) */
      bfn = fn, memcpy(best, pi, sizeof(double) * (size_t)nf);
    if (fn <= 1e-14 * scale ||
        (((fn > 0.999 * fprev && ++stalls > 20) || it == MN_ITERATIONS) &&
         fn <= MN_FLOOR * scale)) { /* (damped from the first stall on) */
      memcpy(lam, pi, sizeof(double) * (size_t)nf);
      if (fkp) memcpy(fkp->mu, mu, sizeof(double) * (size_t)nf), fkp->has_mu = 1;
      return 1;
    }
    if (stalls > 20 || it == MN_ITERATIONS) break;
    { /* the capacitance's rows S: every row of a block outside its set (a cone's edge or
      a ray: its one direction u across it, S its block's first row) */
      sc_int r = 0, b;
      const double tau = stalls > 0 ? fn / scale : 0.0;
      for (b = 0; b < ns; ++b)
        if (ct[b] == 2)
          U[r] = cap + 4 * b + 2, S[r++] = cs[b];
        else
          for (j = 0; j < sc_block_size(p->kind[fk[cs[b]]]); ++j) U[r] = NULL, S[r++] = cs[b] + j;
      for (i = 0; i < r; ++i) {
        const double *u = U[i];
        for (t = 0; t < nn; ++t)
          VS[i * nn + t] = u ? u[0] * V[t * nf + S[i]] + u[1] * V[t * nf + S[i] + 1] :
                               V[t * nf + S[i]];
        x[i] = u ? u[0] * F[S[i]] + u[1] * F[S[i] + 1] : F[S[i]];
      }
      for (i = 0; i < r; ++i)
        for (j = 0; j <= i; ++j) {
          double c = 0.0;
          for (t = 0; t < nn; ++t) c += VS[i * nn + t] * VS[j * nn + t];
          C[i * r + j] = c;
        }
      for (b = 0, i = 0; b < ns; ++b) { /* ((1 + tau) W^-1 - I: blockwise on the diagonal) */
        if (ct[b] == 1 && sc_block_size(p->kind[fk[cs[b]]]) == 2) {
          C[i * r + i] += tau + (1.0 + tau) * cap[4 * b];
          C[(i + 1) * r + i] += (1.0 + tau) * cap[4 * b + 2];
          C[(i + 1) * r + i + 1] += tau + (1.0 + tau) * cap[4 * b + 3];
          i += 2;
        } else
          C[i * r + i] += tau + (1.0 + tau) * cap[4 * b], ++i;
      }
      if (r > 0) sc_psd_solve(r, C, r, x, 1e-13, y, sw, perm);
      for (i = 0; i < nf; ++i) del[i] = 0.0;
      for (i = 0; i < r; ++i)
        if (U[i])
          del[S[i]] = U[i][0] * y[i], del[S[i] + 1] = U[i][1] * y[i];
        else
          del[S[i]] = y[i];
      for (t = 0; t < nn; ++t) { /* del = -F - (I - V V^T) S y (S: U on a direction) */
        double c = 0.0;
        for (i = 0; i < r; ++i) c += VS[i * nn + t] * y[i];
        for (i = 0; i < nf; ++i) del[i] -= c * V[t * nf + i];
      }
      for (i = 0; i < nf; ++i) {
        del[i] = (-F[i] - del[i]) / (1.0 + tau);
        slope -= F[i] * del[i];
      }
    }
    fprev = fn;
    if (!(slope > 0)) break;
    for (ls = 0; ls < 40; ++ls, st *= 0.5) { /* the step, halved while d does not rise */
      double dt = 0.0;
      sc_int nt = 0;
      for (i = 0; i < nf; ++i) tr[i] = mu[i] + st * del[i];
      for (i = 0; i < nf; i += sc_block_size(p->kind[fk[i]]))
        if ((ct[nt] = project(p, fk[i], tr + i, pi + i, cap + 4 * nt))) cs[nt++] = i;
      for (i = 0; i < nf; ++i) dt += tr[i] * (l0[i] - pi[i]) + 0.5 * pi[i] * pi[i];
      if (dt >= dv + 1e-4 * st * slope - 1e-15 * (fabs(dv) + scale * scale)) {
        memcpy(mu, tr, sizeof(double) * (size_t)nf);
        ns = nt;
        dv = dt;
        break;
      }
    }
    if (ls == 40) break;
  }
  if (best && bfn <= MN_FLOOR * scale) { /* (no progress, or a last step off a floor that the
    line search took: the best iterate, where it is at that floor) */
    memcpy(lam, best, sizeof(double) * (size_t)nf);
    return 1;
  }
  return 0;
}

/* Minimum-norm forces on the face (every block whose rows do not accelerate: the forces of
 * the others are fixed by the unique accelerations): lam_F -= N N^T lam_F, N the null space
 * of G_FF (null_space: pivots at most NULL_TOL of the first). Where that leaves a force's set
 * and the null space is one direction v, the minimum of |lam_F + t v| over the t that keep
 * every held force in its set (an interval holding 0, its ends found by bisection to
 * rounding) is taken instead; with more null directions, the minimum-norm forces inside the
 * sets (min_norm_in_sets). Z = L^-1 A^T (n x m, scene_solve.c's) checks that the choice keeps
 * the accelerations (tried once more with the null space refined against Z). Returns 0 when
 * the face's rows are independent (nothing to choose), 1 when the minimum-norm forces were
 * found, 2 when not (a degenerate split ellipse on the face, or the choice not found to
 * rounding: the face's basic solution stays). eps: the rows' accelerations may move by this
 * of their scale (1e-13: rounding; more where nearly dependent rows are taken as dependent);
 * loose (0: none): where neither try keeps them within eps, a try that keeps them within
 * loose is taken, the first one's before the refined one's, returning 3 (the caller's
 * accelerations are then the new forces'). p->w is read (the face) and left as it was: the
 * caller takes w of the new forces where it reads it.
 * fkp (engine.h's sc_face_keep, or NULL): what the last choice on the same G kept (a
 * contact-friction fixed point's inner solves share G, and nearly all of their choices are
 * on one face): the face's rows (face, nf of them; nf -1: nothing kept), its null space (nn
 * orthonormal vectors in v, nf doubles each: the same bits as found again, G_FF being the
 * same), room for cap rows (face: cap sc_ints, v: cap^2 doubles), and where has_mu, the last
 * choice's dual point on that face (mu, cap doubles: min_norm_in_sets' start). Taken where
 * the face is the same rows, else found and kept there. The holder sets nf to -1 wherever G
 * changes. */
SC_INTERNAL int sc_min_norm_face(sc_problem *p, const double *Z, double *work, double eps,
                                 double loose, sc_face_keep *fkp) {
  const sc_int m = p->m;
  sc_int F[512], fk[512], perm[512], nf, i, j, nnull = 0;
  double *A, *V, *ev;
  if ((nf = sc_face_rows(p, F, fk)) == 0) return 0; /* (every block whose rows do not
    accelerate) */
  A = work;
  V = A + nf * nf;
  ev = V + nf * nf;
  if (fkp && fkp->nf == nf && !memcmp(fkp->face, F, sizeof(sc_int) * (size_t)nf)) {
    nnull = fkp->nn; /* (a copy: the refined try overwrites V) */
    memcpy(V, fkp->v, sizeof(double) * (size_t)(nnull * nf));
  } else {
    for (i = 0; i < nf; ++i) /* (the lower triangle: all that null_space reads) */
      for (j = 0; j <= i; ++j) A[i * nf + j] = p->G[F[i] * m + F[j]];
    nnull = null_space(nf, A, V, ev, perm, NULL_TOL);
    if (fkp && nf > fkp->cap) fkp = NULL; /* (no room: nothing kept) */
    if (fkp) {
      fkp->nf = nf, fkp->nn = nnull, fkp->has_mu = 0;
      memcpy(fkp->face, F, sizeof(sc_int) * (size_t)nf);
      memcpy(fkp->v, V, sizeof(double) * (size_t)(nnull * nf));
    }
  }
  if (nnull == 0) return 0;
  /* (A, G_FF's factor, is free by now: the loose try is kept there) */
  return sc_min_norm_basis(p, Z, nf, F, fk, V, nnull, ev, eps, loose, loose > 0 ? A : NULL,
                           fkp);
}

/* The forces of sc_min_norm_basis's loose try where one was kept (returns 3), else 2. */
static int loose_try(sc_problem *p, sc_int nf, const sc_int *F, const double *kept) {
  sc_int i;
  if (!kept) return 2;
  for (i = 0; i < nf; ++i) p->lam[F[i]] = kept[i];
  return 3;
}

/* sc_min_norm_face's choice on the face's rows F (nf, fk: their blocks) with the null space V
 * (nnull orthonormal vectors, V + t nf) given (scene_rescue.c's: from Z's QR). Returns 1 when
 * the minimum-norm forces were found, 2 when not, 3 when found within loose only (kept: nf
 * doubles for that try, NULL without). Work: 2 nf^2 + 12 nf + n^2 + 3 n doubles. */
SC_INTERNAL int sc_min_norm_basis(sc_problem *p, const double *Z, sc_int nf, const sc_int *F,
                                  const sc_int *fk, double *V, sc_int nnull, double *work,
                                  double eps, double loose, double *kept, sc_face_keep *fkp) {
  const sc_int m = p->m;
  sc_int i, j, t, tnull = nnull - 1;
  double *l0 = work + 2 * nf;
  int attempt, have = 0;
  for (attempt = 0;; ++attempt) { /* (again with V refined where the choice moves the
    accelerations beyond rounding) */
    double quad = 0.0;
    int inside = 1;
    if (attempt == 1) refine_null(p, Z, nf, F, V, nnull, l0 + nf);
    for (i = 0; i < nf; ++i) l0[i] = p->lam[F[i]];
    for (t = 0; t < nnull; ++t) {
      double s = 0.0;
      for (i = 0; i < nf; ++i) s += V[t * nf + i] * l0[i];
      for (i = 0; i < nf; ++i) l0[i] -= s * V[t * nf + i];
    }
    for (i = 0; i < nf; i += sc_block_size(p->kind[fk[i]]))
      if (!sc_in_set(p, fk[i], l0 + i, 1e-13, 1)) inside = 0;
    if (!inside && (nnull > 1 || attempt == 1)) { /* the minimum inside the sets, by its
      dual's Newton */
      const int warm = fkp && fkp->has_mu; /* (from the kept point: where that fails, from
        l0 again, as without it) */
      if (!min_norm_in_sets(p, nf, fk, l0, V, nnull, l0, l0 + nf, fkp, NULL) &&
          !(warm && min_norm_in_sets(p, nf, fk, l0, V, nnull, l0, l0 + nf, fkp, NULL)))
        return loose_try(p, nf, F, have ? kept : NULL);
    } else if (!inside) { /* one null direction: the forces' interval along it */
      double tstar = 0.0, lim[2];
      int side;
      for (i = 0; i < nf; ++i) tstar -= V[tnull * nf + i] * p->lam[F[i]];
      for (side = 0; side < 2; ++side) { /* the interval's ends: every block stays in its set */
        double dir = side ? 1.0 : -1.0, lo = 0.0, hi = 1.0, l[2];
        int it, ok = 1;
        for (it = 0; it < 80 && ok; ++it) { /* grow until one block leaves */
          for (i = 0; i < nf && ok; i += sc_block_size(p->kind[fk[i]])) {
            l[0] = p->lam[F[i]] + dir * hi * V[tnull * nf + i];
            if (sc_block_size(p->kind[fk[i]]) == 2)
              l[1] = p->lam[F[i + 1]] + dir * hi * V[tnull * nf + i + 1];
            if (!sc_in_set(p, fk[i], l, 1e-12, 0)) ok = 0;
          }
          if (ok) { lo = hi; hi *= 2.0 * (1.0 + p->fscale); }
        }
        if (ok) { lim[side] = INFINITY; continue; }
        for (it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
          double mid = 0.5 * (lo + hi);
          int in = 1;
          for (i = 0; i < nf && in; i += sc_block_size(p->kind[fk[i]])) {
            l[0] = p->lam[F[i]] + dir * mid * V[tnull * nf + i];
            if (sc_block_size(p->kind[fk[i]]) == 2)
              l[1] = p->lam[F[i + 1]] + dir * mid * V[tnull * nf + i + 1];
            if (!sc_in_set(p, fk[i], l, 1e-12, 0)) in = 0;
          }
          if (in) lo = mid; else hi = mid;
        }
        lim[side] = lo;
      }
      tstar = fmax(-lim[0], fmin(lim[1], tstar));
      for (i = 0; i < nf; ++i) l0[i] = p->lam[F[i]] + tstar * V[tnull * nf + i];
      for (i = 0; i < nf; i += sc_block_size(p->kind[fk[i]])) /* rounding onto the sets */
        sc_in_set(p, fk[i], l0 + i, INFINITY, 1);
    }
    /* the forces may change only along A^T's null space: the accelerations stay put to
     * rounding, |A_F^T dlam|^2_{M^-1} = |Z_F dlam|^2 (else the choice is tried again with V
     * refined, then refused; summed as squares, its rounding is that of Z dlam squared:
     * dlam^T G_FF dlam would carry G's rounding times |dlam|^2, far above the bound) */
    for (t = 0; t < p->n; ++t) {
      double t2 = 0.0;
      for (j = 0; j < nf; ++j) t2 += Z[t * m + F[j]] * (l0[j] - p->lam[F[j]]);
      quad += t2 * t2;
    }
    if (quad <= eps * eps * p->wscale * p->fscale) break;
    if (kept && !have && quad <= loose * loose * p->wscale * p->fscale) {
      memcpy(kept, l0, sizeof(double) * (size_t)nf);
      have = 1;
    }
    if (attempt == 1) return loose_try(p, nf, F, have ? kept : NULL);
  }
  for (i = 0; i < nf; ++i) p->lam[F[i]] = l0[i];
  return 1;
}


/* The minimum-norm forces among those of a family (declared in scene_sets.h). */
SC_INTERNAL int sc_min_norm_rows(const sc_problem *p, sc_int nf, const sc_int *fk, double *Gff,
                                 double tol, double *lam, double *work) {
  double *V = work, *l0 = V + nf * nf, *ev = l0 + nf;
  sc_int perm[512], i, t, nn;
  if (nf > 512) return 2;
  if ((nn = null_space(nf, Gff, V, ev, perm, tol)) == 0) return 0;
  memcpy(l0, lam, sizeof(double) * (size_t)nf); /* (its part orthogonal to V: l0) */
  for (t = 0; t < nn; ++t) {
    double c = 0.0;
    for (i = 0; i < nf; ++i) c += V[t * nf + i] * l0[i];
    for (i = 0; i < nf; ++i) l0[i] -= c * V[t * nf + i];
  }
  return min_norm_in_sets(p, nf, fk, l0, V, nn, lam, ev, NULL, ev + 2 * nf * nf + 12 * nf) ?
         1 : 2;
}
