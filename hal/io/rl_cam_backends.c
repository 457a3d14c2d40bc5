/* rl_cam_backends: the camera backends' names (rl_cam_backends.h). */
#include "rl_cam_backends.h"

#include <stdio.h>
#include <string.h>

const char *const rl_cam_backend_names[RL_CAM_BACKEND_COUNT] = {"png", "v4l2", "libcamera", "sim"};

int rl_cam_backend_find(const char *name)
{
    int i;
    for (i = 0; i < RL_CAM_BACKEND_COUNT; i++)
        if (strcmp(name, rl_cam_backend_names[i]) == 0)
            return i;
    return -1;
}

const char *rl_cam_backend_list(char *out, size_t len)
{
    size_t at = 0;
    int i;
    out[0] = '\0';
    for (i = 0; i < RL_CAM_BACKEND_COUNT && at < len; i++) {
        const char *sep = i == 0 ? "" : i == RL_CAM_BACKEND_COUNT - 1 ? " or " : ", ";
        int k = snprintf(out + at, len - at, "%s%s", sep, rl_cam_backend_names[i]);
        at += k > 0 ? (size_t)k : 0;
    }
    return out;
}
