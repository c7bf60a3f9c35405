/* snakecg's engine: the closest points between a general scene's shapes (placed by
 * scene_place.c; the rows from them: scene_rows.c).
 *
 * Every shape is a core and a radius: a link's capsule (a segment, the robot's radius), a
 * disc or a peg (a point), a box (a convex polygon, counter-clockwise, radius 0), a wall (a
 * half-plane, its normal into the free side). sc_shape_closest returns the signed distance of
 * two shapes' surfaces, continuous through contact: > 0 their distance, < 0 minus their
 * penetration depth (the least translation that parts them: the origin's depth in the hull of
 * the cores' difference B - A, plus the radii), and the contacts: the surface points on A and
 * on B and the unit normal from A to B. Apart, the closest features: one contact, two where
 * two features are parallel (the ends of the shared stretch); overlapping, the supporting
 * features along the parting normal: a corner gives one, flush edges the ends of their shared
 * stretch. Contacts closer than `merge` (the contact tolerance) are one. Tolerances relative
 * to the scene's size `scale`:
 *   1e-12  equal distances (ties between candidate pairs), cores that overlap (else touch)
 *   1e-9   a parallel stretch worth two contacts, a supporting edge, a point on an edge
 * Where the cores touch (distance within 1e-9 scale) the normal is the touched edge's, or a
 * segment's side toward the other body, or the line between the shapes' centroids.
 * A link's segment and a box (the pushes' pair): the hull's edges are the box's and the
 * segment's two directions, known without building the hull, and the origin's side of each
 * (computed once) decides both whether the shapes are apart (the separating axes are those
 * edges' normals) and how deep the cores overlap.
 */
#include "snakecg_layout.h"
#include "engine.h"

/* Segment k of a shape (an edge of a polygon; a segment's one; a point twice). */
static void segment_of(const sc_shape *s, int k, const double **a, const double **b) {
  if (s->kind == SC_POLYGON) {
    *a = s->p[k];
    *b = s->p[(k + 1) % s->np];
  } else if (s->kind == SC_SEGMENT) {
    *a = s->p[0];
    *b = s->p[1];
  } else {
    *a = *b = s->p[0];
  }
}

static int segments(const sc_shape *s) { return s->kind == SC_POLYGON ? s->np : 1; }

/* The point of segment [a, b] nearest p. */
static void point_segment(const double *p, const double *a, const double *b, double *out) {
  double d0 = b[0] - a[0], d1 = b[1] - a[1], L = d0 * d0 + d1 * d1, t = 0.0;
  if (L != 0) {
    t = ((p[0] - a[0]) * d0 + (p[1] - a[1]) * d1) / L;
    t = t > 1.0 ? 1.0 : (t < 0.0 ? 0.0 : t);
  }
  out[0] = a[0] + t * d0;
  out[1] = a[1] + t * d1;
}

/* Which of the k distances |(x_i, y_i)| can be the least or within tie of it (at most tie
 * more): the others are certainly farther, by their squares (relative rounding ~1e-16 against
 * a margin of 1e-13, and of tie itself; squares below 1e-280 not trusted); their distances
 * (hypot) are not needed. The kept ones' into dist, the others' INFINITY. */
static void nearest(int k, const double (*xy)[2], double tie, double *dist) {
  double sq[SC_TOUCH_MAX], least = INFINITY, cut;
  int i;
  for (i = 0; i < k; ++i) {
    sq[i] = xy[i][0] * xy[i][0] + xy[i][1] * xy[i][1];
    if (sq[i] < least) least = sq[i];
  }
  cut = (sqrt(least) * (1 + 1e-13) + tie) * (1 + 1e-13);
  cut = cut * cut > 1e-280 ? cut * cut : INFINITY;
  for (i = 0; i < k; ++i) dist[i] = sq[i] > cut ? INFINITY : hypot(xy[i][0], xy[i][1]);
}

static void put(double *pairs, int *np, const double *p, const double *q) {
  double *o = pairs + 4 * (*np)++;
  o[0] = p[0];
  o[1] = p[1];
  o[2] = q[0];
  o[3] = q[1];
}

/* Nearest point pairs of two segments, appended to pairs (4 doubles each): one, or the two
 * ends of the shared stretch of parallel ones (its middle where shorter than merge), or
 * every candidate at the least distance. */
static void segment_pairs(const double *a0, const double *a1, const double *b0, const double *b1,
                          double scale, double merge, double *pairs, int *np) {
  double da[2] = {a1[0] - a0[0], a1[1] - a0[1]}, db[2] = {b1[0] - b0[0], b1[1] - b0[1]};
  double cross = da[0] * db[1] - da[1] * db[0], c[4][4], d[4][2], dist[4], best, la = 1.0,
         lb = 1.0;
  int i;
  /* not parallel by the squares (a margin of 1e-6 on rounding; cross^2 above 1e-280: then
   * neither segment is a point, la, lb > 0): the lengths, not needed, are not taken */
  const int apart = cross * cross > 1e-280 &&
                    cross * cross > 1.000001e-24 * (da[0] * da[0] + da[1] * da[1]) *
                                        (db[0] * db[0] + db[1] * db[1]);
  if (!apart) {
    la = hypot(da[0], da[1]);
    lb = hypot(db[0], db[1]);
  }
  if (!apart && la > 0 && lb > 0 && fabs(cross) <= 1e-12 * la * lb) { /* parallel: b's ends on a */
    double u[2] = {da[0] / la, da[1] / la}, s0, s1, lo, hi;
    s0 = (b0[0] - a0[0]) * u[0] + (b0[1] - a0[1]) * u[1];
    s1 = (b1[0] - a0[0]) * u[0] + (b1[1] - a0[1]) * u[1];
    if (s1 < s0) {
      double t = s0;
      s0 = s1;
      s1 = t;
    }
    lo = s0 > 0.0 ? s0 : 0.0;
    hi = s1 < la ? s1 : la;
    if (hi - lo > 1e-9 * scale) {
      double s[2] = {lo, hi}, pa[2], pb[2];
      int two = hi - lo > merge;
      if (!two) s[0] = 0.5 * (lo + hi);
      for (i = 0; i < 1 + two; ++i) {
        pa[0] = a0[0] + s[i] * u[0];
        pa[1] = a0[1] + s[i] * u[1];
        point_segment(pa, b0, b1, pb);
        put(pairs, np, pa, pb);
      }
      return;
    }
  }
  c[0][0] = a0[0]; c[0][1] = a0[1];
  point_segment(a0, b0, b1, c[0] + 2);
  c[1][0] = a1[0]; c[1][1] = a1[1];
  point_segment(a1, b0, b1, c[1] + 2);
  point_segment(b0, a0, a1, c[2]);
  c[2][2] = b0[0]; c[2][3] = b0[1];
  point_segment(b1, a0, a1, c[3]);
  c[3][2] = b1[0]; c[3][3] = b1[1];
  if (la > 0 && lb > 0 && cross != 0) { /* crossing interiors */
    double w0 = b0[0] - a0[0], w1 = b0[1] - a0[1];
    double t = (w0 * db[1] - w1 * db[0]) / cross, s = (w0 * da[1] - w1 * da[0]) / cross;
    if (0 < t && t < 1 && 0 < s && s < 1) {
      double x[2] = {a0[0] + t * da[0], a0[1] + t * da[1]};
      put(pairs, np, x, x);
      return;
    }
  }
  best = INFINITY;
  for (i = 0; i < 4; ++i) {
    d[i][0] = c[i][2] - c[i][0];
    d[i][1] = c[i][3] - c[i][1];
  }
  nearest(4, (const double(*)[2])d, 1e-12 * scale, dist);
  for (i = 0; i < 4; ++i)
    if (dist[i] < best) best = dist[i];
  for (i = 0; i < 4; ++i)
    if (dist[i] <= best + 1e-12 * scale) put(pairs, np, c[i], c[i] + 2);
}

/* The convex hull (counter-clockwise, no collinear points; Andrew's monotone chain) of the
 * cores' difference B - A, every core point of B less every one of A, into h; its count. */
static int difference_hull(const sc_shape *A, const sc_shape *B, double (*h)[2]) {
  double p[16][2], t0, t1;
  int n = 0, i, j, k = 0, lo;
  for (i = 0; i < A->np; ++i)
    for (j = 0; j < B->np; ++j, ++n) {
      p[n][0] = B->p[j][0] - A->p[i][0];
      p[n][1] = B->p[j][1] - A->p[i][1];
    }
  for (i = 1; i < n; ++i) /* sorted by x, then y */
    for (j = i; j > 0 && (p[j][0] < p[j - 1][0] ||
                          (p[j][0] == p[j - 1][0] && p[j][1] < p[j - 1][1])); --j) {
      t0 = p[j][0], t1 = p[j][1];
      p[j][0] = p[j - 1][0], p[j][1] = p[j - 1][1];
      p[j - 1][0] = t0, p[j - 1][1] = t1;
    }
#define TURN(a, b, c) \
  (((b)[0] - (a)[0]) * ((c)[1] - (a)[1]) - ((b)[1] - (a)[1]) * ((c)[0] - (a)[0]))
  for (i = 0; i < n; ++i) { /* the lower chain, then the upper */
    while (k >= 2 && TURN(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k][0] = p[i][0], h[k++][1] = p[i][1];
  }
  for (i = n - 2, lo = k + 1; i >= 0; --i) {
    while (k >= lo && TURN(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k][0] = p[i][0], h[k++][1] = p[i][1];
  }
#undef TURN
  return n == 1 ? 1 : k - 1;
}

/* The edges of the difference hull of a segment A (not a point) and a polygon B, without
 * the hull: B's edges and the segment's two directions, each by its outward normal o (the
 * right of the edge e, counter-clockwise) as the origin's side x = max (B_j - A_i) . o of
 * the hull's points (x >= 0 inside; the hull's x = a x e, a its point on the edge), into
 * e and x; their count (np of B + 2). */
static int segment_polygon_edges(const sc_shape *A, const sc_shape *B, double (*e)[2],
                                 double *x) {
  const double *a0 = A->p[0], *a1 = A->p[1];
  const double d0 = a1[0] - a0[0], d1 = a1[1] - a0[1];
  int k, j, m = B->np;
  for (k = 0; k < m; ++k) { /* B's edge k: its first corner less A's point least along o */
    const double *b = B->p[k], *c = B->p[(k + 1) % m];
    const double e0 = c[0] - b[0], e1 = c[1] - b[1];
    const double x0 = (b[0] - a0[0]) * e1 - (b[1] - a0[1]) * e0;
    const double x1 = (b[0] - a1[0]) * e1 - (b[1] - a1[1]) * e0;
    e[k][0] = e0, e[k][1] = e1;
    x[k] = x0 > x1 ? x0 : x1;
  }
  { /* the segment's two directions: B's corner farthest along o (along -d: the sums along d
     * negated, exactly, so the least of them) */
    double most = -INFINITY, fewest = INFINITY;
    for (j = 0; j < m; ++j) {
      const double v = (B->p[j][0] - a0[0]) * d1 - (B->p[j][1] - a0[1]) * d0;
      most = v > most ? v : most;
      fewest = v < fewest ? v : fewest;
    }
    e[m][0] = d0, e[m][1] = d1, x[m] = most;
    e[m + 1][0] = -d0, e[m + 1][1] = -d1, x[m + 1] = -fewest;
  }
  return m + 2;
}

/* A link's segment (of some length) and a box (a polygon of 3 or 4 corners): the pair whose
 * difference hull's edges segment_polygon_edges gives. */
static int segment_polygon(const sc_shape *A, const sc_shape *B) {
  return A->kind == SC_SEGMENT && B->kind == SC_POLYGON && B->np >= 3 && B->np <= 4 &&
         (A->p[0][0] != A->p[1][0] || A->p[0][1] != A->p[1][1]);
}

/* core_overlap of a segment and a polygon from their difference hull's m edges e and the
 * origin's sides x (segment_polygon_edges). */
static double edges_overlap(const double (*e)[2], const double *x, int m, double *n) {
  double r[6], least = INFINITY, depth = INFINITY;
  int i;
  for (i = 0; i < m; ++i)
    if (x[i] < 0) return 0.0; /* the origin outside an edge's line: apart */
  for (i = 0; i < m; ++i) { /* the squared distances c^2 = x^2 / |e|^2: the least first */
    const double q = e[i][0] * e[i][0] + e[i][1] * e[i][1];
    r[i] = q > 1e-280 && x[i] < 1e100 ? x[i] * x[i] / q : INFINITY;
    least = r[i] < least ? r[i] : least;
  }
  for (i = 0; i < m; ++i) {
    const double e0 = e[i][0], e1 = e[i][1];
    double L, c;
    if (e0 == 0 && e1 == 0) continue; /* a corner repeated */
    if (least > 1e-200 && least < 1e200 && r[i] > least * 1.000001)
      continue; /* c certainly beyond the least (relative rounding ~1e-15 of r) */
    L = hypot(e0, e1);
    c = x[i] / L;
    if (c < depth) {
      depth = c;
      n[0] = -e1 / L;
      n[1] = e0 / L;
    }
  }
  return depth > 0 && depth < INFINITY ? depth : 0.0;
}

/* How deep the cores overlap (> 0; else 0): the origin's depth in their difference hull, from
 * its nearest edge, whose inward normal is the normal n from A to B that parts them by it
 * (the least translation). A hull without interior (points, a segment) holds no depth. (A
 * link's segment and a box: edges_overlap, the hull's edges known without it.) */
static double core_overlap(const sc_shape *A, const sc_shape *B, double *n) {
  double h[33][2], depth = INFINITY;
  int m, i;
  m = difference_hull(A, B, h);
  if (m < 3) return 0.0;
  for (i = 0; i < m; ++i) /* the origin outside an edge's line: no depth (c < 0 below) */
    if (h[i][0] * (h[(i + 1) % m][1] - h[i][1]) - h[i][1] * (h[(i + 1) % m][0] - h[i][0]) < 0)
      return 0.0;
  for (i = 0; i < m; ++i) {
    const double *a = h[i], *b = h[(i + 1) % m];
    double e0 = b[0] - a[0], e1 = b[1] - a[1], L, c, x = a[0] * e1 - a[1] * e0; /* x >= 0 */
    if (depth < 1e100 && depth > 1e-100 && x * x > depth * depth * (e0 * e0 + e1 * e1) * 1.000001)
      continue; /* c = x / |e| certainly beyond the least so far (by squares: no hypot) */
    L = hypot(e0, e1);
    c = x / L; /* the origin inside this edge's line by c */
    if (c < depth) {
      depth = c;
      n[0] = -e1 / L;
      n[1] = e0 / L;
    }
  }
  return depth > 0 ? depth : 0.0;
}

/* The lesser of two numbers (inline: libm's fmin is a call). */
static double lesser(double a, double b) { return b < a ? b : a; }

/* The contacts of cores that overlap, parted along n by depth, into out (the core points):
 * A's supporting feature along n and B's against it; a corner gives one contact, two flush
 * edges the ends of their shared stretch (one at its middle where shorter than merge). */
static void overlap_touches(const sc_shape *A, const sc_shape *B, const double *n,
                            double scale, double merge, sc_touch *out, int *count) {
  const double t[2] = {-n[1], n[0]}, eps = 1e-9 * scale;
  double ha = -INFINITY, hb = INFINITY, ua[2] = {INFINITY, -INFINITY}, ub[2], u[2];
  int i, k, m = 1;
  ub[0] = INFINITY, ub[1] = -INFINITY;
  for (i = 0; i < A->np; ++i) ha = sc_max(ha, A->p[i][0] * n[0] + A->p[i][1] * n[1]);
  for (i = 0; i < B->np; ++i) hb = lesser(hb, B->p[i][0] * n[0] + B->p[i][1] * n[1]);
  for (i = 0; i < A->np; ++i) /* the supporting features' stretches along t */
    if (A->p[i][0] * n[0] + A->p[i][1] * n[1] >= ha - eps) {
      double s = A->p[i][0] * t[0] + A->p[i][1] * t[1];
      ua[0] = lesser(ua[0], s), ua[1] = sc_max(ua[1], s);
    }
  for (i = 0; i < B->np; ++i)
    if (B->p[i][0] * n[0] + B->p[i][1] * n[1] <= hb + eps) {
      double s = B->p[i][0] * t[0] + B->p[i][1] * t[1];
      ub[0] = lesser(ub[0], s), ub[1] = sc_max(ub[1], s);
    }
  if (ua[1] - ua[0] <= eps) { /* A's corner */
    u[0] = ua[0];
  } else if (ub[1] - ub[0] <= eps) { /* B's corner */
    u[0] = ub[0];
  } else { /* flush edges: the ends of the shared stretch, or its middle */
    double lo = sc_max(ua[0], ub[0]), hi = lesser(ua[1], ub[1]);
    m = hi - lo > merge ? 2 : 1;
    u[0] = m == 2 ? lo : 0.5 * (lo + hi);
    u[1] = hi;
  }
  for (k = 0; k < m; ++k) {
    sc_touch *c = out + (*count)++;
    for (i = 0; i < 2; ++i) {
      c->a[i] = ha * n[i] + u[k] * t[i];
      c->b[i] = hb * n[i] + u[k] * t[i];
      c->n[i] = n[i];
    }
  }
}

/* The outward normal of a polygon at its core point q on an edge's interior (1), else 0 (a
 * corner; and always 0 for a segment or a point: no outward normal of their own). */
static int feature_normal(const sc_shape *sh, const double *q, double scale, double *n) {
  int k;
  if (sh->kind != SC_POLYGON && sh->kind != SC_SEGMENT) return 0;
  for (k = 0; k < segments(sh); ++k) {
    const double *a, *b;
    double e0, e1, L, t;
    segment_of(sh, k, &a, &b);
    e0 = b[0] - a[0];
    e1 = b[1] - a[1];
    L = hypot(e0, e1);
    if (L == 0) continue;
    t = ((q[0] - a[0]) * e0 + (q[1] - a[1]) * e1) / (L * L);
    if (1e-9 < t && t < 1 - 1e-9 &&
        fabs((q[0] - a[0]) * e1 - (q[1] - a[1]) * e0) / L <= 1e-9 * scale) {
      if (sh->kind != SC_POLYGON) return 0;
      n[0] = e1 / L;
      n[1] = -e0 / L;
      return 1;
    }
  }
  return 0;
}

/* The mean of a shape's core points. */
SC_INTERNAL void sc_shape_centroid(const sc_shape *s, double *c) {
  int i;
  c[0] = c[1] = 0.0;
  for (i = 0; i < s->np; ++i) {
    c[0] += s->p[i][0];
    c[1] += s->p[i][1];
  }
  c[0] /= s->np;
  c[1] /= s->np;
}

/* The normal from A to B where the cores touch at p (on A) and q (on B). */
static void touching_normal(const sc_shape *A, const sc_shape *B, const double *p,
                            const double *q, double scale, double *n) {
  double nn[2], ca[2], cb[2];
  int side;
  if (feature_normal(B, q, scale, nn)) {
    n[0] = -nn[0];
    n[1] = -nn[1];
    return;
  }
  if (feature_normal(A, p, scale, n)) return;
  for (side = 0; side < 2; ++side) { /* a tip on a segment's side: its normal, toward the other */
    const sc_shape *sh = side ? B : A, *toward = side ? A : B;
    const double *pt = side ? q : p;
    double e0, e1, L, perp[2], sign = side ? -1.0 : 1.0, c[2];
    if (sh->kind != SC_SEGMENT) continue;
    e0 = sh->p[1][0] - sh->p[0][0];
    e1 = sh->p[1][1] - sh->p[0][1];
    L = hypot(e0, e1);
    perp[0] = -e1 / L;
    perp[1] = e0 / L;
    sc_shape_centroid(toward, c);
    if ((c[0] - pt[0]) * perp[0] + (c[1] - pt[1]) * perp[1] < 0) {
      perp[0] = -perp[0];
      perp[1] = -perp[1];
    }
    n[0] = sign * perp[0];
    n[1] = sign * perp[1];
    return;
  }
  sc_shape_centroid(A, ca); /* corner to corner: the line between the centroids */
  sc_shape_centroid(B, cb);
  {
    double d0 = cb[0] - ca[0], d1 = cb[1] - ca[1], L = hypot(d0, d1);
    n[0] = d0 / L;
    n[1] = d1 / L;
  }
}

/* The surfaces of A and B certainly farther apart than beyond (1, else 0): the projections
 * of their cores on a polygon's edge normal or a segment's normal apart by more than beyond,
 * the radii and 1e-9 scale (a margin over the rounding here and in sc_shape_closest), by the
 * squares (no square root). Points and half-planes give no axis. */
static int apart(const sc_shape *A, const sc_shape *B, double beyond, double scale) {
  const sc_shape *S[2] = {A, B};
  const double need = beyond + A->radius + B->radius + 1e-9 * scale;
  int s, k, i;
  if (!(need < INFINITY) || A->kind == SC_HALFPLANE || B->kind == SC_HALFPLANE) return 0;
  for (s = 0; s < 2; ++s) {
    const int ne = S[s]->kind == SC_POLYGON ? S[s]->np : S[s]->kind == SC_SEGMENT ? 1 : 0;
    for (k = 0; k < ne; ++k) {
      const double *a = S[s]->p[k], *b = S[s]->p[(k + 1) % S[s]->np];
      const double ex = a[1] - b[1], ey = b[0] - a[0];
      double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, sep;
      int t;
      for (t = 0; t < 2; ++t)
        for (i = 0; i < S[t]->np; ++i) {
          const double v = S[t]->p[i][0] * ex + S[t]->p[i][1] * ey; /* (inline, not libm's) */
          lo[t] = v < lo[t] ? v : lo[t];
          hi[t] = v > hi[t] ? v : hi[t];
        }
      sep = sc_max(lo[1] - hi[0], lo[0] - hi[1]);
      if (sep > 0 && sep * sep > need * need * (ex * ex + ey * ey)) return 1;
    }
  }
  return 0;
}

/* The signed distance of A's and B's surfaces and their contacts (at most SC_TOUCH_MAX, in
 * out; their count in *count), those closer than merge one; where they are certainly
 * farther apart than beyond (apart), INFINITY and no contacts. A is never a half-plane. */
SC_INTERNAL double sc_shape_closest(const sc_shape *A, const sc_shape *B, double scale,
                                    double merge, double beyond, sc_touch *out, int *count) {
  double pairs[4 * SC_TOUCH_MAX], dist[SC_TOUCH_MAX], core = INFINITY, depth, nrm[2] = {0.0, 0.0};
  int np = 0, i, j, k;
  *count = 0;
  if (B->kind == SC_HALFPLANE) {
    const double *n = B->normal;
    double vals[4], best = INFINITY, d, off = B->p[0][0] * n[0] + B->p[0][1] * n[1];
    int m = A->kind == SC_POINT ? 1 : A->np;
    for (i = 0; i < m; ++i) {
      vals[i] = A->p[i][0] * n[0] + A->p[i][1] * n[1] - off;
      if (vals[i] < best) best = vals[i];
    }
    d = best - A->radius;
    for (i = 0; i < m; ++i) {
      sc_touch *t;
      if (!(vals[i] <= best + 1e-12 * scale)) continue;
      t = out + (*count)++;
      for (k = 0; k < 2; ++k) {
        t->a[k] = A->p[i][k] - A->radius * n[k];
        t->b[k] = t->a[k] - (vals[i] - best) * n[k] - d * n[k];
        t->n[k] = -n[k];
      }
    }
    return d;
  }
  if (B->kind == SC_POINT && A->kind != SC_POLYGON) { /* a capsule or disc and a point apart:
                                                          * the nearest point, one contact */
    const double *q = B->p[0];
    double p[2], dd;
    point_segment(q, A->p[0], A->p[A->kind == SC_SEGMENT ? 1 : 0], p);
    dd = hypot(q[0] - p[0], q[1] - p[1]);
    if (dd > 1e-9 * scale) { /* else the general path below (the features' normals) */
      for (k = 0; k < 2; ++k) {
        out->n[k] = (q[k] - p[k]) / dd;
        out->a[k] = p[k] + A->radius * out->n[k];
        out->b[k] = q[k] - B->radius * out->n[k];
      }
      *count = 1;
      return dd - A->radius - B->radius;
    }
  }
  if (segment_polygon(A, B)) { /* a link and a box: apart and overlap from the hull's edges */
    double e[6][2], x[6];
    const int m = segment_polygon_edges(A, B, e, x);
    const double need = beyond + A->radius + B->radius + 1e-9 * scale;
    for (i = 0; need < INFINITY && i < m; ++i) /* apart's axes, the same margin */
      if (x[i] < 0 && x[i] * x[i] > need * need * (e[i][0] * e[i][0] + e[i][1] * e[i][1]))
        return INFINITY;
    depth = edges_overlap((const double(*)[2])e, x, m, nrm);
  } else {
    if (apart(A, B, beyond, scale)) return INFINITY;
    depth = core_overlap(A, B, nrm);
  }
  merge = fmax(merge, 1e-9 * scale);
  if (depth > 1e-12 * scale) { /* overlapping cores: their least translation */
    overlap_touches(A, B, nrm, scale, merge, out, count);
    core = -depth;
  }
  for (i = 0; depth <= 1e-12 * scale && i < segments(A); ++i)
    for (j = 0; j < segments(B); ++j) {
      const double *a0, *a1, *b0, *b1;
      segment_of(A, i, &a0, &a1);
      segment_of(B, j, &b0, &b1);
      segment_pairs(a0, a1, b0, b1, scale, merge, pairs, &np);
    }
  {
    double d[SC_TOUCH_MAX][2];
    for (i = 0; i < np; ++i) {
      d[i][0] = pairs[4 * i + 2] - pairs[4 * i];
      d[i][1] = pairs[4 * i + 3] - pairs[4 * i + 1];
    }
    nearest(np, (const double(*)[2])d, 1e-12 * scale, dist);
  }
  for (i = 0; i < np; ++i)
    if (dist[i] < core) core = dist[i];
  for (i = 0; i < np; ++i) {
    const double *p = pairs + 4 * i, *q = p + 2;
    double n[2];
    int dup = 0;
    sc_touch *t;
    if (dist[i] > core + 1e-12 * scale) continue;
    for (j = 0; j < *count && !dup; ++j) /* kept before: the core points out[j].a, .b */
      dup = hypot(p[0] - out[j].a[0], p[1] - out[j].a[1]) <= merge &&
            hypot(q[0] - out[j].b[0], q[1] - out[j].b[1]) <= merge;
    if (dup) continue;
    if (dist[i] > 1e-9 * scale) {
      n[0] = (q[0] - p[0]) / dist[i];
      n[1] = (q[1] - p[1]) / dist[i];
    } else {
      touching_normal(A, B, p, q, scale, n);
    }
    t = out + (*count)++;
    for (k = 0; k < 2; ++k) { /* the core points for now: moved to the surfaces below */
      t->a[k] = p[k];
      t->b[k] = q[k];
      t->n[k] = n[k];
    }
  }
  for (j = 0; j < *count; ++j)
    for (k = 0; k < 2; ++k) {
      out[j].a[k] += A->radius * out[j].n[k];
      out[j].b[k] -= B->radius * out[j].n[k];
    }
  return core - A->radius - B->radius;
}
