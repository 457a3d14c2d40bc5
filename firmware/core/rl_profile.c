#include "rl_profile.h"

#include <math.h>

/* Pixels binned by the shape's normalized radius, a circle's included:
 * for (1, 0, 1) every step below gives the same bits as dx^2 + dy^2. */
static void gather(const rl_image *img, double cx, double cy, double r, const rl_shape *sh,
                   rl_profile *p)
{
    double ext = RL_PROFILE_EXTENT * r, scale = RL_PROFILE_BINS / ext, e2 = ext * ext, sxx = 0;
    /* the ellipse's extent along x and y */
    double hx = ext * sqrt(sh->c), hy = ext * sqrt(sh->a);
    int x, y, k, x0 = (int)ceil(cx - hx), x1 = (int)floor(cx + hx);
    int y0 = (int)ceil(cy - hy), y1 = (int)floor(cy + hy);
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
        double dy = y - cy, cdy2 = sh->c * dy * dy, b2dy = 2 * sh->b * dy;
        for (x = x0; x <= x1; x++) {
            double dx = x - cx, d2 = (sh->a * dx + b2dy) * dx + cdy2, v;
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

void rl_profile_gather(const rl_image *img, double cx, double cy, double r, rl_profile *p)
{
    rl_shape circle = rl_shape_circle();
    gather(img, cx, cy, r, &circle, p);
}

void rl_profile_gather_shaped(const rl_image *img, double cx, double cy, double r,
                              const rl_shape *sh, rl_profile *p)
{
    rl_shape circle = rl_shape_circle();
    gather(img, cx, cy, r, sh ? sh : &circle, p);
}

rl_shape rl_shape_circle(void)
{
    rl_shape s;
    s.a = s.c = 1.0;
    s.b = 0.0;
    return s;
}

int rl_shape_is_circle(const rl_shape *s)
{
    return s->a == 1.0 && s->b == 0.0 && s->c == 1.0;
}

rl_shape rl_shape_from_moments(double cxx, double cxy, double cyy)
{
    double det = cxx * cyy - cxy * cxy, tr = cxx + cyy, disc, l1, l2, root;
    rl_shape s = rl_shape_circle();
    if (!(det > 0) || !(tr > 0))
        return s;
    disc = sqrt(fmax(0.0, 0.25 * tr * tr - det));
    l1 = 0.5 * tr + disc;
    l2 = 0.5 * tr - disc;
    if (!(l2 > 0) || sqrt(l2 / l1) > 0.97)
        return s;
    /* the inverse covariance, scaled to determinant 1 */
    root = sqrt(det);
    s.a = cyy / root;
    s.b = -cxy / root;
    s.c = cxx / root;
    return s;
}

double rl_shape_step(const rl_shape *sh, double c, double s)
{
    return 1.0 / sqrt(sh->a * c * c + 2 * sh->b * c * s + sh->c * s * s);
}
