#include "rl_cam.h"

#include <stdio.h>
#include <string.h>
#include "rl_cam_backends.h"

void rl_cam_defaults(rl_cam_config *cc)
{
    memset(cc, 0, sizeof *cc);
    cc->backend = "png";
    cc->device = "";
    cc->rate = 10.0;
    cc->stamp = RL_CAM_STAMP_AUTO;
}

/* How each backend opens and describes its device, in the order of
 * rl_cam_backend_names. */
typedef rl_err (*probe_fn)(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err, size_t errlen);
static const struct {
    rl_cam_open_fn open;
    probe_fn probe;
} backends[RL_CAM_BACKEND_COUNT] = {
    {rl_cam_open_png, rl_cam_probe_png},
    {rl_cam_open_v4l2, rl_cam_probe_v4l2},
    {rl_cam_open_libcamera, rl_cam_probe_libcamera},
    {rl_cam_open_sim, rl_cam_probe_sim},
};

/* The backend cc names (none: png), or -1 with err saying so. */
static int backend(const rl_cam_config *cc, char *err, size_t errlen)
{
    char names[64];
    int i = cc->backend == NULL ? 0 : rl_cam_backend_find(cc->backend);
    if (i < 0)
        snprintf(err, errlen, "camera backend '%s' is not %s", cc->backend,
                 rl_cam_backend_list(names, sizeof names));
    return i;
}

rl_err rl_cam_open(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    int b;
    rl_err e;
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", cc->device ? cc->device : "");
    if ((b = backend(cc, err, errlen)) < 0)
        return RL_EUNSUPPORTED;
    e = backends[b].open(c, cc, err, errlen);
    c->readout_us = cc->readout_us > 0 ? cc->readout_us : 0;
    c->exposure_us = cc->exposure_us > 0 ? cc->exposure_us : 0;
    c->stamp = cc->stamp;
    return e;
}

uint64_t rl_cam_middle_time(uint64_t t_us, rl_cam_stamp stamp, int readout_us, int exposure_us)
{
    /* row i is exposed from t0 + i readout / rows for the exposure, then
     * read: the middle row's mid-exposure is t0 + readout / 2 +
     * exposure / 2, the first row read at t0 + exposure, the last at
     * t0 + readout + exposure */
    uint64_t r = (uint64_t)(readout_us > 0 ? readout_us : 0) / 2, e = (uint64_t)(exposure_us > 0 ? exposure_us : 0) / 2;
    switch (stamp) {
    case RL_CAM_STAMP_EXPOSURE_START: return t_us + r + e;
    case RL_CAM_STAMP_FRAME_START: return t_us + r > e ? t_us + r - e : 0;
    case RL_CAM_STAMP_FRAME_END: return t_us > r + e ? t_us - r - e : 0;
    default: return t_us;
    }
}

rl_err rl_cam_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f)
{
    rl_err e;
    c->error[0] = '\0';
    f->name = NULL;
    f->stamp = RL_CAM_STAMP_MIDDLE;
    f->exposure_us = 0;
    if (c->ops == NULL)
        return RL_ENODEV;
    e = c->ops->grab(c, timeout_ms, f);
    /* a device's stamps where the configuration puts them (a driver that
     * says otherwise); given times (png, sim) stay as they are */
    if (e == RL_OK && f->stamp != RL_CAM_STAMP_MIDDLE && c->stamp != RL_CAM_STAMP_AUTO)
        f->stamp = (rl_cam_stamp)c->stamp;
    if (e == RL_OK)
        f->t_us = rl_cam_middle_time(f->t_us, f->stamp, c->readout_us,
                                     f->exposure_us > 0 ? f->exposure_us : c->exposure_us);
    return e;
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
    int b = backend(cc, err, errlen);
    return b < 0 ? RL_EUNSUPPORTED : backends[b].probe(cc, line, ctx, err, errlen);
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
