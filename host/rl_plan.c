#include "rl_plan.h"

#include <math.h>
#include "rl_calib.h"
#include "rl_config.h"
#include "rl_family.h"

void rl_plan_defaults(rl_plan_input *in)
{
    in->landmarks = 0;
    in->width = 640;
    in->height = 480;
    in->fx = 0.0;
    in->distance = 0.0;
    in->min_ring_px = 2.0;
    in->max_diameter = 0.210;
    in->step = 0.005;
}

/* Lattice points of pitch p inside the rectangle of half-sizes (hw, hh)
 * centred at (ox, oy) and rotated by th. */
static int count_in(double p, double hw, double hh, double ox, double oy, double th)
{
    double c = cos(th), s = sin(th), reach = sqrt(hw * hw + hh * hh);
    int i0 = (int)floor((ox - reach) / p), i1 = (int)ceil((ox + reach) / p);
    int j0 = (int)floor((oy - reach) / p), j1 = (int)ceil((oy + reach) / p);
    int i, j, n = 0;
    for (i = i0; i <= i1; i++)
        for (j = j0; j <= j1; j++) {
            double dx = i * p - ox, dy = j * p - oy;
            double u = c * dx + s * dy, v = -s * dx + c * dy;
            if (fabs(u) <= hw && fabs(v) <= hh)
                n++;
        }
    return n;
}

int rl_plan_min_in_view(double p, double w, double h, int samples)
{
    int a, sx, sy, best = 1 << 30;
    /* The square lattice repeats every 90 degrees and every cell, so one
     * cell and a quarter turn cover every pose. */
    for (a = 0; a < 90; a++) {
        double th = a * M_PI / 180.0;
        for (sx = 0; sx < samples; sx++)
            for (sy = 0; sy < samples; sy++) {
                int n = count_in(p, w / 2, h / 2, (sx + 0.5) * p / samples,
                                 (sy + 0.5) * p / samples, th);
                if (n < best)
                    best = n;
            }
    }
    return best;
}

rl_err rl_plan_compute(const rl_plan_input *in, rl_plan_result *out)
{
    int n, k;
    double zone1, R, uw, uh, lo, hi;
    rl_family fam;
    out->bits = 0;
    if (in->landmarks <= 0 || in->width <= 0 || in->height <= 0 || in->width > RL_MAX_IMAGE_DIM ||
        in->height > RL_MAX_IMAGE_DIM || !(in->fx >= RL_CALIB_MIN_F && in->fx <= RL_CALIB_MAX_F) ||
        !(in->distance > 0 && in->distance <= 1000) || !(in->min_ring_px > 0 && in->min_ring_px <= 1000) ||
        !(in->step > 0 && in->step <= 1))
        return RL_EINVAL;
    for (n = RL_FAMILY_MIN_BITS; n <= RL_MAX_BITS && (1 << n) - 2 < in->landmarks; n++)
        ;
    if (n > RL_MAX_BITS)
        return RL_ERANGE;
    if (rl_family_init(&fam, n) != RL_OK)
        return RL_ERANGE;
    out->bits = n;
    out->px_per_m = in->fx / in->distance;
    out->view_w = in->width / out->px_per_m;
    out->view_h = in->height / out->px_per_m;
    /* Code zone 1 (next to the outer ring) is the narrowest: equal areas
     * make the zones thinner towards the outside. */
    zone1 = RL_OUTER_RING_INNER * (1.0 - sqrt((double)(n - 1) / n));
    out->diameter_min = 2.0 * (in->min_ring_px / zone1) / out->px_per_m;
    out->diameter = ceil(out->diameter_min / in->step - 1e-9) * in->step;
    R = out->radius_px = out->diameter / 2 * out->px_per_m;
    {
        double r[RL_MAX_BITS + 2];
        rl_family_radii(&fam, r);
        for (k = 0; k <= n; k++)
            out->ring_px[k] = (r[k] - r[k + 1]) * R;
    }
    /* A landmark is whole in view when its centre is at least R (plus a
     * pixel) inside every image side. */
    uw = (in->width - 2 * (R + 1)) / out->px_per_m;
    uh = (in->height - 2 * (R + 1)) / out->px_per_m;
    out->pitch_max = out->pitch = 0;
    if (uw > 0 && uh > 0) {
        lo = 0.01;
        hi = sqrt(uw * uw + uh * uh);
        while (hi - lo > 0.002) {
            double mid = (lo + hi) / 2;
            if (rl_plan_min_in_view(mid, uw, uh, 16) >= 2)
                lo = mid;
            else
                hi = mid;
        }
        out->pitch_max = lo;
        out->pitch = floor(0.95 * lo / 0.005) * 0.005;
    }
    if (out->diameter > in->max_diameter + 1e-12)
        return RL_ERANGE;
    return RL_OK;
}
