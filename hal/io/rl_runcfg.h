/* rl_runcfg: ringloc.yaml, the one configuration of the firmware
 * (`ringloc-fw`, `ringloc run`).
 *
 *   camera:
 *     backend: v4l2          # png | v4l2 | libcamera | sim
 *     device: /dev/video0    # png: a directory or a list file of PNGs; sim: a pipe of
 *                            # 'T_US FILE' lines (ringloc-render --path stream)
 *     width: 640
 *     height: 480
 *     rate: 10               # frames per second
 *     loop: false            # png: start again at the end of the frames
 *     exposure: auto         # auto, or the exposure time in microseconds
 *     gain: auto             # auto, or the analogue gain
 *     readout: 0             # a rolling shutter's readout, first row to last, ms
 *                            # (0: a global shutter): docs/results.md
 *     stamp: auto            # where the device's frame times lie: auto (as the backend
 *                            # says), exposure_start, frame_start or frame_end
 *   calibration: camera.yaml # ROS camera_info or OpenCV YAML
 *   map: map.yaml
 *   robot: robot.yaml
 *   offsets: offsets.yaml    # optional: the paper's offset maps instead of the pinhole model
 *   serial:
 *     device: /dev/serial0   # a tty, a pty, a file, or "-" for standard output
 *     baud: 115200
 *   recognition:
 *     local: always          # always (default) | auto (the paper's) | never
 *     min_score: 0.80        # global pass
 *     local_min_score: 0.75  # local pass
 *     gamma: auto            # the camera's tone curve: auto, 2.2 (sRGB), 1 (linear)
 *     track_every: 0         # 0 (default): every frame read in full; N: tracking
 *                            # windows between full frames, a full frame every N (10)
 *   log_interval: 5          # seconds between repeats of one kind of log line
 *   record:                  # optional: save frames while running
 *     dir: /var/lib/ringloc/drive
 *     every: 10              # one frame in this many
 *     max_mb: 1000           # stop recording at this much on disk
 *   http:                    # optional: the live web view (off when absent)
 *     listen: 0.0.0.0:8080   # ADDR:PORT (rl_listen.h)
 *     token: s3cret          # optional: asked of every request (?token= or a header)
 *
 * Relative paths are relative to the configuration file's folder.
 *
 *   static rl_runcfg rc;
 *   char err[768];
 *   if (rl_runcfg_load("/etc/ringloc/ringloc.yaml", &rc, err, sizeof err) == RL_OK)
 *       use(rc.cam_backend, rc.map, rc.baud);
 */
#ifndef RL_RUNCFG_H
#define RL_RUNCFG_H

#include <stddef.h>
#include "rl_recog.h"

typedef struct {
    char cam_backend[32], cam_device[512];
    int cam_width, cam_height;  /* 0: the device's */
    double cam_rate;            /* frames per second (default 10) */
    int cam_loop;               /* png: start again at the end (default false) */
    double cam_exposure_us;     /* 0: auto (default); else microseconds */
    double cam_gain;            /* 0: auto (default); else the analogue gain */
    double cam_readout_ms;      /* a rolling shutter's readout, ms (0, default: global) */
    char cam_stamp[16];         /* where the device's times lie: auto (default), exposure_start,
                                   frame_start or frame_end (rl_cam_stamp) */
    char calibration[512], map[512], robot[512], offsets[512];
    char serial[512];
    int baud;
    int baud_line;      /* line of serial.baud (0: not given), for the caller's check */
    rl_local_policy local;
    double min_score, local_min_score;
    double gamma;          /* the camera's tone curve (rl_recog_config.gamma; 0: auto) */
    int track_every;       /* tracking windows: a full frame every this many; 0 (default): off */
    double log_interval;
    char record_dir[512];       /* "" : no recording */
    int record_every;           /* default 10 */
    double record_max_mb;       /* default 1000 */
    char http_listen[64];       /* "" : no web view */
    char http_token[129];       /* "" : none asked */
} rl_runcfg;

/* Read path into c (defaults for what it leaves out). RL_ENOTFOUND,
 * RL_EFORMAT or RL_ERANGE with one line in err naming the file, line and
 * key. The baud rate is checked by the caller against what its serial
 * line supports (rl_serial_baud_ok). */
RL_CHECK rl_err rl_runcfg_load(const char *path, rl_runcfg *c, char *err, size_t errlen);

#endif
