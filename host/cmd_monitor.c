/* ringloc monitor: decode pose and status frames, one JSON line each. */
#define _XOPEN_SOURCE 600
#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>
#include "rl_cli.h"
#include "rl_clock.h"
#include "rl_cmd.h"
#include "rl_outfile.h"
#include "rl_packet.h"
#include "rl_ptylink.h"
#include "rl_serial.h"
#include "rl_stop.h"

static const char *monitor_help =
    "usage: ringloc monitor [--baud 115200] [--follow] [--record FILE [--arrivals FILE]]\n"
    "                       DEVICE|FILE\n"
    "       ringloc monitor --pty LINK [--force] [--record FILE [--arrivals FILE]]\n\n"
    "Decode ringloc's pose and status frames (ARCOS framing) from a serial device or\n"
    "a recorded file and print one JSON line per frame:\n"
    "  {\"type\": \"pose\", \"version\": 2, \"seq\": 7, \"time_ms\": 123456, \"x\": 1.203,\n"
    "   \"y\": -0.502, \"yaw\": 0.312, \"landmarks_used\": 4, \"flags\": 1, \"residual\": 0.0021,\n"
    "   \"latency_ms\": 8.5, \"sigma\": {\"x\": 0.0011, \"y\": 0.0009, \"yaw\": 0.0004},\n"
    "   \"tilt\": {\"roll\": 0.0012, \"pitch\": -0.0051}}\n"
    "(flags: bit 0 the local pass was used, bit 1 the tilt was solved; version 1\n"
    "frames, from older firmware, have no sigma and tilt)\n"
    "  {\"type\": \"status\", \"seq\": 9, \"time_ms\": 123520, \"reason\": 1,\n"
    "   \"landmarks_identified\": 1, \"candidates\": 3}\n"
    "(reason: 1 too few landmarks, 2 camera error, 3 camera timeout, 4 configuration\n"
    "error, 5 ambiguous: the landmarks fit several places of a map that repeats ids)\n"
    "Garbage and damaged frames are skipped (counted on exit).\n\n"
    "  --pty LINK   create a pseudo-terminal, make LINK point to its device (give\n"
    "               LINK to 'ringloc run' as serial.device), and decode what comes;\n"
    "               ends when the writer closes it. LINK may be new, or a link a\n"
    "               monitor left to a pseudo-terminal that is gone; anything else\n"
    "               there is refused (kept)\n"
    "  --force      with --pty: replace whatever LINK is (not a folder)\n"
    "  --follow     keep reading a file as it grows\n"
    "  --record FILE    also keep every byte read in FILE (a recording 'ringloc fuse'\n"
    "                   replays), written whole when the monitor ends (Ctrl-C)\n"
    "  --arrivals FILE  and when each pose frame arrived: 'seq arrival_seconds' a line,\n"
    "                   on this computer's monotonic clock (CLOCK_MONOTONIC), stamped as\n"
    "                   its bytes are read: log the odometry on the same clock and give\n"
    "                   both to 'ringloc fuse --arrivals'\n";

/* The fields a well-formed frame cannot hold (a yaw beyond pi, a flag or
 * status reason ringloc does not send, a tilt beyond 90 degrees), as the
 * JSON list ", \"out_of_range\": [...]" (empty when all are in range). */
static void out_of_range(const rl_msg *m, char *out, size_t len)
{
    const char *bad[6];
    int n = 0, i;
    size_t used;
    if (m->type == RL_PACKET_POSE) {
        if (m->yaw_e4 > 31416 || m->yaw_e4 < -31416)
            bad[n++] = "yaw";
        if (m->flags & ~3u)
            bad[n++] = "flags";
        if (m->version >= 2 && (m->roll_e4 > 15708 || m->roll_e4 < -15708))
            bad[n++] = "tilt.roll";
        if (m->version >= 2 && (m->pitch_e4 > 15708 || m->pitch_e4 < -15708))
            bad[n++] = "tilt.pitch";
    } else if (m->reason < RL_STATUS_TOO_FEW || m->reason > RL_STATUS_AMBIGUOUS)
        bad[n++] = "reason";
    out[0] = '\0';
    if (n == 0)
        return;
    used = (size_t)snprintf(out, len, ", \"out_of_range\": [");
    for (i = 0; i < n && used < len; i++)
        used += (size_t)snprintf(out + used, len - used, "%s\"%s\"", i ? ", " : "", bad[i]);
    if (used < len)
        snprintf(out + used, len - used, "]");
}

static void print_msg(const rl_msg *m)
{
    char flagged[128];
    out_of_range(m, flagged, sizeof flagged);
    if (m->type == RL_PACKET_POSE) {
        printf("{\"type\": \"pose\", \"version\": %u, \"seq\": %u, \"time_ms\": %lu, \"x\": %.3f, "
               "\"y\": %.3f, \"yaw\": %.4f, \"landmarks_used\": %u, \"flags\": %u, \"residual\": %.4f, "
               "\"latency_ms\": %.1f",
               m->version, m->seq, (unsigned long)m->time_ms, m->x_mm / 1000.0, m->y_mm / 1000.0,
               m->yaw_e4 / 1e4, m->used, m->flags, m->residual_e4 / 1e4, m->latency_e4 / 10.0);
        if (m->version >= 2)
            printf(", \"sigma\": {\"x\": %.4f, \"y\": %.4f, \"yaw\": %.4f}, \"tilt\": {\"roll\": %.4f, "
                   "\"pitch\": %.4f}", m->sigma_x_e4 / 1e4, m->sigma_y_e4 / 1e4, m->sigma_yaw_e4 / 1e4,
                   m->roll_e4 / 1e4, m->pitch_e4 / 1e4);
        printf("%s}\n", flagged);
    } else
        printf("{\"type\": \"status\", \"seq\": %u, \"time_ms\": %lu, \"reason\": %u, "
               "\"landmarks_identified\": %u, \"candidates\": %u%s}\n",
               m->seq, (unsigned long)m->time_ms, m->reason, m->identified, m->candidates, flagged);
    fflush(stdout);
}

/* Where the frames come from. */
typedef struct {
    int fd;
    const char *name;  /* the file, device or --pty link */
    int is_pty;        /* our own pseudo-terminal: poll, and end when its writer leaves */
    int follow;        /* at the end, wait for more (a serial line, --follow) */
} monitor_src;

/* --pty LINK: a pseudo-terminal, LINK pointing at it. */
static int open_pty(const char *C, const char *link_path, int force, rl_ptylink *pty, monitor_src *in)
{
    char err[600];
    if (rl_ptylink_open(pty, link_path, force, 0, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    fprintf(stderr, "ringloc monitor: listening on %s (-> %s)\n", link_path, pty->name);
    in->fd = pty->fd;
    in->name = link_path;
    in->is_pty = 1;
    return 0;
}

/* A file, or a serial line (raw, read until stopped). */
static int open_file(const char *C, const char *path, monitor_src *in)
{
    struct stat st;
    in->name = path;
    in->fd = open(path, O_RDONLY | O_NOCTTY);
    if (in->fd < 0)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: %s", path, strerror(errno));
    if (fstat(in->fd, &st) == 0 && S_ISCHR(st.st_mode)) {
        struct termios t;
        /* a serial line or a pty: read until stopped; another character
         * device (/dev/null) ends like a file */
        if (tcgetattr(in->fd, &t) == 0) {
            cfmakeraw(&t);
            t.c_cc[VMIN] = 1;
            t.c_cc[VTIME] = 0;
            tcsetattr(in->fd, TCSANOW, &t);
            in->follow = 1;
        }
    }
    return 0;
}

/* The recording (--record, --arrivals): NULL streams when not asked for. */
typedef struct {
    FILE *bytes, *arrivals;
} monitor_rec;

/* Read and decode until the end, a signal or an error; each frame
 * printed as a JSON line and counted in *frames, the bytes and the pose
 * frames' arrivals recorded. 0, or the exit code. */
static int monitor_loop(const char *C, const monitor_src *in, rl_decoder *d, const monitor_rec *rec,
                        unsigned long *frames)
{
    uint8_t buf[4096];
    rl_msg m;
    int seen = 0;
    while (!rl_stop_requested()) {
        ssize_t n, i;
        if (in->is_pty) {
            struct pollfd p;
            p.fd = in->fd;
            p.events = POLLIN;
            /* nothing yet, or a signal (the loop's test sees it): no blocking read */
            if (poll(&p, 1, 200) <= 0)
                continue;
        }
        n = read(in->fd, buf, sizeof buf);
        if (n > 0) {
            double arrival = rl_clock_now_s(); /* the bytes' arrival, as a controller stamps it */
            seen = 1;
            if (rec->bytes)
                fwrite(buf, 1, (size_t)n, rec->bytes); /* checked when committed */
            for (i = 0; i < n; i++)
                if (rl_decoder_push(d, buf[i], &m)) {
                    print_msg(&m);
                    if (rec->arrivals && m.type == RL_PACKET_POSE)
                        fprintf(rec->arrivals, "%u %.6f\n", m.seq, arrival);
                    (*frames)++;
                }
            if (ferror(stdout))
                return 0; /* the output is gone: the exit status says so (rl_cli_finish) */
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (in->is_pty && n < 0 && errno == EIO) {
            /* no writer on the other side: before it came, wait; after, done */
            if (seen)
                break;
            usleep(50000);
            continue;
        }
        if (n == 0 && in->follow) {
            usleep(100000);
            continue;
        }
        if (n < 0)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s: %s", in->name, strerror(errno));
        break; /* end of file */
    }
    return 0;
}

int rl_cmd_monitor(int argc, char **argv)
{
    static const struct option opts[] = {{"pty", required_argument, 0, 'p'},
                                         {"baud", required_argument, 0, 'b'},
                                         {"follow", no_argument, 0, 'f'},
                                         {"force", no_argument, 0, 'F'},
                                         {"record", required_argument, 0, 'r'},
                                         {"arrivals", required_argument, 0, 'a'},
                                         {"help", no_argument, 0, 'h'},
                                         {0, 0, 0, 0}};
    const char *C = "monitor", *link_path = NULL, *rec_path = NULL, *arr_path = NULL;
    rl_outfile ro, ao;
    monitor_rec rec = {NULL, NULL};
    char err[1200];
    int c, r, follow = 0, force = 0, baud = 115200;
    unsigned long frames = 0;
    monitor_src in;
    rl_ptylink pty;
    rl_decoder d;

    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        switch (c) {
        case 'p': link_path = optarg; break;
        case 'b':
            if (!rl_cli_int(C, "--baud", optarg, 0, 10000000, &baud))
                return RL_EXIT_USAGE;
            if (!rl_serial_baud_ok(baud))
                return rl_cli_fail(C, RL_EXIT_USAGE, "--baud: %d is not a supported baud rate "
                                   "(9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600)", baud);
            break;
        case 'f': follow = 1; break;
        case 'F': force = 1; break;
        case 'r': rec_path = optarg; break;
        case 'a': arr_path = optarg; break;
        case 'h': fputs(monitor_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if ((link_path == NULL) == (optind >= argc))
        return rl_cli_fail(C, RL_EXIT_USAGE, "give a DEVICE or FILE, or --pty LINK (see --help)");
    if (force && link_path == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--force goes with --pty LINK");
    if (arr_path && !rec_path)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--arrivals: give --record FILE too (the frames they stamp)");
    if (rec_path && rl_outfile_open(&ro, rec_path, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (arr_path && rl_outfile_open(&ao, arr_path, err, sizeof err) != RL_OK) {
        rl_outfile_abort(&ro);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    rec.bytes = rec_path ? ro.f : NULL;
    rec.arrivals = arr_path ? ao.f : NULL;
    rl_stop_on_signals(0);
    memset(&in, 0, sizeof in);
    in.follow = follow;
    if ((r = link_path ? open_pty(C, link_path, force, &pty, &in) : open_file(C, argv[optind], &in)) == 0) {
        rl_decoder_init(&d);
        r = monitor_loop(C, &in, &d, &rec, &frames);
        if (link_path)
            rl_ptylink_close(&pty);
        else
            close(in.fd);
    }
    if (r != 0) { /* the user's old recordings stay as they were */
        if (rec_path)
            rl_outfile_abort(&ro);
        if (arr_path)
            rl_outfile_abort(&ao);
        return r;
    }
    if ((rec_path && rl_outfile_commit(&ro, err, sizeof err) != RL_OK) ||
        (arr_path && rl_outfile_commit(&ao, err, sizeof err) != RL_OK)) {
        if (arr_path)
            rl_outfile_abort(&ao); /* safe after a commit */
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    fprintf(stderr, "ringloc monitor: %lu frames decoded, %lu rejected\n", frames, d.bad);
    return 0;
}
