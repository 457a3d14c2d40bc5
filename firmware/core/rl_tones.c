#include "rl_tones.h"

#include <math.h>
#include <stddef.h>

/* Votes of past frames fade by this much a frame: a change of camera
 * settings is followed within some twenty frames. */
#define VOTE_FADE 0.9
/* Votes the other curve must lead by to become the current one: two, as
 * one landmark more in each of the first two frames is no camera's curve
 * (paper darker than the ceiling passes the contrast rule more often in
 * grey levels than in light); a linear camera takes the third frame. */
#define SWITCH_LEAD 2.0
/* Landmarks more that make a frame's own choice clear. */
#define CLEAR_LEAD 2

void rl_tones_init(rl_tones *ts, double gamma)
{
    int k;
    ts->n = gamma > 0 ? 1 : 2;
    ts->gamma[0] = gamma > 0 ? gamma : 2.2; /* cameras for robots mostly speak sRGB */
    /* the other image formation: grey levels mixed (read linearly), or,
     * for a camera said to be linear, light under the sRGB-like curve */
    ts->gamma[1] = ts->gamma[0] == 1.0 ? 2.2 : 1.0;
    for (k = 0; k < RL_TONES_MAX; k++) {
        rl_tone_init(&ts->tone[k], ts->gamma[k]);
        ts->votes[k] = 0;
    }
    {
        /* rl_tone_init's darkness of each level (its packed words' low
         * halves), the same arithmetic */
        int v;
        for (v = 0; v < 256; v++) {
            double l = RL_TONE_MAX * pow(v / 255.0, RL_TONES_STEEP);
            ts->steep_dark[v] = (uint16_t)(RL_TONE_MAX - (int)(l + 0.5));
        }
    }
    ts->current = 0;
    ts->frames = 0;
}

static int settled(const rl_tones *ts)
{
    return ts->n < 2 || fabs(ts->votes[0] - ts->votes[1]) >= RL_TONES_SETTLE;
}

int rl_tones_to_try(const rl_tones *ts, int *which)
{
    which[0] = ts->current;
    if (ts->n < 2 || (settled(ts) && ts->frames % RL_TONES_RECHECK != 0))
        return 1;
    which[1] = 1 - ts->current;
    return 2;
}

int rl_tones_vote(rl_tones *ts, const int *which, int n, const int *identified)
{
    int k, best = 0, other, cur = 0;
    ts->frames++;
    if (n < 2)
        return 0;
    /* which[0] is the current curve: another is better only with more */
    for (k = 1; k < n; k++)
        if (identified[k] > identified[best])
            best = k;
    other = best == 0 ? 1 : 0;
    if (identified[best] == 0)
        return 0; /* a frame with none says nothing: no vote, and the votes kept as they
                     were (a settled curve stays settled across empty frames) */
    for (k = 0; k < ts->n; k++)
        ts->votes[k] *= VOTE_FADE;
    /* a tie with landmarks: the current curve does as well (on sharp
     * frames both read alike, and the choice settles instead of reading
     * every frame twice) */
    if (identified[best] > identified[other])
        ts->votes[which[best]] += 1.0;
    else if (identified[0] > 0)
        ts->votes[which[0]] += 1.0;
    /* the current curve changes when the other leads it clearly */
    if (ts->votes[1 - ts->current] > ts->votes[ts->current] + SWITCH_LEAD)
        ts->current = 1 - ts->current;
    /* the frame: read through what it says clearly, else the current curve */
    if (identified[best] >= identified[other] + CLEAR_LEAD)
        return best;
    for (k = 0; k < n; k++)
        if (which[k] == ts->current)
            cur = k;
    return cur;
}

int rl_tones_decided(int current, int other, int left)
{
    /* rl_tones_vote with which[0] current: identified[1] <= identified[0]
     * leaves best at 0, a vote for the current curve (or none, with none
     * identified) and the frame read through it; identified[1] >=
     * identified[0] + CLEAR_LEAD votes for the other and reads the frame
     * through it */
    return other + left <= current || other >= current + CLEAR_LEAD;
}

const rl_tone *rl_tones_doubt(const rl_tones *ts, const rl_tone *used)
{
    if (settled(ts))
        return NULL;
    return used == &ts->tone[0] ? &ts->tone[1] : &ts->tone[0];
}

const rl_tone *rl_tones_other(const rl_tones *ts, const rl_tone *used)
{
    return used == &ts->tone[0] ? &ts->tone[1] : &ts->tone[0];
}

void rl_tones_steep(const rl_tones *ts, rl_tone *t)
{
    int v;
    for (v = 0; v < 256; v++) {
        t->packed[v] = RL_TONE_PACK_COUNT + ts->steep_dark[v];
        t->light[v] = (float)(RL_TONE_MAX - ts->steep_dark[v]);
    }
}

const rl_tone *rl_tones_current(const rl_tones *ts)
{
    return &ts->tone[ts->current];
}

double rl_tones_gamma(const rl_tones *ts)
{
    return ts->gamma[ts->current];
}
