#include "cam_libcamera.h"

#include "rl_module.h"

/* The libcamera backend's entry points, from its module on first use. */

static const rl_module module = RL_CAM_LIBCAMERA_MODULE;

rl_err rl_cam_open_libcamera(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    void (*fn)(void);
    rl_cam_open_fn open;
    rl_err e = rl_module_symbol(&module, "rl_cam_libcamera_open", &fn, err, errlen);
    if (e != RL_OK)
        return e;
    open = (rl_cam_open_fn)fn;
    return open(c, cc, err, errlen);
}

rl_err rl_cam_probe_libcamera(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err,
                              size_t errlen)
{
    void (*fn)(void);
    rl_cam_libcamera_probe_fn probe;
    rl_err e = rl_module_symbol(&module, "rl_cam_libcamera_probe", &fn, err, errlen);
    if (e != RL_OK)
        return e;
    probe = (rl_cam_libcamera_probe_fn)fn;
    return probe(cc, line, ctx, err, errlen);
}
