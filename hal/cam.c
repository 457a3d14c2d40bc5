#include "rl_cam.h"

#include <stdio.h>
#include <string.h>

void rl_cam_defaults(rl_cam_config *cc)
{
    memset(cc, 0, sizeof *cc);
    cc->backend = "png";
    cc->device = "";
    cc->rate = 10.0;
}

rl_err rl_cam_open(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", cc->device ? cc->device : "");
    if (cc->open != NULL)
        return cc->open(c, cc, err, errlen);
    if (cc->backend == NULL || strcmp(cc->backend, "png") == 0)
        return rl_cam_open_png(c, cc, err, errlen);
    if (strcmp(cc->backend, "v4l2") == 0)
        return rl_cam_open_v4l2(c, cc, err, errlen);
    if (strcmp(cc->backend, "libcamera") == 0)
        return rl_cam_open_libcamera(c, cc, err, errlen);
    snprintf(err, errlen, "camera backend '%s' is not png, v4l2 or libcamera", cc->backend);
    return RL_EUNSUPPORTED;
}

rl_err rl_cam_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f)
{
    c->error[0] = '\0';
    if (c->ops == NULL)
        return RL_ENODEV;
    return c->ops->grab(c, timeout_ms, f);
}

void rl_cam_release(rl_cam *c, rl_cam_frame *f)
{
    if (c->ops != NULL && c->ops->release != NULL)
        c->ops->release(c, f);
}

void rl_cam_close(rl_cam *c)
{
    if (c->ops != NULL)
        c->ops->close(c);
    c->ops = NULL;
    c->state = NULL;
}

rl_err rl_cam_probe(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err, size_t errlen)
{
    if (cc->backend == NULL || strcmp(cc->backend, "png") == 0)
        return rl_cam_probe_png(cc, line, ctx, err, errlen);
    if (strcmp(cc->backend, "v4l2") == 0)
        return rl_cam_probe_v4l2(cc, line, ctx, err, errlen);
    if (strcmp(cc->backend, "libcamera") == 0)
        return rl_cam_probe_libcamera(cc, line, ctx, err, errlen);
    snprintf(err, errlen, "camera backend '%s' is not png, v4l2 or libcamera", cc->backend);
    return RL_EUNSUPPORTED;
}

#ifndef RL_HAVE_LIBCAMERA
rl_err rl_cam_open_libcamera(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    (void)c;
    (void)cc;
    snprintf(err, errlen, "camera backend libcamera is not built in (libcamera-dev was not found "
                          "when ringloc was built)");
    return RL_EUNSUPPORTED;
}

rl_err rl_cam_probe_libcamera(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err,
                              size_t errlen)
{
    rl_cam c;
    (void)line;
    (void)ctx;
    return rl_cam_open_libcamera(&c, cc, err, errlen);
}
#endif
