#include "rl_label.h"

#include <string.h>

size_t rl_label_bytes(int height, int cap_runs, int cap_regions)
{
    /* each slice may be padded up to RL_WS_ALIGN - 1 bytes */
    return (size_t)cap_runs * (2 * sizeof(uint16_t) + sizeof(int32_t)) +
           (size_t)(height + 1) * sizeof(int32_t) + (size_t)cap_regions * sizeof(rl_region) +
           4 * RL_WS_ALIGN;
}

rl_err rl_label_init(rl_label *lb, rl_ws *ws, int width, int height, int cap_runs,
                     int cap_regions)
{
    rl_err e;
    if (width <= 0 || height <= 0 || width > 65535 || cap_runs <= 0 || cap_regions <= 0)
        return RL_EINVAL;
    lb->width = width;
    lb->height = height;
    lb->max_height = height;
    lb->cap_runs = cap_runs;
    lb->cap_regions = cap_regions;
    lb->n_runs = lb->n_regions = lb->overflow = lb->rows_left = 0;
    if ((e = rl_ws_alloc(ws, (size_t)cap_runs * sizeof(uint16_t), RL_WS_ALIGN, (void **)&lb->x0)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)cap_runs * sizeof(uint16_t), RL_WS_ALIGN, (void **)&lb->x1)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)cap_runs * sizeof(int32_t), RL_WS_ALIGN, (void **)&lb->tag)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)(height + 1) * sizeof(int32_t), RL_WS_ALIGN, (void **)&lb->row)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)cap_regions * sizeof(rl_region), RL_WS_ALIGN, (void **)&lb->reg)) != RL_OK)
        return e;
    return RL_OK;
}

/* Word-at-a-time skipping over pixels outside the band. For a band that
 * starts at 0 and ends at or below 128 (dark ROIs), or starts at 128 or
 * above and ends at 256 (light sources), "does any of these 8 bytes fall
 * in the band" is one expression on a 64-bit word (the classic has-less-
 * than test), and most of a ceiling frame is skipped 8 pixels at a time. */
#define ONES 0x0101010101010101ull
#define HIGHS 0x8080808080808080ull

static uint64_t load8(const uint8_t *p)
{
    uint64_t w;
    memcpy(&w, p, sizeof w);
    return w;
}

/* First x >= from with lo <= row[x] < hi, or width. */
static int skip_outside(const uint8_t *row, int from, int width, int lo, int hi)
{
    int x = from;
    if (lo == 0 && hi <= 128 && hi > 0) {
        uint64_t n = ONES * (uint64_t)hi;
        while (x + 8 <= width) {
            uint64_t w = load8(row + x);
            if (((w - n) & ~w & HIGHS) != 0)
                break;
            x += 8;
        }
    } else if (lo == 0 && hi > 128 && hi < 256) {
        /* a byte under 128 is in the band; bytes of 128 and up compare
         * their low 7 bits with hi - 128 (< 128, so the test holds) */
        uint64_t n = ONES * (uint64_t)(hi - 128);
        while (x + 8 <= width) {
            uint64_t w = load8(row + x), low = w & ~HIGHS;
            if ((~w & HIGHS) != 0 || ((low - n) & ~low & HIGHS) != 0)
                break;
            x += 8;
        }
    } else if (hi == 256 && lo >= 128) {
        uint64_t n = ONES * (uint64_t)(256 - lo);
        while (x + 8 <= width) {
            uint64_t w = ~load8(row + x); /* 255 - v < 256 - lo  <=>  v >= lo */
            if (((w - n) & ~w & HIGHS) != 0)
                break;
            x += 8;
        }
    }
    while (x < width && (unsigned)(row[x] - lo) >= (unsigned)(hi - lo))
        x++;
    return x;
}

static int32_t find(int32_t *p, int32_t a)
{
    while (p[a] != a) {
        p[a] = p[p[a]]; /* path halving */
        a = p[a];
    }
    return a;
}

static void unite(int32_t *p, int32_t a, int32_t b)
{
    a = find(p, a);
    b = find(p, b);
    /* the older run stays root: roots are then the first run of a region
     * in raster order, which keeps region order deterministic */
    if (a < b)
        p[b] = a;
    else if (b < a)
        p[a] = b;
}

/* The runs of pixels in [lo, hi), row by row, joined with the previous
 * row's runs they touch (8-connected). RL_ELIMIT past cap_runs. */
/* Append run [a, b] of the current row and join it with the previous
 * row's runs it touches (8-connected): they are sorted, so the forward
 * pointer *j suffices. */
static rl_err add_run(rl_label *lb, int a, int b, int *n, int *j, int prev_end)
{
    int32_t *p = lb->tag;
    int jj;
    if (*n == lb->cap_runs)
        return RL_ELIMIT;
    lb->x0[*n] = (uint16_t)a;
    lb->x1[*n] = (uint16_t)b;
    p[*n] = *n;
    while (*j < prev_end && (int)lb->x1[*j] + 1 < a)
        (*j)++;
    for (jj = *j; jj < prev_end && (int)lb->x0[jj] <= b + 1; jj++)
        unite(p, *n, jj);
    (*n)++;
    return RL_OK;
}

/* 1 if a tile row's thresholds lie within a few grey levels of each
 * other (an evenly lit row): its runs are then found 8 pixels at a time
 * under the largest (*hi), each pixel checked against its own tile's. */
static int nearly_even(const uint8_t *his, int nx, int *hi)
{
    int i, lo = 255, top = 0;
    for (i = 0; i < nx; i++) {
        if (his[i] < lo) lo = his[i];
        if (his[i] > top) top = his[i];
    }
    *hi = top;
    return top - lo <= 12;
}

/* The runs of pixels in [lo, hi) (hi per tile column of the row's tile
 * row when map is given), row by row. RL_ELIMIT past cap_runs. */
static rl_err collect_runs(rl_label *lb, const rl_image *img, int lo, int hi, const rl_label_map *map)
{
    int x, y, n = 0, prev_start = 0, prev_end = 0, sh = 0, even = 0;
    const uint8_t *his = NULL;
    rl_err e;
    while (map && (1 << sh) < map->tile)
        sh++;
    for (y = 0; y < img->height; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        int start = n, j = prev_start;
        if (map && (y & ((1 << sh) - 1)) == 0) {
            his = map->hi + (size_t)(y >> sh) * (size_t)map->nx;
            even = nearly_even(his, map->nx, &hi);
        }
        lb->row[y] = n;
        x = 0;
        while (x < img->width) {
            int a, end = img->width, h = hi;
            if (his && !even) {
                /* one tile column at a time, each with its own threshold */
                end = ((x >> sh) + 1) << sh;
                end = end < img->width ? end : img->width;
                h = his[x >> sh];
            }
            /* unsigned trick: lo <= v < hi  <=>  (v - lo) < (hi - lo) */
            x = h > lo ? skip_outside(row, x, end, lo, h) : end;
            if (x >= end)
                continue;
            if (even && (unsigned)(row[x] - lo) >= (unsigned)(his[x >> sh] - lo)) {
                x++; /* under the row's largest threshold, not its own tile's */
                continue;
            }
            a = x;
            while (x < img->width &&
                   (unsigned)(row[x] - lo) < (unsigned)((his ? his[x >> sh] : hi) - lo))
                x++;
            if ((e = add_run(lb, a, x - 1, &n, &j, prev_end)) != RL_OK) {
                /* out of runs (a frame of noise or a fine pattern): the
                 * rows before this one are labelled, this one and the rest
                 * are left out and counted */
                int k;
                lb->rows_left = img->height - y;
                n = lb->row[y];
                for (k = y + 1; k <= img->height; k++)
                    lb->row[k] = n;
                lb->n_runs = n;
                return RL_OK;
            }
        }
        prev_start = start;
        prev_end = n;
    }
    lb->row[img->height] = n;
    lb->n_runs = n;
    return RL_OK;
}

/* Runs into regions (specks, and regions past cap_regions, dropped). */
static void resolve_regions(rl_label *lb, int min_area)
{
    int r, n = lb->n_runs;
    int32_t *p = lb->tag;
    /* The tag array goes through four meanings, one linear pass each; the
     * root of a region is its first run in raster order (see unite), so a
     * root is always visited before its members:
     * 1. tag = the run's root;
     * 2. roots hold -area, members still their root;
     * 3. roots hold the encoded region (-2 - index) or -1 if dropped (a
     *    speck, or past cap_regions), members copy their root's;
     * 4. tag = region index or -1. */
    for (r = 0; r < n; r++)
        p[r] = find(p, r);
    for (r = 0; r < n; r++) {
        int len = lb->x1[r] - lb->x0[r] + 1;
        if (p[r] == r)
            p[r] = -len;
        else
            p[p[r]] -= len;
    }
    for (r = 0; r < n; r++) {
        if (p[r] < 0) {
            int area = -p[r];
            if (area < min_area) {
                p[r] = -1;
            } else if (lb->n_regions == lb->cap_regions) {
                lb->overflow++;
                p[r] = -1;
            } else {
                rl_region *g = &lb->reg[lb->n_regions];
                g->area = 0;
                g->x0 = g->y0 = 32767;
                g->x1 = g->y1 = -1;
                g->sx = g->sy = 0.0;
                p[r] = -2 - lb->n_regions;
                lb->n_regions++;
            }
        } else {
            p[r] = p[p[r]];
        }
    }
    for (r = 0; r < n; r++)
        p[r] = p[r] <= -2 ? -2 - p[r] : -1;
}

/* Area, box and coordinate sums of every region. */
static void region_stats(rl_label *lb)
{
    int32_t *p = lb->tag;
    int y, r;
    for (y = 0; y < lb->height; y++)
        for (r = lb->row[y]; r < lb->row[y + 1]; r++) {
            rl_region *g;
            int len;
            if (p[r] < 0)
                continue;
            g = &lb->reg[p[r]];
            len = lb->x1[r] - lb->x0[r] + 1;
            g->area += len;
            if (lb->x0[r] < g->x0) g->x0 = (int16_t)lb->x0[r];
            if (lb->x1[r] > g->x1) g->x1 = (int16_t)lb->x1[r];
            if (y < g->y0) g->y0 = (int16_t)y;
            if (y > g->y1) g->y1 = (int16_t)y;
            g->sx += 0.5 * (double)(lb->x0[r] + lb->x1[r]) * len;
            g->sy += (double)y * len;
        }
}

static rl_err label(rl_label *lb, const rl_image *img, int lo, int hi, const rl_label_map *map,
                    int min_area)
{
    rl_err e;
    if (!rl_image_valid(img) || img->width > 65535 || img->height > lb->max_height)
        return RL_EINVAL;
    lb->width = img->width;
    lb->height = img->height;
    lb->n_runs = lb->n_regions = lb->overflow = lb->rows_left = 0;
    if ((e = collect_runs(lb, img, lo < 0 ? 0 : lo, hi, map)) != RL_OK)
        return e;
    resolve_regions(lb, min_area);
    region_stats(lb);
    return RL_OK;
}

rl_err rl_label_band(rl_label *lb, const rl_image *img, int lo, int hi, int min_area)
{
    return label(lb, img, lo, hi, NULL, min_area);
}

rl_err rl_label_dark(rl_label *lb, const rl_image *img, const rl_label_map *map, int min_area)
{
    if (map == NULL || map->tile <= 0 || (map->tile & (map->tile - 1)) != 0 ||
        map->nx * map->tile < img->width ||
        map->ny * map->tile < img->height)
        return RL_EINVAL;
    return label(lb, img, 0, 256, map, min_area);
}

void rl_label_moments(const rl_label *lb, int reg, double *cxx, double *cxy, double *cyy)
{
    const rl_region *g = &lb->reg[reg];
    double mx = g->sx / g->area, my = g->sy / g->area, sxx = 0, sxy = 0, syy = 0;
    int y, r;
    for (y = g->y0; y <= g->y1; y++)
        for (r = lb->row[y]; r < lb->row[y + 1]; r++) {
            double a, b, len, dy, sx;
            if (lb->tag[r] != reg)
                continue;
            /* sums over the run's x0 .. x1 about the centroid, in closed form */
            a = lb->x0[r] - mx;
            b = lb->x1[r] - mx;
            len = b - a + 1;
            dy = y - my;
            sx = 0.5 * (a + b) * len;
            sxx += len * (a * a + a * (len - 1) + (len - 1) * (2 * len - 1) / 6.0);
            sxy += dy * sx;
            syy += dy * dy * len;
        }
    *cxx = sxx / g->area;
    *cxy = sxy / g->area;
    *cyy = syy / g->area;
}
