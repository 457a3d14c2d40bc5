#include "rl_tone.h"

#include <math.h>

void rl_tone_init(rl_tone *t, double gamma)
{
    int v;
    for (v = 0; v < 256; v++) {
        double l = RL_TONE_MAX * pow(v / 255.0, gamma);
        t->light[v] = (float)l;
        t->dark[v] = (uint16_t)(RL_TONE_MAX - (int)(l + 0.5));
        t->packed[v] = RL_TONE_PACK_COUNT + t->dark[v];
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
    double mid = 0.5 * (rl_tone_light(t, g0) + rl_tone_light(t, g1));
    int v;
    for (v = 0; v < 255 && rl_tone_light(t, v + 0.5) < mid; v++)
        ;
    return v;
}
