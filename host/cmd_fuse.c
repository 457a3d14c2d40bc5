/* ringloc fuse: an odometry log and a pose-frame stream through rl_fuse,
 * the fused pose at a chosen rate as JSON lines (replaying a drive, tuning
 * the filter). */
#define _XOPEN_SOURCE 600
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "cmd_fuse_live.h"
#include "rl_cli.h"
#include "rl_clock.h"
#include "rl_cmd.h"
#include "rl_fuse.h"
#include "rl_infile.h"
#include "rl_odolog.h"
#include "rl_outfile.h"
#include "rl_serial.h"
#include "rl_stop.h"

static const char *fuse_help =
    "usage: ringloc fuse --odometry LOG [--arrivals FILE | --time-offset S] [--rate 100]\n"
    "                    [--baud 115200] [--track 0.33] [--wheel-noise 0.0002] [--out FILE]\n"
    "                    [--fates FILE] FRAMES\n\n"
    "Fuse a robot's odometry with ringloc's pose frames (rl_fuse: each frame at its capture\n"
    "time, the odometry since replayed, implausible frames rejected, the odometry's wheel\n"
    "and track scales learned) and print the fused pose at RATE per second, one JSON line\n"
    "per tick from the first frame's arrival to the log's last sample:\n"
    "  {\"t\": 12.340, \"x\": 1.2034, \"y\": -0.5021, \"yaw\": 0.31204, \"sigma\": {\"x\": 0.0004,\n"
    "   \"y\": 0.0003, \"yaw\": 0.00021}, \"scale\": 1.0098, \"turn\": 0.9903, \"v\": 0.9981,\n"
    "   \"w\": 1.6612}\n"
    "(scale, turn: the odometry's learned scales; v, w: the fused speed, m/s, and turn rate,\n"
    "rad/s)\n"
    "and on exit what became of the frames (applied, rejected, ...).\n\n"
    "  --odometry LOG  one sample a line, 't x y yaw' (s, m, m, rad), on the controller's clock;\n"
    "                  '-': live, from standard input as the robot drives, its times on\n"
    "                  CLOCK_MONOTONIC, with FRAMES a serial device or pty: the fused pose\n"
    "                  printed at each odometry sample as it comes (until the odometry\n"
    "                  ends, the device closes, or Ctrl-C)\n"
    "  FRAMES          pose frames as 'ringloc monitor' reads them: a recorded file (see\n"
    "                  --arrivals), or a serial device or pty, read until it closes (or\n"
    "                  Ctrl-C), each frame stamped on arrival with this computer's monotonic\n"
    "                  clock, which the odometry log must then share; the capture times are\n"
    "                  then found from the frames' time_ms (the camera board's clock) and\n"
    "                  the arrivals, as a controller does (rl_fuse_msg_add)\n"
    "  --arrivals FILE when each recorded frame arrived: one line per pose frame of FRAMES,\n"
    "                  in order, 'seq arrival_seconds' on the odometry's clock ('ringloc\n"
    "                  monitor --arrivals' writes it): the drive replayed as the controller\n"
    "                  saw it. Without it, a recorded frame's capture time is its time_ms\n"
    "                  on the odometry's clock plus --time-offset S\n"
    "  --fates FILE    one line per frame as its fate is decided: 'seq capture_s fate d2\n"
    "                  clock_reset' (fate: applied, rejected, restarted (the robot was\n"
    "                  carried), too-old, out-of-order, lost, untimed (the board's clock\n"
    "                  not yet known); d2: the squared Mahalanobis distance)\n"
    "  --rate HZ       ticks a second (1 .. 1000)\n"
    "  --track M       the odometry's nominal track width (m)\n"
    "  --wheel-noise M each wheel's travel error after 1 m (m); rl_fuse.h has the rest\n"
    "  --out FILE      write the JSON lines there (whole or not at all) instead of stdout\n";

typedef struct {
    double arrival; /* when it can be known, on the controller's clock */
    rl_fuse_frame fr;
    rl_msg m;       /* as decoded */
} timed_frame;

typedef struct {
    timed_frame *f;
    size_t n, cap;
    unsigned long status, damaged;
    int by_clock;   /* capture times from time_ms and the arrivals (rl_fuse_msg_add) */
} frame_list;

static int push(frame_list *l, const timed_frame *tf)
{
    if (l->n == l->cap) {
        size_t nc = l->cap ? 2 * l->cap : 256;
        timed_frame *nf = realloc(l->f, nc * sizeof *nf);
        if (nf == NULL)
            return -1;
        l->f = nf;
        l->cap = nc;
    }
    l->f[l->n++] = *tf;
    return 0;
}

/* Bytes into frames: a device's stamped on arrival, a file's from time_ms. */
static int take(frame_list *l, rl_decoder *d, const uint8_t *buf, size_t n, int live, int baud,
                double offset)
{
    size_t i;
    rl_msg m;
    for (i = 0; i < n; i++) {
        timed_frame tf;
        if (!rl_decoder_push(d, buf[i], &m))
            continue;
        if (m.type != RL_PACKET_POSE) {
            l->status++;
            continue;
        }
        tf.m = m;
        if (live) {
            tf.arrival = rl_clock_now_s();
            rl_fuse_frame_from_msg(&m, tf.arrival, baud, &tf.fr);
        } else {
            double delay;
            rl_fuse_frame_from_msg(&m, 0, baud, &tf.fr); /* t = -(latency + line time) */
            delay = -tf.fr.t;
            tf.fr.t = m.time_ms * 1e-3 + offset;
            tf.arrival = tf.fr.t + delay;
        }
        if (push(l, &tf) != 0)
            return -1;
    }
    return 0;
}

/* The arrivals of l's frames from FILE ('seq arrival_seconds', one line a
 * pose frame, in order): 0, or an exit code after the error line. */
static int read_arrivals(const char *C, const char *path, frame_list *l)
{
    char line[256], rest;
    size_t k = 0;
    long no = 0;
    unsigned seq;
    double a;
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: %s", path, strerror(errno));
    while (fgets(line, sizeof line, f)) {
        no++;
        if (sscanf(line, " %c", &rest) != 1 || rest == '#')
            continue;
        if (sscanf(line, "%u %lf %c", &seq, &a, &rest) != 2 || !isfinite(a) || seq > 65535) {
            fclose(f);
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s:%ld: expected 'seq arrival_seconds'", path, no);
        }
        if (k >= l->n || l->f[k].m.seq != seq) {
            fclose(f);
            if (k >= l->n)
                return rl_cli_fail(C, RL_EXIT_FAIL, "%s:%ld: more arrivals than the %lu pose frames", path,
                                   no, (unsigned long)l->n);
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s:%ld: sequence %u, but pose frame %lu is %u: not "
                               "this recording's arrivals?", path, no, seq, (unsigned long)k + 1, l->f[k].m.seq);
        }
        l->f[k++].arrival = a;
    }
    fclose(f);
    if (k != l->n)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: %lu arrivals for %lu pose frames", path, (unsigned long)k,
                           (unsigned long)l->n);
    l->by_clock = 1;
    return 0;
}

/* All the frames of FRAMES: 0, or an exit code after the error line. */
static int read_frames(const char *C, const char *path, int baud, double offset, frame_list *l)
{
    struct stat st;
    rl_decoder d;
    uint8_t buf[4096];
    char err[600];
    int fd, live = 0, seen = 0;
    rl_serial dev;
    rl_err e;
    rl_decoder_init(&d);
    if (stat(path, &st) == 0 && S_ISCHR(st.st_mode)) {
        if (rl_serial_open(&dev, path, baud, 0, err, sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
        fd = dev.fd;
        live = dev.is_tty;
    } else if ((fd = rl_infile_open(path, "a file of pose frames", &e, err, sizeof err)) < 0)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    while (!rl_stop_requested()) {
        ssize_t n;
        if (live) {
            struct pollfd p;
            p.fd = fd;
            p.events = POLLIN;
            if (poll(&p, 1, 200) <= 0)
                continue;
        }
        n = read(fd, buf, sizeof buf);
        if (n > 0) {
            seen = 1;
            if (take(l, &d, buf, (size_t)n, live, baud, offset) != 0) {
                close(fd);
                return rl_cli_fail(C, RL_EXIT_FAIL, "%s: out of memory", path);
            }
            continue;
        }
        if (n < 0 && (errno == EINTR || errno == EAGAIN))
            continue;
        if (live && n < 0 && errno == EIO && !seen) { /* a pty whose writer has not come yet */
            usleep(50000);
            continue;
        }
        if (n < 0 && !(live && errno == EIO)) {
            int en = errno;
            close(fd);
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s: %s", path, strerror(en));
        }
        break;
    }
    close(fd);
    l->damaged = d.bad;
    l->by_clock = live;
    return 0;
}

/* The longest odometry log replayed (a day): longer, its times jump. */
#define FUSE_MAX_SPAN 86400.0

/* The controller's loop: odometry and frames in the order they become
 * known, the pose at every tick, until SIGINT or SIGTERM; returns the
 * ticks written, *unfed the frames that arrived after the log's end. */
static long replay(rl_fuse *f, const rl_odolog *log, const frame_list *l, double rate, int baud, FILE *out,
                   FILE *fates, size_t *unfed)
{
    size_t io = 0, jf = 0;
    unsigned long seen = 0;
    long k, ticks = 0, nt = (long)floor((log->s[log->n - 1].t - log->s[0].t) * rate + 1e-9);
    for (k = 0; k <= nt && !rl_stop_requested(); k++) {
        double t = log->s[0].t + k / rate;
        rl_fuse_pose p;
        while ((io < log->n && log->s[io].t <= t) || (jf < l->n && l->f[jf].arrival <= t)) {
            if (jf >= l->n || (io < log->n && log->s[io].t <= l->f[jf].arrival)) {
                const rl_odosample *s = &log->s[io++];
                (void)!rl_fuse_odometry(f, s->t, s->x, s->y, s->yaw); /* times checked on loading */
            } else if (l->by_clock) {
                (void)!rl_fuse_msg_add(f, &l->f[jf].m, l->f[jf].arrival, baud); /* in f->stats */
                jf++;
            } else
                (void)!rl_fuse_frame_add(f, &l->f[jf++].fr); /* outcomes counted in f->stats */
            rl_fuse_log_fate(f, &seen, fates);
        }
        if (rl_fuse_pose_at(f, t, &p) == RL_OK) {
            rl_fuse_print_pose(out, &p);
            ticks++;
        }
    }
    *unfed = l->n - jf;
    return ticks;
}

/* The filter, its history HISTORY_S s of the log's odometry (at its mean
 * rate); 0, or an exit code after the error line. */
#define HISTORY_S 5.0
static int start_filter(const char *C, rl_fuse *f, const rl_fuse_config *cfg, const rl_odolog *log,
                        rl_fuse_entry **hist)
{
    double span = log->s[log->n - 1].t - log->s[0].t;
    size_t n = rl_fuse_history_count(HISTORY_S, span > 0 ? (log->n - 1) / span : 1);
    if (n == 0 || (*hist = malloc(n * sizeof **hist)) == NULL)
        return rl_cli_fail(C, RL_EXIT_FAIL, "no memory for %.0f s of odometry", HISTORY_S);
    if (rl_fuse_init(f, cfg, *hist, n) != RL_OK) {
        free(*hist);
        *hist = NULL;
        return rl_cli_fail(C, RL_EXIT_USAGE, "the filter's settings are out of range");
    }
    return 0;
}

/* --odometry -: stdin's odometry and a device's frames as they come
 * (cmd_fuse_live.c); 0, or an exit code after the error line. */
#define LIVE_HZ 200.0 /* the fastest odometry the live history is sized for */
static int live(const char *C, const rl_fuse_config *cfg, const char *dev_path, int baud, const char *fates_path)
{
    static rl_fuse f;
    size_t n = rl_fuse_history_count(HISTORY_S, LIVE_HZ);
    rl_fuse_entry *hist = malloc(n * sizeof *hist);
    unsigned long frames = 0;
    struct stat st;
    rl_serial dev;
    rl_outfile fo;
    char err[1200];
    int rc;
    if (hist == NULL)
        return rl_cli_fail(C, RL_EXIT_FAIL, "no memory for %.0f s of odometry", HISTORY_S);
    if (rl_fuse_init(&f, cfg, hist, n) != RL_OK) {
        free(hist);
        return rl_cli_fail(C, RL_EXIT_USAGE, "the filter's settings are out of range");
    }
    if (stat(dev_path, &st) != 0 || !S_ISCHR(st.st_mode)) {
        int en = errno;
        free(hist);
        if (!S_ISCHR(st.st_mode) && en != ENOENT)
            return rl_cli_fail(C, RL_EXIT_USAGE, "%s: --odometry - reads a serial device or pty, not a file",
                               dev_path);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: %s", dev_path, strerror(en));
    }
    if (rl_serial_open(&dev, dev_path, baud, 0, err, sizeof err) != RL_OK) {
        free(hist);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    if (fates_path && rl_outfile_open(&fo, fates_path, err, sizeof err) != RL_OK) {
        rl_serial_close(&dev);
        free(hist);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    rl_stop_on_signals(0);
    rc = rl_fuse_live(C, &f, 0, dev.fd, dev_path, baud, stdout, fates_path ? fo.f : NULL, &frames);
    rl_serial_close(&dev);
    free(hist);
    if (fates_path && (rc != 0 ? (rl_outfile_abort(&fo), 0) : rl_outfile_commit(&fo, err, sizeof err) != RL_OK))
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (rc == 0)
        fprintf(stderr, "ringloc fuse: %lu pose frames: %lu applied, %lu rejected, %lu restarts (carried), "
                        "%lu before the board's clock was known, %lu clock resets\n", frames, f.stats.applied,
                f.stats.rejected, f.stats.recoveries, f.stats.untimed, f.stats.clock_resets);
    return rc;
}

static int by_arrival(const void *a, const void *b)
{
    double x = ((const timed_frame *)a)->arrival, y = ((const timed_frame *)b)->arrival;
    return (x > y) - (x < y);
}

/* the options into cfg and the rest; 0, or an exit code after the error line */
static int options(const char *C, int argc, char **argv, rl_fuse_config *cfg, const char **odo,
                   const char **out, double *rate, int *baud, double *offset, const char **arrivals,
                   const char **fates)
{
    static const struct option opts[] = {
        {"arrivals", required_argument, 0, 'a'}, {"fates", required_argument, 0, 'F'},
        {"odometry", required_argument, 0, 'o'}, {"rate", required_argument, 0, 'r'},
        {"baud", required_argument, 0, 'b'},     {"time-offset", required_argument, 0, 'T'},
        {"track", required_argument, 0, 't'},    {"wheel-noise", required_argument, 0, 'w'},
        {"out", required_argument, 0, 'O'},      {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    int c;
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        int ok = 1;
        switch (c) {
        case 'o': *odo = optarg; break;
        case 'a': *arrivals = optarg; break;
        case 'F': *fates = optarg; break;
        case 'O': *out = optarg; break;
        case 'r': ok = rl_cli_double(C, "--rate", optarg, 1, 1000, rate); break;
        case 'T': ok = rl_cli_double(C, "--time-offset", optarg, -1e9, 1e9, offset); break;
        case 't': ok = rl_cli_double(C, "--track", optarg, 0.01, 10, &cfg->track); break;
        case 'w': ok = rl_cli_double(C, "--wheel-noise", optarg, 0, 1, &cfg->wheel_noise); break;
        case 'b':
            ok = rl_cli_int(C, "--baud", optarg, 0, 10000000, baud);
            if (ok && !rl_serial_baud_ok(*baud))
                return rl_cli_fail(C, RL_EXIT_USAGE, "--baud: %d is not a supported baud rate "
                                   "(9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600)", *baud);
            break;
        case 'h': fputs(fuse_help, stdout); return -1;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
        if (!ok)
            return RL_EXIT_USAGE;
    }
    if (*odo == NULL || optind != argc - 1)
        return rl_cli_fail(C, RL_EXIT_USAGE, "give --odometry LOG and one FRAMES file or device (see --help)");
    return 0;
}

int rl_cmd_fuse(int argc, char **argv)
{
    const char *C = "fuse", *odo = NULL, *out_path = NULL, *arrivals = NULL, *fates_path = NULL;
    rl_outfile fo;
    static rl_fuse f;
    rl_fuse_entry *hist = NULL;
    rl_fuse_config cfg;
    double rate = 100, offset = 0;
    int baud = 115200, rc;
    long ticks;
    size_t unfed = 0;
    rl_odolog log;
    frame_list l;
    rl_outfile o;
    char err[1200];
    FILE *out = stdout;
    rl_fuse_defaults(&cfg);
    if ((rc = options(C, argc, argv, &cfg, &odo, &out_path, &rate, &baud, &offset, &arrivals, &fates_path)) != 0)
        return rc < 0 ? 0 : rc;
    if (strcmp(odo, "-") == 0)
        return live(C, &cfg, argv[optind], baud, fates_path);
    if (rl_odolog_load(odo, &log, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (!(log.s[log.n - 1].t - log.s[0].t <= FUSE_MAX_SPAN)) {
        double span = log.s[log.n - 1].t - log.s[0].t;
        rl_odolog_free(&log);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: its times span %.3g s, more than a day: do they jump?", odo, span);
    }
    if ((rc = start_filter(C, &f, &cfg, &log, &hist)) != 0) {
        rl_odolog_free(&log);
        return rc;
    }
    rl_stop_on_signals(0);
    memset(&l, 0, sizeof l);
    if ((rc = read_frames(C, argv[optind], baud, offset, &l)) != 0) {
        rl_odolog_free(&log);
        free(l.f);
        free(hist);
        return rc;
    }
    if (l.n == 0 || (arrivals && (rc = read_arrivals(C, arrivals, &l)) != 0)) {
        rl_odolog_free(&log);
        free(l.f);
        free(hist);
        if (l.n > 0)
            return rc;
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: no pose frames (%lu status frames, %lu damaged)",
                           argv[optind], l.status, l.damaged);
    }
    qsort(l.f, l.n, sizeof *l.f, by_arrival);
    if ((out_path && rl_outfile_open(&o, out_path, err, sizeof err) != RL_OK) ||
        (fates_path && rl_outfile_open(&fo, fates_path, err, sizeof err) != RL_OK &&
         (!out_path || (rl_outfile_abort(&o), 1)))) {
        rl_odolog_free(&log);
        free(l.f);
        free(hist);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    if (out_path)
        out = o.f;
    ticks = replay(&f, &log, &l, rate, baud, out, fates_path ? fo.f : NULL, &unfed);
    rl_odolog_free(&log);
    free(l.f);
    free(hist);
    if (ticks == 0) { /* the user's old files stay as they were */
        if (out_path)
            rl_outfile_abort(&o);
        if (fates_path)
            rl_outfile_abort(&fo);
        return rl_cli_fail(C, RL_EXIT_FAIL, "no pose: %s covers no time the frames could be fused in", odo);
    }
    if (fates_path && rl_outfile_commit(&fo, err, sizeof err) != RL_OK) {
        if (out_path)
            rl_outfile_abort(&o);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    if (out_path && rl_outfile_commit(&o, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    fprintf(stderr, "ringloc fuse: %ld poses; %lu pose frames: %lu applied, %lu rejected, %lu restarts "
                    "(carried), %lu older than the odometry kept, %lu out of order, %lu before the board's "
                    "clock was known, %lu clock resets, %lu past the odometry's end; %lu status frames, "
                    "%lu damaged\n",
            ticks, (unsigned long)l.n, f.stats.applied, f.stats.rejected, f.stats.recoveries,
            f.stats.too_old, f.stats.out_of_order, f.stats.untimed, f.stats.clock_resets,
            f.stats.waiting_lost + (unsigned long)f.has_waiting + (unsigned long)unfed, l.status, l.damaged);
    return 0;
}
