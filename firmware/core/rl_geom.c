#include "rl_geom.h"

#include <math.h>

int rl_geom_box_has(const rl_box *b, double x, double y)
{
    return x >= b->x0 && x <= b->x1 && y >= b->y0 && y <= b->y1;
}

int rl_geom_box_inside(const rl_box *in, const rl_box *out)
{
    return in->x0 >= out->x0 && in->x1 <= out->x1 && in->y0 >= out->y0 && in->y1 <= out->y1;
}

double rl_geom_box_gap(const rl_box *a, const rl_box *b)
{
    double dx = a->x0 > b->x1 ? a->x0 - b->x1 : b->x0 > a->x1 ? b->x0 - a->x1 : 0;
    double dy = a->y0 > b->y1 ? a->y0 - b->y1 : b->y0 > a->y1 ? b->y0 - a->y1 : 0;
    return sqrt(dx * dx + dy * dy);
}

void rl_geom_square_in(int W, int H, double cx, double cy, double half, int border, rl_box *b)
{
    b->x0 = (int)ceil(cx - half);
    b->y0 = (int)ceil(cy - half);
    b->x1 = (int)floor(cx + half);
    b->y1 = (int)floor(cy + half);
    if (b->x0 < border) b->x0 = border;
    if (b->y0 < border) b->y0 = border;
    if (b->x1 > W - 1 - border) b->x1 = W - 1 - border;
    if (b->y1 > H - 1 - border) b->y1 = H - 1 - border;
}

void rl_geom_circle_box(int W, int H, double cx, double cy, double r, rl_box *box)
{
    box->x0 = cx - r > 0 ? (int)floor(cx - r) : 0;
    box->y0 = cy - r > 0 ? (int)floor(cy - r) : 0;
    box->x1 = cx + r < W - 1 ? (int)ceil(cx + r) : W - 1;
    box->y1 = cy + r < H - 1 ? (int)ceil(cy + r) : H - 1;
}

double rl_geom_disk_visible(double r, double d)
{
    double seg;
    if (d >= r)
        return 1.0;
    if (d <= -r)
        return 0.0;
    seg = r * r * acos(d / r) - d * sqrt(r * r - d * d); /* the part beyond the edge */
    return 1.0 - seg / (M_PI * r * r);
}

double rl_geom_visible_in(int W, int H, double cx, double cy, double r)
{
    double v = 1.0;
    v = fmin(v, rl_geom_disk_visible(r, cx + 0.5));
    v = fmin(v, rl_geom_disk_visible(r, W - 0.5 - cx));
    v = fmin(v, rl_geom_disk_visible(r, cy + 0.5));
    v = fmin(v, rl_geom_disk_visible(r, H - 0.5 - cy));
    return v;
}

int rl_geom_disk_complete(int W, int H, double cx, double cy, double r)
{
    return cx - r >= -0.5 && cy - r >= -0.5 && cx + r <= W - 0.5 && cy + r <= H - 0.5;
}
