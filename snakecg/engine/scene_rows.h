/* snakecg's engine: what a general scene's rows (scene_rows.c) hand to its time step
 * (scene_step.c): the links' cosines and sines taken at a state's kinematics, which the next
 * step's bias forces read instead of taking them again. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_ROWS_H
#define SNAKECG_ENGINE_SCENE_ROWS_H

/* the generated bias forces from the links' cosines and sines (bias_forces_cs) */
int SNAKECG_BC(const double **arg, double **res, sc_int *iw, double *w, int mem);
int SNAKECG_BC_WORK(sc_int *sz_arg, sc_int *sz_res, sc_int *sz_iw, sc_int *sz_w);
/* The links' (cos phi_i, sin phi_i) (2 n_l) of the last sc_scene_state_rows call that kept
 * its scratch in keep and took the bodies' inertia (M not null) with status 0, at its q. */
SC_INTERNAL const double *sc_scene_rows_cs(const void *keep);
#endif
