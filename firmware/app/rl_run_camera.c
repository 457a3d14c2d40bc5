/* rl_run_camera: the camera as the loop's source (rl_run_camera.h). */
#include "rl_run_camera.h"

#include <string.h>

/* The camera as a source. */
static rl_err cam_open(void *ctx, char *err, size_t errlen)
{
    rl_run_camera *rc = (rl_run_camera *)ctx;
    return rl_cam_open(&rc->cam, &rc->cc, err, errlen);
}
static rl_err cam_grab(void *ctx, int timeout_ms, rl_cam_frame *f)
{
    return rl_cam_grab(&((rl_run_camera *)ctx)->cam, timeout_ms, f);
}
static void cam_release(void *ctx, rl_cam_frame *f)
{
    rl_cam_release(&((rl_run_camera *)ctx)->cam, f);
}
static void cam_close(void *ctx)
{
    rl_cam_close(&((rl_run_camera *)ctx)->cam);
}
static const char *cam_error(void *ctx)
{
    return ((rl_run_camera *)ctx)->cam.error;
}
static const char *cam_info(void *ctx)
{
    return ((rl_run_camera *)ctx)->cam.info;
}

rl_run_source rl_run_camera_source(rl_run_camera *rc, const rl_cam_config *cc)
{
    rl_run_source s;
    memset(rc, 0, sizeof *rc);
    rc->cc = *cc;
    s.open = cam_open;
    s.grab = cam_grab;
    s.release = cam_release;
    s.close = cam_close;
    s.error = cam_error;
    s.info = cam_info;
    s.ctx = rc;
    return s;
}
