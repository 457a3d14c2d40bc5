/* rl_run_camera: the camera (rl_cam: PNG files, V4L2, libcamera) as the
 * loop's source (rl_run.h's rl_run_source): open, grab, release and close
 * passed through, the camera's own error and description read back.
 *
 *   rl_run_camera camera;
 *   rl_cam_config cc;
 *   rl_run_io io;
 *   rl_cam_defaults(&cc);
 *   memset(&io, 0, sizeof io);
 *   io.source = rl_run_camera_source(&camera, &cc);   // camera kept while the loop runs
 */
#ifndef RL_RUN_CAMERA_H
#define RL_RUN_CAMERA_H

#include "rl_cam.h"
#include "rl_run.h"

typedef struct {
    rl_cam cam;
    rl_cam_config cc;
} rl_run_camera;

/* A source over rc (set up from cc here; the caller's, kept while the
 * source is used). */
rl_run_source rl_run_camera_source(rl_run_camera *rc, const rl_cam_config *cc);

#endif
