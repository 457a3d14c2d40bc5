#include "v4l2_ctrl.h"

#include <errno.h>
#include <linux/videodev2.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The control's range; 0 if the device has no such control (or it is
 * disabled). */
static int query(const v4l2_dev *d, uint32_t id, struct v4l2_queryctrl *q)
{
    memset(q, 0, sizeof *q);
    q->id = id;
    return v4l2_ioctl(d, VIDIOC_QUERYCTRL, q) == 0 && !(q->flags & V4L2_CTRL_FLAG_DISABLED);
}

static int set(const v4l2_dev *d, uint32_t id, int value)
{
    struct v4l2_control c;
    c.id = id;
    c.value = value;
    return v4l2_ioctl(d, VIDIOC_S_CTRL, &c) == 0;
}

/* A manual value within the control's range, or why not. */
static rl_err set_in_range(const v4l2_dev *d, uint32_t id, const char *name, long value, char *what,
                           size_t wlen)
{
    struct v4l2_queryctrl q;
    if (!query(d, id, &q)) {
        snprintf(what, wlen, "offers no %s control", name);
        return RL_EUNSUPPORTED;
    }
    if (value < q.minimum || value > q.maximum) {
        snprintf(what, wlen, "%s %ld is outside the device's %d .. %d", name, value, q.minimum, q.maximum);
        return RL_EUNSUPPORTED;
    }
    if (!set(d, id, (int)value)) {
        snprintf(what, wlen, "cannot set %s to %ld: %s", name, value, v4l2_dev_why(errno));
        return RL_EUNSUPPORTED;
    }
    return RL_OK;
}

rl_err v4l2_ctrl_apply(const v4l2_dev *d, int exposure_us, double gain, char *info, size_t ilen,
                       char *what, size_t wlen)
{
    struct v4l2_queryctrl q;
    char ex[64], ga[64];
    rl_err e;
    if (exposure_us > 0) {
        long units = lround(exposure_us / 100.0);
        if (query(d, V4L2_CID_EXPOSURE_AUTO, &q) && !set(d, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL)) {
            snprintf(what, wlen, "cannot turn automatic exposure off: %s", v4l2_dev_why(errno));
            return RL_EUNSUPPORTED;
        }
        if ((e = set_in_range(d, V4L2_CID_EXPOSURE_ABSOLUTE, "exposure (100 us units)", units < 1 ? 1 : units,
                              what, wlen)) != RL_OK)
            return e;
        snprintf(ex, sizeof ex, "exposure %ld us", (units < 1 ? 1 : units) * 100);
    } else {
        /* UVC cameras name their automatic mode aperture priority */
        if (query(d, V4L2_CID_EXPOSURE_AUTO, &q) && !set(d, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_AUTO))
            (void)set(d, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_APERTURE_PRIORITY);
        snprintf(ex, sizeof ex, "exposure auto");
    }
    if (gain > 0) {
        if (query(d, V4L2_CID_AUTOGAIN, &q) && !set(d, V4L2_CID_AUTOGAIN, 0)) {
            snprintf(what, wlen, "cannot turn automatic gain off: %s", v4l2_dev_why(errno));
            return RL_EUNSUPPORTED;
        }
        if ((e = set_in_range(d, V4L2_CID_GAIN, "gain", lround(gain), what, wlen)) != RL_OK)
            return e;
        snprintf(ga, sizeof ga, "gain %ld", lround(gain));
    } else {
        if (query(d, V4L2_CID_AUTOGAIN, &q))
            (void)set(d, V4L2_CID_AUTOGAIN, 1);
        snprintf(ga, sizeof ga, "gain auto");
    }
    snprintf(info, ilen, "%s, %s", ex, ga);
    return RL_OK;
}

void v4l2_ctrl_list(const v4l2_dev *d, rl_cam_line_fn line, void *ctx)
{
    struct v4l2_queryctrl q;
    char text[200];
    int n = 0;
    memset(&q, 0, sizeof q);
    q.id = V4L2_CTRL_FLAG_NEXT_CTRL;
    while (n < 256 && v4l2_ioctl(d, VIDIOC_QUERYCTRL, &q) == 0) {
        struct v4l2_control c;
        n++;
        if (!(q.flags & V4L2_CTRL_FLAG_DISABLED) && q.type != V4L2_CTRL_TYPE_CTRL_CLASS) {
            c.id = q.id;
            c.value = 0;
            if (v4l2_ioctl(d, VIDIOC_G_CTRL, &c) == 0)
                snprintf(text, sizeof text, "  control %-32.32s %d .. %d step %d, default %d, now %d",
                         (const char *)q.name, q.minimum, q.maximum, q.step, q.default_value, c.value);
            else
                snprintf(text, sizeof text, "  control %-32.32s %d .. %d step %d, default %d",
                         (const char *)q.name, q.minimum, q.maximum, q.step, q.default_value);
            line(ctx, text);
        }
        q.id |= V4L2_CTRL_FLAG_NEXT_CTRL;
    }
    if (n == 0)
        line(ctx, "  no controls");
}
