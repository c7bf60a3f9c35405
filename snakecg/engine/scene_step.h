/* snakecg's engine: what a general scene's step (scene_step.c) hands to its run
 * (scene_run.c): the links' cosines and sines at the state the steps ended at, taken at its
 * rows' kinematics. Included after engine.h. */
#ifndef SNAKECG_ENGINE_SCENE_STEP_H
#define SNAKECG_ENGINE_SCENE_STEP_H

/* The links' (cos phi_i, sin phi_i) (2 n_l) at x where the last rows of the steps that keep
 * their scratch in keep (sc_scene_step_kept's) were taken at x's q; else null. */
SC_INTERNAL const double *sc_scene_step_cs(const void *keep, const double *x);
#endif
