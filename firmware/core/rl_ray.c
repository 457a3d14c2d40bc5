#include "rl_ray.h"

#include <math.h>

/* By rotation from the first direction: four trigonometric calls instead
 * of 2 n. */
void rl_ray_dirs(int n, double *c, double *s)
{
    double dc = cos(2 * M_PI / n), ds = sin(2 * M_PI / n);
    int a;
    c[0] = cos(M_PI / n);
    s[0] = sin(M_PI / n);
    for (a = 1; a < n; a++) {
        c[a] = c[a - 1] * dc - s[a - 1] * ds;
        s[a] = s[a - 1] * dc + c[a - 1] * ds;
    }
}

int rl_ray_inside(const rl_image *img, double x0, double y0, double x1, double y1)
{
    return x0 >= 0 && x1 >= 0 && y0 >= 0 && y1 >= 0 && x0 < img->width - 1 &&
           x1 < img->width - 1 && y0 < img->height - 1 && y1 < img->height - 1;
}

/* rl_ray_sample's loop; inlined twice, once with light 256, where the
 * compiler drops the four tests a sample (a byte is never 256). */
static inline int sample_ray(const rl_image *img, const rl_tone *tone, double x, double y, double dx,
                             double dy, int n, int light, float *out)
{
    float fx0 = (float)x, fy0 = (float)y, fdx = (float)dx, fdy = (float)dy;
    int i, st = img->stride;
    for (i = 0; i < n; i++) {
        float px = fx0 + (float)i * fdx, py = fy0 + (float)i * fdy, fx, fy, top, bot;
        int x0 = (int)px, y0 = (int)py; /* px, py >= 0: truncation is floor */
        const uint8_t *p = img->data + (size_t)y0 * (size_t)st + x0;
        int p00 = p[0], p01 = p[1], p10 = p[st], p11 = p[st + 1];
        if (p00 >= light || p01 >= light || p10 >= light || p11 >= light)
            return 0;
        fx = px - (float)x0;
        fy = py - (float)y0;
        top = tone->light[p00] + fx * (tone->light[p01] - tone->light[p00]);
        bot = tone->light[p10] + fx * (tone->light[p11] - tone->light[p10]);
        out[i] = top + fy * (bot - top);
    }
    return 1;
}

int rl_ray_sample(const rl_image *img, const rl_tone *tone, double x, double y, double dx,
                  double dy, int n, int light, float *out)
{
    if (light > 255)
        return sample_ray(img, tone, x, y, dx, dy, n, 256, out);
    return sample_ray(img, tone, x, y, dx, dy, n, light, out);
}
