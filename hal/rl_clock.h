/* rl_clock: the one clock of the firmware (monotonic, microseconds).
 *
 * Capture times, latencies, paces and backoffs all read it. The main loop
 * reaches it through an rl_clock, so that its tests can run a fake one.
 *
 *   uint64_t t0 = rl_clock_now_us();
 *   rl_clock_sleep_us(2000);
 *   rl_clock c = rl_clock_system();
 *   uint64_t t1 = c.now_us(c.ctx);            // the same clock, t1 >= t0 + 2000
 */
#ifndef RL_CLOCK_H
#define RL_CLOCK_H

#include <stdint.h>

/* CLOCK_MONOTONIC in microseconds. */
uint64_t rl_clock_now_us(void);

/* The same in seconds (tools' and commands' time stamps). */
double rl_clock_now_s(void);

/* Sleep for us microseconds (signals may cut it short). */
void rl_clock_sleep_us(uint64_t us);

typedef struct {
    uint64_t (*now_us)(void *ctx);
    void (*sleep_us)(void *ctx, uint64_t us);
    void *ctx;
} rl_clock;

/* The system clock above as an rl_clock. */
rl_clock rl_clock_system(void);

#endif
