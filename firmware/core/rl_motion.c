#include "rl_motion.h"

#include <math.h>
#include "rl_geom.h"

/* Radii the gradients are taken over, shares of r: the code zones and the
 * outer ring (the centre dot's edge is a few pixels round; the quiet zone
 * beyond 1.15 r holds none of the landmark's). */
#define INNER 0.25
#define OUTER 1.15
/* Pixels an axis needs (of the some 330 a whole 24 px landmark gives it at
 * every pixel). */
#define MIN_PIXELS 40

/* tan(22.5 degrees): the wedge's half-width about an axis. */
#define WEDGE_TAN 0.41421356

/* The axis a pixel at (dx, dy) lies on: within 22.5 degrees of a row or a
 * column, else on the diagonal its signs give. */
static int axis_of(double dx, double dy)
{
    double ax = fabs(dx), ay = fabs(dy);
    if (ay <= WEDGE_TAN * ax)
        return 0;
    if (ax <= WEDGE_TAN * ay)
        return 2;
    return (dx > 0) == (dy > 0) ? 1 : 3;
}

int rl_motion_on_axis(double dx, double dy, int a)
{
    return axis_of(dx, dy) == a;
}

int rl_motion_measure(const rl_image *img, double cx, double cy, double r, rl_motion *m)
{
    double sum[RL_MOTION_AXES] = {0}, n[RL_MOTION_AXES] = {0}, lo2 = INNER * INNER * r * r,
           hi2 = OUTER * OUTER * r * r;
    rl_box b;
    int x, y, a;
    /* central differences: one pixel in from the image's edge */
    rl_geom_square_in(img->width, img->height, cx, cy, OUTER * r, 1, &b);
    for (y = b.y0; y <= b.y1; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - cy;
        for (x = b.x0; x <= b.x1; x++) {
            double dx = x - cx, d2 = dx * dx + dy * dy, gx, gy, g;
            if (d2 < lo2 || d2 > hi2)
                continue;
            gx = (double)row[x + 1] - row[x - 1];
            gy = (double)row[x + (int)img->stride] - row[x - (int)img->stride];
            g = (gx * dx + gy * dy) / sqrt(d2);
            a = axis_of(dx, dy);
            sum[a] += g * g;
            n[a] += 1;
        }
    }
    for (a = 0; a < RL_MOTION_AXES; a++) {
        if (n[a] < MIN_PIXELS)
            return 0;
        m->energy[a] = sum[a] / n[a];
    }
    /* axes compared with the one at right angles only: the pixel grid
     * differences the diagonals from the rows and columns (a still
     * landmark's diagonals read 0.75-0.95 of its rows' energy) */
    m->ratio = 2;
    for (a = 0; a < RL_MOTION_AXES / 2; a++) {
        double e0 = m->energy[a], e1 = m->energy[a + 2], lo = e0 < e1 ? e0 : e1, hi = e0 < e1 ? e1 : e0;
        if (!(hi > 0))
            return 0;
        if (lo / hi < m->ratio) {
            m->ratio = lo / hi;
            m->axis = e0 < e1 ? a + 2 : a;
        }
    }
    return 1;
}
