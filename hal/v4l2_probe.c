/* --probe for the V4L2 camera: the device, every format with its sizes
 * (marking those ringloc takes, and the one it would stream), and every
 * control with its range. */
#include <linux/videodev2.h>
#include <stdio.h>
#include <string.h>
#include "rl_cam.h"
#include "v4l2_ctrl.h"
#include "v4l2_dev.h"
#include "v4l2_format.h"

/* "640x480 1280x720 ..." or "160x120 .. 1920x1080 step 16x16" */
static void sizes(const v4l2_dev *d, uint32_t fourcc, char *out, size_t len)
{
    size_t used = 0;
    unsigned i;
    out[0] = '\0';
    for (i = 0; i < 64 && used < len; i++) {
        struct v4l2_frmsizeenum fs;
        int w;
        memset(&fs, 0, sizeof fs);
        fs.index = i;
        fs.pixel_format = fourcc;
        if (v4l2_ioctl(d, VIDIOC_ENUM_FRAMESIZES, &fs) < 0)
            break;
        if (fs.type == V4L2_FRMSIZE_TYPE_DISCRETE)
            w = snprintf(out + used, len - used, "%s%ux%u", used ? " " : "", fs.discrete.width,
                         fs.discrete.height);
        else
            w = snprintf(out + used, len - used, "%ux%u .. %ux%u step %ux%u", fs.stepwise.min_width,
                         fs.stepwise.min_height, fs.stepwise.max_width, fs.stepwise.max_height,
                         fs.stepwise.step_width, fs.stepwise.step_height);
        used += w > 0 ? (size_t)w : 0;
        if (fs.type != V4L2_FRMSIZE_TYPE_DISCRETE)
            break;
    }
    if (used == 0)
        snprintf(out, len, "(sizes not listed)");
}

rl_err rl_cam_probe_v4l2(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err, size_t errlen)
{
    v4l2_dev d;
    char what[256], text[512], list[384], name[8];
    int width = cc->width > 0 ? cc->width : 640, height = cc->height > 0 ? cc->height : 480;
    const v4l2f *best;
    unsigned i;
    rl_err e = v4l2_dev_open(&d, cc->v4l2_sys, cc->device, what, sizeof what);
    if (e != RL_OK) {
        snprintf(err, errlen, "%s: %s", cc->device, what);
        return e;
    }
    snprintf(text, sizeof text, "v4l2 %s: %s (driver %s)", cc->device, d.card, d.driver);
    line(ctx, text);
    line(ctx, "formats (* ringloc takes it):");
    for (i = 0; i < 64; i++) {
        struct v4l2_fmtdesc fd;
        const v4l2f *f;
        memset(&fd, 0, sizeof fd);
        fd.index = i;
        fd.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (v4l2_ioctl(&d, VIDIOC_ENUM_FMT, &fd) < 0)
            break;
        f = v4l2f_find(fd.pixelformat);
        v4l2f_name(fd.pixelformat, name);
        sizes(&d, fd.pixelformat, list, sizeof list);
        snprintf(text, sizeof text, "  %c %s %-24.24s %s", f ? '*' : ' ', name, (const char *)fd.description, list);
        line(ctx, text);
    }
    if ((best = v4l2_dev_choose(&d, width, height, what, sizeof what)) != NULL) {
        v4l2f_name(best->fourcc, name);
        snprintf(text, sizeof text, "at %dx%d ringloc would stream %s", width, height, name);
    } else {
        snprintf(text, sizeof text, "at %dx%d ringloc takes none of these formats", width, height);
    }
    line(ctx, text);
    line(ctx, "controls:");
    v4l2_ctrl_list(&d, line, ctx);
    v4l2_dev_close(&d);
    return RL_OK;
}
