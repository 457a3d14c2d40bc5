#include "rl_illum.h"

#include <string.h>

/* The largest tile (px): its samples' sums fit tile_level's fields. */
#define RL_ILLUM_MAX_TILE 64

/* Tiles of about a twentieth of the frame's width, a power of two (32 px
 * at 640): the labeller finds a pixel's tile by a shift. */
static int tile_size(int W)
{
    int t = 16;
    while (t < RL_ILLUM_MAX_TILE && 2 * t <= W / 14)
        t *= 2;
    return t;
}

rl_err rl_illum_init(rl_illum *il, rl_ws *ws, int W, int H)
{
    rl_err e;
    size_t n;
    il->tile = tile_size(W);
    il->nx = (W + il->tile - 1) / il->tile;
    il->ny = (H + il->tile - 1) / il->tile;
    n = (size_t)il->nx * (size_t)il->ny;
    if ((e = rl_ws_alloc(ws, n, RL_WS_ALIGN, (void **)&il->level)) != RL_OK ||
        (e = rl_ws_alloc(ws, n, RL_WS_ALIGN, (void **)&il->bright)) != RL_OK ||
        (e = rl_ws_alloc(ws, n, RL_WS_ALIGN, (void **)&il->hi)) != RL_OK)
        return e;
    il->map.hi = il->hi;
    il->map.tile = il->tile;
    il->map.nx = il->nx;
    il->map.ny = il->ny;
    il->typical = 255;
    return RL_OK;
}

/* A sample's four counts packed in one word (illum_words): from the top,
 * 1 when it is no lamp (n), 1 when it is also at or above the dark
 * threshold (n_hi), its level when no lamp (sum), its level when both
 * (sum_hi), 16 bits each. A tile has at most 16 x 8 samples (64 px
 * tiles: every fourth row, every eighth column), so n and n_hi stay
 * under 256 and the sums at most 128 x 255 = 32640 < 2^16: no field carries into
 * the next, and the word's sums are the four plain sums. */
#define FIELD 16
#define N_SHIFT (3 * FIELD)
#define NHI_SHIFT (2 * FIELD)
#define SUM_SHIFT FIELD
#define FIELD_MASK 0xffffu
/* A tile's samples: every ROW_STEP-th row, every COL_STEP-th column. */
#define ROW_STEP 4
#define COL_STEP 8
#if (RL_ILLUM_MAX_TILE / ROW_STEP) * (RL_ILLUM_MAX_TILE / COL_STEP) * 255 > 0xffff
#error "rl_illum packs a tile's sums in 16 bits: too many samples a tile"
#endif

/* Each grey level's packed sample word under thr and light. */
static void illum_words(uint64_t *word, int thr, int light)
{
    unsigned v;
    for (v = 0; v < 256; v++) {
        uint64_t m = v < (unsigned)light, h = m & (v >= (unsigned)thr);
        word[v] = m << N_SHIFT | h << NHI_SHIFT | (v * m) << SUM_SHIFT | v * h;
    }
}

/* A tile's ceiling level: the mean of its samples at or above the frame's
 * dark threshold when they are at least a quarter of them, else the mean
 * of them all (a tile in a shadow, or inside a landmark's ink: its
 * neighbours then tell); every fourth row and eighth column (32 samples of
 * a 32 px tile), lamps left out, one add of a packed word a sample
 * (illum_words: a ceiling's texture makes tests unpredictable); 0 when it
 * is all lamp. */
static int tile_level(const rl_image *img, const uint64_t *word, int x0, int y0, int x1, int y1)
{
    uint64_t acc = 0;
    unsigned sum, n, sum_hi, n_hi;
    int x, y;
    for (y = y0; y < y1; y += ROW_STEP) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        for (x = x0; x < x1; x += COL_STEP)
            acc += word[row[x]];
    }
    n = (unsigned)(acc >> N_SHIFT) & FIELD_MASK;
    n_hi = (unsigned)(acc >> NHI_SHIFT) & FIELD_MASK;
    sum = (unsigned)(acc >> SUM_SHIFT) & FIELD_MASK;
    sum_hi = (unsigned)acc & FIELD_MASK;
    if (n < 3)
        return 0;
    return (int)(4 * n_hi >= n ? sum_hi / n_hi : sum / n);
}

/* The largest known level of a tile and its eight neighbours, or 0. */
static int spread(const rl_illum *il, int tx, int ty)
{
    int best = 0, dx, dy;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int x = tx + dx, y = ty + dy, v;
            if (x < 0 || y < 0 || x >= il->nx || y >= il->ny)
                continue;
            v = il->level[y * il->nx + x];
            if (v > best)
                best = v;
        }
    return best;
}

/* The median of the known tile levels (the frame's typical ceiling), or
 * fallback when none is known. */
static int median_level(const rl_illum *il, int fallback)
{
    unsigned count[256];
    int i, n = il->nx * il->ny, known = 0, acc = 0;
    memset(count, 0, sizeof count);
    for (i = 0; i < n; i++)
        if (il->level[i] > 0) {
            count[il->level[i]]++;
            known++;
        }
    if (known == 0)
        return fallback;
    for (i = 1; i < 256; i++)
        if ((acc += (int)count[i]) * 2 >= known)
            return i;
    return fallback;
}

void rl_illum_measure(rl_illum *il, const rl_image *img, const rl_levels *lv)
{
    int tx, ty, T = il->tile;
    double ref;
    uint64_t word[256];
    illum_words(word, lv->threshold, lv->light);
    for (ty = 0; ty < il->ny; ty++)
        for (tx = 0; tx < il->nx; tx++) {
            int x1 = (tx + 1) * T < img->width ? (tx + 1) * T : img->width;
            int y1 = (ty + 1) * T < img->height ? (ty + 1) * T : img->height;
            il->level[ty * il->nx + tx] =
                (uint8_t)tile_level(img, word, tx * T, ty * T, x1, y1);
        }
    /* the threshold follows the light: the same fraction of the local
     * level as the frame's threshold is of its background */
    double bg = lv->bg > 1 ? lv->bg : 1, ratio = lv->threshold / bg;
    ratio = ratio < 0.3 ? 0.3 : ratio > 0.75 ? 0.75 : ratio;
    ref = median_level(il, (int)(bg + 0.5));
    il->typical = ref > 1 ? ref : 1;
    for (ty = 0; ty < il->ny; ty++)
        for (tx = 0; tx < il->nx; tx++) {
            int i = ty * il->nx + tx, b = spread(il, tx, ty), hi;
            il->bright[i] = (uint8_t)(b > 0 ? b : (int)il->typical); /* unknown: the frame's */
            hi = (int)(ratio * il->bright[i] + 0.5);
            il->hi[i] = (uint8_t)(hi < 1 ? 1 : hi > lv->light ? lv->light : hi);
        }
}

double rl_illum_scale(const rl_illum *il, double u, double v)
{
    int tx = (int)(u / il->tile), ty = (int)(v / il->tile);
    if (tx < 0) tx = 0;
    if (ty < 0) ty = 0;
    if (tx >= il->nx) tx = il->nx - 1;
    if (ty >= il->ny) ty = il->ny - 1;
    return il->bright[ty * il->nx + tx] / il->typical;
}
