/* rl_robotfile: robot YAML -> rl_mount.
 *
 *   camera_mount: {x: 0.0, y: 0.0, z: 0.880, yaw: 0.0, roll: 0.0, pitch: 0.0}
 *   rocking: 0.005
 *
 * The camera's optical centre in the robot frame; z above the floor. x, y
 * and yaw default to 0 (the spec's mounting); z is required. roll (about
 * the robot's x) and pitch (about its y), radians, are the mount's tilt
 * from vertical (`ringloc calibrate-mount` measures them; default 0).
 * rocking: how far the robot leans on its floor while it drives, radians
 * (a standard deviation per axis; default RL_POSE_TILT_PRIOR, 0.005; 0 a
 * robot that never leans): what a pose from a level fit is unsure by.
 *
 *   rl_mount mount;
 *   char err[256];
 *   if (rl_robotfile_load("robot.yaml", &mount, err, sizeof err) == RL_OK)
 *       use(mount.z);
 */
#ifndef RL_ROBOTFILE_H
#define RL_ROBOTFILE_H

#include <stddef.h>
#include "rl_pose.h"

RL_CHECK rl_err rl_robotfile_load(const char *path, rl_mount *m, char *err, size_t errlen);
RL_CHECK rl_err rl_robotfile_save(const char *path, const rl_mount *m, char *err, size_t errlen);

#endif
