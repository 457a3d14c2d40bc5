/* rl_place_obs: one frame's identified landmarks as the place search
 * (rl_place.c) sees them: on the ceiling of a level robot, each at the
 * height of the map landmark it is tried as. Internal to the core.
 *
 *   extern const rl_place *pl;
 *   rl_mount mount = {0, 0, 0.88, 0, 0, 0, RL_POSE_TILT_PRIOR};
 *   rl_place_obs o;
 *   double x, y;
 *   rl_place_obs_make(pl, &cam, &mount, res.landmarks, res.n_landmarks, NULL, &o);
 *   if (o.n >= 2 && rl_place_obs_usable(pl, &o, 4)) {
 *       rl_place_obs_at(pl, &o, 0, 4, &x, &y); // observation 0 were it map landmark 4
 *       use(x, y, rl_place_obs_distance(&o, 0, 1));
 *   }
 */
#ifndef RL_PLACE_OBS_H
#define RL_PLACE_OBS_H

#include "rl_place_index.h"

/* One frame's identified landmarks on the ceiling of a level robot. A
 * landmark that hangs lower (or higher) than the ceiling lies on its ray
 * nearer to (or further from) the mount's point (mx, my): its point
 * scales about it with its height above the camera (obs_at). */
typedef struct {
    int n;
    int det[RL_MAX_LANDMARKS]; /* the detection it came from */
    int id[RL_MAX_LANDMARKS];
    double px[RL_MAX_LANDMARKS], py[RL_MAX_LANDMARKS]; /* robot frame, at the ceiling's height, m */
    double mx, my, cz, Z;      /* the mount's point and height; the ceiling above it, m */
    double spread;             /* the map's heights' largest scale off 1 (0: one plane) */
} rl_place_obs;

/* Detections on the ceiling, complete ones first, then nearest the image
 * centre (the best measured propose first). */
void rl_place_obs_make(const rl_place *pl, const rl_calib *cam, const rl_mount *mount, const rl_detection *lm, int n,
                       const rl_offsets *offsets, rl_place_obs *o);

/* Observations i and j's distance at the ceiling's height, m. */
double rl_place_obs_distance(const rl_place_obs *o, int i, int j);

/* 1 when map landmark m hangs far enough above the camera to be matched
 * (RL_POSE_MIN_DEPTH). */
int rl_place_obs_usable(const rl_place *pl, const rl_place_obs *o, int m);

/* Observation k's point were it map landmark m (at m's height). */
void rl_place_obs_at(const rl_place *pl, const rl_place_obs *o, int k, int m, double *x, double *y);

/* How far observation k's point may move with the height of the map
 * landmark it is (0 on a map of one plane). */
double rl_place_obs_slack(const rl_place_obs *o, int k);

/* Observations i and j's distance were they map landmarks a and b. */
double rl_place_obs_distance_at(const rl_place *pl, const rl_place_obs *o, int i, int j, int a, int b);

#endif
