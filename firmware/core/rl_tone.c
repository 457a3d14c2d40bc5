#include "rl_tone.h"

#include <math.h>

void rl_tone_init(rl_tone *t, double gamma)
{
    int v;
    for (v = 0; v < 256; v++) {
        double l = RL_TONE_MAX * pow(v / 255.0, gamma);
        t->light[v] = (float)l;
        /* its darkness, RL_TONE_MAX - light rounded, in the low word */
        t->packed[v] = RL_TONE_PACK_COUNT + (uint64_t)(RL_TONE_MAX - (int)(l + 0.5));
    }
}

double rl_tone_light(const rl_tone *t, double grey)
{
    int i;
    if (!(grey > 0))
        return t->light[0];
    if (grey >= 255)
        return t->light[255];
    i = (int)grey;
    return t->light[i] + (grey - i) * (t->light[i + 1] - t->light[i]);
}

int rl_tone_midway(const rl_tone *t, double g0, double g1)
{
    /* the first v under 255 whose light at v + 0.5 reaches mid, else 255:
     * a curve's light never falls as the grey level rises (rl_tone_init's
     * powers), so it is found by halving [lo, hi], where every v under lo
     * stays under mid and hi is the answer or 255 */
    double mid = 0.5 * (rl_tone_light(t, g0) + rl_tone_light(t, g1));
    int lo = 0, hi = 255;
    while (lo < hi) {
        int v = (lo + hi) / 2;
        if (rl_tone_light(t, v + 0.5) < mid)
            lo = v + 1;
        else
            hi = v;
    }
    return lo;
}
