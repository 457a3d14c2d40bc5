/* rl_packet_sink: the loop's reports as ARCOS-framed pose and status
 * packets on a line (the serial port, or a test's buffer).
 *
 * A report with a pose becomes a pose packet (capture time, position,
 * yaw, sigmas, tilt, latency from capture to sending, the local pass flag);
 * any other a status packet with its reason. The packet's sequence number
 * is the report's, so a controller sees a gap where the line dropped one.
 *
 *   rl_packet_line line;            // the serial line's open, write, close
 *   rl_packet_sink ps;
 *   rl_run_io io;
 *   memset(&line, 0, sizeof line);
 *   io.sink = rl_packet_sink_make(&ps, &line);
 */
#ifndef RL_PACKET_SINK_H
#define RL_PACKET_SINK_H

#include <stddef.h>
#include <stdint.h>
#include "rl_packet.h"
#include "rl_run.h"

typedef struct {
    rl_err (*open)(void *ctx, char *err, size_t errlen);
    rl_err (*write)(void *ctx, const uint8_t *p, size_t n);
    void (*close)(void *ctx);
    /* the system's reason for the last failed write ("No space left on
     * device"), or NULL; may be NULL */
    const char *(*why)(void *ctx);
    void *ctx;
} rl_packet_line;

typedef struct {
    rl_packet_line line;
} rl_packet_sink;

/* The message a report makes. */
void rl_packet_from_report(const rl_run_report *rep, rl_msg *m);

/* A sink writing each report's packet to line (kept in ps). */
rl_run_sink rl_packet_sink_make(rl_packet_sink *ps, const rl_packet_line *line);

#endif
