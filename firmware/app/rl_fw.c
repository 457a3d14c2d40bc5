/* The firmware: frames in from the camera, pose frames out on the serial
 * line, until SIGINT, SIGTERM or SIGHUP (or the end of a PNG sequence). */
#include <getopt.h>
#include <stdio.h>
#include <string.h>
#include "rl_fw.h"

#include "rl_cli.h"
#include "rl_fw_side.h"
#include "rl_notify.h"
#include "rl_listen.h"
#include "rl_packet_sink.h"
#include "rl_record.h"
#include "rl_stop.h"
#include "rl_run.h"
#include "rl_runcfg.h"
#include "rl_serial.h"
#include "rl_clock.h"

static const char *run_help =
    "usage: %s --config ringloc.yaml [--frames N] [--record DIR] [--http ADDR:PORT] [--probe]\n"
    "       [--no-track]\n\n"
    "The firmware: grab frames from the camera, recognize landmarks, compute the\n"
    "robot's pose and send it as ARCOS-framed pose frames on the serial line (a\n"
    "status frame when there is no pose). Camera and serial faults are survived:\n"
    "the device is reopened with backoff and status frames say what happened.\n"
    "Stops on SIGINT, SIGTERM or SIGHUP, at the end of a PNG sequence, or after N\n"
    "frames.\n"
    "Logs go to standard error, repeated lines at most every log_interval s.\n"
    "See rl_runcfg.h or the README for the configuration file.\n\n"
    "  --frames N   stop after N frames\n"
    "  --record DIR save one frame in record.every (default 10) as PNG into DIR,\n"
    "               with DIR/frames.txt (name, capture time ms) for 'ringloc survey'\n"
    "               or playing back; at most record.max_mb (1000) on disk\n"
    "  --http ADDR:PORT  a live web view: the camera image with the landmarks found\n"
    "               and why others were not, the map drawn into it, focus, the map,\n"
    "               the pose, faults with their causes, lossless snapshots (read-only\n"
    "               but for starting and stopping recording; http.token in the\n"
    "               file asks for a token; on an address beyond 127.0.0.1 and ::1\n"
    "               without one, a token is made for the run and printed; a browser\n"
    "               asks for it as a password: docs/view.md)\n"
    "  --probe      list what the configured camera offers (formats, sizes,\n"
    "               controls) and exit\n"
    "  --no-track   read every frame in full whatever recognition.track_every\n"
    "               says (the default: tracking windows, read only round where\n"
    "               the map's landmarks must be once placed, are asked for with\n"
    "               recognition.track_every: N, a full frame every Nth:\n"
    "               docs/tracking.md)\n\n"
    "Recording and the web view never stop the pose frames: one that cannot start\n"
    "(a port taken, an address not there yet, a read-only or full folder) is said\n"
    "in one line and tried again every 5 s. Under systemd (Type=notify) the\n"
    "firmware says READY=1 and pings the watchdog while frames are recognized.\n"
    "See docs/service.md.\n";

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
    if (o->s.broken && !rl_stop_requested()) {
        fprintf(stderr, "%s: serial: standard output closed (broken pipe); stopping\n", o->prefix);
        rl_stop_request();
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
    rl_site site;
    rl_cam_config cam;
} fw_setup;

/* The camera the configuration names, at the calibration's size (a
 * configured one was checked to be it): a device streams it, a PNG frame
 * of another size is skipped. */
static void camera_config(const rl_runcfg *cfg, const rl_calib *calib, rl_cam_config *cc)
{
    rl_cam_defaults(cc);
    cc->backend = cfg->cam_backend;
    cc->device = cfg->cam_device;
    cc->width = calib ? calib->width : cfg->cam_width;
    cc->height = calib ? calib->height : cfg->cam_height;
    cc->rate = cfg->cam_rate;
    cc->loop = cfg->cam_loop;
    cc->exposure_us = (int)(cfg->cam_exposure_us + 0.5);
    cc->gain = cfg->cam_gain;
    cc->readout_us = (int)(cfg->cam_readout_ms * 1000 + 0.5);
    cc->stamp = strcmp(cfg->cam_stamp, "exposure_start") == 0 ? RL_CAM_STAMP_EXPOSURE_START
                : strcmp(cfg->cam_stamp, "frame_start") == 0  ? RL_CAM_STAMP_FRAME_START
                : strcmp(cfg->cam_stamp, "frame_end") == 0    ? RL_CAM_STAMP_FRAME_END
                                                              : RL_CAM_STAMP_AUTO;
}

/* Load and check every file; one error line and 0 on failure. */
static int load_setup(const char *C, const char *config, fw_setup *s)
{
    char err[768], size_from[600];
    rl_runcfg *cfg = &s->cfg;
    rl_site_files files;
    if (rl_runcfg_load(config, cfg, err, sizeof err) != RL_OK)
        return !rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (!rl_serial_baud_ok(cfg->baud))
        return !rl_cli_fail(C, RL_EXIT_FAIL, "%s:%d: serial.baud: %d is not a supported baud rate "
                            "(9600 .. 921600)", config, cfg->baud_line, cfg->baud);
    snprintf(size_from, sizeof size_from, "%s: camera.width, camera.height", config);
    rl_site_files_init(&files);
    files.calibration = cfg->calibration;
    files.map = cfg->map;
    files.robot = cfg->robot;
    files.offsets = cfg->offsets;
    files.width = cfg->cam_width;
    files.height = cfg->cam_height;
    files.size_from = size_from;
    if (rl_site_load(&s->site, &files, err, sizeof err) != RL_OK)
        return !rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    camera_config(cfg, &s->site.calib, &s->cam);
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

/* The recognizer for the map's landmarks at the calibration's size, and
 * the place index of a map that repeats ids. */
static int prepare_site(const char *C, fw_setup *s)
{
    rl_recog_config rc;
    char err[768];
    rl_recog_defaults(&rc);
    rc.local = s->cfg.local;
    rc.min_score = s->cfg.min_score;
    rc.local_min_score = s->cfg.local_min_score;
    rc.gamma = s->cfg.gamma;
    if (rl_site_prepare(&s->site, &rc, err, sizeof err) != RL_OK)
        return !rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    return 1;
}

/* What watches the loop besides the serial line: the side features and
 * systemd's watchdog, pinged for frames recognized only. */
typedef struct {
    rl_fw_side *side;
    rl_notify notify;
} fw_watch;

static void fw_observe(void *ctx, const rl_run_report *rep)
{
    fw_watch *w = (fw_watch *)ctx;
    rl_fw_side_observe(w->side, rep);
    if (rep->event == RL_RUN_FRAME)
        rl_notify_alive(&w->notify, rep->sent_us);
}

static void wire_io(const fw_setup *s, out_ctx *octx, rl_packet_sink *ps, fw_watch *watch, rl_run_camera *cam,
                    const char *prefix, rl_run_io *io)
{
    rl_packet_line line;
    octx->path = s->cfg.serial;
    octx->prefix = prefix;
    octx->baud = s->cfg.baud;
    line.open = out_open;
    line.write = out_write;
    line.close = out_close;
    line.why = out_why;
    line.ctx = octx;
    memset(io, 0, sizeof *io);
    io->source = rl_run_camera_source(cam, &s->cam);
    io->sink = rl_packet_sink_make(ps, &line);
    io->observe = fw_observe;
    io->observe_ctx = watch;
    io->clock = rl_clock_system();
    io->log = log_line;
    io->log_ctx = (void *)prefix;
}

static void run_loop(rl_runner *runner, long max_frames)
{
    while (!rl_stop_requested()) {
        if (rl_run_step(runner) == RL_ENOTFOUND)
            break;
        if (max_frames > 0 && rl_run_counts_of(runner)->frames >= max_frames)
            break;
    }
    rl_run_close(runner);
}

/* --config and --frames; 0 to go on, else the exit code (--help: 0 with
 * *done set). */
static int parse_args(const char *C, const char *prefix, int argc, char **argv,
                      const char **config, long *max_frames, int *probe, const char **record,
                      const char **http, int *no_track, int *done)
{
    static const struct option opts[] = {{"config", required_argument, 0, 'c'},
                                         {"frames", required_argument, 0, 'n'},
                                         {"probe", no_argument, 0, 'p'},
                                         {"record", required_argument, 0, 'R'},
                                         {"http", required_argument, 0, 'H'},
                                         {"no-track", no_argument, 0, 'T'},
                                         {"help", no_argument, 0, 'h'},
                                         {0, 0, 0, 0}};
    char hint[160], why[160];
    int c, v;
    rl_listen l;
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
        case 'T': *no_track = 1; break;
        case 'R': *record = optarg; break;
        case 'H':
            if (rl_listen_parse(optarg, &l, why, sizeof why) != RL_OK)
                return rl_cli_fail(C, RL_EXIT_USAGE, "--http: %s", why);
            *http = optarg;
            break;
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
    camera_config(&cfg, NULL, &cc);
    if (rl_cam_probe(&cc, print_line, NULL, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "camera: %s", err);
    return 0;
}

/* Recording (--record DIR, or record.dir) and the web view (--http
 * ADDR:PORT, or http.listen) asked for: each tried now, and again from
 * the loop while it cannot start; neither stops the pose frames. */
static void start_side(fw_setup *s, const char *record, const char *http, rl_fw_side *side)
{
    if (record != NULL)
        snprintf(s->cfg.record_dir, sizeof s->cfg.record_dir, "%s", record);
    if (http != NULL)
        snprintf(s->cfg.http_listen, sizeof s->cfg.http_listen, "%s", http);
    side->rcc.dir = s->cfg.record_dir;
    side->rcc.every = s->cfg.record_every;
    side->rcc.max_mb = s->cfg.record_max_mb;
    side->listen = s->cfg.http_listen;
    side->token = s->cfg.http_token;
    side->map = &s->site.map;
    side->site = &s->site;
    side->serial = s->cfg.serial;
    rl_fw_side_start(side, rl_clock_now_us());
}

/* The loop's settings from the configuration. */
static void run_config(const rl_runcfg *cfg, rl_run_config *rc)
{
    rl_run_defaults(rc);
    rc->log_interval_us = (uint64_t)(cfg->log_interval * 1e6);
    if (cfg->cam_rate > 0)
        rc->timeout_ms = (int)(3000.0 / cfg->cam_rate) > 200 ? (int)(3000.0 / cfg->cam_rate) : 200;
    rc->track.full_every = cfg->track_every;
    rc->readout = cfg->cam_readout_ms / 1000.0;
}

static void print_summary(const char *prefix, const rl_run_counts *n, const out_ctx *octx)
{
    fprintf(stderr, "%s: %ld frames, %ld poses, %ld status frames, %ld camera errors, "
                    "%ld bad frames, %ld timeouts, %ld serial errors, %ld frames dropped%s; %ld read by tracking "
                    "windows\n",
            prefix, n->frames, n->poses, n->statuses, n->camera_errors, n->bad_frames, n->camera_timeouts,
            n->sink_errors, n->dropped,
            rl_stop_requested() ? (octx->s.broken ? " (standard output closed)" : " (stopped by signal)") : "",
            n->windowed);
}

int rl_fw_main(const char *C, int argc, char **argv)
{
    static fw_setup s;
    static rl_result res;
    static rl_runner runner;
    static out_ctx octx;
    static rl_packet_sink ps;
    static rl_fw_side side;
    static fw_watch watch;
    static rl_run_camera cam;
    static char prefix[128];
    rl_run_io io;
    rl_run_config rc;
    const char *config = NULL, *record = NULL, *http = NULL;
    long max_frames = 0;
    int code, done, probe = 0, no_track = 0;

    rl_cli_prefix(C, prefix, sizeof prefix);
    if ((code = parse_args(C, prefix, argc, argv, &config, &max_frames, &probe, &record, &http, &no_track, &done)) != 0 ||
        done)
        return code;
    if (probe)
        return probe_camera(C, config);
    /* start-up: everything that can fail in configuration fails here, once */
    if (!load_setup(C, config, &s) || !prepare_site(C, &s))
        return RL_EXIT_FAIL;
    rl_fw_side_init(&side, prefix, &runner, s.site.calib.width, s.site.calib.height);
    watch.side = &side;
    wire_io(&s, &octx, &ps, &watch, &cam, prefix, &io);
    start_side(&s, record, http, &side);
    run_config(&s.cfg, &rc);
    if (no_track)
        rc.track.full_every = 0;
    rl_run_init(&runner, &rc, &io, &s.site, &res);
    /* a closed terminal or a service reload: stop with the summary; a
     * vanished reader of standard output is a write error */
    rl_stop_on_signals(RL_STOP_HUP | RL_STOP_NO_SIGPIPE);
    fprintf(stderr, "%s: %s camera %s, %d landmarks in %s%s, poses to %s at %d baud\n", prefix,
            s.cfg.cam_backend, s.cfg.cam_device, s.site.map.count, s.cfg.map,
            s.site.place.pl ? " (ids repeat: places found from constellations)" : "", s.cfg.serial, s.cfg.baud);
    /* under systemd (Type=notify): ready once everything that can stop
     * the start is behind */
    rl_notify_open(&watch.notify);
    rl_notify_send(&watch.notify, "READY=1");
    run_loop(&runner, max_frames);
    rl_notify_send(&watch.notify, "STOPPING=1");
    print_summary(prefix, rl_run_counts_of(&runner), &octx);
    rl_fw_side_stop(&side);
    rl_notify_close(&watch.notify);
    if (s.site.place.pl)
        fprintf(stderr, "%s: %ld poses tracked from the last one, %ld frames ambiguous\n", prefix,
                rl_run_counts_of(&runner)->tracked, rl_run_counts_of(&runner)->ambiguous);
    rl_site_free(&s.site);
    if (rl_run_counts_of(&runner)->poses + rl_run_counts_of(&runner)->statuses == 0)
        return rl_cli_fail(C, RL_EXIT_FAIL, "no frame reached %s", s.cfg.serial); /* a failed run */
    return 0;
}
