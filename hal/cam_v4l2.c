/* V4L2 camera (USB webcams, CSI and ISP drivers): mmap streaming in the
 * best format the device offers at the configured size (v4l2_format.h),
 * exposure and gain as configured (v4l2_ctrl.h). A buffer the driver
 * flags as damaged, that is short of a whole frame, or whose index is not
 * one of ours is dropped (RL_EFORMAT: counted by the run loop, never
 * recognized). A device that vanishes reports RL_ENODEV and one that
 * stops streaming RL_ETIMEOUT; the run loop reopens it. Capture times are
 * the driver's monotonic buffer timestamps. All system calls go through
 * rl_v4l2_sys, so a test runs this file against a fake device. */
#include <errno.h>
#include <linux/videodev2.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include "rl_cam.h"
#include "rl_mjpeg.h"
#include "v4l2_ctrl.h"
#include "v4l2_dev.h"
#include "v4l2_format.h"

#define V4L2_BUFFERS 4

typedef struct {
    v4l2_dev d;
    const v4l2f *fmt;
    int width, height;
    size_t stride, need;       /* bytes per line; bytes a frame fills (0: compressed) */
    void *map[V4L2_BUFFERS];
    size_t len[V4L2_BUFFERS];
    int nbuf, streaming;
    int queue_errno;           /* a failed re-queue on release, reported by the next grab */
    uint8_t *grey;             /* packed and MJPEG formats: the converted frame */
    rl_mjpeg *jpeg;
    long index;
} v4l2_state;

static void v4l2_close(rl_cam *c)
{
    v4l2_state *s = (v4l2_state *)c->state;
    int i;
    enum v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (s == NULL)
        return;
    if (s->d.fd >= 0) {
        if (s->streaming)
            (void)v4l2_ioctl(&s->d, VIDIOC_STREAMOFF, &type);
        for (i = 0; i < s->nbuf; i++)
            if (s->map[i] != NULL && s->map[i] != MAP_FAILED)
                s->d.sys->munmap(s->d.sys->ctx, s->map[i], s->len[i]);
        v4l2_dev_close(&s->d);
    }
    rl_mjpeg_free(s->jpeg);
    free(s->grey);
    free(s);
}

static rl_err queue(v4l2_state *s, unsigned index)
{
    struct v4l2_buffer b;
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = index;
    return v4l2_ioctl(&s->d, VIDIOC_QBUF, &b) == 0 ? RL_OK : RL_EIO;
}

/* A device error's code, its reason in c->error. */
static rl_err device_error(rl_cam *c, const char *doing, int err)
{
    snprintf(c->error, sizeof c->error, "%s: %s: %s", c->name, doing, v4l2_dev_why(err));
    return err == ENODEV || err == ENXIO ? RL_ENODEV : RL_EIO;
}

/* Give a buffer that will not be recognized back to the driver. */
static rl_err drop(rl_cam *c, v4l2_state *s, unsigned index)
{
    if (queue(s, index) != RL_OK)
        return device_error(c, "re-queueing a buffer", errno);
    return RL_EFORMAT;
}

/* The buffer's time into f: the driver's when it is on the monotonic
 * clock (rl_clock's), stamped at the start of the exposure or (V4L2's
 * default) when the last row came in; else now, the frame's end. */
static void capture_time(const struct v4l2_buffer *b, rl_cam_frame *f)
{
    uint64_t t = (uint64_t)b->timestamp.tv_sec * 1000000u + (uint64_t)b->timestamp.tv_usec;
    if ((b->flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC && t != 0) {
        f->t_us = t;
        f->stamp = (b->flags & V4L2_BUF_FLAG_TSTAMP_SRC_MASK) == V4L2_BUF_FLAG_TSTAMP_SRC_SOE
                       ? RL_CAM_STAMP_EXPOSURE_START
                       : RL_CAM_STAMP_FRAME_END;
        return;
    }
    f->t_us = rl_clock_now_us();
    f->stamp = RL_CAM_STAMP_FRAME_END;
}

static rl_err v4l2_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f)
{
    v4l2_state *s = (v4l2_state *)c->state;
    struct pollfd p;
    struct v4l2_buffer b;
    char why[128];
    int r;
    if (s->queue_errno != 0) {
        int e = s->queue_errno;
        s->queue_errno = 0;
        return device_error(c, "re-queueing a buffer", e);
    }
    p.fd = s->d.fd;
    p.events = POLLIN;
    p.revents = 0;
    r = s->d.sys->poll(s->d.sys->ctx, &p, timeout_ms);
    if (r == 0 || (r < 0 && errno == EINTR)) {
        snprintf(c->error, sizeof c->error, "%s: no frame in %d ms", c->name, timeout_ms);
        return RL_ETIMEOUT;
    }
    if (r < 0)
        return device_error(c, "waiting for a frame", errno);
    if (p.revents & (POLLERR | POLLHUP | POLLNVAL))
        return device_error(c, "waiting for a frame", ENODEV);
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    if (v4l2_ioctl(&s->d, VIDIOC_DQBUF, &b) < 0) {
        if (errno == EAGAIN) {
            snprintf(c->error, sizeof c->error, "%s: no frame in %d ms", c->name, timeout_ms);
            return RL_ETIMEOUT;
        }
        return device_error(c, "taking a frame", errno);
    }
    f->index = s->index++;
    if (b.index >= (unsigned)s->nbuf) {
        /* not a buffer of ours: nothing to give back */
        snprintf(c->error, sizeof c->error, "%s: frame %ld came in buffer %u of %d; dropped", c->name,
                 f->index, b.index, s->nbuf);
        return RL_EFORMAT;
    }
    if (b.flags & V4L2_BUF_FLAG_ERROR) {
        snprintf(c->error, sizeof c->error, "%s: frame %ld is flagged damaged by the driver; dropped",
                 c->name, f->index);
        return drop(c, s, b.index);
    }
    if (b.bytesused == 0 || b.bytesused > s->len[b.index] || (s->need && b.bytesused < s->need)) {
        snprintf(c->error, sizeof c->error, "%s: frame %ld has %u bytes, a %s frame %lu; dropped", c->name,
                 f->index, b.bytesused, s->fmt->name, (unsigned long)(s->need ? s->need : s->len[b.index]));
        return drop(c, s, b.index);
    }
    f->slot = (int)b.index;
    capture_time(&b, f);
    if (s->fmt->kind == V4L2F_PLANE) {
        f->img = rl_image_view(s->width, s->height, (int)s->stride, (uint8_t *)s->map[b.index]);
        return RL_OK;
    }
    if (s->fmt->kind == V4L2F_PACKED) {
        v4l2f_copy_luma(s->fmt, (const uint8_t *)s->map[b.index], s->stride, s->width, s->height, s->grey);
    } else if (rl_mjpeg_grey(s->jpeg, (const uint8_t *)s->map[b.index], b.bytesused, s->width, s->height,
                             s->grey, why, sizeof why) != RL_OK) {
        snprintf(c->error, sizeof c->error, "%s: frame %ld: %s; dropped", c->name, f->index, why);
        return drop(c, s, b.index);
    }
    f->img = rl_image_view(s->width, s->height, s->width, s->grey);
    return RL_OK;
}

static void v4l2_release(rl_cam *c, rl_cam_frame *f)
{
    v4l2_state *s = (v4l2_state *)c->state;
    if (f->slot >= 0 && f->slot < s->nbuf && queue(s, (unsigned)f->slot) != RL_OK && s->queue_errno == 0)
        s->queue_errno = errno ? errno : EIO;
}

static const rl_cam_ops v4l2_ops = {v4l2_grab, v4l2_release, v4l2_close};

static rl_err fail(rl_cam *c, char *err, size_t errlen, rl_err e, const char *what)
{
    snprintf(err, errlen, "%s: %s", c->name, what);
    rl_cam_close(c);
    return e;
}

/* Set the format and check what the driver made of it: the size asked
 * for, a stride that holds a row, an image size that holds a frame. */
static rl_err set_format(v4l2_state *s, int width, int height, char *what, size_t len)
{
    struct v4l2_format fmt;
    char got[8];
    memset(&fmt, 0, sizeof fmt);
    fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    fmt.fmt.pix.width = (unsigned)width;
    fmt.fmt.pix.height = (unsigned)height;
    fmt.fmt.pix.pixelformat = s->fmt->fourcc;
    fmt.fmt.pix.field = V4L2_FIELD_NONE;
    if (v4l2_ioctl(&s->d, VIDIOC_S_FMT, &fmt) < 0) {
        int en = errno;
        snprintf(what, len, "cannot set %s %dx%d: %s", s->fmt->name, width, height, v4l2_dev_why(en));
        return en == EBUSY ? RL_ENODEV : RL_EUNSUPPORTED;
    }
    v4l2f_name(fmt.fmt.pix.pixelformat, got);
    if (fmt.fmt.pix.pixelformat != s->fmt->fourcc || (int)fmt.fmt.pix.width != width ||
        (int)fmt.fmt.pix.height != height) {
        snprintf(what, len, "gives %s %ux%u when asked for %s %dx%d", got, fmt.fmt.pix.width,
                 fmt.fmt.pix.height, s->fmt->name, width, height);
        return RL_EUNSUPPORTED;
    }
    s->width = width;
    s->height = height;
    s->stride = fmt.fmt.pix.bytesperline ? fmt.fmt.pix.bytesperline : v4l2f_min_stride(s->fmt, width);
    if (s->fmt->kind != V4L2F_JPEG && s->stride < v4l2f_min_stride(s->fmt, width)) {
        snprintf(what, len, "reports %lu bytes per line, less than a row of %d %s pixels",
                 (unsigned long)s->stride, width, s->fmt->name);
        return RL_EUNSUPPORTED;
    }
    s->need = v4l2f_frame_bytes(s->fmt, s->stride, height);
    if (s->need && fmt.fmt.pix.sizeimage && fmt.fmt.pix.sizeimage < s->need) {
        snprintf(what, len, "reports %u bytes per frame, less than %lu for %s %dx%d", fmt.fmt.pix.sizeimage,
                 (unsigned long)s->need, s->fmt->name, width, height);
        return RL_EUNSUPPORTED;
    }
    return RL_OK;
}

static rl_err map_buffers(v4l2_state *s, char *what, size_t len)
{
    struct v4l2_requestbuffers req;
    int i;
    memset(&req, 0, sizeof req);
    req.count = V4L2_BUFFERS;
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    if (v4l2_ioctl(&s->d, VIDIOC_REQBUFS, &req) < 0) {
        int en = errno;
        snprintf(what, len, "cannot get mmap buffers: %s", v4l2_dev_why(en));
        return en == EBUSY ? RL_ENODEV : RL_EIO;
    }
    if (req.count < 2) {
        snprintf(what, len, "gave %u mmap buffers, at least 2 are needed", req.count);
        return RL_EIO;
    }
    s->nbuf = (int)(req.count > V4L2_BUFFERS ? V4L2_BUFFERS : req.count);
    for (i = 0; i < s->nbuf; i++) {
        struct v4l2_buffer b;
        memset(&b, 0, sizeof b);
        b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        b.memory = V4L2_MEMORY_MMAP;
        b.index = (unsigned)i;
        if (v4l2_ioctl(&s->d, VIDIOC_QUERYBUF, &b) < 0) {
            snprintf(what, len, "cannot query buffer %d: %s", i, v4l2_dev_why(errno));
            return RL_EIO;
        }
        if (b.length < s->need || b.length == 0) {
            snprintf(what, len, "buffer %d holds %u bytes, a frame needs %lu", i, b.length,
                     (unsigned long)s->need);
            return RL_EUNSUPPORTED;
        }
        s->len[i] = b.length;
        s->map[i] = s->d.sys->mmap(s->d.sys->ctx, b.length, s->d.fd, (off_t)b.m.offset);
        if (s->map[i] == MAP_FAILED) {
            s->map[i] = NULL;
            snprintf(what, len, "cannot map buffer %d: %s", i, v4l2_dev_why(errno));
            return RL_EIO;
        }
        if (queue(s, (unsigned)i) != RL_OK) {
            snprintf(what, len, "cannot queue buffer %d: %s", i, v4l2_dev_why(errno));
            return RL_EIO;
        }
    }
    return RL_OK;
}

rl_err rl_cam_open_v4l2(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    v4l2_state *s;
    enum v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    char what[256], ctl[96];
    int width = cc->width > 0 ? cc->width : 640, height = cc->height > 0 ? cc->height : 480;
    rl_err e;
    s = calloc(1, sizeof *s);
    if (s == NULL)
        return fail(c, err, errlen, RL_ENOMEM, "out of memory");
    s->d.fd = -1;
    c->state = s;
    c->ops = &v4l2_ops;
    if ((e = v4l2_dev_open(&s->d, cc->v4l2_sys, cc->device, what, sizeof what)) != RL_OK)
        return fail(c, err, errlen, e, what);
    if ((s->fmt = v4l2_dev_choose(&s->d, width, height, what, sizeof what)) == NULL)
        return fail(c, err, errlen, RL_EUNSUPPORTED, what);
    if ((e = set_format(s, width, height, what, sizeof what)) != RL_OK)
        return fail(c, err, errlen, e, what);
    if (cc->rate > 0) {
        struct v4l2_streamparm parm;
        memset(&parm, 0, sizeof parm);
        parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        parm.parm.capture.timeperframe.numerator = 1000;
        parm.parm.capture.timeperframe.denominator = (unsigned)(cc->rate * 1000);
        (void)v4l2_ioctl(&s->d, VIDIOC_S_PARM, &parm); /* a hint; cameras round it */
    }
    if ((e = v4l2_ctrl_apply(&s->d, cc->exposure_us, cc->gain, ctl, sizeof ctl, what, sizeof what)) != RL_OK)
        return fail(c, err, errlen, e, what);
    if (s->fmt->kind != V4L2F_PLANE &&
        (s->grey = malloc((size_t)s->width * (size_t)s->height)) == NULL)
        return fail(c, err, errlen, RL_ENOMEM, "out of memory");
    if (s->fmt->kind == V4L2F_JPEG && (s->jpeg = rl_mjpeg_new()) == NULL)
        return fail(c, err, errlen, RL_ENOMEM, "cannot make a JPEG decoder");
    if ((e = map_buffers(s, what, sizeof what)) != RL_OK)
        return fail(c, err, errlen, e, what);
    if (v4l2_ioctl(&s->d, VIDIOC_STREAMON, &type) < 0) {
        int en = errno;
        snprintf(what, sizeof what, "cannot start streaming: %s", v4l2_dev_why(en));
        return fail(c, err, errlen, en == EBUSY ? RL_ENODEV : RL_EIO, what);
    }
    s->streaming = 1;
    snprintf(c->info, sizeof c->info, "%s (%s), %s %dx%d%s, %s", s->d.card, s->d.driver, s->fmt->name,
             s->width, s->height, s->fmt->kind == V4L2F_PLANE ? " lent as is" : "", ctl);
    return RL_OK;
}
