/* rl_cam: the camera, where a frame enters.
 *
 * One interface, several backends chosen by name at run time: "png" (a
 * directory or list of PNG files played at a rate and decoded one at a
 * time, for the host and the demo), "v4l2" (USB webcams and CSI drivers,
 * mmap streaming, the best of GREY, NV12, YU12, YUYV, UYVY and MJPEG the
 * device offers), "libcamera" (the Raspberry Pi camera; built only where
 * libcamera is found), "sim" (frames a renderer draws as a simulated robot
 * moves: each carries its pose's time as capture time, hal/cam_sim.c). A frame is lent, not copied where its format
 * allows: grab gives a view into the backend's buffer with its capture
 * time from the driver (rl_clock.h's monotonic clock), release gives it
 * back. Exposure and gain are automatic unless set. The loop takes a
 * camera as its frame source (rl_run.h), where a test puts its double; the
 * V4L2 backend is tested under a fake device (rl_cam_config.v4l2_sys,
 * rl_v4l2_sys.h).
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
struct rl_v4l2_sys;
/* A backend's open: fills c->ops and c->state. */
typedef rl_err (*rl_cam_open_fn)(struct rl_cam *c, const struct rl_cam_config *cc, char *err,
                                 size_t errlen);

typedef struct rl_cam_config {
    const char *backend; /* "png", "v4l2", "libcamera", "sim" */
    const char *device;  /* png: directory or list file; v4l2: /dev/videoN; libcamera: index */
    const char *const *files; /* png: these files in this order instead of device (n_files of them;
                                 kept, not copied); with width 0 each frame has its own size */
    int n_files;
    int width, height;   /* wanted size (0: the device's) */
    double rate;         /* frames per second (png: playback rate; 0 = as fast as possible) */
    int loop;            /* png: start again at the end instead of RL_ENOTFOUND */
    int exposure_us;     /* 0: automatic exposure; else the exposure time, microseconds */
    double gain;         /* 0: automatic gain; else the (analogue) gain */
    int readout_us;      /* a rolling shutter's readout, first row to last (0: a global
                            shutter): with the exposure, where a backend's stamp lies in the
                            frame (rl_cam_frame.stamp) moves it to the middle row's mid-exposure */
    int stamp;           /* where a device's stamps lie (rl_cam_stamp), for a driver that says
                            otherwise; RL_CAM_STAMP_AUTO (default): as the backend says */
    const struct rl_v4l2_sys *v4l2_sys; /* v4l2: its system calls (NULL: the real ones) */
} rl_cam_config;

/* Where a backend's stamp was taken in the frame's exposure. */
typedef enum {
    RL_CAM_STAMP_MIDDLE = 0,   /* the middle row's mid-exposure (png, sim: the time given) */
    RL_CAM_STAMP_EXPOSURE_START, /* the first row's exposure began (a v4l2 driver's
                                  start-of-exposure stamp: uvcvideo's) */
    RL_CAM_STAMP_FRAME_START,  /* the first row was read, its exposure over (libcamera's
                                  SensorTimestamp on a Raspberry Pi: the frame-start interrupt) */
    RL_CAM_STAMP_FRAME_END     /* the last row was read (a v4l2 driver's end-of-frame stamp,
                                  V4L2's default; the time of arrival where there is no stamp) */
} rl_cam_stamp;
#define RL_CAM_STAMP_AUTO (-1) /* rl_cam_config.stamp: where the backend says */

typedef struct {
    rl_image img;        /* grey view, valid until released */
    uint64_t t_us;       /* capture time, monotonic clock, microseconds: the middle row's
                            mid-exposure (rl_cam_grab moves the backend's stamp there by the
                            readout and the exposure, as far as they are known) */
    rl_cam_stamp stamp;  /* the backend's: where its stamp was taken */
    int exposure_us;     /* the backend's: the frame's exposure (0: unknown, the configured one) */
    long index;          /* frame number since open */
    const char *name;    /* the frame's file (png), or NULL */
    int slot;            /* backend's buffer, for release */
} rl_cam_frame;

typedef struct {
    RL_CHECK rl_err (*grab)(struct rl_cam *c, int timeout_ms, rl_cam_frame *f);
    void (*release)(struct rl_cam *c, rl_cam_frame *f);
    void (*close)(struct rl_cam *c);
} rl_cam_ops;

typedef struct rl_cam {
    const rl_cam_ops *ops;
    int readout_us, exposure_us, stamp; /* the configuration's (rl_cam_grab's stamps) */
    void *state;         /* backend's, allocated at open (never per frame) */
    char name[160];      /* device, for messages */
    char error[384];     /* why the last grab failed, naming the file or device ("" if unknown) */
    char info[256];      /* what was opened: format, size, exposure (for the log) */
} rl_cam;

void rl_cam_defaults(rl_cam_config *cc);

/* Open and start the backend. Errors: RL_ENOTFOUND/RL_ENODEV (no such
 * device or files), RL_EUNSUPPORTED (backend not built in, format not
 * offered), RL_EIO; err names the device. */
RL_CHECK rl_err rl_cam_open(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);

/* Wait up to timeout_ms for the next frame: RL_ETIMEOUT if none came,
 * RL_ENOTFOUND at the end of a PNG sequence, RL_EFORMAT for a bad frame
 * that was skipped (grab again), RL_EIO / RL_ENODEV when the device
 * failed (close and open again). c->error says why. */
RL_CHECK rl_err rl_cam_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f);
void rl_cam_release(rl_cam *c, rl_cam_frame *f);
void rl_cam_close(rl_cam *c);

/* A stamp taken where `stamp` says, moved to the middle row's
 * mid-exposure of a frame read in readout_us with exposure_us (0:
 * unknown, left out). */
uint64_t rl_cam_middle_time(uint64_t t_us, rl_cam_stamp stamp, int readout_us, int exposure_us);

/* Describe the device of cc (formats, sizes, controls) without
 * streaming, a line at a time through line(ctx, text). err names the
 * device on failure. */
typedef void (*rl_cam_line_fn)(void *ctx, const char *text);
RL_CHECK rl_err rl_cam_probe(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err,
                             size_t errlen);

/* Backends (hal/cam_*.c). */
RL_CHECK rl_err rl_cam_open_png(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);
RL_CHECK rl_err rl_cam_open_v4l2(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);
RL_CHECK rl_err rl_cam_open_libcamera(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);
/* A PNG's size read from its header into w, h, and *block (of *cap bytes,
 * realloc'd) grown to hold it decoded; err names the file (png and sim). */
RL_CHECK rl_err rl_cam_png_fit(const char *path, void **block, size_t *cap, int *w, int *h, char *err,
                               size_t errlen);
RL_CHECK rl_err rl_cam_open_sim(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen);
RL_CHECK rl_err rl_cam_probe_png(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err,
                                 size_t errlen);
RL_CHECK rl_err rl_cam_probe_v4l2(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err,
                                  size_t errlen);
RL_CHECK rl_err rl_cam_probe_libcamera(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx,
                                       char *err, size_t errlen);
RL_CHECK rl_err rl_cam_probe_sim(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err,
                                 size_t errlen);

#endif
