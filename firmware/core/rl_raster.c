#include "rl_raster.h"

#include <math.h>

/* Subsamples per axis for pixels that straddle a zone boundary. 8x8 keeps
 * the coverage error under 1/64 of a pixel per boundary crossing. */
#define SUB 8

rl_raster_cut rl_raster_cut_side(int side, double at)
{
    rl_raster_cut c;
    c.nx = side == 0 ? 1.0 : side == 1 ? -1.0 : 0.0;
    c.ny = side == 2 ? 1.0 : side == 3 ? -1.0 : 0.0;
    c.d = side == 0 || side == 2 ? at : -at;
    return c;
}

static int near_boundary(const double *radii, int nb, double dist, double r)
{
    int i;
    for (i = 0; i < nb; i++)
        if (fabs(dist - radii[i] * r) < 0.75) /* a pixel's half-diagonal is 0.707 */
            return 1;
    return 0;
}

rl_err rl_raster_draw(const rl_family *fam, int id, double cx, double cy, double r,
                    const rl_raster_cut *cut, rl_image *dark, rl_image *mask)
{
    double radii[RL_MAX_BITS + 2];
    int x, y, nb;
    if (fam == NULL || !rl_image_valid(dark) || !(r > 0.0))
        return RL_EINVAL;
    if (mask != NULL && (!rl_image_valid(mask) || mask->width != dark->width ||
                         mask->height != dark->height))
        return RL_EINVAL;
    if (!rl_family_valid(fam, id))
        return RL_ERANGE;
    rl_family_radii(fam, radii);
    nb = fam->bits + 1; /* r[N+1] = 0 is no boundary */
    for (y = 0; y < dark->height; y++) {
        uint8_t *d = dark->data + (size_t)y * (size_t)dark->stride;
        uint8_t *m = mask ? mask->data + (size_t)y * (size_t)mask->stride : NULL;
        double dy = y - cy;
        for (x = 0; x < dark->width; x++) {
            double dx = x - cx, dist = sqrt(dx * dx + dy * dy);
            int v;
            if (cut != NULL && cut->nx * x + cut->ny * y > cut->d) {
                d[x] = 0;
                if (m)
                    m[x] = 0;
                continue;
            }
            if (m)
                m[x] = 255;
            if (dist > r + 0.75) {
                v = 0;
            } else if (!near_boundary(radii, nb, dist, r)) {
                v = 255 * rl_family_dark_at(fam, id, dist / r);
            } else {
                int sx, sy, n = 0;
                for (sy = 0; sy < SUB; sy++) {
                    double py = dy + (sy + 0.5) / SUB - 0.5;
                    for (sx = 0; sx < SUB; sx++) {
                        double px = dx + (sx + 0.5) / SUB - 0.5;
                        n += rl_family_dark_at(fam, id, sqrt(px * px + py * py) / r);
                    }
                }
                v = (255 * n + SUB * SUB / 2) / (SUB * SUB);
            }
            d[x] = (uint8_t)v;
        }
    }
    return RL_OK;
}

rl_err rl_raster_square(const rl_family *fam, int id, const rl_raster_cut *cut, rl_image *dark,
                      rl_image *mask)
{
    double c;
    if (!rl_image_valid(dark) || dark->width != dark->height)
        return RL_EINVAL;
    c = (dark->width - 1) / 2.0;
    return rl_raster_draw(fam, id, c, c, dark->width / 2.0, cut, dark, mask);
}
