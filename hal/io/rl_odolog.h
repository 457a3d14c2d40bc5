/* rl_odolog: a robot's odometry log, for `ringloc fuse`: one sample a
 * line, "t x y yaw" (seconds on the controller's clock, metres, radians;
 * spaces or commas between), '#' starting a comment. Times must increase.
 *
 *   rl_odolog log;
 *   char err[600];
 *   if (rl_odolog_load("odometry.txt", &log, err, sizeof err) == RL_OK) {
 *       use(log.n, log.s[0].t, log.s[0].x);
 *       rl_odolog_free(&log);
 *   } else
 *       use(err);   // "odometry.txt:12: time 3.5 does not follow 3.6"
 */
#ifndef RL_ODOLOG_H
#define RL_ODOLOG_H

#include <stddef.h>
#include "rl_error.h"

typedef struct {
    double t, x, y, yaw;
} rl_odosample;

typedef struct {
    rl_odosample *s; /* n samples, times increasing (heap: rl_odolog_free) */
    size_t n;
} rl_odolog;

/* Load the log at path: RL_OK, or RL_ENOTFOUND / RL_EIO / RL_EFORMAT /
 * RL_ENOMEM with err "PATH[:LINE]: reason" and nothing to free. An empty
 * log is RL_EFORMAT. */
RL_CHECK rl_err rl_odolog_load(const char *path, rl_odolog *log, char *err, size_t errlen);

void rl_odolog_free(rl_odolog *log);

/* One line of a log into *s (the line is changed: its comment cut): 1 a
 * sample, 0 blank or a comment, -1 malformed. */
int rl_odolog_parse_line(char *line, rl_odosample *s);

#endif
