/* snakecg's engine: the paper's contact check (geometry.c) from the links' cosines and sines
 * a caller already has (scene_run.c's run: the step's, taken at its rows' kinematics).
 * Included after engine.h. */
#ifndef SNAKECG_ENGINE_GEOMETRY_H
#define SNAKECG_ENGINE_GEOMETRY_H

/* sc_geo_depth at the state y with the links' (cos phi_i, sin phi_i) given in cs (2 n_l;
 * phi_1 = theta, phi_{i+1} = phi_i + q_i), equal to its own within rounding. */
SC_INTERNAL double sc_geo_depth_cs(const sc_geometry *g, const double *y, const double *cs,
                                   sc_int *pair);
#endif
