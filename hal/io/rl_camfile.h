/* rl_camfile: camera calibration files -> rl_camera.
 *
 * Recognised automatically:
 * - ROS camera_info YAML: image_width, image_height, camera_matrix {rows,
 *   cols, data}, distortion_model (plumb_bob: 5 coefficients,
 *   rational_polynomial: 8), distortion_coefficients {data};
 * - OpenCV FileStorage YAML ("%YAML:1.0", camera_matrix and
 *   distortion_coefficients as !!opencv-matrix; image_width and
 *   image_height are required there too).
 * Errors name the file, line and key (wrong matrix sizes, missing keys).
 *
 *   rl_camera calib;
 *   char err[256];
 *   if (rl_camfile_load("camera.yaml", &calib, err, sizeof err) != RL_OK)
 *       fprintf(stderr, "ringloc: %s\n", err);   // "camera.yaml:4: camera_matrix: ..."
 */
#ifndef RL_CAMFILE_H
#define RL_CAMFILE_H

#include <stddef.h>
#include "rl_camera.h"

RL_CHECK rl_err rl_camfile_load(const char *path, rl_camera *cam, char *err, size_t errlen);

/* Write a ROS camera_info YAML. */
RL_CHECK rl_err rl_camfile_save(const char *path, const rl_camera *cam, char *err,
                                size_t errlen);

#endif
