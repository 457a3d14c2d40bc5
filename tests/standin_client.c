/* standin_client: the controller's side in C on the project's own ARCOS
 * code (rl_arcos for the robot's packets, rl_packet's decoder for the pose
 * frames, rl_fuse between them: rl_fuse_msg_add, the capture from the
 * board's clock), against ringloc-standin: the handshake
 * checked step by step, a drive commanded with ENABLE, VEL and RVEL, the
 * odometry of every server information packet (15-bit positions unwrapped
 * as ARIA does, stamped when read and moved to the 100 ms packet cycle:
 * rl_fuse_cycle) fused with the frames read from the pty, one line per
 * packet "t x y yaw odo_x odo_y odo_yaw sigma" (t: CLOCK_MONOTONIC s) for
 * the script to judge against the stand-in's truth.
 * usage: standin_client PORT FRAMES_PTY SECONDS VEL_MM_S ROTVEL_DEG_S LOG */
#define _DEFAULT_SOURCE 1
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>
#include "rl_arcos.h"
#include "rl_fuse.h"

#define ANGLE_UNIT (2 * M_PI / 4096)

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int fail(const char *what)
{
    fprintf(stderr, "FAIL: standin_client: %s\n", what);
    return 1;
}

static void send_cmd(int fd, int cmd, int has_arg, int arg)
{
    uint8_t b[RL_ARCOS_MAX];
    size_t n = has_arg ? rl_arcos_command_int(b, cmd, arg) : rl_arcos_command(b, cmd);
    if (write(fd, b, n) != (ssize_t)n)
        fprintf(stderr, "standin_client: write: %s\n", strerror(errno));
}

/* the next packet from the robot within 1 s: its payload length, or -1 */
static int next_packet(int fd, rl_arcos_reader *r, uint8_t *pl)
{
    double end = now_s() + 1.0;
    size_t n;
    while (now_s() < end) {
        uint8_t b;
        struct pollfd p;
        p.fd = fd;
        p.events = POLLIN;
        if (poll(&p, 1, 50) <= 0)
            continue;
        if (read(fd, &b, 1) != 1)
            return -1;
        if (rl_arcos_reader_push(r, b, pl, &n))
            return (int)n;
    }
    return -1;
}

/* SYNC0, SYNC1, SYNC2 each answered in kind; SYNC2 with the robot's names */
static int handshake(int fd, rl_arcos_reader *r)
{
    uint8_t pl[RL_ARCOS_MAX];
    int k, n = 0;
    for (k = 0; k < 3; k++) {
        send_cmd(fd, k, 0, 0);
        n = next_packet(fd, r, pl);
        if (n < 1 || pl[0] != k)
            return fail("a SYNC step was not answered in kind");
    }
    pl[n < RL_ARCOS_MAX ? n : RL_ARCOS_MAX - 1] = 0;
    if (n < 4 || strcmp((char *)pl + 1, "ringloc-standin") != 0 ||
        strcmp((char *)pl + 1 + strlen((char *)pl + 1) + 1, "Pioneer") != 0)
        return fail("SYNC2 did not name the robot");
    printf("handshake: SYNC0 SYNC1 SYNC2 answered; name %s, type Pioneer\n", (char *)pl + 1);
    send_cmd(fd, RL_ARCOS_OPEN, 1, 1);
    return 0;
}

static int get16(const uint8_t *p)
{
    return p[0] | (p[1] << 8);
}

typedef struct {
    int have;
    int lx, ly;          /* the last packet's 15-bit positions */
    double x, y;         /* unwrapped, mm */
} odo_track;

/* a server information packet read at `read`: its odometry into the
 * filter at its cycle's time, the fused pose then into the log; 1 when it
 * was one */
static int sip(rl_fuse *f, rl_fuse_cycle *cy, odo_track *o, const uint8_t *pl, int n, double read, FILE *log)
{
    int x, y, dx, dy;
    double yaw, t;
    rl_fuse_pose p;
    if (n < 20 || (pl[0] != RL_ARCOS_SIP_STOPPED && pl[0] != RL_ARCOS_SIP_MOVING))
        return 0;
    t = rl_fuse_cycle_stamp(cy, read);
    x = get16(pl + 1) & 0x7FFF;
    y = get16(pl + 3) & 0x7FFF;
    yaw = (int16_t)get16(pl + 5) * ANGLE_UNIT;
    dx = o->have ? x - o->lx : 0;
    dy = o->have ? y - o->ly : 0;
    if (dx > 0x1000) dx -= 0x8000;
    if (dx < -0x1000) dx += 0x8000;
    if (dy > 0x1000) dy -= 0x8000;
    if (dy < -0x1000) dy += 0x8000;
    o->x += dx;
    o->y += dy;
    o->lx = x;
    o->ly = y;
    o->have = 1;
    if (rl_fuse_odometry(f, t, o->x / 1000, o->y / 1000, yaw) == RL_OK && rl_fuse_pose_at(f, t, &p) == RL_OK)
        fprintf(log, "%.4f %.5f %.5f %.5f %.4f %.4f %.5f %.6f\n", t, p.x, p.y, p.yaw, o->x / 1000, o->y / 1000,
                yaw, sqrt(p.cov[0][0] + p.cov[1][1]));
    return 1;
}

static int open_line(const char *path)
{
    struct termios t;
    int fd = open(path, O_RDONLY | O_NOCTTY | O_NONBLOCK);
    if (fd >= 0 && tcgetattr(fd, &t) == 0) {
        cfmakeraw(&t);
        tcsetattr(fd, TCSANOW, &t);
    }
    return fd;
}

static int connect_to(int port)
{
    struct sockaddr_in a;
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd >= 0 && connect(fd, (struct sockaddr *)&a, sizeof a) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

int main(int argc, char **argv)
{
    static rl_fuse f;
    static rl_fuse_entry hist[64];
    static rl_fuse_cycle cy;
    rl_fuse_config cfg;
    rl_arcos_reader r;
    rl_decoder d;
    odo_track o;
    unsigned long sips = 0;
    double end;
    int rfd, lfd;
    FILE *log;
    if (argc != 7)
        return fail("usage: standin_client PORT FRAMES_PTY SECONDS VEL_MM_S ROTVEL_DEG_S LOG");
    if ((rfd = connect_to(atoi(argv[1]))) < 0 || (lfd = open_line(argv[2])) < 0 ||
        (log = fopen(argv[6], "w")) == NULL)
        return fail("cannot reach the stand-in (port, pty) or write the log");
    rl_fuse_defaults(&cfg);
    cfg.wheel_noise = 0.0005;
    if (rl_fuse_init(&f, &cfg, hist, rl_fuse_history_count(2.5, 10)) != RL_OK || /* 10 SIPs a second */
        rl_fuse_cycle_init(&cy, 0.1) != RL_OK)
        return fail("rl_fuse_init");
    rl_arcos_reader_init(&r);
    rl_decoder_init(&d);
    memset(&o, 0, sizeof o);
    if (handshake(rfd, &r) != 0)
        return 1;
    send_cmd(rfd, RL_ARCOS_ENABLE, 1, 1);
    send_cmd(rfd, RL_ARCOS_VEL, 1, atoi(argv[4]));
    send_cmd(rfd, RL_ARCOS_RVEL, 1, atoi(argv[5]));
    for (end = now_s() + atof(argv[3]); now_s() < end;) {
        struct pollfd p[2];
        uint8_t buf[256], pl[RL_ARCOS_MAX];
        ssize_t n, i;
        size_t len;
        p[0].fd = rfd;
        p[1].fd = lfd;
        p[0].events = p[1].events = POLLIN;
        if (poll(p, 2, 50) <= 0)
            continue;
        if ((p[0].revents & POLLIN) && (n = read(rfd, buf, sizeof buf)) > 0)
            for (i = 0; i < n; i++)
                if (rl_arcos_reader_push(&r, buf[i], pl, &len))
                    sips += (unsigned long)sip(&f, &cy, &o, pl, (int)len, now_s(), log);
        if ((p[1].revents & POLLIN) && (n = read(lfd, buf, sizeof buf)) > 0)
            for (i = 0; i < n; i++) {
                rl_msg m;
                if (!rl_decoder_push(&d, buf[i], &m) || m.type != RL_PACKET_POSE)
                    continue;
                /* the arrival stamped as read; the capture from the board's clock */
                (void)!rl_fuse_msg_add(&f, &m, now_s(), 115200); /* counted in f.stats */
            }
    }
    send_cmd(rfd, RL_ARCOS_STOP, 0, 0);
    send_cmd(rfd, RL_ARCOS_CLOSE, 0, 0);
    close(rfd);
    close(lfd);
    fclose(log);
    printf("server information packets: %lu; pose frames: %lu applied, %lu rejected, %lu restarts, %lu clock "
           "resets, %lu untimed, %lu damaged\n", sips, f.stats.applied, f.stats.rejected, f.stats.recoveries,
           f.stats.clock_resets, f.stats.untimed, d.bad);
    return 0;
}
