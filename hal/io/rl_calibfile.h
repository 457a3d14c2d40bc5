/* rl_calibfile: camera calibration files -> rl_calib.
 *
 * Recognised automatically:
 * - ROS camera_info YAML: image_width, image_height, camera_matrix {rows,
 *   cols, data}, distortion_model (plumb_bob: 5 coefficients,
 *   rational_polynomial: 5, 8, 12 (thin prism) or 14 (tilted sensor, only
 *   when its terms are 0), equidistant: 4), distortion_coefficients {data};
 * - OpenCV FileStorage YAML ("%YAML:1.0", camera_matrix and
 *   distortion_coefficients as !!opencv-matrix): the standard model by
 *   the count (5, 8, 12, 14), fisheye_model: 1 (OpenCV's calibration
 *   sample) for a fisheye's 4; 4 coefficients without a model are
 *   ambiguous (k1 k2 p1 p2, or a fisheye) and an error. image_width and
 *   image_height may be left out when the caller knows the size
 *   (rl_calibfile_load_sized).
 * Errors name the file, line and key (wrong matrix sizes, missing keys).
 *
 *   rl_calib calib;
 *   char err[256];
 *   if (rl_calibfile_load("camera.yaml", &calib, err, sizeof err) != RL_OK)
 *       fprintf(stderr, "ringloc: %s\n", err);   // "camera.yaml:4: camera_matrix: ..."
 */
#ifndef RL_CALIBFILE_H
#define RL_CALIBFILE_H

#include <stddef.h>
#include "rl_calib.h"

RL_CHECK rl_err rl_calibfile_load(const char *path, rl_calib *cam, char *err, size_t errlen);
/* The same; width x height (0 x 0: none) is the image size when the file
 * gives none. */
RL_CHECK rl_err rl_calibfile_load_sized(const char *path, int width, int height, rl_calib *cam, char *err,
                                      size_t errlen);

/* Write a ROS camera_info YAML. */
RL_CHECK rl_err rl_calibfile_save(const char *path, const rl_calib *cam, char *err,
                                size_t errlen);

#endif
