/* render_stream: the poses a simulator streams to the renderer
 * (ringloc-render --path stream), one line each, "T_US X Y YAW": the
 * pose's time in microseconds and the robot's pose in the site's frame
 * (m, m, rad). Read from a file descriptor a line at a time; with newest
 * set, the lines already waiting are skipped to the last, so a renderer
 * slower than the simulator draws where the robot is now, not where it
 * was (the skipped ones are counted).
 *
 *   render_stream st;
 *   render_stream_open(&st, 0, "stdin", 1);
 *   while (render_stream_next(&st, &t, &x, &y, &yaw) == 1)
 *       draw(t, x, y, yaw);
 */
#ifndef RENDER_STREAM_H
#define RENDER_STREAM_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    int fd;
    const char *name;  /* for messages */
    int newest;        /* skip to the last waiting line */
    char buf[4096];
    size_t have;
    long line_no;      /* lines read */
    long skipped;      /* poses skipped as stale */
} render_stream;

void render_stream_open(render_stream *st, int fd, const char *name, int newest);

/* The next pose: 1, 0 at the end of the stream, -1 with one line on
 * stderr naming the stream and line (a malformed line, a read error). */
int render_stream_next(render_stream *st, uint64_t *t_us, double *x, double *y, double *yaw);

#endif
