/* rl_calib: pinhole camera intrinsics with plumb_bob, rational (with
 * OpenCV's thin-prism terms) or fisheye (equidistant) distortion, in
 * OpenCV / ROS camera_info conventions.
 *
 *   rl_calib cam;
 *   rl_calib_defaults(&cam, 640, 480, 70.0 * M_PI / 180);  // ideal lens
 */
#ifndef RL_CALIB_H
#define RL_CALIB_H

#include "rl_error.h"

typedef enum {
    RL_DIST_NONE = 0,      /* ideal pinhole */
    RL_DIST_FISHEYE = 4,   /* k1 k2 k3 k4 of theta_d = theta (1 + k1 theta^2 + ... + k4 theta^8)
                              (OpenCV fisheye, ROS equidistant) */
    RL_DIST_PLUMB_BOB = 5, /* k1 k2 p1 p2 k3 */
    RL_DIST_RATIONAL = 8   /* k1 k2 p1 p2 k3 k4 k5 k6, then thin prism s1 s2 s3 s4 (0 if not given) */
} rl_dist_model;
#define RL_CALIB_MAX_COEFFS 12

typedef struct {
    int width, height;      /* image size the calibration is for */
    double fx, fy, cx, cy;  /* camera matrix, pixels (pixel centres at integers) */
    rl_dist_model model;
    double k[RL_CALIB_MAX_COEFFS]; /* distortion in OpenCV order; unused ones 0 */
} rl_calib;

/* An ideal camera of the given size and horizontal field of view
 * (radians), principal point at the image centre. */
void rl_calib_defaults(rl_calib *cam, int width, int height, double hfov);

/* Limits of a camera model: focal lengths in pixels, the principal point
 * within a frame's size of the image, distortion coefficients. */
#define RL_CALIB_MIN_F 1.0
#define RL_CALIB_MAX_F 1e6
#define RL_CALIB_MAX_K 1e4

/* RL_OK if the sizes are 1 .. RL_MAX_IMAGE_DIM, the focal lengths in RL_CALIB_MIN_F ..
 * RL_CALIB_MAX_F, the principal point within one frame's size of the
 * image and every coefficient finite and at most RL_CALIB_MAX_K; else
 * RL_ERANGE. */
RL_CHECK rl_err rl_calib_check(const rl_calib *cam);

/* Apply the distortion model to normalized coordinates (x/z, y/z). */
void rl_calib_distort(const rl_calib *cam, double x, double y, double *xd, double *yd);

/* Invert the distortion model iteratively (as OpenCV's undistortPoints):
 * distorted normalized -> ideal normalized. */
void rl_calib_undistort(const rl_calib *cam, double xd, double yd, double *x, double *y);

/* Normalized ideal coordinates -> pixel (distortion applied). */
void rl_calib_project(const rl_calib *cam, double x, double y, double *u, double *v);

/* Pixel -> normalized ideal coordinates (distortion removed). */
void rl_calib_unproject(const rl_calib *cam, double u, double v, double *x, double *y);

/* The ideal normalized image of a circle's centre from the pixel centre
 * of its outer edge (u, v), radius its radius in normalized units.
 * Through a distorting lens the edge is centred off the centre's image by
 * (radius^2 / 4) times the lens map's Laplacian; taken off, then
 * undistorted. */
void rl_calib_centre(const rl_calib *cam, double u, double v, double radius, double *x, double *y);

/* The radius in normalized ideal units of a circle whose image has
 * radius r px about (u, v): the mean distance of the four points r px
 * left, right, above and below, undistorted. */
double rl_calib_radius(const rl_calib *cam, double u, double v, double r);

#endif
