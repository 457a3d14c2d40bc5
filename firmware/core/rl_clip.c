/* rl_clip: a landmark's clipped light side (rl_clip.h). */
#include "rl_clip.h"

#include <math.h>
#include <stdint.h>

#include "rl_twins_rank.h"

double rl_clip_disk_share(const rl_image *img, double u, double v, double r, int level, int row_step)
{
    int x, y, n = 0, at = 0;
    int y0 = (int)ceil(v - r), y1 = (int)floor(v + r);
    for (y = y0 < 0 ? 0 : y0; y <= y1 && y < img->height; y += row_step) {
        double h = sqrt(fmax(0.0, r * r - (y - v) * (y - v)));
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        int x0 = (int)ceil(u - h), x1 = (int)floor(u + h);
        for (x = x0 < 0 ? 0 : x0; x <= x1 && x < img->width; x++) {
            n++;
            at += row[x] >= level;
        }
    }
    return n > 0 ? (double)at / n : 0.0;
}

int rl_clip_refuses(const rl_recog *rec, const rl_image *img, int light, const rl_detection *d)
{
    return rl_clip_disk_share(img, d->u, d->v, RL_CLIP_REACH * d->radius, RL_CLIP_LEVEL, 1) >= RL_CLIP_SHARE &&
           !rl_twins_rank_keeps(rec, img, rec->tone, light, d);
}
