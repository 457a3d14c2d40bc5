/* line_delay: a serial line's delay for whole packets, in order: each
 * packet queued with the time its last byte is to be read, never before
 * the one ahead of it has gone plus its own time on the wire; sent by
 * line_delay_due once that time has come. Used by ringloc-standin (its
 * frames on a pty) and ringloc-sim-line (ringloc-fw's frames, relayed).
 *
 *   line_delay q;
 *   line_delay_init(&q);
 *   line_delay_push(&q, pkt, n, now + delay, n * 10.0 / 115200);  // 0: full, dropped
 *   line_delay_due(&q, fd, rl_clock_now_s());                   // what is due, written to fd
 *   q.sent, q.dropped                                            // counts */
#ifndef LINE_DELAY_H
#define LINE_DELAY_H

#include <stddef.h>
#include <stdint.h>
#include "rl_arcos.h"

#define LINE_DELAY_QUEUE 16

typedef struct {
    uint8_t pkt[LINE_DELAY_QUEUE][RL_ARCOS_MAX];
    size_t len[LINE_DELAY_QUEUE];
    double when[LINE_DELAY_QUEUE];
    int n;
    double last;                 /* when the last queued packet is read */
    unsigned long sent, dropped; /* written whole; dropped (queue full, or the reader's buffer) */
} line_delay;

void line_delay_init(line_delay *q);

/* Queue n bytes (at most RL_ARCOS_MAX) to be read at `when` (s), or, if
 * later, line_time after the packet ahead. 0 when the queue is full (the
 * packet dropped and counted). */
int line_delay_push(line_delay *q, const uint8_t *pkt, size_t n, double when, double line_time);

/* Write to fd every packet due at `now`; one the reader has no room for is
 * dropped and counted. */
void line_delay_due(line_delay *q, int fd, double now);

#endif
