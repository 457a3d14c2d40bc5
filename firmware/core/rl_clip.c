/* rl_clip: a landmark's clipped light side (rl_clip.h). */
#include "rl_clip.h"

#include <math.h>

#include "rl_twins_rank.h"

double rl_clip_share(const rl_image *img, double u, double v, double r)
{
    double reach = RL_CLIP_REACH * r, r2 = reach * reach;
    int x0 = (int)floor(u - reach), x1 = (int)ceil(u + reach);
    int y0 = (int)floor(v - reach), y1 = (int)ceil(v + reach);
    long all = 0, clipped = 0;
    int x, y;
    if (x0 < 0)
        x0 = 0;
    if (y0 < 0)
        y0 = 0;
    if (x1 > img->width - 1)
        x1 = img->width - 1;
    if (y1 > img->height - 1)
        y1 = img->height - 1;
    for (y = y0; y <= y1; y++) {
        const uint8_t *row = img->data + (size_t)y * img->stride;
        double dy = y - v;
        for (x = x0; x <= x1; x++) {
            double dx = x - u;
            if (dx * dx + dy * dy > r2)
                continue;
            all++;
            clipped += row[x] >= RL_CLIP_LEVEL;
        }
    }
    return all > 0 ? (double)clipped / (double)all : 0.0;
}

int rl_clip_refuses(const rl_recog *rec, const rl_image *img, int light, const rl_detection *d)
{
    return rl_clip_share(img, d->u, d->v, d->radius) >= RL_CLIP_SHARE &&
           !rl_twins_rank_keeps(rec, img, rec->tone, light, d);
}
