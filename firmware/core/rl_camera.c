#include "rl_camera.h"

#include <math.h>
#include <string.h>

void rl_camera_defaults(rl_camera *cam, int width, int height, double hfov)
{
    memset(cam, 0, sizeof *cam);
    cam->width = width;
    cam->height = height;
    cam->fx = cam->fy = (width / 2.0) / tan(hfov / 2.0);
    cam->cx = (width - 1) / 2.0;
    cam->cy = (height - 1) / 2.0;
    cam->model = RL_DIST_NONE;
}

rl_err rl_camera_check(const rl_camera *cam)
{
    int i;
    if (cam->width <= 0 || cam->height <= 0 || !(cam->fx > 0.0) || !(cam->fy > 0.0) ||
        !isfinite(cam->fx) || !isfinite(cam->fy) || !isfinite(cam->cx) || !isfinite(cam->cy))
        return RL_ERANGE;
    for (i = 0; i < 8; i++)
        if (!isfinite(cam->k[i]))
            return RL_ERANGE;
    return RL_OK;
}
