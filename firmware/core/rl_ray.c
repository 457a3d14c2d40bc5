#include "rl_ray.h"

#include <float.h>
#include <math.h>
#include <string.h>
#include "rl_clones.h"

/* rl_ray_sample_lit finds light by NaN samples: a build that assumes no
 * NaN (-ffast-math, -Ofast, -ffinite-math-only) would read through light. */
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "rl_ray.c tests samples for NaN: build the core without -ffast-math, -Ofast or -ffinite-math-only"
#endif

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

/* The samples are placed in float (x + i dx, each term rounded): a
 * position up to the image's size is off by at most some 6 float epsilons
 * of that size, so an end closer than SLACK of them to the last column or
 * row could land on it and read the pixel past it. */
#define SLACK (8 * FLT_EPSILON)

int rl_ray_inside(const rl_image *img, double x0, double y0, double x1, double y1)
{
    double slack = SLACK * (img->width > img->height ? img->width : img->height);
    double xm = img->width - 1 - slack, ym = img->height - 1 - slack;
    return x0 >= 0 && x1 >= 0 && y0 >= 0 && y1 >= 0 && x0 < xm && x1 < xm && y0 < ym && y1 < ym;
}

/* rl_ray_sample's loop from sample i0 on, the light of grey levels from
 * lt; inlined with light 256 too, where the compiler drops the four tests
 * a sample (a byte is never 256). nan_stops: lt is an rl_ray_lit's, and a
 * NaN sample stops the ray (constant, the test dropped where 0). */
static inline int sample_from(const rl_image *img, const float *lt, float fx0, float fy0, float fdx,
                              float fdy, int i0, int n, int light, int nan_stops, float *out)
{
    int i, st = img->stride;
    for (i = i0; i < n; i++) {
        float px = fx0 + (float)i * fdx, py = fy0 + (float)i * fdy, fx, fy, top, bot;
        int x0 = (int)px, y0 = (int)py; /* px, py >= 0: truncation is floor */
        const uint8_t *p = img->data + (size_t)y0 * (size_t)st + x0;
        int p00 = p[0], p01 = p[1], p10 = p[st], p11 = p[st + 1];
        if (p00 >= light || p01 >= light || p10 >= light || p11 >= light)
            return 0;
        fx = px - (float)x0;
        fy = py - (float)y0;
        top = lt[p00] + fx * (lt[p01] - lt[p00]);
        bot = lt[p10] + fx * (lt[p11] - lt[p10]);
        out[i] = top + fy * (bot - top);
        if (nan_stops && out[i] != out[i])
            return 0;
    }
    return 1;
}

static inline int sample_ray(const rl_image *img, const rl_tone *tone, double x, double y, double dx,
                             double dy, int n, int light, float *out)
{
    return sample_from(img, tone->light, (float)x, (float)y, (float)dx, (float)dy, 0, n, light, 0, out);
}

/* GCC's vector extensions with __builtin_convertvector (GCC 9 on, clang) */
#if defined(__GNUC__) && (defined(__clang__) || __GNUC__ >= 9) && !defined(RL_NO_VECTOR_EXT)
#define RAY_VECTORS 1
#endif

#ifdef RAY_VECTORS
typedef float ray_v4 __attribute__((vector_size(16)));
typedef int ray_i4 __attribute__((vector_size(16)));
typedef long long ray_l2 __attribute__((vector_size(16))); /* a lane mask read as two halves */

/* sample_ray four samples at a time: the positions and the interpolation
 * in 4-lane vectors, the same operations lane by lane as sample_ray's in
 * turn (the same floats); the pixels and their light (from lt) fetched one
 * by one, the light level tested for the four together (the same answer:
 * 0 when any sample touches light; out is then left part written), or
 * with nan_stops (as sample_from) the four samples tested for NaN together. */
static inline int sample_ray_v4(const rl_image *img, const float *lt, double x, double y, double dx,
                                 double dy, int n, int light, int nan_stops, float *out)
{
    float fx0 = (float)x, fy0 = (float)y, fdx = (float)dx, fdy = (float)dy;
    int i, k, st = img->stride;
    /* the samples' indices as floats, counted up by 4 (exact) */
    ray_v4 fi = {0.0f, 1.0f, 2.0f, 3.0f}, four = {4.0f, 4.0f, 4.0f, 4.0f};
    ray_i4 vst = {st, st, st, st};
    int lit = 0; /* a sample touched a pixel at or above light */
    for (i = 0; i + 4 <= n; i += 4, fi += four) {
        ray_v4 px = fx0 + fi * fdx, py = fy0 + fi * fdy, fx, fy, l00, l01, l10, l11, top, bot, o;
        ray_i4 x0 = __builtin_convertvector(px, ray_i4), y0 = __builtin_convertvector(py, ray_i4);
        /* each sample's pixel offset in the image (rl_ray_sample: under
         * 2^31), the four pixels' light gathered into arrays */
        ray_i4 off = y0 * vst + x0;
        int offs[4];
        float a00[4], a01[4], a10[4], a11[4];
        memcpy(offs, &off, sizeof offs);
        fx = px - __builtin_convertvector(x0, ray_v4);
        fy = py - __builtin_convertvector(y0, ray_v4);
        for (k = 0; k < 4; k++) {
            const uint8_t *p = img->data + offs[k];
            int p00 = p[0], p01 = p[1], p10 = p[st], p11 = p[st + 1];
            lit |= (p00 >= light) | (p01 >= light) | (p10 >= light) | (p11 >= light);
            a00[k] = lt[p00];
            a01[k] = lt[p01];
            a10[k] = lt[p10];
            a11[k] = lt[p11];
        }
        if (lit)
            return 0;
        memcpy(&l00, a00, sizeof l00);
        memcpy(&l01, a01, sizeof l01);
        memcpy(&l10, a10, sizeof l10);
        memcpy(&l11, a11, sizeof l11);
        top = l00 + fx * (l01 - l00);
        bot = l10 + fx * (l11 - l10);
        o = top + fy * (bot - top);
        if (nan_stops) {
            /* any NaN of the four: the mask's two halves (fewer
             * instructions than its four lanes) */
            ray_l2 nan = (ray_l2)(o != o);
            if (nan[0] | nan[1])
                return 0;
        }
        memcpy(out + i, &o, sizeof o);
    }
    /* the last samples as sample_ray takes them */
    return sample_from(img, lt, fx0, fy0, fdx, fdy, i, n, light, nan_stops, out);
}
#endif

RL_CLONES_AVX2
int rl_ray_sample(const rl_image *img, const rl_tone *tone, double x, double y, double dx,
                  double dy, int n, int light, float *out)
{
#ifdef RAY_VECTORS
    /* the vector path's pixel offsets are ints */
    if ((double)img->height * img->stride < 2147483647.0)
        return light > 255 ? sample_ray_v4(img, tone->light, x, y, dx, dy, n, 256, 0, out)
                           : sample_ray_v4(img, tone->light, x, y, dx, dy, n, light, 0, out);
#endif
    if (light > 255)
        return sample_ray(img, tone, x, y, dx, dy, n, 256, out);
    return sample_ray(img, tone, x, y, dx, dy, n, light, out);
}

/* A copy and a fill (light is mostly near the top: few NaNs), about 190
 * instructions where a test a level took 1,800. */
void rl_ray_lit_init(rl_ray_lit *lit, const rl_tone *tone, int light)
{
    int g, under = light < 0 ? 0 : light > 256 ? 256 : light;
    memcpy(lit->light, tone->light, (size_t)under * sizeof lit->light[0]);
    for (g = under; g < 256; g++)
        lit->light[g] = NAN;
}

/* A sample is NaN exactly when one of its four pixels is at or above the
 * light level: tone's light is finite, and a NaN among the four carries
 * through every term of the interpolation, even at weight 0 (0 * NaN is
 * NaN), as rl_ray_sample stops on a pixel whatever its weight. The core
 * is built without fast-math (firmware/CMakeLists.txt), under which the
 * NaN test could be dropped; test_ray would then fail. */
RL_CLONES_AVX2
int rl_ray_sample_lit(const rl_image *img, const rl_ray_lit *lit, double x, double y, double dx,
                      double dy, int n, float *out)
{
#ifdef RAY_VECTORS
    if ((double)img->height * img->stride < 2147483647.0)
        return sample_ray_v4(img, lit->light, x, y, dx, dy, n, 256, 1, out);
#endif
    return sample_from(img, lit->light, (float)x, (float)y, (float)dx, (float)dy, 0, n, 256, 1, out);
}
