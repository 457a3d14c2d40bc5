#include "rl_light.h"

#include "rl_result.h"

rl_err rl_light_find(rl_label *lb, const rl_image *img, int level, int min_area, rl_result *res)
{
    int i, H = img->height;
    rl_image half;
    rl_err e;
    if (level >= 256)
        return RL_OK;
    /* every other row: a view with twice the stride */
    half = rl_image_view(img->width, (H + 1) / 2, img->stride * 2, img->data);
    if ((e = rl_label_band(lb, &half, level, 256, min_area)) != RL_OK)
        return e;
    res->dropped.lights += lb->overflow + (lb->rows_left > 0);
    for (i = 0; i < lb->n_regions; i++) {
        const rl_region *g = &lb->reg[i];
        rl_box b;
        b.x0 = g->x0;
        b.y0 = 2 * g->y0;
        b.x1 = g->x1;
        b.y1 = 2 * g->y1 + 1 < H ? 2 * g->y1 + 1 : H - 1;
        rl_result_add_light(res, &b);
    }
    return RL_OK;
}
