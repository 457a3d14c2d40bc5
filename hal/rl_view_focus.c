#include "rl_view_focus.h"

#include <math.h>

#define RAYS 32
/* Samples along a ray, half a pixel apart, from 4 px inside the edge to
 * 4 px outside. */
#define STEPS 17
#define REACH 4.0

/* Bilinear grey at (x, y), inside the image. */
static double grey(const uint8_t *img, int w, double x, double y)
{
    int x0 = (int)x, y0 = (int)y;
    double fx = x - x0, fy = y - y0;
    const uint8_t *p = img + (size_t)y0 * (size_t)w + (size_t)x0;
    return (1 - fy) * ((1 - fx) * p[0] + fx * p[1]) + fy * ((1 - fx) * p[w] + fx * p[w + 1]);
}

/* One ray's steepest step over its height; 0 with no contrast. */
static double ray(const uint8_t *img, int w, const rl_detection *d, double a)
{
    double s[STEPS], steep = 0, in, out;
    int i;
    for (i = 0; i < STEPS; i++) {
        double r = d->radius - REACH + i * (2 * REACH / (STEPS - 1));
        s[i] = grey(img, w, d->u + r * cos(a), d->v + r * sin(a));
    }
    for (i = 1; i < STEPS - 1; i++) {
        /* central difference, per pixel */
        double g = (s[i + 1] - s[i - 1]) / (2 * (2 * REACH / (STEPS - 1)));
        if (g > steep)
            steep = g;
    }
    in = 0.5 * (s[0] + s[1]);
    out = 0.5 * (s[STEPS - 1] + s[STEPS - 2]);
    return out - in > 8 ? steep / (out - in) : 0;
}

double rl_view_focus_landmark(const uint8_t *img, int w, int h, const rl_detection *d)
{
    double sum = 0, reach = d->radius + REACH + 2;
    int i, n = 0;
    /* wholly inside, the edge's samples too (NaN fails every test) */
    if (!d->complete || !(d->radius >= 6) || !(d->u - reach >= 0 && d->v - reach >= 0 && d->u + reach <= w - 2 &&
                                               d->v + reach <= h - 2))
        return NAN;
    for (i = 0; i < RAYS; i++) {
        double f = ray(img, w, d, 2 * M_PI * i / RAYS);
        if (f > 0) {
            sum += f;
            n++;
        }
    }
    /* a ring whose edge shows on fewer than half the rays: a lamp's glare
     * or a cut sheet, not an edge to judge */
    return n >= RAYS / 2 ? sum / n : NAN;
}

double rl_view_focus_frame(const uint8_t *img, int w, int h, const rl_result *res, double *per)
{
    double v[RL_MAX_LANDMARKS], t;
    int i, j, n = 0;
    for (i = 0; i < res->n_landmarks && i < RL_MAX_LANDMARKS; i++) {
        double f = rl_view_focus_landmark(img, w, h, &res->landmarks[i]);
        if (per != NULL)
            per[i] = f;
        if (isnan(f))
            continue;
        for (t = f, j = n++; j > 0 && v[j - 1] > t; j--)
            v[j] = v[j - 1];
        v[j] = t;
    }
    if (n == 0)
        return NAN;
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double rl_view_focus_blur_px(double f)
{
    return f > 0 ? 1.0 / (f * sqrt(2 * M_PI)) : NAN;
}
