/* The geometry a simulation checks (snakecg/geometry.py, ContactCheck, is its reference):
 * every link against the object and every pair of non-neighbouring links against each other,
 * as overlap depths (m, 0 when apart), at a state y = (q, q_obj, ...).
 *
 * Part of the engine (not generated); used by integrate.c and run.c through engine.h. The links are the segments of the planar chain (rear end of link 1 at
 * (x, y) - c_1 e_1, each link's front end the next one's rear end; phi_1 = theta,
 * phi_{i+1} = phi_i + q_i), or capsules of a radius; the object is the square plate of half
 * side h centred at q_obj[0..1], turned by q_obj[2].
 *   - link and object: radius + the depth of the segment's deepest point inside the plate
 *     (the distance to the plate's boundary, concave and piecewise linear along the segment:
 *     its maximum is at an end or where two of its pieces meet), or, outside it,
 *     radius - the distance from the segment to the plate;
 *   - two links: 2 radius - the distance between the segments or, when they cross, plus the
 *     least distance from an end of one to the other (continuous: 0 where they touch).
 * The pairs are numbered as ContactCheck.pairs: link i (from 0) and the object is pair i,
 * then the links (i, j), i < j - 1, in order. A pair whose bounding circles (a link's about
 * its middle, the plate's about its centre, widened by the radius) are apart has overlap 0
 * and is not measured further.
 * Also the rows' velocities A V from the generated `link_jacobians` (integrate.c, events.c):
 * here, not in contact.c, so that contact.c and forward.c compile alone into a spatial
 * scene's library, which has no planar link Jacobians. */
#include <math.h>
#include <string.h>

#include "snakecg_layout.h"
#include "engine.h"
#include "geometry.h"

#define SC_GEO_NL SNAKECG_NL
/* the larger and smaller of two numbers (inlined: the library's fmax and fmin are calls) */
static double sc_geo_max(double a, double b) { return a > b ? a : b; }
static double sc_geo_min(double a, double b) { return a < b ? a : b; }


static double sc_geo_cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

/* Distance from (px, py) to the segment a-b (geometry.point_segment_distance). */
static double sc_geo_point_segment(double px, double py, double ax, double ay, double bx,
                                double by) {
  const double dx = bx - ax, dy = by - ay, dd = dx * dx + dy * dy;
  double t = dd > 0 ? ((px - ax) * dx + (py - ay) * dy) / dd : 0.0, ex, ey;
  t = t < 0 ? 0.0 : (t > 1 ? 1.0 : t);
  ex = px - (ax + t * dx);
  ey = py - (ay + t * dy);
  return sqrt(ex * ex + ey * ey);
}

/* Whether the segments a0-a1 and b0-b1 cross (each one's ends strictly on both sides of the
 * other's line). */
static int sc_geo_crossing(const double *a0, const double *a1, const double *b0,
                           const double *b1) {
  const double dax = a1[0] - a0[0], day = a1[1] - a0[1];
  const double dbx = b1[0] - b0[0], dby = b1[1] - b0[1];
  const double s1 = sc_geo_cross(dbx, dby, a0[0] - b0[0], a0[1] - b0[1]);
  const double s2 = sc_geo_cross(dbx, dby, a1[0] - b0[0], a1[1] - b0[1]);
  const double s3 = sc_geo_cross(dax, day, b0[0] - a0[0], b0[1] - a0[1]);
  const double s4 = sc_geo_cross(dax, day, b1[0] - a0[0], b1[1] - a0[1]);
  return s1 * s2 < 0 && s3 * s4 < 0;
}

/* The least distance from an end of a0-a1 or b0-b1 to the other, and whether they cross. */
static double sc_geo_ends(const double *a0, const double *a1, const double *b0, const double *b1,
                       int *crossing) {
  *crossing = sc_geo_crossing(a0, a1, b0, b1);
  return sc_geo_min(sc_geo_min(sc_geo_point_segment(a0[0], a0[1], b0[0], b0[1], b1[0], b1[1]),
                   sc_geo_point_segment(a1[0], a1[1], b0[0], b0[1], b1[0], b1[1])),
              sc_geo_min(sc_geo_point_segment(b0[0], b0[1], a0[0], a0[1], a1[0], a1[1]),
                   sc_geo_point_segment(b1[0], b1[1], a0[0], a0[1], a1[0], a1[1])));
}

/* The depth of the deepest point of the segment a-b (in the plate's frame) inside the plate
 * of half side h, 0 when it stays outside (geometry.object_penetration). */
static double sc_geo_plate_depth(double ax, double ay, double bx, double by, double h) {
  const double dx = bx - ax, dy = by - ay;
  /* both ends beyond one of the plate's sides (by far more than the rounding of the points
   * below): every point outside, the depth 0 */
  const double m = h + 1e-12 * (h + fabs(ax) + fabs(ay) + fabs(bx) + fabs(by));
  double ts[6], best = 0.0;
  int k;
  if ((ax > m && bx > m) || (ax < -m && bx < -m) || (ay > m && by > m) || (ay < -m && by < -m))
    return 0.0;
  ts[0] = 0.0, ts[1] = 1.0, ts[2] = -ax / dx, ts[3] = -ay / dy;
  ts[4] = -(ax - ay) / (dx - dy), ts[5] = -(ax + ay) / (dx + dy);
  for (k = 0; k < 6; ++k) {
    double t = isfinite(ts[k]) ? ts[k] : 0.0;
    t = t < 0 ? 0.0 : (t > 1 ? 1.0 : t);
    best = sc_geo_max(best, h - sc_geo_max(fabs(ax + t * dx), fabs(ay + t * dy)));
  }
  return best;
}

/* The overlap of the link a-b (in the plate's frame) and the plate of half side h. */
static double sc_geo_link_plate(double ax, double ay, double bx, double by, double h, double r) {
  const double d = sc_geo_plate_depth(ax, ay, bx, by, h);
  if (r <= 0) return d;
  if (d > 0) return d + r;
  { /* outside: the distance to the plate's edges (the corners built only here) */
    const double c[5][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}, {-h, -h}};
    const double a[2] = {ax, ay}, b[2] = {bx, by};
    double dist = INFINITY;
    int k, crossing;
    for (k = 0; k < 4; ++k) {
      const double e = sc_geo_ends(a, b, c[k], c[k + 1], &crossing);
      dist = sc_geo_min(dist, crossing ? 0.0 : e);
    }
    return sc_geo_max(0.0, r - dist);
  }
}

/* The largest overlap at the state y and its pair (the first of equals). */
double sc_geo_depth(const sc_geometry *g, const double *y, sc_int *pair) {
  double cs[2 * SC_GEO_NL], phi = y[2];
  sc_int i;
  for (i = 0; i < SC_GEO_NL; ++i) {
    if (i) phi += y[2 + i];
    cs[2 * i] = cos(phi);
    cs[2 * i + 1] = sin(phi);
  }
  return sc_geo_depth_cs(g, y, cs, pair);
}

/* sc_geo_depth from the links' (cos phi_i, sin phi_i) in cs (2 n_l): geometry.h. */
SC_INTERNAL double sc_geo_depth_cs(const sc_geometry *g, const double *y, const double *cs,
                                   sc_int *pair) {
  double rear[SC_GEO_NL][2], front[SC_GEO_NL][2], best = 0.0;
  const double h = g->half, r = g->radius, ox = y[SNAKECG_NS], oy = y[SNAKECG_NS + 1];
  const double cs_o = cos(y[SNAKECG_NS + 2]), sn = sin(y[SNAKECG_NS + 2]);
  const double reach = h * 1.4142135623730951 + r; /* the plate's circle, widened */
  sc_int i, j, p = 0;
  for (i = 0; i < SC_GEO_NL; ++i) {
    const double ex = cs[2 * i], ey = cs[2 * i + 1];
    if (i == 0) {
      rear[0][0] = y[0] - g->com1 * ex;
      rear[0][1] = y[1] - g->com1 * ey;
    } else {
      rear[i][0] = front[i - 1][0];
      rear[i][1] = front[i - 1][1];
    }
    front[i][0] = rear[i][0] + g->length[i] * ex;
    front[i][1] = rear[i][1] + g->length[i] * ey;
  }
  *pair = 0;
  for (i = 0; i < SC_GEO_NL; ++i, ++p) { /* the links and the object */
    const double mx = 0.5 * (rear[i][0] + front[i][0]) - ox;
    const double my = 0.5 * (rear[i][1] + front[i][1]) - oy, far = 0.5 * g->length[i] + reach;
    if (mx * mx + my * my <= far * far) { /* in the plate's frame */
      const double ax = cs_o * (rear[i][0] - ox) + sn * (rear[i][1] - oy);
      const double ay = -sn * (rear[i][0] - ox) + cs_o * (rear[i][1] - oy);
      const double bx = cs_o * (front[i][0] - ox) + sn * (front[i][1] - oy);
      const double by = -sn * (front[i][0] - ox) + cs_o * (front[i][1] - oy);
      const double d = sc_geo_link_plate(ax, ay, bx, by, h, r);
      if (d > best) best = d, *pair = p;
    }
  }
  for (i = 0; i < SC_GEO_NL; ++i) /* non-neighbouring links */
    for (j = i + 2; j < SC_GEO_NL; ++j, ++p) {
      const double mx = 0.5 * (rear[i][0] + front[i][0] - rear[j][0] - front[j][0]);
      const double my = 0.5 * (rear[i][1] + front[i][1] - rear[j][1] - front[j][1]);
      const double far = 0.5 * (g->length[i] + g->length[j]) + 2 * r;
      if (mx * mx + my * my <= far * far) {
        int crossing;
        double e, d;
        /* segments (radius 0) apart or touching overlap by max(0, -e) = 0: their ends'
         * distances are needed only where they cross */
        if (r <= 0 && !sc_geo_crossing(rear[i], front[i], rear[j], front[j])) continue;
        e = sc_geo_ends(rear[i], front[i], rear[j], front[j], &crossing);
        d = sc_geo_max(0.0, 2 * r - (crossing ? -e : e));
        if (d > best) best = d, *pair = p;
      }
    }
  return best;
}

/* The first violation: at t, the state y (NY), its overlap and pair. */
void sc_geo_record(sc_geometry *g, double t, const double *y, double depth, sc_int pair) {
  g->found = 1;
  g->t = t;
  g->depth = depth;
  g->pair = pair;
  memcpy(g->y, y, sizeof(double) * NY);
}

/* The contact check at n states Y (n x NY, row-major): the largest overlap of each in depth,
 * its pair in pair (as a double). Returns 0. */
int SNAKECG_EXPORT(core_contact_depth)(const sc_geometry *g, sc_int n, const double *Y,
                                      double *depth, double *pair) {
  sc_int k, p;
  for (k = 0; k < n; ++k) {
    depth[k] = sc_geo_depth(g, Y + k * NY, &p);
    pair[k] = (double)p;
  }
  return 0;
}

/* The first of n states whose largest overlap exceeds tol (rows of `stride` doubles from Y,
 * each q then q_obj: a record read in place): its index, or n where none; that overlap and
 * its pair into out[0], out[1]. */
int SNAKECG_EXPORT(core_contact_first)(const sc_geometry *g, sc_int n, const double *Y,
                                      sc_int stride, double tol, double *out) {
  sc_int k, p;
  for (k = 0; k < n; ++k) {
    const double d = sc_geo_depth(g, Y + k * stride, &p);
    if (d > tol) {
      out[0] = d;
      out[1] = (double)p;
      return (int)k;
    }
  }
  return (int)n;
}

/* A V (snakecg.simulate.dynamics.Dynamics.row_velocities): the gap rate (row 0) and the
 * wheels' lateral velocities, from the generated `link_jacobians` at q (its status, 0 on
 * success). The link twists J v; the wheel row of link i is (-sin phi_i, cos phi_i,
 * wheel_offset_i) on its twist, the contact row the normal n = side (-sin phi_k, cos phi_k)
 * on the velocity of the object's contact point (rho in the object frame) relative to the
 * link's, less the sliding term side omega_k (s - c_k). */
int sc_row_velocities(sc_work_t *ws, const double *scene, const double *rho, int k,
                      double c_k, const double *q, const double *v, const double *qo,
                      const double *vo, double s, double *av) {
  enum { ns = SNAKECG_NS, nl = SNAKECG_NL };
  const double *woff = scene + SCENE_wheel_offset;
  const double sig = scene[SCENE_side];
  double J[3 * SNAKECG_NL * SNAKECG_NS], tw[3 * SNAKECG_NL], phi = q[2], spk = 0.0, cpk = 0.0;
  double n0, n1, cs, sn, rx, ry, p0, p1;
  int i, j;
  ws->arg[LJ_IN_q] = q;
  ws->arg[LJ_IN_K] = scene + SCENE_K;
  ws->res[LJ_OUT_J] = J;
  if (SNAKECG_LJ(ws->arg, ws->res, ws->iw, ws->w, 0)) return 1;
  for (i = 0; i < 3 * nl; ++i) {
    double t = 0.0;
    for (j = 0; j < ns; ++j) t += J[i + 3 * nl * j] * v[j];
    tw[i] = t;
  }
  for (i = 0; i < nl; ++i) { /* phi_1 = theta, phi_{i+1} = phi_i + q_i */
    double sp, cp;
    if (i) phi += q[2 + i];
    sp = sin(phi);
    cp = cos(phi);
    if (i == k) {
      spk = sp;
      cpk = cp;
    }
    av[1 + i] = -sp * tw[3 * i] + cp * tw[3 * i + 1] + woff[i] * tw[3 * i + 2];
  }
  n0 = sig * -spk;
  n1 = sig * cpk;
  cs = cos(qo[2]);
  sn = sin(qo[2]);
  rx = rho[0];
  ry = rho[1];
  p0 = vo[0] - vo[2] * (sn * rx + cs * ry);
  p1 = vo[1] + vo[2] * (cs * rx - sn * ry);
  av[0] = n0 * (p0 - tw[3 * k]) + n1 * (p1 - tw[3 * k + 1]) - sig * tw[3 * k + 2] * (s - c_k);
  return 0;
}
