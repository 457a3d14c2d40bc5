/* ringloc fuse, live: see cmd_fuse_live.h. */
#define _XOPEN_SOURCE 600
#include <errno.h>
#include <math.h>
#include <poll.h>
#include <string.h>
#include <unistd.h>
#include "cmd_fuse_live.h"
#include "rl_cli.h"
#include "rl_clock.h"
#include "rl_odolog.h"
#include "rl_stop.h"

void rl_fuse_print_pose(FILE *out, const rl_fuse_pose *p)
{
    fprintf(out, "{\"t\": %.3f, \"x\": %.4f, \"y\": %.4f, \"yaw\": %.5f, \"sigma\": {\"x\": %.4f, "
                 "\"y\": %.4f, \"yaw\": %.5f}, \"scale\": %.4f, \"turn\": %.4f, \"v\": %.4f, \"w\": %.4f}\n",
            p->t, p->x, p->y, p->yaw, sqrt(p->cov[0][0]), sqrt(p->cov[1][1]), sqrt(p->cov[2][2]),
            p->scale, p->turn, p->v, p->w);
}

static const char *fate_name(rl_fuse_fate fate)
{
    static const char *names[] = {"none", "applied", "rejected", "restarted", "too-old", "out-of-order",
                                  "lost", "untimed"};
    return (unsigned)fate < sizeof names / sizeof names[0] ? names[fate] : "?";
}

void rl_fuse_log_fate(const rl_fuse *f, unsigned long *seen, FILE *fates)
{
    rl_fuse_event ev;
    rl_fuse_last_event(f, &ev);
    if (fates && ev.n != *seen)
        fprintf(fates, "%u %.4f %s %.2f %d\n", ev.seq, ev.t, fate_name(ev.fate), ev.d2, ev.clock_reset);
    *seen = ev.n;
}

/* The odometry stream's complete lines in buf[0..*len): each fused, the
 * pose at its time printed; the rest kept. 0, or an exit code. */
static int odometry_lines(const char *C, rl_fuse *f, char *buf, size_t *len, long *no, FILE *out)
{
    char *start = buf, *nl;
    while ((nl = memchr(start, '\n', (size_t)(buf + *len - start))) != NULL) {
        rl_odosample s;
        rl_fuse_pose p;
        int r;
        *nl = '\0';
        (*no)++;
        r = rl_odolog_parse_line(start, &s);
        start = nl + 1;
        if (r == 0)
            continue;
        if (r < 0)
            return rl_cli_fail(C, RL_EXIT_FAIL, "odometry:%ld: not 't x y yaw'", *no);
        if (rl_fuse_odometry(f, s.t, s.x, s.y, s.yaw) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "odometry:%ld: time %.6g does not follow the last", *no, s.t);
        if (rl_fuse_pose_at(f, s.t, &p) == RL_OK) {
            rl_fuse_print_pose(out, &p);
            fflush(out);
        }
    }
    *len = (size_t)(buf + *len - start);
    memmove(buf, start, *len);
    return 0;
}

int rl_fuse_live(const char *C, rl_fuse *f, int odo_fd, int dev_fd, const char *dev_name, int baud,
                 FILE *out, FILE *fates, unsigned long *frames)
{
    char line[8192];
    size_t len = 0;
    long no = 0;
    unsigned long seen = 0;
    int got_frame = 0, rc;
    rl_decoder d;
    rl_decoder_init(&d);
    while (!rl_stop_requested()) {
        struct pollfd p[2];
        uint8_t buf[4096];
        ssize_t n, i;
        p[0].fd = odo_fd;
        p[1].fd = dev_fd;
        p[0].events = p[1].events = POLLIN;
        if (poll(p, 2, 200) <= 0)
            continue;
        if (p[1].revents & (POLLIN | POLLHUP | POLLERR)) {
            n = read(dev_fd, buf, sizeof buf);
            if (n > 0) {
                double arrival = rl_clock_now_s(); /* as a controller stamps it */
                got_frame = 1;
                for (i = 0; i < n; i++) {
                    rl_msg m;
                    if (!rl_decoder_push(&d, buf[i], &m) || m.type != RL_PACKET_POSE)
                        continue;
                    (*frames)++;
                    (void)!rl_fuse_msg_add(f, &m, arrival, baud); /* its fate: below */
                    rl_fuse_log_fate(f, &seen, fates);
                }
            } else if (n == 0 || (errno == EIO && got_frame))
                break; /* the device closed */
            else if (errno == EIO) /* a pty whose writer has not come yet */
                usleep(50000);
            else if (errno != EINTR && errno != EAGAIN)
                return rl_cli_fail(C, RL_EXIT_FAIL, "%s: %s", dev_name, strerror(errno));
        }
        if (p[0].revents & (POLLIN | POLLHUP)) {
            n = read(odo_fd, line + len, sizeof line - 1 - len);
            if (n == 0)
                break; /* the odometry ended */
            if (n < 0 && errno != EINTR && errno != EAGAIN)
                return rl_cli_fail(C, RL_EXIT_FAIL, "odometry: %s", strerror(errno));
            if (n > 0) {
                len += (size_t)n;
                if ((rc = odometry_lines(C, f, line, &len, &no, out)) != 0)
                    return rc;
                rl_fuse_log_fate(f, &seen, fates); /* a frame that waited for the odometry */
                if (len == sizeof line - 1)
                    return rl_cli_fail(C, RL_EXIT_FAIL, "odometry:%ld: a line longer than %lu bytes", no + 1,
                                       (unsigned long)sizeof line);
            }
        }
    }
    return 0;
}
