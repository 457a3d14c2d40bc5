/* rl_fuse_clock: the camera board's clock on the controller's, for
 * rl_fuse.c (internal). Every pose frame carries its capture time on the
 * board's clock (time_ms); the controller stamps its arrival. What lies
 * between them beyond the frame's own latency field and its bytes on the
 * line is never negative, so the lowest points of arrival - known delay -
 * time_ms over time (their lower envelope) are the offset between the two
 * clocks, and the envelope's slope their drift. A firmware restart
 * (time_ms going back, the sequence going back or far ahead) or an offset
 * that changed (a frame arriving before it could have been sent, or
 * several in a row a second later than the envelope) starts it afresh.
 *
 *   rl_fuse_clock k;
 *   double t, sd;
 *   int reset;
 *   rl_fuse_clock_init(&k);
 *   reset = rl_fuse_clock_stamp(&k, 52000, 7, 0.0185, 12.31, &t, &sd);
 *   // t: the capture on the controller's clock, sd: its uncertainty
 *   // (HUGE_VAL until the delays are known), reset: 1 when this frame
 *   // restarted the clock
 */
#ifndef RL_FUSE_CLOCK_H
#define RL_FUSE_CLOCK_H

#include <stdint.h>
#include "rl_fuse.h"

/* no frame seen yet; what was learned of the transport's delays is lost */
void rl_fuse_clock_init(rl_fuse_clock *k);

/* A frame captured at time_ms on the board's clock with sequence seq,
 * `known` s of its delay accounted for (latency field and line time),
 * arriving at `arrival` on the controller's clock: its capture time there
 * (*t) and that time's standard deviation (*sd). 1 when this frame reset
 * the clock (a restart or a changed offset), else 0. */
int rl_fuse_clock_stamp(rl_fuse_clock *k, uint32_t time_ms, uint16_t seq, double known,
                        double arrival, double *t, double *sd);

#endif
