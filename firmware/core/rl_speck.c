#include "rl_speck.h"

#include <math.h>

int rl_speck_area(const rl_recog_config *cfg)
{
    int n = cfg->family.bits;
    double r = cfg->min_radius;
    double zone = M_PI * 0.64 * r * r / n;
    int a = (int)(0.1 * zone);
    return a < 2 ? 2 : a;
}
