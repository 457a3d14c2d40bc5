/* Simulation camera: frames a renderer draws as a simulated robot moves
 * (ringloc-render --path stream). The device is a pipe or file of lines
 * "T_US FILE": each line a frame already written to FILE (a PNG, relative
 * to the device's folder unless absolute) and the time, in microseconds,
 * of the pose it was rendered at. That time is the frame's capture time:
 * a frame is as old as its pose, however long it took to render and read,
 * so the clock is the simulator's, not this process's. The line is read
 * only when the frame is grabbed, which keeps renderer and firmware in
 * lockstep through the pipe. A malformed line or an unreadable frame is
 * reported (RL_EFORMAT, c->error naming the device and line) and skipped;
 * the end of the stream is RL_ENOTFOUND. */
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "rl_cam.h"
#include "rl_png.h"

typedef struct {
    int fd;
    char dev[512], path[1600];
    char buf[2048];        /* bytes read and not yet a whole line */
    size_t have;
    long line_no, next;
    int width, height;     /* 0: each frame's own */
    void *block;
    size_t cap;
} sim_state;

static void sim_close(rl_cam *c)
{
    sim_state *s = (sim_state *)c->state;
    if (s == NULL)
        return;
    if (s->fd >= 0)
        close(s->fd);
    free(s->block);
    free(s);
}

/* The next whole line into line (without its newline): 1, 0 at the end
 * of the stream, -1 on a timeout, -2 on a read error (errno). */
static int next_line(sim_state *s, int timeout_ms, char *line, size_t len)
{
    for (;;) {
        char *nl = memchr(s->buf, '\n', s->have);
        ssize_t k;
        if (nl != NULL || s->have == sizeof s->buf) {
            size_t n = nl ? (size_t)(nl - s->buf) : s->have;
            snprintf(line, len, "%.*s", (int)n, s->buf);
            n += nl ? 1 : 0;
            memmove(s->buf, s->buf + n, s->have - n);
            s->have -= n;
            s->line_no++;
            return 1;
        }
        if (timeout_ms >= 0) {
            struct pollfd p = {s->fd, POLLIN, 0};
            int r = poll(&p, 1, timeout_ms);
            if (r == 0)
                return -1;
            if (r < 0 && errno != EINTR)
                return -2;
        }
        k = read(s->fd, s->buf + s->have, sizeof s->buf - s->have);
        if (k < 0 && (errno == EINTR || errno == EAGAIN))
            continue;
        if (k < 0)
            return -2;
        if (k == 0) {
            if (s->have == 0)
                return 0;
            s->buf[s->have++] = '\n'; /* a last line without its newline */
            continue;
        }
        s->have += (size_t)k;
    }
}

/* "T_US FILE" into t and s->path: 0, or -1 if the line is not that. */
static int parse_line(sim_state *s, const char *line, uint64_t *t)
{
    char *end;
    const char *file, *slash = strrchr(s->dev, '/');
    unsigned long long v;
    errno = 0;
    v = strtoull(line, &end, 10);
    if (end == line || errno != 0 || (*end != ' ' && *end != '\t') || line[0] == '-')
        return -1;
    for (file = end; *file == ' ' || *file == '\t'; file++)
        ;
    if (*file == '\0')
        return -1;
    *t = (uint64_t)v;
    if (file[0] == '/' || slash == NULL)
        snprintf(s->path, sizeof s->path, "%s", file);
    else
        snprintf(s->path, sizeof s->path, "%.*s%s", (int)(slash - s->dev + 1), s->dev, file);
    return 0;
}

/* The block large enough for s->path's frame, of the configured size. */
static rl_err fit_block(sim_state *s, char *err, size_t errlen)
{
    int w, h;
    rl_err e = rl_cam_png_fit(s->path, &s->block, &s->cap, &w, &h, err, errlen);
    if (e == RL_OK && s->width > 0 && (w != s->width || h != s->height)) {
        snprintf(err, errlen, "%.300s: image is %dx%d but the camera is set to %dx%d", s->path, w, h, s->width,
                 s->height);
        return RL_EFORMAT;
    }
    return e;
}

static rl_err sim_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f)
{
    sim_state *s = (sim_state *)c->state;
    char line[1200], err[sizeof c->error];
    uint64_t t = 0;
    rl_err e;
    int r = next_line(s, timeout_ms, line, sizeof line);
    memset(&f->img, 0, sizeof f->img);
    if (r == 0)
        return RL_ENOTFOUND;
    if (r == -1)
        return RL_ETIMEOUT;
    if (r == -2) {
        snprintf(c->error, sizeof c->error, "%.200s: %s", s->dev, strerror(errno));
        return RL_EIO;
    }
    if (parse_line(s, line, &t) != 0) {
        snprintf(c->error, sizeof c->error, "%.200s:%ld: not 'T_US FILE': '%.80s'", s->dev, s->line_no, line);
        return RL_EFORMAT;
    }
    f->index = s->next++;
    f->slot = 0;
    f->name = s->path;
    f->t_us = t;
    e = fit_block(s, err, sizeof err);
    if (e == RL_OK)
        e = rl_png_read_gray_into(s->path, s->block, s->cap, &f->img, err, sizeof err);
    if (e != RL_OK) {
        snprintf(c->error, sizeof c->error, "%s", err);
        memset(&f->img, 0, sizeof f->img);
        return RL_EFORMAT;
    }
    return RL_OK;
}

static void sim_release(rl_cam *c, rl_cam_frame *f)
{
    (void)c;
    (void)f;
}

static const rl_cam_ops sim_ops = {sim_grab, sim_release, sim_close};

rl_err rl_cam_open_sim(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    sim_state *s;
    const char *dev = cc->device;
    if (dev == NULL || dev[0] == '\0') {
        snprintf(err, errlen, "(none): the sim camera needs a pipe or file of 'T_US FILE' lines");
        return RL_ENOTFOUND;
    }
    if ((s = calloc(1, sizeof *s)) == NULL) {
        snprintf(err, errlen, "%s: out of memory", dev);
        return RL_ENOMEM;
    }
    snprintf(s->dev, sizeof s->dev, "%s", dev);
    s->width = cc->width > 0 && cc->height > 0 ? cc->width : 0;
    s->height = s->width > 0 ? cc->height : 0;
    /* a pipe opened for reading waits for its writer: the renderer starts first or after, either works */
    if ((s->fd = open(dev, O_RDONLY | O_CLOEXEC)) < 0) {
        snprintf(err, errlen, "%s: %s", dev, strerror(errno));
        free(s);
        return errno == ENOENT ? RL_ENOTFOUND : RL_EIO;
    }
    c->state = s;
    c->ops = &sim_ops;
    return RL_OK;
}

rl_err rl_cam_probe_sim(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err, size_t errlen)
{
    char text[700];
    (void)err;
    (void)errlen;
    snprintf(text, sizeof text, "sim %s: frames from a renderer following a pose stream ('T_US FILE' lines), "
             "each with its pose's time as capture time", cc->device ? cc->device : "(none)");
    line(ctx, text);
    return RL_OK;
}
