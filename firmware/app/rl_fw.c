/* The firmware: frames in from the camera, pose frames out on the serial
 * line, until SIGINT or SIGTERM (or the end of a PNG sequence). */
#include <getopt.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include "rl_fw.h"

#include "rl_calibfile.h"
#include "rl_cli.h"
#include "rl_heap_recog.h"
#include "rl_heap_place.h"
#include "rl_mapfile.h"
#include "rl_offsetsfile.h"
#include "rl_robotfile.h"
#include "rl_record.h"
#include "rl_run.h"
#include "rl_runcfg.h"
#include "rl_serial.h"
#include "rl_clock.h"

static const char *run_help =
    "usage: %s --config ringloc.yaml [--frames N] [--record DIR] [--probe]\n\n"
    "The firmware: grab frames from the camera, recognize landmarks, compute the\n"
    "robot's pose and send it as ARCOS-framed pose frames on the serial line (a\n"
    "status frame when there is no pose). Camera and serial faults are survived:\n"
    "the device is reopened with backoff and status frames say what happened.\n"
    "Stops on SIGINT/SIGTERM, at the end of a PNG sequence, or after N frames.\n"
    "Logs go to standard error, repeated lines at most every log_interval s.\n"
    "See rl_runcfg.h or the README for the configuration file.\n\n"
    "  --frames N   stop after N frames\n"
    "  --record DIR save one frame in record.every (default 10) as PNG into DIR,\n"
    "               with DIR/frames.txt (name, capture time ms) for 'ringloc survey'\n"
    "               or playing back; at most record.max_mb (1000) on disk\n"
    "  --probe      list what the configured camera offers (formats, sizes,\n"
    "               controls) and exit\n";

static volatile sig_atomic_t stop_flag;

static void on_signal(int sig)
{
    (void)sig;
    stop_flag = 1;
}

typedef struct {
    rl_serial s;
    const char *path;
    int baud;
    int opened; /* once: a reopen creates nothing */
    const char *prefix;
} out_ctx;

static rl_err out_open(void *ctx, char *err, size_t errlen)
{
    out_ctx *o = (out_ctx *)ctx;
    rl_err e = rl_serial_open(&o->s, o->path, o->baud, o->opened ? 0 : RL_SERIAL_MAY_CREATE, err,
                              errlen);
    if (e == RL_OK)
        o->opened = 1;
    return e;
}
static rl_err out_write(void *ctx, const uint8_t *p, size_t n)
{
    out_ctx *o = (out_ctx *)ctx;
    rl_err e = rl_serial_write(&o->s, p, n, 100);
    if (o->s.broken && !stop_flag) {
        fprintf(stderr, "%s: serial: standard output closed (broken pipe); stopping\n", o->prefix);
        stop_flag = 1;
    }
    return e;
}
static void out_close(void *ctx)
{
    rl_serial_close(&((out_ctx *)ctx)->s);
}
static const char *out_why(void *ctx)
{
    int en = ((out_ctx *)ctx)->s.errnum;
    return en ? strerror(en) : NULL;
}

static void log_line(void *ctx, const char *line)
{
    fprintf(stderr, "%s: %s\n", (const char *)ctx, line);
}

/* Everything the firmware reads at start-up. */
typedef struct {
    rl_runcfg cfg;
    rl_calib calib;
    rl_map map;
    rl_mount mount;
    rl_offsets offsets;
    rl_cam_config cam;
} fw_setup;

/* Load and check every file; one error line and 0 on failure. */
static int load_setup(const char *C, const char *config, fw_setup *s)
{
    char err[768];
    rl_runcfg *cfg = &s->cfg;
    if (rl_runcfg_load(config, cfg, err, sizeof err) != RL_OK ||
        rl_calibfile_load_sized(cfg->calibration, cfg->cam_width, cfg->cam_height, &s->calib, err, sizeof err) != RL_OK ||
        rl_mapfile_load(cfg->map, &s->map, err, sizeof err) != RL_OK ||
        rl_robotfile_load(cfg->robot, &s->mount, err, sizeof err) != RL_OK ||
        (cfg->offsets[0] && rl_offsetsfile_load(cfg->offsets, &s->offsets, err, sizeof err) != RL_OK))
        return !rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (!rl_serial_baud_ok(cfg->baud))
        return !rl_cli_fail(C, RL_EXIT_FAIL, "%s:%d: serial.baud: %d is not a supported baud rate "
                            "(9600 .. 921600)", config, cfg->baud_line, cfg->baud);
    if ((cfg->cam_width && cfg->cam_width != s->calib.width) ||
        (cfg->cam_height && cfg->cam_height != s->calib.height))
        return !rl_cli_fail(C, RL_EXIT_FAIL, "%s: camera is %dx%d but %s is for %dx%d", config,
                            cfg->cam_width, cfg->cam_height, cfg->calibration, s->calib.width,
                            s->calib.height);
    if (s->map.count == 0 || !(s->map.ceiling_height > s->mount.z))
        return !rl_cli_fail(C, RL_EXIT_FAIL, "%s: %s", cfg->map,
                            s->map.count == 0 ? "the map has no landmarks"
                                              : "the camera is not below the ceiling");
    rl_cam_defaults(&s->cam);
    s->cam.backend = cfg->cam_backend;
    s->cam.device = cfg->cam_device;
    /* the calibration's size (a configured one was checked to be it above):
     * a device streams it, a PNG frame of another size is skipped */
    s->cam.width = s->calib.width;
    s->cam.height = s->calib.height;
    s->cam.rate = cfg->cam_rate;
    s->cam.loop = cfg->cam_loop;
    s->cam.exposure_us = (int)(cfg->cam_exposure_us + 0.5);
    s->cam.gain = cfg->cam_gain;
    if (strcmp(cfg->cam_backend, "png") == 0) {
        /* files do not appear later, as a device may: a missing or empty
         * sequence is a configuration error */
        rl_cam probe;
        if (rl_cam_open(&probe, &s->cam, err, sizeof err) != RL_OK)
            return !rl_cli_fail(C, RL_EXIT_FAIL, "%s: camera.device: %s", config, err);
        rl_cam_close(&probe);
    }
    return 1;
}

/* The recognizer for the map's landmarks at the calibration's size. */
static int make_recognizer(const char *C, const fw_setup *s, rl_heap_recog *hr)
{
    rl_recog_config rc;
    rl_err e;
    rl_recog_defaults(&rc);
    rc.local = s->cfg.local;
    rc.min_score = s->cfg.min_score;
    rc.local_min_score = s->cfg.local_min_score;
    rc.gamma = s->cfg.gamma;
    rl_heap_recog_init_map(hr, &rc, &s->map);
    if ((e = rl_heap_recog_prepare(hr, s->calib.width, s->calib.height)) != RL_OK)
        return !rl_cli_fail(C, RL_EXIT_FAIL, "cannot prepare recognition for %dx%d: %s",
                            s->calib.width, s->calib.height, rl_strerror(e));
    return 1;
}

static void wire_io(const fw_setup *s, out_ctx *octx, const char *prefix, rl_run_io *io)
{
    octx->path = s->cfg.serial;
    octx->prefix = prefix;
    octx->baud = s->cfg.baud;
    memset(io, 0, sizeof *io);
    io->cam = &s->cam;
    io->out.open = out_open;
    io->out.write = out_write;
    io->out.close = out_close;
    io->out.why = out_why;
    io->out.ctx = octx;
    io->clock = rl_clock_system();
    io->log = log_line;
    io->log_ctx = (void *)prefix;
}

static void on_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL); /* a closed terminal or a service reload: stop with the summary */
    signal(SIGPIPE, SIG_IGN); /* a vanished reader is a write error, not a death */
}

static void run_loop(rl_runner *runner, long max_frames)
{
    while (!stop_flag) {
        if (rl_run_step(runner) == RL_ENOTFOUND)
            break;
        if (max_frames > 0 && runner->frames >= max_frames)
            break;
    }
    rl_run_close(runner);
}

/* --config and --frames; 0 to go on, else the exit code (--help: 0 with
 * *done set). */
static int parse_args(const char *C, const char *prefix, int argc, char **argv,
                      const char **config, long *max_frames, int *probe, const char **record, int *done)
{
    static const struct option opts[] = {{"config", required_argument, 0, 'c'},
                                         {"frames", required_argument, 0, 'n'},
                                         {"probe", no_argument, 0, 'p'},
                                         {"record", required_argument, 0, 'R'},
                                         {"help", no_argument, 0, 'h'},
                                         {0, 0, 0, 0}};
    char hint[160];
    int c, v;
    *done = 0;
    optind = 1;
    snprintf(hint, sizeof hint, "see '%s --help'", prefix);
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        switch (c) {
        case 'c': *config = optarg; break;
        case 'n':
            if (!rl_cli_int(C, "--frames", optarg, 0, 2147483647L, &v))
                return RL_EXIT_USAGE;
            *max_frames = v;
            break;
        case 'p': *probe = 1; break;
        case 'R': *record = optarg; break;
        case 'h': printf(run_help, prefix); *done = 1; return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (optind < argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "unexpected argument '%s' (%s)", argv[optind], hint);
    if (*config == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--config FILE is required (%s)", hint);
    return 0;
}

static void print_line(void *ctx, const char *text)
{
    (void)ctx;
    printf("%s\n", text);
}

/* --probe: the configuration's camera described; only ringloc.yaml is
 * read, so a camera can be looked at before the rest is set up. */
static int probe_camera(const char *C, const char *config)
{
    static rl_runcfg cfg;
    rl_cam_config cc;
    char err[768];
    if (rl_runcfg_load(config, &cfg, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    rl_cam_defaults(&cc);
    cc.backend = cfg.cam_backend;
    cc.device = cfg.cam_device;
    cc.width = cfg.cam_width;
    cc.height = cfg.cam_height;
    cc.rate = cfg.cam_rate;
    cc.loop = cfg.cam_loop;
    if (rl_cam_probe(&cc, print_line, NULL, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "camera: %s", err);
    return 0;
}

typedef struct {
    rl_record rec;
    const char *prefix;
} record_ctx;

/* Each frame offered to the recorder; when recording stopped (a full
 * disk, the folder gone, max_mb) the log says so then, once. */
static void record_frame(void *ctx, const rl_cam_frame *f)
{
    record_ctx *rc = (record_ctx *)ctx;
    const char *news;
    rl_record_offer(&rc->rec, &f->img, f->index, f->t_us);
    if ((news = rl_record_news(&rc->rec)) != NULL)
        log_line((void *)rc->prefix, news);
}

int rl_fw_main(const char *C, int argc, char **argv)
{
    static fw_setup s;
    static rl_result res;
    static rl_runner runner;
    static out_ctx octx;
    static char prefix[128];
    rl_heap_recog hr;
    rl_heap_place hp;
    rl_run_io io;
    const char *config = NULL;
    long max_frames = 0;
    static record_ctx rec;
    const char *record = NULL;
    int rc, done, probe = 0, recording = 0;

    rl_cli_prefix(C, prefix, sizeof prefix);
    if ((rc = parse_args(C, prefix, argc, argv, &config, &max_frames, &probe, &record, &done)) != 0 || done)
        return rc;
    if (probe)
        return probe_camera(C, config);
    /* start-up: everything that can fail in configuration fails here, once */
    if (!load_setup(C, config, &s) || !make_recognizer(C, &s, &hr))
        return RL_EXIT_FAIL;
    if ((rc = rl_heap_place_init(&hp, &s.map, NULL)) != RL_OK) {
        rl_heap_recog_free(&hr);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: the place index: %s", s.cfg.map, rl_strerror((rl_err)rc));
    }
    wire_io(&s, &octx, prefix, &io);
    if (record != NULL)
        snprintf(s.cfg.record_dir, sizeof s.cfg.record_dir, "%s", record);
    if (s.cfg.record_dir[0]) {
        rl_record_config rcc;
        char err[512];
        rl_record_defaults(&rcc);
        rcc.dir = s.cfg.record_dir;
        rcc.every = s.cfg.record_every;
        rcc.max_mb = s.cfg.record_max_mb;
        if (rl_record_start(&rec.rec, &rcc, s.calib.width, s.calib.height, err, sizeof err) != RL_OK) {
            rl_heap_recog_free(&hr);
            rl_heap_place_free(&hp);
            return rl_cli_fail(C, RL_EXIT_FAIL, "record: %s", err);
        }
        rec.prefix = prefix;
        fprintf(stderr, "%s: recording one frame in %d to %s\n", prefix, rec.rec.every, rec.rec.dir);
        io.frame = record_frame;
        io.frame_ctx = &rec;
        recording = 1;
    }
    rl_run_init(&runner, &io, hr.rec, &s.calib, &s.map, &s.mount, &res);
    runner.offsets = s.cfg.offsets[0] ? &s.offsets : NULL;
    runner.place = hp.pl;
    runner.log_interval_us = (uint64_t)(s.cfg.log_interval * 1e6);
    if (s.cfg.cam_rate > 0)
        runner.timeout_ms = (int)(3000.0 / s.cfg.cam_rate) > 200 ? (int)(3000.0 / s.cfg.cam_rate) : 200;
    on_signals();
    fprintf(stderr, "%s: %s camera %s, %d landmarks in %s%s, poses to %s at %d baud\n", prefix,
            s.cfg.cam_backend, s.cfg.cam_device, s.map.count, s.cfg.map,
            hp.pl ? " (ids repeat: places found from constellations)" : "", s.cfg.serial, s.cfg.baud);
    run_loop(&runner, max_frames);
    fprintf(stderr, "%s: %ld frames, %ld poses, %ld status frames, %ld camera errors, "
                    "%ld bad frames, %ld timeouts, %ld serial errors, %ld frames dropped%s\n",
            prefix, runner.frames, runner.poses, runner.statuses, runner.camera_errors,
            runner.bad_frames, runner.camera_timeouts, runner.serial_errors, runner.dropped,
            stop_flag ? (octx.s.broken ? " (standard output closed)" : " (stopped by signal)") : "");
    if (recording) {
        const char *news;
        rl_record_stop(&rec.rec);
        /* a stop the writer met after the last frame is logged now */
        if ((news = rl_record_news(&rec.rec)) != NULL)
            log_line((void *)prefix, news);
        fprintf(stderr, "%s: recorded %ld frames (%.1f MB) to %s, %ld skipped while the disk was behind%s%s\n",
                prefix, rec.rec.saved, rec.rec.bytes / 1e6, rec.rec.dir, rec.rec.skipped,
                rec.rec.error[0] ? "; " : "", rec.rec.error);
    }
    if (hp.pl)
        fprintf(stderr, "%s: %ld poses tracked from the last one, %ld frames ambiguous\n", prefix, runner.tracked,
                runner.ambiguous);
    rl_heap_recog_free(&hr);
    rl_heap_place_free(&hp);
    if (runner.poses + runner.statuses == 0) /* nothing ever reached the line: a failed run */
        return rl_cli_fail(C, RL_EXIT_FAIL, "no frame reached %s", s.cfg.serial);
    return 0;
}
