/* V4L2 camera for USB webcams: mmap streaming, GREY frames lent as they
 * are, YUYV frames reduced to their Y plane in a buffer allocated at open.
 * A device that vanishes (unplugged) reports RL_ENODEV; the run loop then
 * reopens it with backoff. */
#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>
#include "rl_cam.h"

#define V4L2_BUFFERS 4

typedef struct {
    int fd;
    uint32_t fourcc;
    int width, height, stride;
    void *map[V4L2_BUFFERS];
    size_t len[V4L2_BUFFERS];
    int nbuf;
    uint8_t *grey; /* YUYV only: the Y plane */
    long index;
} v4l2_state;

static int xioctl(int fd, unsigned long req, void *arg)
{
    int r;
    do
        r = ioctl(fd, req, arg);
    while (r < 0 && errno == EINTR);
    return r;
}

static void v4l2_close(rl_cam *c)
{
    v4l2_state *s = (v4l2_state *)c->state;
    int i;
    enum v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (s == NULL)
        return;
    if (s->fd >= 0) {
        xioctl(s->fd, VIDIOC_STREAMOFF, &type);
        for (i = 0; i < s->nbuf; i++)
            if (s->map[i] && s->map[i] != MAP_FAILED)
                munmap(s->map[i], s->len[i]);
        close(s->fd);
    }
    free(s->grey);
    free(s);
}

static rl_err v4l2_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f)
{
    v4l2_state *s = (v4l2_state *)c->state;
    struct pollfd p;
    struct v4l2_buffer b;
    int r;
    p.fd = s->fd;
    p.events = POLLIN;
    p.revents = 0;
    r = poll(&p, 1, timeout_ms);
    if (r == 0)
        return RL_ETIMEOUT;
    if (r < 0)
        return errno == EINTR ? RL_ETIMEOUT : RL_EIO;
    if (p.revents & (POLLERR | POLLHUP | POLLNVAL))
        return RL_ENODEV;
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    if (xioctl(s->fd, VIDIOC_DQBUF, &b) < 0)
        return errno == EAGAIN ? RL_ETIMEOUT : errno == ENODEV ? RL_ENODEV : RL_EIO;
    f->slot = (int)b.index;
    f->index = s->index++;
    f->t_us = (uint64_t)b.timestamp.tv_sec * 1000000u + (uint64_t)b.timestamp.tv_usec;
    if (f->t_us == 0)
        f->t_us = rl_clock_now_us();
    if (s->fourcc == V4L2_PIX_FMT_GREY) {
        f->img = rl_image_view(s->width, s->height, s->stride, (uint8_t *)s->map[b.index]);
    } else { /* YUYV: Y is every other byte */
        const uint8_t *src = (const uint8_t *)s->map[b.index];
        int x, y;
        for (y = 0; y < s->height; y++)
            for (x = 0; x < s->width; x++)
                s->grey[(size_t)y * s->width + x] = src[(size_t)y * s->stride + 2 * x];
        f->img = rl_image_view(s->width, s->height, s->width, s->grey);
    }
    return RL_OK;
}

static void v4l2_release(rl_cam *c, rl_cam_frame *f)
{
    v4l2_state *s = (v4l2_state *)c->state;
    struct v4l2_buffer b;
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = (unsigned)f->slot;
    xioctl(s->fd, VIDIOC_QBUF, &b);
}

static const rl_cam_ops v4l2_ops = {v4l2_grab, v4l2_release, v4l2_close};

static rl_err fail(rl_cam *c, char *err, size_t errlen, rl_err e, const char *what)
{
    snprintf(err, errlen, "%s: %s", c->name, what);
    rl_cam_close(c);
    return e;
}

rl_err rl_cam_open_v4l2(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    v4l2_state *s;
    struct v4l2_capability cap;
    struct v4l2_format fmt;
    struct v4l2_requestbuffers req;
    enum v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    char what[256];
    int i;
    s = calloc(1, sizeof *s);
    if (s == NULL)
        return fail(c, err, errlen, RL_ENOMEM, "out of memory");
    c->state = s;
    c->ops = &v4l2_ops;
    s->fd = open(cc->device, O_RDWR | O_NONBLOCK);
    if (s->fd < 0) {
        rl_err e = errno == ENOENT ? RL_ENOTFOUND : RL_ENODEV;
        snprintf(what, sizeof what, "cannot open: %s", strerror(errno));
        return fail(c, err, errlen, e, what);
    }
    if (xioctl(s->fd, VIDIOC_QUERYCAP, &cap) < 0 || !(cap.capabilities & V4L2_CAP_VIDEO_CAPTURE) ||
        !(cap.capabilities & V4L2_CAP_STREAMING))
        return fail(c, err, errlen, RL_EUNSUPPORTED, "not a V4L2 capture device with streaming");
    /* GREY if offered, else YUYV */
    memset(&fmt, 0, sizeof fmt);
    fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    fmt.fmt.pix.width = (unsigned)(cc->width > 0 ? cc->width : 640);
    fmt.fmt.pix.height = (unsigned)(cc->height > 0 ? cc->height : 480);
    fmt.fmt.pix.pixelformat = V4L2_PIX_FMT_GREY;
    fmt.fmt.pix.field = V4L2_FIELD_NONE;
    if (xioctl(s->fd, VIDIOC_S_FMT, &fmt) < 0 || fmt.fmt.pix.pixelformat != V4L2_PIX_FMT_GREY) {
        fmt.fmt.pix.pixelformat = V4L2_PIX_FMT_YUYV;
        if (xioctl(s->fd, VIDIOC_S_FMT, &fmt) < 0 || fmt.fmt.pix.pixelformat != V4L2_PIX_FMT_YUYV)
            return fail(c, err, errlen, RL_EUNSUPPORTED, "offers neither GREY nor YUYV");
    }
    s->fourcc = fmt.fmt.pix.pixelformat;
    s->width = (int)fmt.fmt.pix.width;
    s->height = (int)fmt.fmt.pix.height;
    s->stride = (int)fmt.fmt.pix.bytesperline;
    if ((cc->width && s->width != cc->width) || (cc->height && s->height != cc->height)) {
        snprintf(what, sizeof what, "gives %dx%d, not the configured %dx%d", s->width, s->height,
                 cc->width, cc->height);
        return fail(c, err, errlen, RL_EUNSUPPORTED, what);
    }
    if (cc->rate > 0) {
        struct v4l2_streamparm parm;
        memset(&parm, 0, sizeof parm);
        parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        parm.parm.capture.timeperframe.numerator = 1000;
        parm.parm.capture.timeperframe.denominator = (unsigned)(cc->rate * 1000);
        xioctl(s->fd, VIDIOC_S_PARM, &parm); /* a hint; cameras round it */
    }
    if (s->fourcc == V4L2_PIX_FMT_YUYV &&
        (s->grey = malloc((size_t)s->width * (size_t)s->height)) == NULL)
        return fail(c, err, errlen, RL_ENOMEM, "out of memory");
    memset(&req, 0, sizeof req);
    req.count = V4L2_BUFFERS;
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    if (xioctl(s->fd, VIDIOC_REQBUFS, &req) < 0 || req.count < 2)
        return fail(c, err, errlen, RL_EIO, "cannot get mmap buffers");
    s->nbuf = (int)(req.count > V4L2_BUFFERS ? V4L2_BUFFERS : req.count);
    for (i = 0; i < s->nbuf; i++) {
        struct v4l2_buffer b;
        memset(&b, 0, sizeof b);
        b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        b.memory = V4L2_MEMORY_MMAP;
        b.index = (unsigned)i;
        if (xioctl(s->fd, VIDIOC_QUERYBUF, &b) < 0)
            return fail(c, err, errlen, RL_EIO, "cannot query buffers");
        s->len[i] = b.length;
        s->map[i] = mmap(NULL, b.length, PROT_READ | PROT_WRITE, MAP_SHARED, s->fd, b.m.offset);
        if (s->map[i] == MAP_FAILED || xioctl(s->fd, VIDIOC_QBUF, &b) < 0)
            return fail(c, err, errlen, RL_EIO, "cannot map buffers");
    }
    if (xioctl(s->fd, VIDIOC_STREAMON, &type) < 0)
        return fail(c, err, errlen, RL_EIO, "cannot start streaming");
    return RL_OK;
}
