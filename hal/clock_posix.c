#include "rl_clock.h"

#include <time.h>

uint64_t rl_clock_now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

double rl_clock_now_s(void)
{
    return (double)rl_clock_now_us() * 1e-6;
}

void rl_clock_sleep_us(uint64_t us)
{
    struct timespec ts;
    ts.tv_sec = (time_t)(us / 1000000u);
    ts.tv_nsec = (long)(us % 1000000u) * 1000L;
    nanosleep(&ts, NULL);
}

static uint64_t system_now(void *ctx)
{
    (void)ctx;
    return rl_clock_now_us();
}

static void system_sleep(void *ctx, uint64_t us)
{
    (void)ctx;
    rl_clock_sleep_us(us);
}

rl_clock rl_clock_system(void)
{
    rl_clock c;
    c.now_us = system_now;
    c.sleep_us = system_sleep;
    c.ctx = NULL;
    return c;
}
