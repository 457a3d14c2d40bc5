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
    "usage: ringloc fuse --odometry LOG [--rate 100] [--baud 115200] [--time-offset S]\n"
    "                    [--track 0.33] [--wheel-noise 0.001] [--out FILE] FRAMES\n\n"
    "Fuse a robot's odometry with ringloc's pose frames (rl_fuse: each frame at its capture\n"
    "time, the odometry since replayed, implausible frames rejected, the odometry's wheel\n"
    "and track scales learned) and print the fused pose at RATE per second, one JSON line\n"
    "per tick from the first frame's arrival to the log's last sample:\n"
    "  {\"t\": 12.340, \"x\": 1.2034, \"y\": -0.5021, \"yaw\": 0.31204, \"sigma\": {\"x\": 0.0004,\n"
    "   \"y\": 0.0003, \"yaw\": 0.00021}, \"scale\": 1.0098, \"turn\": 0.9903}\n"
    "and on exit what became of the frames (applied, rejected, ...).\n\n"
    "  --odometry LOG  one sample a line, 't x y yaw' (s, m, m, rad), on the controller's clock\n"
    "  FRAMES          pose frames as 'ringloc monitor' reads them: a recorded file, whose\n"
    "                  frames' capture time is their time_ms on the controller's clock plus\n"
    "                  --time-offset; or a serial device or pty, read until it closes (or\n"
    "                  Ctrl-C), each frame stamped on arrival with this computer's monotonic\n"
    "                  clock (capture = arrival - latency - the bytes' time at --baud), which\n"
    "                  the odometry log must then share\n"
    "  --rate HZ       ticks a second (1 .. 1000)\n"
    "  --track M       the odometry's nominal track width (m)\n"
    "  --wheel-noise M each wheel's travel error after 1 m (m); rl_fuse.h has the rest\n"
    "  --out FILE      write the JSON lines there (whole or not at all) instead of stdout\n";

typedef struct {
    double arrival; /* when it can be known, on the controller's clock */
    rl_fuse_frame fr;
} timed_frame;

typedef struct {
    timed_frame *f;
    size_t n, cap;
    unsigned long status, damaged;
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
    return 0;
}

static void print_pose(FILE *out, const rl_fuse_pose *p)
{
    fprintf(out, "{\"t\": %.3f, \"x\": %.4f, \"y\": %.4f, \"yaw\": %.5f, \"sigma\": {\"x\": %.4f, "
                 "\"y\": %.4f, \"yaw\": %.5f}, \"scale\": %.4f, \"turn\": %.4f}\n",
            p->t, p->x, p->y, p->yaw, sqrt(p->cov[0][0]), sqrt(p->cov[1][1]), sqrt(p->cov[2][2]),
            p->scale, p->turn);
}

/* The longest odometry log replayed (a day): longer, its times jump. */
#define FUSE_MAX_SPAN 86400.0

/* The controller's loop: odometry and frames in the order they become
 * known, the pose at every tick, until SIGINT or SIGTERM; returns the
 * ticks written, *unfed the frames that arrived after the log's end. */
static long replay(rl_fuse *f, const rl_odolog *log, const frame_list *l, double rate, FILE *out, size_t *unfed)
{
    size_t io = 0, jf = 0;
    long k, ticks = 0, nt = (long)floor((log->s[log->n - 1].t - log->s[0].t) * rate + 1e-9);
    for (k = 0; k <= nt && !rl_stop_requested(); k++) {
        double t = log->s[0].t + k / rate;
        rl_fuse_pose p;
        while ((io < log->n && log->s[io].t <= t) || (jf < l->n && l->f[jf].arrival <= t)) {
            if (jf >= l->n || (io < log->n && log->s[io].t <= l->f[jf].arrival)) {
                const rl_odosample *s = &log->s[io++];
                (void)!rl_fuse_odometry(f, s->t, s->x, s->y, s->yaw); /* times checked on loading */
            } else
                (void)!rl_fuse_frame_add(f, &l->f[jf++].fr); /* outcomes counted in f->stats */
        }
        if (rl_fuse_pose_at(f, t, &p) == RL_OK) {
            print_pose(out, &p);
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

static int by_arrival(const void *a, const void *b)
{
    double x = ((const timed_frame *)a)->arrival, y = ((const timed_frame *)b)->arrival;
    return (x > y) - (x < y);
}

/* the options into cfg and the rest; 0, or an exit code after the error line */
static int options(const char *C, int argc, char **argv, rl_fuse_config *cfg, const char **odo,
                   const char **out, double *rate, int *baud, double *offset)
{
    static const struct option opts[] = {
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
    const char *C = "fuse", *odo = NULL, *out_path = NULL;
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
    if ((rc = options(C, argc, argv, &cfg, &odo, &out_path, &rate, &baud, &offset)) != 0)
        return rc < 0 ? 0 : rc;
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
    if (l.n == 0) {
        rl_odolog_free(&log);
        free(l.f);
        free(hist);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: no pose frames (%lu status frames, %lu damaged)",
                           argv[optind], l.status, l.damaged);
    }
    qsort(l.f, l.n, sizeof *l.f, by_arrival);
    if (out_path && rl_outfile_open(&o, out_path, err, sizeof err) != RL_OK) {
        rl_odolog_free(&log);
        free(l.f);
        free(hist);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    if (out_path)
        out = o.f;
    ticks = replay(&f, &log, &l, rate, out, &unfed);
    rl_odolog_free(&log);
    free(l.f);
    free(hist);
    if (ticks == 0) { /* the user's old file stays as it was */
        if (out_path)
            rl_outfile_abort(&o);
        return rl_cli_fail(C, RL_EXIT_FAIL, "no pose: %s covers no time the frames could be fused in", odo);
    }
    if (out_path && rl_outfile_commit(&o, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    fprintf(stderr, "ringloc fuse: %ld poses; %lu pose frames: %lu applied, %lu rejected, %lu restarts "
                    "(carried), %lu older than the odometry kept, %lu out of order, %lu past the odometry's "
                    "end; %lu status frames, %lu damaged\n",
            ticks, (unsigned long)l.n, f.stats.applied, f.stats.rejected, f.stats.recoveries,
            f.stats.too_old, f.stats.out_of_order,
            f.stats.waiting_lost + (unsigned long)f.has_waiting + (unsigned long)unfed, l.status, l.damaged);
    return 0;
}
