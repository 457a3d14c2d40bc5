#include "v4l2_dev.h"
#include "v4l2_format.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <stdio.h>
#include <string.h>

int v4l2_ioctl(const v4l2_dev *d, unsigned long req, void *arg)
{
    int r;
    do
        r = d->sys->ioctl(d->sys->ctx, d->fd, req, arg);
    while (r < 0 && errno == EINTR);
    return r;
}

const char *v4l2_dev_why(int err)
{
    if (err == EBUSY)
        return "device busy (another program is using it)";
    if (err == ENODEV || err == ENXIO)
        return "device gone (unplugged?)";
    if (err == EACCES || err == EPERM)
        return "permission denied (is the user in the video group?)";
    return strerror(err);
}

rl_err v4l2_dev_open(v4l2_dev *d, const rl_v4l2_sys *sys, const char *path, char *what, size_t len)
{
    struct v4l2_capability cap;
    uint32_t caps;
    memset(d, 0, sizeof *d);
    d->sys = sys ? sys : rl_v4l2_sys_real();
    do
        d->fd = d->sys->open(d->sys->ctx, path, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    while (d->fd < 0 && errno == EINTR);
    if (d->fd < 0) {
        int e = errno;
        snprintf(what, len, "%s", e == ENOENT ? "no such device" : v4l2_dev_why(e));
        return e == ENOENT ? RL_ENOTFOUND : RL_ENODEV;
    }
    memset(&cap, 0, sizeof cap);
    if (v4l2_ioctl(d, VIDIOC_QUERYCAP, &cap) < 0) {
        snprintf(what, len, "not a V4L2 device (%s)", v4l2_dev_why(errno));
        v4l2_dev_close(d);
        return RL_EUNSUPPORTED;
    }
    caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    snprintf(d->driver, sizeof d->driver, "%.31s", (const char *)cap.driver);
    snprintf(d->card, sizeof d->card, "%.63s", (const char *)cap.card);
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
        snprintf(what, len, "%s (%s) is not a video capture device with streaming", d->card, d->driver);
        v4l2_dev_close(d);
        return RL_EUNSUPPORTED;
    }
    return RL_OK;
}

void v4l2_dev_close(v4l2_dev *d)
{
    if (d->fd >= 0 && d->sys != NULL)
        d->sys->close(d->sys->ctx, d->fd);
    d->fd = -1;
}

int v4l2_dev_offers(const v4l2_dev *d, uint32_t fourcc, int width, int height)
{
    struct v4l2_frmsizeenum fs;
    unsigned i;
    for (i = 0; i < 256; i++) {
        memset(&fs, 0, sizeof fs);
        fs.index = i;
        fs.pixel_format = fourcc;
        if (v4l2_ioctl(d, VIDIOC_ENUM_FRAMESIZES, &fs) < 0)
            return i == 0 ? -1 : 0;
        if (fs.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
            if ((int)fs.discrete.width == width && (int)fs.discrete.height == height)
                return 1;
        } else {
            const struct v4l2_frmsize_stepwise *s = &fs.stepwise;
            unsigned w = (unsigned)width, h = (unsigned)height;
            unsigned sw = s->step_width ? s->step_width : 1, sh = s->step_height ? s->step_height : 1;
            return w >= s->min_width && w <= s->max_width && h >= s->min_height && h <= s->max_height &&
                   (w - s->min_width) % sw == 0 && (h - s->min_height) % sh == 0;
        }
    }
    return 0;
}

/* The best format offered at width x height, or NULL with the device's
 * own formats listed in what. */
const v4l2f *v4l2_dev_choose(const v4l2_dev *d, int width, int height, char *what, size_t len)
{
    const v4l2f *best = NULL;
    char offered[160] = "";
    size_t used = 0;
    unsigned i;
    for (i = 0; i < 64; i++) {
        struct v4l2_fmtdesc fd;
        const v4l2f *f;
        char name[8];
        memset(&fd, 0, sizeof fd);
        fd.index = i;
        fd.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (v4l2_ioctl(d, VIDIOC_ENUM_FMT, &fd) < 0)
            break;
        v4l2f_name(fd.pixelformat, name);
        if (used < sizeof offered) {
            int w = snprintf(offered + used, sizeof offered - used, "%s%s", used ? " " : "", name);
            used += w > 0 ? (size_t)w : 0;
        }
        f = v4l2f_find(fd.pixelformat);
        if (f == NULL || v4l2_dev_offers(d, f->fourcc, width, height) == 0)
            continue;
        if (best == NULL || v4l2f_rank(f->fourcc) < v4l2f_rank(best->fourcc))
            best = f;
    }
    if (best == NULL)
        snprintf(what, len, "offers none of GREY, NV12, YU12, YUYV, UYVY, MJPG at %dx%d (it has: %s)", width,
                 height, used ? offered : "no formats");
    return best;
}
