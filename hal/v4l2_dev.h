/* v4l2_dev: a V4L2 capture device through the system-call seam
 * (rl_v4l2_sys.h): opening it with one clear reason when that fails, and
 * what it offers. Internal to the V4L2 camera (cam_v4l2.c, v4l2_probe.c,
 * v4l2_ctrl.c).
 *
 *   v4l2_dev d;
 *   char why[128];
 *   if (v4l2_dev_open(&d, NULL, "/dev/video0", why, sizeof why) == RL_OK) {
 *       use(d.card, v4l2_dev_offers(&d, 0x59455247u, 640, 480)); // 'GREY' at 640x480?
 *       v4l2_dev_close(&d);
 *   }
 */
#ifndef V4L2_DEV_H
#define V4L2_DEV_H

#include <stddef.h>
#include <stdint.h>
#include "rl_error.h"
#include "rl_v4l2_sys.h"
#include "v4l2_format.h"

typedef struct {
    const rl_v4l2_sys *sys;
    int fd;
    char driver[32], card[64];
} v4l2_dev;

/* ioctl, EINTR retried; -1 with errno set on failure. */
int v4l2_ioctl(const v4l2_dev *d, unsigned long req, void *arg);

/* Open path (sys NULL: the real calls) and check it captures video by
 * streaming. On failure the reason is in what (no device name):
 * RL_ENOTFOUND (no such device), RL_ENODEV (busy, no permission, gone),
 * RL_EUNSUPPORTED (not a capture device). */
RL_CHECK rl_err v4l2_dev_open(v4l2_dev *d, const rl_v4l2_sys *sys, const char *path, char *what,
                              size_t len);
void v4l2_dev_close(v4l2_dev *d);

/* Whether the device offers fourcc at width x height: 1 yes, 0 no, -1
 * it does not enumerate its sizes (then setting the format tells). */
int v4l2_dev_offers(const v4l2_dev *d, uint32_t fourcc, int width, int height);

/* The format ringloc streams at width x height: the best (v4l2f_rank) of
 * those it takes that the device offers there; NULL with the device's own
 * formats listed in what. Streaming and --probe both ask this. */
const v4l2f *v4l2_dev_choose(const v4l2_dev *d, int width, int height, char *what, size_t len);

/* The reason of a failed ioctl in words, EBUSY as a busy device. */
const char *v4l2_dev_why(int err);

#endif
