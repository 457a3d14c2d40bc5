/* rl_shutter: a rolling shutter's frame brought to one instant.
 *
 * A rolling shutter (most CMOS cameras: every Raspberry Pi camera, USB
 * webcams) exposes the rows one after another, top to bottom over the
 * readout time. On a moving robot each landmark is then seen from where
 * the camera was when its row was exposed: at 1 m/s and a 33 ms readout
 * the frame's first and last rows see the ceiling from 33 mm apart, and
 * a pose solved from their centres is off by a few millimetres
 * (docs/results.md, "A rolling shutter"). Given the robot's motion (its
 * velocity and turn rate, from the last poses or odometry), each centre
 * is moved to where the middle row would have seen it: the frame's pose
 * is then the middle row's, at the frame's capture time taken there
 * (rl_cam.h: the camera's readout moves the backends' stamps to it).
 *
 *   static rl_pose prev, last, pose;       // the last two poses, 0.1 s apart
 *   rl_mount mount;
 *   rl_motion m;
 *   rl_err e;
 *   rl_mount_defaults(&mount, 0.88);
 *   if (rl_motion_between(&prev, 12.3, &last, 12.4, 12.5, 0.5, &m))
 *       rl_shutter_correct(&cam, &mount, map.ceiling_height - mount.z, 0.033, &m,
 *                          res.landmarks, res.n_landmarks);  // rows read in 33 ms
 *   e = rl_pose_solve(&cam, &map, &mount, res.landmarks, res.n_landmarks, NULL, &pose);
 *   use(e);
 */
#ifndef RL_SHUTTER_H
#define RL_SHUTTER_H

#include "rl_calib.h"
#include "rl_pose.h"
#include "rl_recog.h"

/* The robot's motion in its own frame (REP-103): forward and left
 * velocity, m/s, and turn rate (counter-clockwise from above), rad/s. */
typedef struct {
    double forward, left, turn;
} rl_motion;

/* The motion of a frame at time t from the last two poses, a at ta and b
 * at tb (s): the robot taken as on a steady arc from a to b, its velocity
 * along the arc in the frame of the arc's mid-heading, and its turn rate. 0
 * (m untouched) when tb - ta is not in (0, max_gap], t - tb not in
 * [0, max_gap] (old poses say nothing of the frame's motion; time going
 * back, nothing at all) or a pose is not finite. */
int rl_motion_between(const rl_pose *a, double ta, const rl_pose *b, double tb, double t, double max_gap,
                      rl_motion *m);

/* Move the ceiling point (fwd, left) (m, the camera's level frame: image
 * top forward, +u left) seen dt seconds after the middle row to where the
 * middle row sees it, the robot moving as m says and the camera mounted as
 * `mount` says. */
void rl_shutter_move(const rl_mount *mount, double dt, const rl_motion *m, double *fwd, double *left);

/* Move the centres of lm[0 .. n) (u, v, px) to where the middle row of a
 * frame read top to bottom in readout_s seconds would have seen them,
 * the robot moving as m says; the camera `distance` (m) below the
 * ceiling, level (its tilt moves every centre alike, second order here).
 * Nothing is moved for readout_s <= 0, a NULL m or a bad distance. */
void rl_shutter_correct(const rl_calib *cam, const rl_mount *mount, double distance, double readout_s,
                        const rl_motion *m, rl_detection *lm, int n);

/* The same, each landmark at its own distance: lm[i] `distance[i]` (m)
 * above the camera (a landmark on a beam or a lower panel is nearer, and
 * the travel moves it further in the image: D / (D - M) times a
 * ceiling's landmark at D). Nothing is moved for readout_s <= 0, a NULL m
 * or distance; lm[i] is not moved for a bad distance[i]. */
void rl_shutter_correct_each(const rl_calib *cam, const rl_mount *mount, const double *distance, double readout_s,
                             const rl_motion *m, rl_detection *lm, int n);

#endif
