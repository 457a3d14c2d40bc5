/* rl_fuse_cycle: odometry samples moved from their read times to their
 * cycle (see rl_fuse.h). The cycle's samples are frames of a board whose
 * clock counts periods: sample k was sent at k x period on the
 * controller's crystal, and rl_fuse_clock finds where that lies on the
 * program's clock from the reads that met the least delay. */
#include <math.h>
#include <string.h>
#include "rl_fuse_clock.h"

#define KNOWN_SD_PERIODS 0.25 /* the envelope used once its time is known this well */
#define KNOWN_SPAN 2.0        /* s of cycles seen first: a program's first reads come in a burst
                                 (the packets queued while it connected), an envelope too late */
#define LOST_RUN 2            /* reads in a row whole periods late, a cycle apart: lost */

rl_err rl_fuse_cycle_init(rl_fuse_cycle *c, double period)
{
    if (!(period > 0 && period <= 10))
        return RL_EINVAL;
    memset(c, 0, sizeof *c);
    rl_fuse_clock_init(&c->clock);
    c->period = period;
    c->last = -HUGE_VAL;
    return RL_OK;
}

/* the envelope's time of cycle k's sample (the clock's line) */
static double envelope(const rl_fuse_cycle *c, uint32_t k)
{
    double b = k * c->period;
    return b + c->clock.a + c->clock.b * (b - c->clock.c0);
}

/* the stamp of a read: later than the last one given, not after the read */
static double given(rl_fuse_cycle *c, double t, double read)
{
    if (t > read)
        t = read;
    if (t <= c->last) /* the odometry's times must increase */
        t = fmin(read, c->last + 1e-6);
    c->last = t;
    return t;
}

/* A read a cycle or more after the envelope, spaced like the cycle (not
 * behind a stalled read): a stall, or cycles lost on the line. The first
 * is taken for a stall (0: its cycle's time), unless it lies a whole number
 * of cycles late as closely as the reads usually lie on the envelope, as
 * the next packet after a lost one does (-1: its read time); when the next
 * read is late too, the cycles were lost and are counted in (1). */
static int lost(rl_fuse_cycle *c, double read, double gap)
{
    double d = read - envelope(c, c->k), j = floor(d / c->period + 0.5);
    double close = fmin(c->period / 4, fmax(0.002, 3 * c->clock.excess));
    if (!c->known || gap < c->period / 2 || j < 1) {
        c->late = 0;
        return 0;
    }
    if (++c->late < LOST_RUN)
        return fabs(d - j * c->period) <= close ? -1 : 0;
    c->k += (uint32_t)j;
    c->lost += (unsigned long)j;
    c->late = 0;
    return 1;
}

double rl_fuse_cycle_stamp(rl_fuse_cycle *c, double read)
{
    double t, sd, gap = read - c->prev_read;
    if (!isfinite(read))
        return read;
    c->prev_read = read;
    if (lost(c, read, gap) < 0) { /* lost or stalled: not known yet */
        c->k++;
        return given(c, read, read);
    }
    (void)rl_fuse_clock_stamp(&c->clock, (uint32_t)llround(fmod(c->k * c->period * 1e3, 4294967296.0)),
                              (uint16_t)c->k, 0, read, &t, &sd);
    c->k++;
    c->known = sd <= KNOWN_SD_PERIODS * c->period && (c->clock.n - 1) * c->period >= KNOWN_SPAN - 1e-9;
    return given(c, c->known ? t : read, read);
}
