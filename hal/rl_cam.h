/* rl_cam: the camera, where a frame enters.
 *
 * One interface, several backends chosen by name at run time: "png" (a
 * directory or list of PNG files played at a rate, for the host and the
 * demo), "v4l2" (USB webcams, mmap streaming, GREY or YUYV), "libcamera"
 * (the Raspberry Pi camera; built only where libcamera is found). A frame
 * is lent, not copied: grab gives a view into the backend's buffer with
 * its capture time (rl_clock.h), release gives it back. A test double is
 * one more backend: rl_cam_config.open.
 *
 *   rl_cam cam;
 *   rl_cam_config cc;
 *   rl_cam_frame f;
 *   char err[256];
 *   rl_cam_defaults(&cc);
 *   cc.backend = "v4l2";
 *   cc.device = "/dev/video0";
 *   if (rl_cam_open(&cam, &cc, err, sizeof err) == RL_OK) {
 *       while (rl_cam_grab(&cam, 500, &f) == RL_OK) {
 *           use(f.img.width, f.t_us);
 *           rl_cam_release(&cam, &f);
 *       }
 *       rl_cam_close(&cam);
 *   }
 */
#ifndef RL_CAM_H
#define RL_CAM_H

#include <stddef.h>
#include <stdint.h>
#include "rl_clock.h"
#include "rl_error.h"
#include "rl_image.h"

struct rl_cam;
struct rl_cam_config;
/* A backend's open: fills c->ops and c->state. */
typedef rl_err (*rl_cam_open_fn)(struct rl_cam *c, const struct rl_cam_config *cc, char *err,
                                 size_t errlen);

typedef struct rl_cam_config {
    const char *backend; /* "png", "v4l2", "libcamera" */
    const char *device;  /* png: directory or list file; v4l2: /dev/videoN; libcamera: index */
    int width, height;   /* wanted size (0: the device's) */
    double rate;         /* frames per second (png: playback rate; 0 = as fast as possible) */
    int loop;            /* png: start again at the end instead of RL_ENOTFOUND */
    rl_cam_open_fn open; /* a backend not named above (a test double); NULL: by name */
    void *open_arg;      /* for that backend */
} rl_cam_config;

typedef struct {
    rl_image img;        /* grey view, valid until released */
    uint64_t t_us;       /* capture time, monotonic clock, microseconds */
    long index;          /* frame number since open */
    int slot;            /* backend's buffer, for release */
} rl_cam_frame;

typedef struct {
    RL_CHECK rl_err (*grab)(struct rl_cam *c, int timeout_ms, rl_cam_frame *f);
    void (*release)(struct rl_cam *c, rl_cam_frame *f);
    void (*close)(struct rl_cam *c);
} rl_cam_ops;

typedef struct rl_cam {
    const rl_cam_ops *ops;
    void *state;         /* backend's, allocated at open (never per frame) */
    char name[160];      /* device, for messages */
} rl_cam;

void rl_cam_defaults(rl_cam_config *cc);

/* Open and start the backend. Errors: RL_ENOTFOUND/RL_ENODEV (no such
 * device or files), RL_EUNSUPPORTED (backend not built in, format not
 * offered), RL_EIO; err names the device. */
RL_CHECK rl_err rl_cam_open(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);

/* Wait up to timeout_ms for the next frame: RL_ETIMEOUT if none came,
 * RL_ENOTFOUND at the end of a PNG sequence, RL_EIO / RL_ENODEV when the
 * device failed (close and open again). */
RL_CHECK rl_err rl_cam_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f);
void rl_cam_release(rl_cam *c, rl_cam_frame *f);
void rl_cam_close(rl_cam *c);

/* Backends (hal/cam_*.c). */
RL_CHECK rl_err rl_cam_open_png(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);
RL_CHECK rl_err rl_cam_open_v4l2(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);
RL_CHECK rl_err rl_cam_open_libcamera(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);

#endif
