/* ringloc run: the firmware. Frames in from the camera, pose frames out on
 * the serial line, until SIGINT or SIGTERM (or the end of a PNG sequence). */
#include <getopt.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "rl_camfile.h"
#include "rl_cli.h"
#include "rl_mapfile.h"
#include "rl_offsetsfile.h"
#include "rl_robotfile.h"
#include "rl_run.h"
#include "rl_runcfg.h"
#include "rl_serial.h"

static const char *run_help =
    "usage: ringloc run --config ringloc.yaml [--frames N]\n\n"
    "The firmware: grab frames from the camera, recognize landmarks, compute the\n"
    "robot's pose and send it as ARCOS-framed pose frames on the serial line (a\n"
    "status frame when there is no pose). Camera and serial faults are survived:\n"
    "the device is reopened with backoff and status frames say what happened.\n"
    "Stops on SIGINT/SIGTERM, at the end of a PNG sequence, or after N frames.\n"
    "Logs go to standard error, repeated lines at most every log_interval s.\n"
    "See rl_runcfg.h or the README for the configuration file.\n";

static volatile sig_atomic_t stop_flag;

static void on_signal(int sig)
{
    (void)sig;
    stop_flag = 1;
}

typedef struct {
    rl_cam cam;
    const rl_cam_config *cc;
} cam_ctx;

static rl_err cam_open(void *ctx, char *err, size_t errlen)
{
    cam_ctx *c = (cam_ctx *)ctx;
    return rl_cam_open(&c->cam, c->cc, err, errlen);
}
static rl_err cam_grab(void *ctx, int timeout_ms, rl_cam_frame *f)
{
    return rl_cam_grab(&((cam_ctx *)ctx)->cam, timeout_ms, f);
}
static void cam_release(void *ctx, rl_cam_frame *f)
{
    rl_cam_release(&((cam_ctx *)ctx)->cam, f);
}
static void cam_close(void *ctx)
{
    rl_cam_close(&((cam_ctx *)ctx)->cam);
}

typedef struct {
    rl_serial s;
    const char *path;
    int baud;
} out_ctx;

static rl_err out_open(void *ctx, char *err, size_t errlen)
{
    out_ctx *o = (out_ctx *)ctx;
    return rl_serial_open(&o->s, o->path, o->baud, err, errlen);
}
static rl_err out_write(void *ctx, const uint8_t *p, size_t n)
{
    return rl_serial_write(&((out_ctx *)ctx)->s, p, n, 100);
}
static void out_close(void *ctx)
{
    rl_serial_close(&((out_ctx *)ctx)->s);
}

static uint64_t now_us(void *ctx)
{
    (void)ctx;
    return rl_cam_now_us();
}
static void sleep_us(void *ctx, uint64_t us)
{
    struct timespec ts;
    (void)ctx;
    ts.tv_sec = (time_t)(us / 1000000u);
    ts.tv_nsec = (long)(us % 1000000u) * 1000L;
    nanosleep(&ts, NULL);
}
static void log_line(void *ctx, const char *line)
{
    (void)ctx;
    fprintf(stderr, "ringloc run: %s\n", line);
}

int rl_cmd_run(int argc, char **argv)
{
    static const struct option opts[] = {{"config", required_argument, 0, 'c'},
                                         {"frames", required_argument, 0, 'n'},
                                         {"help", no_argument, 0, 'h'},
                                         {0, 0, 0, 0}};
    const char *C = "run", *config = NULL;
    static rl_runcfg cfg;
    static rl_map map;
    static rl_result res;
    static rl_runner runner;
    static cam_ctx cctx;
    static out_ctx octx;
    rl_camera calib;
    rl_mount mount;
    rl_offsets offsets;
    rl_recog_config rc;
    rl_recog rec;
    rl_run_io io;
    struct sigaction sa;
    void *mem;
    size_t need;
    long max_frames = 0;
    int c, ids[RL_MAX_MAP_LANDMARKS];
    char err[768];
    rl_err e;

    optind = 1;
    while ((c = getopt_long(argc, argv, "h", opts, NULL)) != -1) {
        switch (c) {
        case 'c': config = optarg; break;
        case 'n': {
            int v;
            if (!rl_cli_int(C, "--frames", optarg, &v) || v < 0)
                return rl_cli_fail(C, RL_EXIT_USAGE, "--frames: expected a count >= 0");
            max_frames = v;
            break;
        }
        case 'h': fputs(run_help, stdout); return 0;
        default: return rl_cli_fail(C, RL_EXIT_USAGE, "see 'ringloc run --help'");
        }
    }
    if (config == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--config FILE is required (see --help)");
    /* start-up: everything that can fail in configuration fails here, once */
    if (rl_runcfg_load(config, &cfg, err, sizeof err) != RL_OK ||
        rl_camfile_load(cfg.calibration, &calib, err, sizeof err) != RL_OK ||
        rl_mapfile_load(cfg.map, &map, err, sizeof err) != RL_OK ||
        rl_robotfile_load(cfg.robot, &mount, err, sizeof err) != RL_OK ||
        (cfg.offsets[0] && rl_offsetsfile_load(cfg.offsets, &offsets, err, sizeof err) != RL_OK))
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if ((cfg.cam.width && cfg.cam.width != calib.width) || (cfg.cam.height && cfg.cam.height != calib.height))
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: camera is %dx%d but %s is for %dx%d", config,
                           cfg.cam.width, cfg.cam.height, cfg.calibration, calib.width, calib.height);
    if (map.count == 0 || !(map.ceiling_height > mount.z))
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: %s", cfg.map,
                           map.count == 0 ? "the map has no landmarks" : "the camera is not below the ceiling");
    rl_recog_defaults(&rc);
    rl_recog_use_map(&rc, &map, ids);
    rc.local = cfg.local;
    rc.min_score = cfg.min_score;
    need = rl_recog_workspace_size(calib.width, calib.height, &rc);
    mem = need ? malloc(need) : NULL; /* the one allocation of the core, at start-up */
    if (mem == NULL || (e = rl_recog_init(&rec, &rc, calib.width, calib.height, mem, need)) != RL_OK) {
        free(mem);
        return rl_cli_fail(C, RL_EXIT_FAIL, "cannot prepare recognition for %dx%d", calib.width, calib.height);
    }
    cctx.cc = &cfg.cam;
    octx.path = cfg.serial;
    octx.baud = cfg.baud;
    memset(&io, 0, sizeof io);
    io.cam_open = cam_open;
    io.cam_grab = cam_grab;
    io.cam_release = cam_release;
    io.cam_close = cam_close;
    io.cam_ctx = &cctx;
    io.out_open = out_open;
    io.out_write = out_write;
    io.out_close = out_close;
    io.out_ctx = &octx;
    io.now_us = now_us;
    io.sleep_us = sleep_us;
    io.log = log_line;
    rl_run_init(&runner, &io, &rec, &calib, &map, &mount, &res);
    runner.offsets = cfg.offsets[0] ? &offsets : NULL;
    runner.log_interval_us = (uint64_t)(cfg.log_interval * 1e6);
    if (cfg.cam.rate > 0)
        runner.timeout_ms = (int)(3000.0 / cfg.cam.rate) > 200 ? (int)(3000.0 / cfg.cam.rate) : 200;

    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN); /* a vanished reader is a write error, not a death */
    fprintf(stderr, "ringloc run: %s camera %s, %d landmarks in %s, poses to %s at %d baud\n",
            cfg.cam_backend, cfg.cam_device, map.count, cfg.map, cfg.serial, cfg.baud);
    while (!stop_flag) {
        if (rl_run_step(&runner) == RL_ENOTFOUND)
            break;
        if (max_frames > 0 && runner.frames >= max_frames)
            break;
    }
    rl_run_close(&runner);
    fprintf(stderr, "ringloc run: %ld frames, %ld poses, %ld status frames, %ld camera errors, "
                    "%ld timeouts, %ld serial errors, %ld frames dropped%s\n",
            runner.frames, runner.poses, runner.statuses, runner.camera_errors,
            runner.camera_timeouts, runner.serial_errors, runner.dropped,
            stop_flag ? " (stopped by signal)" : "");
    free(mem);
    return 0;
}
