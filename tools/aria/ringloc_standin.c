/* ringloc-standin: a Pioneer stand-in that speaks ARCOS on a TCP port (as
 * MobileSim does), for the controller-side tests without a robot: the
 * connection handshake (SYNC0, SYNC1, SYNC2 with its name, type and
 * subtype, OPEN, CLOSE), a server information packet every 100 ms with the
 * odometry of a simulated drive (standin_sim.c), and the motion commands
 * (ENABLE, VEL, RVEL, ROTATE, STOP, ESTOP, SETO). It also plays ringloc's
 * camera: pose frames about the true pose on a pseudo-terminal, 10 a
 * second, each arriving 100 ms after its capture; and it logs the truth. */
#define _XOPEN_SOURCE 600
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <math.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>
#include "rl_cli.h"
#include "rl_clock.h"
#include "rl_outfile.h"
#include "rl_ptylink.h"
#include "rl_stop.h"
#include "line_delay.h"
#include "standin_sim.h"

#define SIP_PERIOD 0.1
#define FRAME_PERIOD 0.1
#define FRAME_DELAY 0.1      /* capture -> the frame's last byte read (no --transport) */
#define FIELD_DELAY 0.015    /* with --transport: what the latency field says */
#define BOARD0 5000.0        /* s on the camera board's clock at the start */
#define BOOT 0.5             /* s a restarted camera board sends nothing */
#define LINE_TIME (39 * 10.0 / 115200)
#define P "ringloc-standin"

static const char *help =
    "usage: ringloc-standin [--port 8101] [--frames-pty LINK] [--truth FILE] [--seconds S]\n"
    "                       [--start X,Y,YAW] [--seed N] [--force] [--transport MAX]\n"
    "                       [--drift PPM] [--restart-at S]\n\n"
    "A Pioneer stand-in speaking ARCOS on TCP port PORT of 127.0.0.1 (ARIA: -remoteHost\n"
    "localhost -remoteRobotTcpPort PORT): the handshake, a server information packet every\n"
    "100 ms with the odometry of a simulated drive (1% wheel scale and 2% track width off,\n"
    "wheel noise), the motion commands VEL, RVEL, ROTATE, ENABLE, STOP, ESTOP, SETO.\n"
    "  --frames-pty LINK  also ringloc's camera: a pseudo-terminal (LINK points to it)\n"
    "                     carrying pose frames about the true pose, 10 a second, each\n"
    "                     read 100 ms after its capture (its latency field says so);\n"
    "                     LINK may be new or a link left to a pseudo-terminal that\n"
    "                     is gone: anything else there is refused (kept)\n"
    "                     time_ms is the camera board's own clock (5000 s at the start)\n"
    "  --force            replace whatever LINK is (not a folder)\n"
    "  --transport MAX    a serial line's delays instead: the latency field says 15 ms,\n"
    "                     then a delay uniform in 0 .. MAX s the field does not carry\n"
    "  --drift PPM        the board's clock runs PPM parts per million fast (negative: slow)\n"
    "  --restart-at S     the camera board restarts S s after the start: time_ms and the\n"
    "                     sequence from 0, 0.5 s without frames\n"
    "  --truth FILE       the true pose every 10 ms, 't x y yaw' (t: CLOCK_MONOTONIC s)\n"
    "  --seconds S        stop after S seconds (default: when the client closes)\n"
    "  --start X,Y,YAW    the true start in the map (default 1,1,0)\n";

typedef struct {
    standin_robot robot;
    int lfd, cfd;          /* listening socket, client (-1: none) */
    int pty;               /* master of the frames' pty (-1: none) */
    rl_ptylink link;       /* it, and the link to it */
    int synced;            /* 0..3: SYNC steps done */
    int open;              /* OPEN received: SIPs flow */
    int served;            /* a client has come and opened */
    rl_arcos_reader rd;
    line_delay q;          /* the frames on their way */
    double transport, drift, restart_at; /* --transport, --drift (ppm), --restart-at (s; < 0 none) */
    double t0;             /* the start */
    int restarted;
    unsigned long sips;
} standin;

static void send_all(standin *s, const uint8_t *b, size_t n)
{
    if (s->cfd >= 0 && write(s->cfd, b, n) != (ssize_t)n) {
        close(s->cfd);
        s->cfd = -1;
    }
}

static void sync_reply(standin *s, int id)
{
    uint8_t p[64], buf[RL_ARCOS_MAX];
    size_t n = 1;
    p[0] = (uint8_t)id;
    if (id == 2) { /* name, type, subtype: ARIA picks its parameters by the subtype */
        static const char names[] = "ringloc-standin\0Pioneer\0p3dx-sh";
        memcpy(p + 1, names, sizeof names);
        n += sizeof names;
    }
    send_all(s, buf, rl_arcos_packet(buf, p, n));
}

static void command(standin *s, const uint8_t *p, size_t n)
{
    int arg = rl_arcos_int_arg(p, n);
    if (s->synced < 3) { /* the handshake: each SYNC echoed in turn */
        if (p[0] == s->synced) {
            sync_reply(s, p[0]);
            s->synced++;
        } else if (p[0] == 0) {
            s->synced = 0;
            sync_reply(s, 0);
            s->synced = 1;
        }
        return;
    }
    switch (p[0]) {
    case RL_ARCOS_OPEN: s->open = s->served = 1; break;
    case RL_ARCOS_CLOSE: s->open = 0; s->synced = 0; s->robot.v_cmd = s->robot.w_cmd = 0; break;
    case RL_ARCOS_ENABLE: s->robot.enabled = arg != 0; break;
    case RL_ARCOS_VEL: s->robot.v_cmd = arg / 1000.0; break;
    case RL_ARCOS_RVEL: case RL_ARCOS_ROTATE: s->robot.w_cmd = arg * M_PI / 180; break;
    case RL_ARCOS_STOP: case RL_ARCOS_ESTOP: s->robot.v_cmd = s->robot.w_cmd = 0; break;
    case RL_ARCOS_SETO: s->robot.ox = s->robot.oy = s->robot.oyaw = 0; break;
    default: break; /* PULSE, CONFIG (ARIA goes on without it), sonar, ...: nothing to do */
    }
}

static int listen_on(int port)
{
    struct sockaddr_in a;
    int one = 1, fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return -1;
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (bind(fd, (struct sockaddr *)&a, sizeof a) != 0 || listen(fd, 1) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

/* a frame captured now (t), queued to be written when it would have
 * arrived (after the one before it: a line keeps the order); time_ms on
 * the board's clock, which restarts with the board */
static void capture(standin *s, double t)
{
    double since = t - s->t0, board, send;
    uint8_t pkt[RL_ARCOS_MAX];
    size_t n;
    if (s->restart_at >= 0 && since >= s->restart_at) {
        if (since < s->restart_at + BOOT)
            return;
        if (!s->restarted)
            s->robot.seq = 0;
        s->restarted = 1;
        board = since - s->restart_at;
    } else
        board = BOARD0 + since;
    board *= 1 + s->drift * 1e-6;
    if (s->transport > 0) {
        n = standin_frame(&s->robot, (uint32_t)(board * 1000), FIELD_DELAY, pkt);
        send = t + FIELD_DELAY + LINE_TIME + s->transport * standin_uniform(&s->robot);
    } else {
        n = standin_frame(&s->robot, (uint32_t)(board * 1000), FRAME_DELAY - LINE_TIME, pkt);
        send = t + FRAME_DELAY;
    }
    line_delay_push(&s->q, pkt, n, send, LINE_TIME);
}

/* the client's bytes, or a new client */
static void network(standin *s)
{
    struct pollfd p[2];
    int n = 0;
    p[n].fd = s->lfd;
    p[n++].events = POLLIN;
    if (s->cfd >= 0) {
        p[n].fd = s->cfd;
        p[n++].events = POLLIN;
    }
    if (poll(p, (nfds_t)n, 1) <= 0)
        return;
    if ((p[0].revents & POLLIN) && s->cfd < 0) {
        s->cfd = accept(s->lfd, NULL, NULL);
        s->synced = s->open = 0;
        rl_arcos_reader_init(&s->rd);
    }
    if (n > 1 && (p[1].revents & (POLLIN | POLLHUP))) {
        uint8_t buf[512], pl[RL_ARCOS_MAX];
        size_t len;
        ssize_t got = read(s->cfd, buf, sizeof buf), i;
        if (got <= 0) {
            close(s->cfd);
            s->cfd = -1;
            s->open = 0;
            return;
        }
        for (i = 0; i < got; i++)
            if (rl_arcos_reader_push(&s->rd, buf[i], pl, &len) && len > 0)
                command(s, pl, len);
    }
}

static int parse_start(const char *arg, double *x, double *y, double *yaw)
{
    char rest;
    return sscanf(arg, "%lf,%lf,%lf%c", x, y, yaw, &rest) == 3 && isfinite(*x) && isfinite(*y) &&
           isfinite(*yaw);
}

/* the simulated robot moved on to `to` (s) */
static void advance(standin *s, double *last, double to)
{
    if (to > *last) {
        standin_step(&s->robot, to - *last);
        *last = to;
    }
}

/* the drive until stopped: 1 ms steps; each SIP, frame and truth line at
 * its own instant, the robot moved to it first (a process the machine
 * runs late sends late, as a line delays, but never a pose of another
 * time: a Pioneer's controller does not stall) */
static void run(standin *s, double seconds, FILE *truth)
{
    double t0 = rl_clock_now_s(), last = t0, next_sip = t0, next_frame = t0, next_truth = t0;
    s->t0 = t0;
    while (!rl_stop_requested()) {
        double t;
        network(s);
        t = rl_clock_now_s();
        if (next_sip < t - 1) /* no client for a while: no burst of SIPs when one comes */
            next_sip = t;
        for (;;) {
            double ev = t;
            int what = 0;
            if (s->open && s->cfd >= 0 && next_sip <= ev)
                ev = next_sip, what = 1;
            if (s->pty >= 0 && next_frame <= ev)
                ev = next_frame, what = 2;
            if (truth && next_truth <= ev)
                ev = next_truth, what = 3;
            if (!what)
                break;
            advance(s, &last, ev);
            if (what == 1) {
                uint8_t buf[RL_ARCOS_MAX];
                send_all(s, buf, standin_sip(&s->robot, buf));
                s->sips++;
                next_sip += SIP_PERIOD;
            } else if (what == 2) {
                capture(s, ev);
                next_frame += FRAME_PERIOD;
            } else {
                fprintf(truth, "%.4f %.5f %.5f %.5f\n", ev, s->robot.tx, s->robot.ty, s->robot.tyaw);
                next_truth += 0.01;
            }
        }
        advance(s, &last, t);
        if (s->pty >= 0)
            line_delay_due(&s->q, s->pty, t);
        if ((seconds > 0 && t - t0 >= seconds) || (seconds <= 0 && s->served && s->cfd < 0))
            break;
    }
}

int main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"port", required_argument, 0, 'p'},  {"frames-pty", required_argument, 0, 'f'},
        {"truth", required_argument, 0, 't'}, {"seconds", required_argument, 0, 's'},
        {"start", required_argument, 0, 'x'}, {"seed", required_argument, 0, 'S'},
        {"force", no_argument, 0, 'F'},
        {"transport", required_argument, 0, 'T'}, {"drift", required_argument, 0, 'D'},
        {"restart-at", required_argument, 0, 'R'}, {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    static standin s;
    const char *pty_link = NULL, *truth_path = NULL;
    double seconds = 0, x = 1, y = 1, yaw = 0;
    int c, port = 8101, seed = 1, force = 0;
    rl_outfile o;
    char err[1200];
    rl_cli_start(P);
    s.restart_at = -1;
    while ((c = rl_cli_getopt(NULL, argc, argv, opts)) != -1) {
        int ok = 1;
        switch (c) {
        case 'p': ok = rl_cli_int(NULL, "--port", optarg, 1, 65535, &port); break;
        case 'f': pty_link = optarg; break;
        case 'F': force = 1; break;
        case 't': truth_path = optarg; break;
        case 's': ok = rl_cli_double(NULL, "--seconds", optarg, 0, 1e6, &seconds); break;
        case 'S': ok = rl_cli_int(NULL, "--seed", optarg, 0, 1000000000, &seed); break;
        case 'T': ok = rl_cli_double(NULL, "--transport", optarg, 0, 1, &s.transport); break;
        case 'D': ok = rl_cli_double(NULL, "--drift", optarg, -1000, 1000, &s.drift); break;
        case 'R': ok = rl_cli_double(NULL, "--restart-at", optarg, 0, 1e6, &s.restart_at); break;
        case 'x':
            if (!parse_start(optarg, &x, &y, &yaw))
                return rl_cli_fail(NULL, RL_EXIT_USAGE, "--start: '%s' is not X,Y,YAW", optarg);
            break;
        case 'h': fputs(help, stdout); return 0;
        default: return RL_EXIT_USAGE;
        }
        if (!ok)
            return RL_EXIT_USAGE;
    }
    if (optind != argc)
        return rl_cli_fail(NULL, RL_EXIT_USAGE, "unexpected argument '%s' (see --help)", argv[optind]);
    standin_init(&s.robot, x, y, yaw, (unsigned)seed);
    line_delay_init(&s.q);
    s.cfd = s.pty = -1;
    if ((s.lfd = listen_on(port)) < 0)
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "127.0.0.1:%d: %s", port, strerror(errno));
    if (pty_link && rl_ptylink_open(&s.link, pty_link, force, 1, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "%s", err);
    s.pty = pty_link ? s.link.fd : -1;
    if (truth_path && rl_outfile_open(&o, truth_path, err, sizeof err) != RL_OK) {
        if (pty_link)
            rl_ptylink_close(&s.link);
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "%s", err);
    }
    rl_stop_on_signals(RL_STOP_NO_SIGPIPE);
    fprintf(stderr, P ": listening on 127.0.0.1:%d%s%s\n", port, pty_link ? ", pose frames on " : "",
            pty_link ? pty_link : "");
    run(&s, seconds, truth_path ? o.f : NULL);
    if (pty_link)
        rl_ptylink_close(&s.link);
    fprintf(stderr, P ": %lu server information packets, %lu pose frames sent, %lu dropped; odometry "
            "(%.3f, %.3f, %.4f), truth (%.4f, %.4f, %.4f)\n", s.sips, s.q.sent, s.q.dropped,
            s.robot.ox, s.robot.oy, s.robot.oyaw, s.robot.tx, s.robot.ty, s.robot.tyaw);
    if (truth_path && rl_outfile_commit(&o, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "%s", err);
    return 0;
}
