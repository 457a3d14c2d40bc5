#include "rl_profile.h"

#include <math.h>

void rl_profile_gather(const rl_image *img, double cx, double cy, double r, rl_profile *p)
{
    double ext = RL_PROFILE_EXTENT * r, scale = RL_PROFILE_BINS / ext, e2 = ext * ext;
    int x, y, k, x0 = (int)ceil(cx - ext), x1 = (int)floor(cx + ext);
    int y0 = (int)ceil(cy - ext), y1 = (int)floor(cy + ext);
    double sxx = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->n[k] = p->sx[k] = 0;
    /* pixels outside the image are not gathered: a cut landmark meets cut
     * templates */
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > img->width - 1) x1 = img->width - 1;
    if (y1 > img->height - 1) y1 = img->height - 1;
    for (y = y0; y <= y1; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - cy, dy2 = dy * dy;
        for (x = x0; x <= x1; x++) {
            double dx = x - cx, d2 = dx * dx + dy2, v;
            if (d2 >= e2)
                continue;
            k = (int)(sqrt(d2) * scale);
            v = 255 - row[x];
            p->n[k] += 1;
            p->sx[k] += v;
            sxx += v * v;
        }
    }
    p->sxx = sxx;
    p->total = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->total += p->n[k];
}
