/* rl_fuse_clock: see rl_fuse_clock.h.
 *
 * The envelope: the board's time is cut into spans of SPAN s, each keeping
 * its lowest point y = arrival - known - capture (the frame that met the
 * least delay); the offset at board time c is the line under every span's
 * point that lies closest to them (least sum of gaps), found among the
 * lines through two of them: the lower hull's edge that fits best, its
 * slope the drift (at most MAX_DRIFT). Fewer than FIT_SPAN s of spans
 * (a slope over a short base is mostly the delays' noise): no slope, the
 * lowest point of the last WINDOW s (100 ppm moves it 1.6 ms in 16 s). */
#include <math.h>
#include <string.h>
#include "rl_fuse_clock.h"

#define SPAN 4.0        /* s of the board's time per envelope point */
#define FIT_SPAN 32.0   /* s the points must cover before a drift is fitted */
#define WINDOW 16.0     /* before: the lowest point of the last this many s */
#define MAX_DRIFT 5e-4  /* 500 ppm: a steeper line is not a crystal's */
#define KNOWN_RUN 4     /* frames before the typical excess is known */
#define EARLY 0.05      /* s (and 4 typical excesses) before the envelope a frame cannot
                           arrive once the delays are known: the offset changed */
#define LATE 1.0        /* s after the envelope ... */
#define LATE_RUN 3      /* ... this many frames in a row: the offset changed */
#define SEQ_AHEAD 1000  /* sequence numbers skipped that mean a restart, not lost frames */
#define EXCESS_RUN 64   /* frames the typical excess is averaged over */

void rl_fuse_clock_init(rl_fuse_clock *k)
{
    memset(k, 0, sizeof *k);
    k->head = -1;
}

static double offset_at(const rl_fuse_clock *k, double c)
{
    return k->a + k->b * (c - k->c0);
}

/* the mean gap between the whole spans' lowest points and the line (one
 * of them on it): how far the envelope of one span may lie above the
 * least delay (the newest span, still filling, is left out) */
static void spread(rl_fuse_clock *k)
{
    double sum = 0;
    int i;
    for (i = 0; i < k->count; i++)
        if (i != k->head)
            sum += fmax(0, k->low[i].y - offset_at(k, k->low[i].c));
    k->spread = k->count > 2 ? sum / (k->count - 2) : 0;
}

static void fit(rl_fuse_clock *k)
{
    double best = HUGE_VAL, lo = HUGE_VAL, cmin = HUGE_VAL, cmax = k->low[k->head].c;
    int i, j, m;
    for (i = 0; i < k->count; i++) {
        if (k->low[i].y < lo && k->low[i].c >= cmax - WINDOW) {
            lo = k->low[i].y;
            k->c0 = k->low[i].c;
        }
        cmin = fmin(cmin, k->low[i].c);
    }
    k->a = lo;
    k->b = 0;
    if (cmax - cmin < FIT_SPAN)
        return;
    for (i = 0; i < k->count; i++)
        for (j = 0; j < k->count; j++) {
            const rl_fuse_clock_pt *p = &k->low[i], *q = &k->low[j];
            double s, cost = 0;
            if (!(q->c - p->c >= SPAN / 2))
                continue;
            s = (q->y - p->y) / (q->c - p->c);
            if (fabs(s) > MAX_DRIFT)
                continue;
            for (m = 0; m < k->count && cost < best; m++) {
                double gap = k->low[m].y - (p->y + s * (k->low[m].c - p->c));
                if (gap < -1e-9)
                    cost = HUGE_VAL;
                else
                    cost += gap;
            }
            if (cost < best) {
                best = cost;
                k->a = p->y;
                k->b = s;
                k->c0 = p->c;
            }
        }
}

/* does this frame say the board restarted or the offset changed? */
static int reset_by(rl_fuse_clock *k, uint32_t time_ms, uint16_t seq, double c, double y)
{
    uint16_t ahead = (uint16_t)(seq - k->last_seq);
    double d;
    if (k->head < 0)
        return 0;
    if (time_ms < k->last_ms || ahead == 0 || ahead > SEQ_AHEAD)
        return 1;
    d = y - offset_at(k, c);
    if (k->excess_n >= KNOWN_RUN && d < -fmax(EARLY, 4 * k->excess))
        return 1;
    k->late = d > LATE ? k->late + 1 : 0;
    return k->late >= LATE_RUN;
}

int rl_fuse_clock_stamp(rl_fuse_clock *k, uint32_t time_ms, uint16_t seq, double known,
                        double arrival, double *t, double *sd)
{
    double c = time_ms * 1e-3, y = arrival - known - c, d;
    int reset = reset_by(k, time_ms, seq, c, y);
    if (reset) { /* the transport's delays stay what they were */
        k->head = -1;
        k->count = 0;
        k->n = 0;
        k->late = 0;
    }
    if (k->head < 0 || c - k->low[k->head].start >= SPAN) {
        k->head = (k->head + 1) % RL_FUSE_CLOCK_SPANS;
        if (k->count < RL_FUSE_CLOCK_SPANS)
            k->count++;
        k->low[k->head].start = c;
        k->low[k->head].c = c;
        k->low[k->head].y = y;
    } else if (y < k->low[k->head].y) {
        k->low[k->head].c = c;
        k->low[k->head].y = y;
    }
    fit(k);
    spread(k);
    d = y - offset_at(k, c);
    if (k->n > 0) { /* the first frame of an envelope lies on it */
        if (k->excess_n < EXCESS_RUN)
            k->excess_n++;
        k->excess += (d - k->excess) / k->excess_n;
    }
    k->n++;
    k->last_ms = time_ms;
    k->last_seq = seq;
    /* the lowest of n delays uniform in 0 .. D lies D / (n + 1) above 0 on
     * average, and D is twice their mean excess: the capture that far
     * earlier, give or take as much, or as much as the spans' lowest
     * points scatter; unknown before KNOWN_RUN frames */
    *t = c + offset_at(k, c) - 2 * k->excess / (k->n + 1);
    *sd = k->excess_n < KNOWN_RUN ? HUGE_VAL : fmax(2 * k->excess / (k->n + 1), k->spread);
    return reset;
}
