#include "render_sensor.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void render_sensor_defaults(render_sensor *se)
{
    memset(se, 0, sizeof *se);
    se->blur = 0.5;
    se->full_well = 6000;
    se->read_noise = 1.5;
    se->adc_bits = 10;
    se->tone = RENDER_TONE_GAMMA22;
}

/* One pass of a 1-D kernel (taps k[-rad .. rad]) along x (dx = 1) or y;
 * the image's edge repeated beyond it. */
static void convolve_1d(const double *src, double *dst, int W, int H, const double *k, int rad, int along_x)
{
    size_t step = along_x ? 1 : (size_t)W;
    int x, y, j;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int at = along_x ? x : y, n = along_x ? W : H;
            double acc = 0;
            if (at >= rad && at < n - rad) { /* every tap inside: the same sum, unclamped */
                const double *p = src + (size_t)y * W + x - rad * step;
                for (j = 0; j <= 2 * rad; j++)
                    acc += k[j] * p[j * step];
            } else {
                for (j = -rad; j <= rad; j++) {
                    int xx = along_x ? x + j : x, yy = along_x ? y : y + j;
                    xx = xx < 0 ? 0 : xx >= W ? W - 1 : xx;
                    yy = yy < 0 ? 0 : yy >= H ? H - 1 : yy;
                    acc += k[j + rad] * src[(size_t)yy * W + xx];
                }
            }
            dst[(size_t)y * W + x] = acc;
        }
}

/* A kernel of nk taps and a frame-sized scratch image; 0, or -1 (both
 * freed) out of memory. */
static int scratch(size_t nk, double **k, size_t npx, double **tmp)
{
    *k = malloc(sizeof(double) * nk);
    *tmp = malloc(sizeof(double) * npx);
    if (*k != NULL && *tmp != NULL)
        return 0;
    free(*k);
    free(*tmp);
    return -1;
}

int render_blur_gauss(double *img, int W, int H, double sigma)
{
    int rad = (int)ceil(3 * sigma), j;
    double *k, *tmp, sum = 0;
    if (sigma <= 0.05)
        return 0;
    if (scratch((size_t)(2 * rad + 1), &k, (size_t)W * H, &tmp) != 0)
        return -1;
    for (j = -rad; j <= rad; j++)
        sum += k[j + rad] = exp(-0.5 * j * j / (sigma * sigma));
    for (j = 0; j <= 2 * rad; j++)
        k[j] /= sum;
    convolve_1d(img, tmp, W, H, k, rad, 1);
    convolve_1d(tmp, img, W, H, k, rad, 0);
    free(k);
    free(tmp);
    return 0;
}

/* A defocus disk of radius r px (area-weighted on a 4x4 subgrid per tap),
 * in place. */
static int blur_disk(double *img, int W, int H, double r)
{
    int rad = (int)ceil(r), n = 2 * rad + 1, x, y, i, j, a, b;
    double *k, *tmp, sum = 0;
    if (r <= 0.3)
        return 0;
    if (scratch((size_t)n * n, &k, (size_t)W * H, &tmp) != 0)
        return -1;
    for (j = -rad; j <= rad; j++)
        for (i = -rad; i <= rad; i++) {
            double w = 0;
            for (b = 0; b < 4; b++)
                for (a = 0; a < 4; a++) {
                    double dx = i + (a + 0.5) / 4 - 0.5, dy = j + (b + 0.5) / 4 - 0.5;
                    w += dx * dx + dy * dy <= r * r;
                }
            sum += k[(j + rad) * n + i + rad] = w;
        }
    for (i = 0; i < n * n; i++)
        k[i] /= sum;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double acc = 0;
            if (x >= rad && x < W - rad && y >= rad && y < H - rad) { /* inside: the same sum, unclamped */
                const double *p = img + (size_t)(y - rad) * W + (x - rad);
                for (j = 0; j < n; j++)
                    for (i = 0; i < n; i++)
                        acc += k[j * n + i] * p[(size_t)j * W + i];
            } else {
                for (j = -rad; j <= rad; j++)
                    for (i = -rad; i <= rad; i++) {
                        int xx = x + i < 0 ? 0 : x + i >= W ? W - 1 : x + i;
                        int yy = y + j < 0 ? 0 : y + j >= H ? H - 1 : y + j;
                        acc += k[(j + rad) * n + i + rad] * img[(size_t)yy * W + xx];
                    }
            }
            tmp[(size_t)y * W + x] = acc;
        }
    memcpy(img, tmp, sizeof(double) * (size_t)W * H);
    free(k);
    free(tmp);
    return 0;
}

/* Photo-electrons counted for a mean of `mean`: Poisson (Knuth's product
 * of uniforms below 30, the normal approximation above). */
static double photons(double mean, const render_rng *rng)
{
    if (mean <= 0)
        return 0;
    if (mean < 30) {
        double l = exp(-mean), p = 1;
        int k = -1;
        do {
            k++;
            p *= rng->uniform();
        } while (p > l);
        return k;
    }
    return mean + sqrt(mean) * rng->normal();
}

static double tone(render_tone t, double x)
{
    x = x < 0 ? 0 : x > 1 ? 1 : x;
    if (t == RENDER_TONE_SRGB)
        return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
    return pow(x, 1 / 2.2);
}

static uint8_t to_u8(double v)
{
    return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v + 0.5);
}

int render_sensor_develop(const render_sensor *se, double *lin, int W, int H, const render_rng *rng,
                          uint8_t *out)
{
    size_t i, n = (size_t)W * H;
    double levels;
    int k, top;
    uint8_t *grey;
    if (render_blur_gauss(lin, W, H, se->blur) != 0 || blur_disk(lin, W, H, se->defocus) != 0)
        return -1;
    top = (1 << (se->adc_bits < 8 ? 8 : se->adc_bits > 16 ? 16 : se->adc_bits)) - 1;
    levels = (double)top;
    /* a raw value is one of top + 1 (q / levels): each one's grey level, once */
    if ((grey = malloc((size_t)top + 1)) == NULL)
        return -1;
    for (k = 0; k <= top; k++)
        grey[k] = to_u8(255.0 * tone(se->tone, k / levels));
    for (i = 0; i < n; i++) {
        double e = photons((lin[i] > 1 ? 1 : lin[i]) * se->full_well, rng);
        double raw = e / se->full_well + se->read_noise / 255.0 * rng->normal();
        /* clamped to [0, 1], a NaN (a zero full well) to 0: the index stays in the table */
        out[i] = grey[(int)floor((raw > 0 ? (raw < 1 ? raw : 1) : 0) * levels + 0.5)];
    }
    free(grey);
    return 0;
}
