/* rl_pose: the robot's pose from identified landmarks.
 *
 * Each identified centre is undistorted (rl_calib_unproject) and
 * projected onto the ceiling plane, distance Z = ceiling_height - camera
 * height above the camera: with the spec's mounting (image top = robot
 * forward, +u = robot left) a centre at normalized (xn, yn) lies at
 * (-yn Z, xn Z) in the camera's horizontal frame. A least-squares rigid
 * fit of those points to the map positions (the paper's two-landmark
 * method is its two-point case) gives the camera's position and heading,
 * and the mounting offset the robot's; the mount's own tilt is applied to
 * every ray first. With three or more landmarks (pinhole model) the
 * robot's tilt is solved too: a Gauss-Newton fit of the robot's pose and
 * roll and pitch to the landmarks' image positions, the ceiling a plane at
 * the map's height (a weak prior keeps the tilt of a poor geometry
 * small). Every pose carries standard deviations from the fit's geometry
 * and its residuals, pooled with the expected centre noise
 * (RL_POSE_PIXEL_SIGMA); a level fit's also carry the tilt it assumed
 * away: with two landmarks the robot's rocking (rl_mount.rocking), with
 * more the lean the tilted fit measured and what it could not rule out. Before fitting, pairwise distances
 * are checked against the map and landmarks that disagree (a wrong id, a
 * landmark moved since the map was made) are dropped and reported.
 *
 *   rl_mount mount;
 *   rl_pose pose;
 *   rl_err e;
 *   rl_mount_defaults(&mount, 0.88);       // camera 0.88 m above the floor
 *   e = rl_pose_solve(&cam, &map, &mount, res.landmarks, res.n_landmarks, NULL, &pose);
 *   if (e == RL_OK)
 *       use(pose.x, pose.y, pose.yaw);
 *   else if (e == RL_ETOOFEW)
 *       use(res.n_landmarks);              // fewer than two usable landmarks
 */
#ifndef RL_POSE_H
#define RL_POSE_H

#include "rl_calib.h"
#include "rl_config.h"
#include "rl_error.h"
#include "rl_map.h"
#include "rl_recog.h"

/* The camera's optical centre in the robot frame (REP-103): x forward,
 * y left, z above the floor, yaw of the image's top edge from robot +x;
 * roll (about the robot's x) and pitch (about its y) of the mount's tilt
 * from vertical, radians. The camera's rotation in the robot frame is
 * Ry(pitch) Rx(roll) Rz(yaw) of its axes (image top, image left, up). */
typedef struct {
    double x, y, z, yaw;
    double roll, pitch;
    double rocking; /* how far the robot leans on its floor, rad (sd per axis,
                       0 .. RL_POSE_ROCKING_MAX; rl_mount_defaults:
                       RL_POSE_TILT_PRIOR; 0: never, as a brace initializer
                       that leaves it out says) */
} rl_mount;

/* The paper's alternative to the pinhole model: the physical offset of a
 * ceiling point from the optical axis (camera horizontal frame, metres at
 * the calibration distance) as a polynomial in the pixel coordinates. */
#define RL_OFFSET_TERMS 10
typedef struct {
    int degree;                  /* 1 .. 3 */
    double u0, v0, scale;        /* pixel normalization: (u - u0) / scale */
    double distance;             /* camera to ceiling at calibration, m */
    double cx[RL_OFFSET_TERMS];  /* forward offset coefficients */
    double cy[RL_OFFSET_TERMS];  /* left offset coefficients */
} rl_offsets;

typedef struct {
    double x, y, yaw;            /* robot base pose in the map frame, m and rad */
    double sigma_x, sigma_y, sigma_yaw; /* their standard deviations, m and rad */
    double roll, pitch;          /* the camera's tilt from vertical (its own x, y axes), rad */
    int tilt_solved;             /* 1: the tilted fit weighs more in the pose (3 or more landmarks);
                                    0: the level fit does (the mount's tilt applied), or two landmarks */
    double tilt_weight;          /* the tilted fit's share of the pose (rl_pose_tilt_weight), 0 .. 1 */
    int fit_valid;               /* three or more landmarks: the tilted fit, whatever its weight: */
    double fit_roll, fit_pitch;  /* the robot's tilt it found (about its x and y), rad */
    double fit_sigma_roll, fit_sigma_pitch;
    double cam_x, cam_y, cam_yaw;/* camera optical centre and heading */
    int used;                    /* landmarks in the fit */
    double residual;             /* RMS distance between map and fitted positions, m (with three or
                                    more landmarks, from the fits' chi-square averaged by weight) */
    int n_dropped;
    int dropped[RL_MAX_LANDMARKS]; /* ids left out as inconsistent */
    int n_unknown;               /* identified ids not in the map */
} rl_pose;

/* Pairwise-distance tolerance: two landmarks agree when their distance
 * apart differs from the map's by at most this much plus 4% of it (a
 * tilted camera stretches the level model by up to 3%). */
#define RL_POSE_PAIR_TOLERANCE 0.05

/* Expected noise of a landmark centre, pixels; a robot's rocking unless
 * its mount says otherwise (rl_mount.rocking), radians; the prior that
 * keeps a solved tilt within reason, radians. */
#define RL_POSE_PIXEL_SIGMA 0.15
#define RL_POSE_TILT_PRIOR 0.005
#define RL_POSE_ROCKING_MAX 0.3 /* the most rl_mount.rocking may say */
#define RL_POSE_TILT_WEAK 0.1
#define RL_POSE_TILT_LEVEL 0.000001 /* the least a level fit's tilt is unsure by (a number, not a lean) */
/* How much better (chi-square, in units of the residual variance) the
 * tilted fit must explain the centres than the level one to weigh as much
 * as the level one in the pose. */
#define RL_POSE_TILT_EVIDENCE 16.0

/* The tilted fit's weight in the pose (0 .. 1) for its evidence: how much
 * lower its misfit is, in units of its residual variance. */
double rl_pose_tilt_weight(double evidence);

/* Fill the mount of the spec's default mounting at height z. */
void rl_mount_defaults(rl_mount *m, double z);

/* Number of polynomial terms of a degree (3, 6 or 10). */
int rl_offsets_terms(int degree);

/* Offset (forward, left) of pixel (u, v) at the calibration distance. */
void rl_offsets_eval(const rl_offsets *o, double u, double v, double *fwd, double *left);

/* Ceiling point of image point (u, v) in the camera's horizontal frame:
 * (forward, left) in metres, with the pinhole model, or with the offset
 * map when `offsets` is not NULL (scaled to the map's distance). */
void rl_pose_ceiling_point(const rl_calib *cam, const rl_offsets *offsets, double distance,
                           double u, double v, double *fwd, double *left);

/* A landmark less than this far above the camera is not used, m. */
#define RL_POSE_MIN_DEPTH 0.1

/* Solve the pose from n identified landmarks. RL_ETOOFEW when fewer than
 * two usable (in the map, consistent) remain; RL_ERANGE when the camera is
 * not below the ceiling or the result is not finite (a calibration or map
 * out of its limits); RL_EINVAL for bad arguments (a camera
 * rl_calib_check refuses among them). Detections no camera of this size
 * can see (more than a frame outside the image) are dropped. On RL_OK
 * every number in `out` is finite and the pose within twice
 * RL_MAP_MAX_COORD; `out` always says what was used and dropped. */
RL_CHECK rl_err rl_pose_solve(const rl_calib *cam, const rl_map *map, const rl_mount *mount,
                              const rl_detection *lm, int n, const rl_offsets *offsets,
                              rl_pose *out);

/* rl_pose_solve with the map landmark of each detection given: match[i]
 * is lm[i]'s index in the map, or -1 when it is not in the map (counted
 * in n_unknown). rl_pose_solve matches each id to its first entry; on a
 * map that repeats ids rl_place_solve finds the match. */
RL_CHECK rl_err rl_pose_solve_matched(const rl_calib *cam, const rl_map *map, const rl_mount *mount,
                                      const rl_detection *lm, int n, const int *match,
                                      const rl_offsets *offsets, rl_pose *out);

/* Where the landmark at map point (X, Y), Z above the floor (the map's
 * ceiling_height, or rl_map_height for a map landmark), is seen in the image (pixels,
 * the centre the recognizer measures, distortion applied) from pose p on
 * the mount: the robot tilted by tilt_weight times the tilt p's fit found
 * (level with two landmarks; the mount's own tilt always applied). 0 when it is behind
 * the camera. The live view draws the map this way over the image. */
int rl_pose_project(const rl_calib *cam, const rl_map *map, const rl_mount *mount, const rl_pose *p, double X,
                    double Y, double Z, double *u, double *v);

/* Where detection d's centre meets the ceiling of a level robot, in the
 * robot frame (forward, left), m; 0 if its ray misses the ceiling. */
int rl_pose_level_point(const rl_calib *cam, const rl_map *map, const rl_mount *mount, const rl_offsets *offsets,
                        const rl_detection *d, double *x, double *y);

#endif
