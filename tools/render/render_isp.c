#include "render_isp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <turbojpeg.h>
#include "render_sensor.h"

static const struct {
    const char *name;
    double lo, hi;
} stages[] = {{"blur", 0.3, 3}, {"scale", 1.2, 4},    {"sharpen", 0.1, 3},
              {"jpeg", 10, 100}, {"scurve", 0.05, 1}, {"ae", 0.05, 2}};

/* One "NAME:VALUE" of length n into stage k of isp: 0, or -1. */
static int parse_stage(const char *s, size_t n, render_isp *isp, char *err, size_t len)
{
    size_t k;
    for (k = 0; k < sizeof stages / sizeof stages[0]; k++) {
        size_t m = strlen(stages[k].name);
        char *end;
        double v;
        if (n <= m + 1 || strncmp(s, stages[k].name, m) != 0 || s[m] != ':')
            continue;
        v = strtod(s + m + 1, &end);
        if (end != s + n || !(v >= stages[k].lo && v <= stages[k].hi)) {
            snprintf(err, len, "--isp: '%.*s': %s takes a value %g .. %g", (int)n, s, stages[k].name,
                     stages[k].lo, stages[k].hi);
            return -1;
        }
        isp->kind[isp->n] = (render_isp_kind)k;
        isp->value[isp->n++] = v;
        return 0;
    }
    snprintf(err, len, "--isp: '%.*s' is not blur:S, scale:F, sharpen:A, jpeg:Q, scurve:K or ae:STOPS",
             (int)n, s);
    return -1;
}

int render_isp_parse(const char *spec, render_isp *isp, char *err, size_t len)
{
    const char *s = spec;
    memset(isp, 0, sizeof *isp);
    while (*s) {
        size_t n = strcspn(s, ",");
        if (isp->n == RENDER_ISP_MAX) {
            snprintf(err, len, "--isp: at most %d stages", RENDER_ISP_MAX);
            return -1;
        }
        if (parse_stage(s, n, isp, err, len) != 0)
            return -1;
        s += n + (s[n] == ',');
    }
    if (isp->n == 0) {
        snprintf(err, len, "--isp: no stage given");
        return -1;
    }
    return 0;
}

static uint8_t to_u8(double v)
{
    return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v + 0.5);
}

/* The frame as doubles (a copy), or NULL out of memory. */
static double *as_doubles(const uint8_t *px, size_t n)
{
    double *d = malloc(sizeof(double) * n);
    size_t i;
    for (i = 0; d != NULL && i < n; i++)
        d[i] = px[i];
    return d;
}

/* Gaussian blur (amount 0) or unsharp mask (amount > 0) of sigma. */
static int blur_or_sharpen(uint8_t *px, int W, int H, double sigma, double amount)
{
    size_t i, n = (size_t)W * H;
    double *d = as_doubles(px, n);
    if (d == NULL || render_blur_gauss(d, W, H, sigma) != 0) {
        free(d);
        return -1;
    }
    for (i = 0; i < n; i++)
        px[i] = to_u8(amount > 0 ? px[i] + amount * (px[i] - d[i]) : d[i]);
    free(d);
    return 0;
}

/* Grey level of the small frame (w x h) at (x, y), bilinear, edges clamped. */
static double bilinear(const double *s, int w, int h, double x, double y)
{
    int x0, y0, x1, y1;
    double fx, fy;
    x = x < 0 ? 0 : x > w - 1 ? w - 1 : x;
    y = y < 0 ? 0 : y > h - 1 ? h - 1 : y;
    x0 = (int)x;
    y0 = (int)y;
    x1 = x0 + 1 < w ? x0 + 1 : x0;
    y1 = y0 + 1 < h ? y0 + 1 : y0;
    fx = x - x0;
    fy = y - y0;
    return (1 - fy) * ((1 - fx) * s[(size_t)y0 * w + x0] + fx * s[(size_t)y0 * w + x1]) +
           fy * ((1 - fx) * s[(size_t)y1 * w + x0] + fx * s[(size_t)y1 * w + x1]);
}

/* Down by f (each small pixel the mean of the grey levels it covers), up
 * again (bilinear). */
static int scale_down_up(uint8_t *px, int W, int H, double f)
{
    int w = (int)(W / f), h = (int)(H / f), x, y;
    double *s, *cnt;
    if (w < 1 || h < 1)
        return 0;
    s = calloc((size_t)w * h, sizeof(double));
    cnt = calloc((size_t)w * h, sizeof(double));
    if (s == NULL || cnt == NULL) {
        free(s);
        free(cnt);
        return -1;
    }
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int sx = (int)(x * (double)w / W), sy = (int)(y * (double)h / H);
            s[(size_t)sy * w + sx] += px[(size_t)y * W + x];
            cnt[(size_t)sy * w + sx] += 1;
        }
    for (x = 0; x < w * h; x++)
        s[x] = cnt[x] > 0 ? s[x] / cnt[x] : 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            px[(size_t)y * W + x] = to_u8(bilinear(s, w, h, (x + 0.5) * w / W - 0.5, (y + 0.5) * h / H - 0.5));
    free(s);
    free(cnt);
    return 0;
}

/* Compressed at quality q and decoded back. */
static int jpeg_round_trip(uint8_t *px, int W, int H, int q)
{
    tjhandle c = tjInitCompress(), d = tjInitDecompress();
    unsigned char *buf = NULL;
    unsigned long size = 0;
    int ok = c != NULL && d != NULL &&
             tjCompress2(c, px, W, W, H, TJPF_GRAY, &buf, &size, TJSAMP_GRAY, q, TJFLAG_ACCURATEDCT) == 0 &&
             tjDecompress2(d, buf, size, px, W, W, H, TJPF_GRAY, TJFLAG_ACCURATEDCT) == 0;
    tjFree(buf);
    if (c != NULL)
        tjDestroy(c);
    if (d != NULL)
        tjDestroy(d);
    return ok ? 0 : -1;
}

/* A monotone curve on grey levels through a table: an S-curve of
 * strength k (x - k sin(2 pi x) / (2 pi)), or a gain g (k < 0 unused). */
static void curve(uint8_t *px, size_t n, double k, double gain)
{
    uint8_t t[256];
    size_t i;
    for (i = 0; i < 256; i++) {
        double x = i / 255.0;
        t[i] = to_u8(255.0 * (gain > 0 ? x * gain : x - k * sin(2 * M_PI * x) / (2 * M_PI)));
    }
    for (i = 0; i < n; i++)
        px[i] = t[px[i]];
}

int render_isp_apply(const render_isp *isp, uint8_t *px, int W, int H, int frame)
{
    int k, r = 0;
    for (k = 0; k < isp->n && r == 0; k++) {
        double v = isp->value[k];
        switch (isp->kind[k]) {
        case RENDER_ISP_BLUR: r = blur_or_sharpen(px, W, H, v, 0); break;
        case RENDER_ISP_SHARPEN: r = blur_or_sharpen(px, W, H, 1.0, v); break;
        case RENDER_ISP_SCALE: r = scale_down_up(px, W, H, v); break;
        case RENDER_ISP_JPEG: r = jpeg_round_trip(px, W, H, (int)v); break;
        case RENDER_ISP_SCURVE: curve(px, (size_t)W * H, v, 0); break;
        case RENDER_ISP_AE:
            /* a slow swing and a jump: no two neighbouring frames alike */
            curve(px, (size_t)W * H, 0, pow(2.0, v * sin(1.9 * frame + 0.4) / 2.2));
            break;
        }
    }
    return r;
}
