/* draw_slanted: see draw_slanted.h. */
#include "draw_slanted.h"
#include <math.h>
#include "rl_templates.h"

rl_image draw_slanted(uint8_t *pix, int w, int h, int id, double cx, double cy, double r, double sigma,
                      double sx)
{
    rl_family fam = {5};
    int x, y;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double dx = (x - cx) / sx, dy = y - cy;
            double dark = rl_templates_value_at(&fam, id, sqrt(dx * dx + dy * dy) / r, sigma);
            pix[y * w + x] = (uint8_t)lround(220 - 190 * dark);
        }
    return rl_image_view(w, h, w, pix);
}
