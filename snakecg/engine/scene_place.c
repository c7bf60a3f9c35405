/* snakecg's engine: a general scene's shapes placed at a configuration (sc_scene_place: the
 * links' segments at their poses, the objects at theirs or placed by the scene, the obstacles
 * once) and the objects' placement for the drawing and a simulation's start
 * (core_scene_place, or core_scene_place_q from a configuration). Their closest points:
 * scene_geometry.c.
 */
#include "snakecg_layout.h"
#include "engine.h"
#include "scene_broad.h"

static void box_corners(double x, double y, double th, double sx, double sy, sc_shape *s) {
  double c = cos(th), sn = sin(th), a = sx / 2, b = sy / 2;
  double lx[4] = {-a, a, a, -a}, ly[4] = {-b, -b, b, b};
  int i;
  s->kind = SC_POLYGON;
  s->np = 4;
  s->radius = 0.0;
  for (i = 0; i < 4; ++i) {
    s->p[i][0] = x + (lx[i] * c + ly[i] * -sn);
    s->p[i][1] = y + (lx[i] * sn + ly[i] * c);
  }
}

/* Every body's shape of the scene packed in pk (links, objects, obstacles) at the link poses
 * P (n_l x 3), with the links' cos and sin of their angles in cs (2 each; taken here into cs
 * unless how & 2: given, the generated scene_kinematics' at the same configuration, its
 * rotation products, equal to them within rounding): the objects at their poses qo (3 n_o; a
 * simulation's state) or, qo null, placed by the scene (a pose, or touching a link on its
 * side at an offset); their poses into pose, the broad phase's bounding circles (a wall:
 * none) into centre (the bodies' x, then their y) and reach as scene_broad.h lays them out.
 * Without how & 1 (all), the parts that do not move (the obstacles' shapes and circles, every
 * reach, the links' and discs' kinds and radii) are kept from an earlier call on the same pk
 * and buffers. */
SC_INTERNAL void sc_scene_place(const double *pk, const double *P, const double *qo, int how,
                                double *cs, sc_shape *shape, double *pose, double *centre,
                                double *reach) {
  const double *lk = pk + (sc_int)pk[SP_LINKS], r = pk[SP_RADIUS];
  const sc_int no = (sc_int)pk[SP_NO], nob = (sc_int)pk[SP_NOB], nl = SNAKECG_NL;
  const sc_int pad = sc_broad_pad(nl + no + nob); /* (centre's y after its x) */
  const int all = how & 1;
  sc_int i, j, k;
  for (i = 0; i < nl; ++i) {
    double c, s, x0, y0, x1, y1, L = lk[LINK_W * i + 1];
    if (!(how & 2)) {
      cs[2 * i] = cos(P[3 * i + 2]);
      cs[2 * i + 1] = sin(P[3 * i + 2]);
    }
    c = cs[2 * i];
    s = cs[2 * i + 1];
    x0 = P[3 * i] - lk[LINK_W * i] * c; /* (the ends in registers: the stores may alias) */
    y0 = P[3 * i + 1] - lk[LINK_W * i] * s;
    x1 = x0 + L * c;
    y1 = y0 + L * s;
    shape[i].p[0][0] = x0, shape[i].p[0][1] = y0, shape[i].p[1][0] = x1, shape[i].p[1][1] = y1;
    centre[i] = 0.5 * (x0 + x1);
    centre[pad + i] = 0.5 * (y0 + y1);
    if (all) /* (the kind, radius and reach: set once) */
      shape[i].kind = SC_SEGMENT, shape[i].np = 2, shape[i].radius = r, reach[i] = 0.5 * L + r;
  }
  for (j = 0; j < no; ++j) {
    const double *o = pk + (sc_int)pk[SP_OBJECTS] + OBJ_W * j;
    double *ps = pose + 3 * j;
    sc_shape *sh = shape + nl + j;
    if (qo) {
      ps[0] = qo[3 * j];
      ps[1] = qo[3 * j + 1];
      ps[2] = qo[3 * j + 2];
    } else if (o[6] == 0.0) {
      ps[0] = o[7];
      ps[1] = o[8];
      ps[2] = o[9];
    } else { /* on the named side of link k, the contact at offset from its rear end */
      sc_int lnk = (sc_int)o[7];
      const double *rear = shape[lnk].p[0], c = cs[2 * lnk], s = cs[2 * lnk + 1];
      double h = o[9] * (r + o[10]);
      ps[0] = rear[0] + o[8] * c - h * s;
      ps[1] = rear[1] + o[8] * s + h * c;
      ps[2] = P[3 * lnk + 2];
    }
    if (o[0] == 1.0) { /* (a disc's kind and radius: set once) */
      if (all) sh->kind = SC_POINT, sh->np = 1, sh->radius = o[3];
      sh->p[0][0] = ps[0];
      sh->p[0][1] = ps[1];
    } else {
      box_corners(ps[0], ps[1], ps[2], o[1], o[2], sh);
    }
    centre[nl + j] = ps[0]; /* a disc's centre; a box's, its corners' mean */
    centre[pad + nl + j] = ps[1];
    if (all) reach[nl + j] = o[0] == 1.0 ? o[3] : 0.5 * hypot(o[1], o[2]);
  }
  for (k = 0; all && k < nob; ++k) {
    const double *o = pk + (sc_int)pk[SP_OBSTACLES] + OBS_W * k;
    sc_shape *sh = shape + nl + no + k;
    double c[2], far = 0.0;
    sh->radius = 0.0;
    sh->p[0][0] = o[1];
    sh->p[0][1] = o[2];
    if (o[0] == 0.0) {
      sh->kind = SC_POINT;
      sh->np = 1;
      sh->radius = o[3];
    } else if (o[0] == 1.0) {
      sh->kind = SC_HALFPLANE;
      sh->np = 1;
      sh->normal[0] = o[4];
      sh->normal[1] = o[5];
    } else {
      sh->kind = SC_POLYGON;
      sh->np = 4;
      for (i = 0; i < 4; ++i) {
        sh->p[i][0] = o[6 + 2 * i];
        sh->p[i][1] = o[7 + 2 * i];
      }
    }
    sc_shape_centroid(sh, c);
    for (j = 0; j < sh->np; ++j) far = fmax(far, hypot(sh->p[j][0] - c[0], sh->p[j][1] - c[1]));
    reach[nl + no + k] = sh->kind == SC_HALFPLANE ? INFINITY : far + sh->radius;
    centre[nl + no + k] = c[0];
    centre[pad + nl + no + k] = c[1];
  }
}

/* The objects' poses (3 n_o each) of the scene packed in pk at n configurations' link poses
 * P (n_l x 3 each), as the forward places them (sc_scene_place): the one home of the
 * placement that the drawing and a simulation's start read. Returns 0, or -1 out of memory. */
int SNAKECG_EXPORT(core_scene_place)(const double *pk, sc_int n, const double *P,
                                     double *pose) {
  const sc_int no = (sc_int)pk[SP_NO], nb = SNAKECG_NL + no,
               pad = sc_broad_pad(nb + (sc_int)pk[SP_NOB]); /* (the circles' layout) */
  sc_shape *shape = (sc_shape *)malloc(sizeof(sc_shape) * (size_t)nb);
  double *d = (double *)malloc(sizeof(double) * (size_t)(2 * SNAKECG_NL + 3 * pad));
  sc_int i;
  const int ok = shape && d;
  if (ok)
    for (i = 0; i < n; ++i) /* the parts that do not move (how = 0) are not read */
      sc_scene_place(pk, P + 3 * SNAKECG_NL * i, 0, 0, d, shape, pose + 3 * no * i,
                     d + 2 * SNAKECG_NL, d + 2 * SNAKECG_NL + 2 * pad);
  free(shape);
  free(d);
  return ok ? 0 : -1;
}

/* The objects' poses (3 n_o) of the scene packed in pk at one configuration q (n_s): the
 * link poses by the generated link_poses (with the scene's parameters, as the model's
 * link_poses takes them), then core_scene_place's placement; the same numbers as those two
 * steps from Python, without their calls' overhead (a simulation's start). Returns 0, -1 out
 * of memory, 1 the generated function refused. */
int SNAKECG_EXPORT(core_scene_place_q)(const double *pk, const double *q, double *pose) {
  const sc_work_fn fns[] = {SNAKECG_LP_WORK};
  double P[3 * SNAKECG_NL];
  sc_work_t ws;
  int code;
  if (sc_work_alloc(&ws, fns, 1)) return -1;
  ws.arg[LP_IN_q] = q, ws.arg[LP_IN_K] = pk + (sc_int)pk[SP_K], ws.res[LP_OUT_poses] = P;
  code = SNAKECG_LP(ws.arg, ws.res, ws.iw, ws.w, 0) ? 1 : 0;
  sc_work_free(&ws);
  return code ? code : SNAKECG_EXPORT(core_scene_place)(pk, 1, P, pose);
}
