/* render_stream: poses streamed to the renderer (render_stream.h). */
#include "render_stream.h"

#include <errno.h>
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void render_stream_open(render_stream *st, int fd, const char *name, int newest)
{
    memset(st, 0, sizeof *st);
    st->fd = fd;
    st->name = name;
    st->newest = newest;
}

/* More bytes into the buffer: >0, 0 at the end, -1 on an error. With
 * wait 0, returns -2 at once when none are waiting. */
static int fill(render_stream *st, int wait)
{
    ssize_t k;
    if (!wait) {
        struct pollfd p = {st->fd, POLLIN, 0};
        if (poll(&p, 1, 0) <= 0)
            return -2;
    }
    do
        k = read(st->fd, st->buf + st->have, sizeof st->buf - st->have);
    while (k < 0 && errno == EINTR);
    if (k > 0)
        st->have += (size_t)k;
    return k > 0 ? 1 : k == 0 ? 0 : -1;
}

/* Take one whole line out of the buffer into line: 1, or 0 if there is
 * none. */
static int take_line(render_stream *st, char *line, size_t len)
{
    char *nl = memchr(st->buf, '\n', st->have);
    size_t n;
    if (nl == NULL)
        return 0;
    n = (size_t)(nl - st->buf);
    snprintf(line, len, "%.*s", (int)n, st->buf);
    memmove(st->buf, nl + 1, st->have - n - 1);
    st->have -= n + 1;
    st->line_no++;
    return 1;
}

/* The next whole line, waiting for it: 1, 0 at the end, -1 on an error. */
static int read_line(render_stream *st, char *line, size_t len)
{
    int r;
    while (!take_line(st, line, len)) {
        if (st->have == sizeof st->buf) {
            fprintf(stderr, "ringloc-render: %s:%ld: line too long\n", st->name, st->line_no + 1);
            return -1;
        }
        if ((r = fill(st, 1)) <= 0) {
            if (r < 0)
                fprintf(stderr, "ringloc-render: %s: %s\n", st->name, strerror(errno));
            return r;
        }
    }
    return 1;
}

int render_stream_next(render_stream *st, uint64_t *t_us, double *x, double *y, double *yaw)
{
    char line[512], next[512], *end;
    unsigned long long t;
    int r = read_line(st, line, sizeof line);
    if (r <= 0)
        return r;
    while (st->newest) { /* the lines already here: keep the last */
        while (st->have < sizeof st->buf && fill(st, 0) > 0)
            ;
        if (!take_line(st, next, sizeof next))
            break;
        memcpy(line, next, sizeof line);
        st->skipped++;
    }
    errno = 0;
    t = strtoull(line, &end, 10);
    if (end != line && line[0] != '-' && errno == 0 && sscanf(end, "%lf %lf %lf", x, y, yaw) == 3 &&
        isfinite(*x) && isfinite(*y) && isfinite(*yaw)) {
        *t_us = (uint64_t)t;
        return 1;
    }
    fprintf(stderr, "ringloc-render: %s:%ld: not 'T_US X Y YAW' (microseconds, m, m, rad): '%.80s'\n", st->name,
            st->line_no, line);
    return -1;
}
