/* rl_cam_backends: the camera backends' names, one list for the run
 * configuration's check (rl_runcfg) and the device layer that opens them
 * (hal/cam.c), so a backend is named in one place. The device layer's
 * table of open and probe functions follows this order.
 *
 *   char names[64];
 *   if (rl_cam_backend_find("v4l2") < 0)
 *       use(rl_cam_backend_list(names, sizeof names));  // "png, v4l2, libcamera or sim"
 */
#ifndef RL_CAM_BACKENDS_H
#define RL_CAM_BACKENDS_H

#include <stddef.h>

#define RL_CAM_BACKEND_COUNT 4

/* "png" (the default: frames from PNG files), "v4l2", "libcamera", "sim"
 * (a renderer following a simulated robot, hal/cam_sim.c). */
extern const char *const rl_cam_backend_names[RL_CAM_BACKEND_COUNT];

/* The index of name in rl_cam_backend_names, or -1. */
int rl_cam_backend_find(const char *name);

/* The names for an error line, "png, v4l2, libcamera or sim", into out; out. */
const char *rl_cam_backend_list(char *out, size_t len);

#endif
