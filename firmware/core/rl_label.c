#include "rl_label.h"

#include <string.h>

size_t rl_label_bytes(int width, int height, int cap_runs, int cap_regions)
{
    /* each slice may be padded up to RL_WS_ALIGN - 1 bytes */
    return (size_t)cap_runs * (2 * sizeof(uint16_t) + sizeof(int32_t)) +
           (size_t)(height + 1) * sizeof(int32_t) + (size_t)cap_regions * sizeof(rl_region) +
           (size_t)width + 6 * RL_WS_ALIGN;
}

rl_err rl_label_init(rl_label *lb, rl_ws *ws, int width, int height, int cap_runs,
                     int cap_regions)
{
    rl_err e;
    if (width <= 0 || height <= 0 || width > 65535 || cap_runs <= 0 || cap_regions <= 0)
        return RL_EINVAL;
    lb->width = width;
    lb->height = height;
    lb->max_width = width;
    lb->max_height = height;
    lb->cap_runs = cap_runs;
    lb->cap_regions = cap_regions;
    lb->n_runs = lb->n_regions = lb->overflow = lb->rows_left = 0;
    if ((e = rl_ws_alloc(ws, (size_t)cap_runs * sizeof(uint16_t), RL_WS_ALIGN, (void **)&lb->x0)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)cap_runs * sizeof(uint16_t), RL_WS_ALIGN, (void **)&lb->x1)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)cap_runs * sizeof(int32_t), RL_WS_ALIGN, (void **)&lb->tag)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)(height + 1) * sizeof(int32_t), RL_WS_ALIGN, (void **)&lb->row)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)cap_regions * sizeof(rl_region), RL_WS_ALIGN, (void **)&lb->reg)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)width, RL_WS_ALIGN, (void **)&lb->span)) != RL_OK)
        return e;
    return RL_OK;
}

/* A row is read CHUNK pixels at a time: each pixel's band test as a byte
 * (16 at once in GCC/Clang vectors), the bytes packed into the bits of
 * one word, and the runs found in the word by counting trailing zeros; a
 * ceiling frame's long stretches outside the band cost a few instructions
 * for 64 pixels. */
#define CHUNK 64
#define ONES 0x0101010101010101ull
/* A word of eight 0/1 bytes times this has byte i's bit at bit 56 + i. */
#define PACK_BITS 0x0102040810204080ull

#if defined(__GNUC__) && !defined(RL_NO_VECTOR_EXT)
#define LABEL_VECTORS 1
typedef uint8_t label_v16 __attribute__((vector_size(16)));
#if defined(__SSE2__)
/* x86: a whole chunk's tests straight into its bits (the sign bits of 16
 * bytes at a time), no bytes to pack */
#include <emmintrin.h>
#define LABEL_MOVEMASK 1
#endif
#endif

static int trailing_zeros(uint64_t w) /* w != 0 */
{
#if defined(__GNUC__)
    return __builtin_ctzll((unsigned long long)w);
#else
    int k = 0;
    while (!(w & 1)) {
        w >>= 1;
        k++;
    }
    return k;
#endif
}

#ifdef LABEL_MOVEMASK
/* chunk_bits of a whole chunk: (row[i] - lo) mod 256 < span[i] is
 * not max(row[i] - lo, span[i]) == row[i] - lo, bytes unsigned. */
static uint64_t whole_chunk_bits(const uint8_t *row, const uint8_t *span, int lo)
{
    const __m128i l = _mm_set1_epi8((char)lo);
    uint64_t bits = 0;
    int i;
    for (i = 0; i < CHUNK; i += 16) {
        __m128i d = _mm_sub_epi8(_mm_loadu_si128((const __m128i *)(const void *)(row + i)), l);
        __m128i sp = _mm_loadu_si128((const __m128i *)(const void *)(span + i));
        unsigned ge = (unsigned)_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_max_epu8(d, sp), d));
        bits |= (uint64_t)(ge ^ 0xffffu) << i;
    }
    return bits;
}
#endif

/* Whether every pixel of a whole chunk is under lo (lo > 0): then none
 * is in the band, whatever the spans. The light labelling's band starts
 * at 235 or more, and most of a frame's chunks hold no pixel that high:
 * on x86 their maximum is taken in 7 vector steps instead of the chunk's
 * tests; elsewhere (aarch64, RL_NO_VECTOR_EXT) eight 64-bit words, the
 * eight bytes of each at once (an add and an and/or: chunk_under_words). */
#ifndef LABEL_MOVEMASK
#define HIGH_BITS (0x80 * ONES)
/* A byte b's low seven bits plus 128 - m reach bit 7 (no carry out of the
 * byte: at most 127 + 128) exactly when they are m or more; so b >= lo
 * is, for lo >= 128, b's bit 7 and its low bits at least lo - 128, and
 * for lo < 128, b's bit 7 or its low bits at least lo. */
static int chunk_under_words(const uint8_t *row, int lo)
{
    uint64_t over = 0, w;
    int i;
    if (lo > 255)
        return 1;
    for (i = 0; i < CHUNK; i += 8) {
        memcpy(&w, row + i, sizeof w); /* byte order does not matter: any byte will do */
        if (lo >= 128)
            over |= ((w & ~HIGH_BITS) + (uint64_t)(256 - lo) * ONES) & w;
        else
            over |= ((w & ~HIGH_BITS) + (uint64_t)(128 - lo) * ONES) | w;
    }
    return (over & HIGH_BITS) == 0;
}
#endif

static int chunk_under(const uint8_t *row, int lo)
{
#ifdef LABEL_MOVEMASK
    const __m128i top = _mm_set1_epi8((char)(lo - 1));
    __m128i m = _mm_max_epu8(_mm_max_epu8(_mm_loadu_si128((const __m128i *)(const void *)row),
                                          _mm_loadu_si128((const __m128i *)(const void *)(row + 16))),
                             _mm_max_epu8(_mm_loadu_si128((const __m128i *)(const void *)(row + 32)),
                                          _mm_loadu_si128((const __m128i *)(const void *)(row + 48))));
    /* every byte at most lo - 1: max(m, lo - 1) is lo - 1 everywhere */
    return _mm_movemask_epi8(_mm_cmpeq_epi8(_mm_max_epu8(m, top), top)) == 0xffff;
#else
    return chunk_under_words(row, lo);
#endif
}

#ifndef LABEL_MOVEMASK
/* Eight bytes, each 0 or with its low bit set, as eight bits (byte i:
 * bit i). */
static uint64_t pack8(const uint8_t *in)
{
    uint64_t w = 0;
#if defined(__GNUC__) && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    memcpy(&w, in, sizeof w);
#else
    int i;
    for (i = 7; i >= 0; i--)
        w = w << 8 | in[i];
#endif
    return (w & ONES) * PACK_BITS >> 56;
}

/* chunk_bits of a whole chunk: each pixel's test as a byte (16 at once
 * in vectors), the bytes packed eight at a time. */
static uint64_t whole_chunk_bits(const uint8_t *row, const uint8_t *span, int lo)
{
    uint8_t in[CHUNK];
    uint64_t bits = 0;
    int i;
#ifdef LABEL_VECTORS
    label_v16 any = {0};
    uint64_t half[2];
    for (i = 0; i < CHUNK; i += 16) {
        label_v16 v, sp, m;
        memcpy(&v, row + i, sizeof v);
        memcpy(&sp, span + i, sizeof sp);
        m = (label_v16)((label_v16)(v - (uint8_t)lo) < sp);
        memcpy(in + i, &m, sizeof m);
        any |= m;
    }
    memcpy(half, &any, sizeof half);
    if ((half[0] | half[1]) == 0)
        return 0; /* most of a ceiling: no pixel in the band */
#else
    for (i = 0; i < CHUNK; i++)
        in[i] = (uint8_t)(row[i] - lo) < span[i];
#endif
    for (i = 0; i < CHUNK; i += 8)
        bits |= pack8(in + i) << i;
    return bits;
}
#endif

/* Bit i set when lo <= row[i] < lo + span[i], for i < n <= CHUNK; the
 * `before` bytes before row and span are theirs too (a row's earlier
 * chunks). Only whole chunks are tested (whole_chunk_bits, one form per
 * target): a row's last, short chunk (a window's: 13 of a 77 px one) is
 * the whole chunk that ends with it, its bits shifted down, where the row
 * is that long; else copied out, its pad's band empty (span 0: no bit). */
static uint64_t chunk_bits(const uint8_t *row, const uint8_t *span, int lo, int n, int before)
{
    uint8_t rs[2][CHUNK];
    if (n == CHUNK)
        return whole_chunk_bits(row, span, lo);
    if (before >= CHUNK - n)
        return whole_chunk_bits(row - (CHUNK - n), span - (CHUNK - n), lo) >> (CHUNK - n);
    memcpy(rs[0], row, (size_t)n);
    memcpy(rs[1], span, (size_t)n);
    memset(rs[0] + n, 0, (size_t)(CHUNK - n));
    memset(rs[1] + n, 0, (size_t)(CHUNK - n));
    return whole_chunk_bits(rs[0], rs[1], lo);
}

static int32_t find(int32_t *p, int32_t a)
{
    while (p[a] != a) {
        p[a] = p[p[a]]; /* path halving */
        a = p[a];
    }
    return a;
}

/* Join the run whose root is `root` (the current run's, kept by the
 * caller) with run b's set; the new root returned. The older root stays
 * root: roots are then the first run of a region in raster order (the
 * least index of its set), which keeps region order deterministic. */
static int32_t unite(int32_t *p, int32_t root, int32_t b)
{
    b = find(p, b);
    if (root < b) {
        p[b] = root;
        return root;
    }
    p[root] = b; /* b == root leaves it as it is */
    return b;
}

/* The runs of pixels in [lo, hi), row by row, joined with the previous
 * row's runs they touch (8-connected). RL_ELIMIT past cap_runs. */
/* Append run [a, b] of the current row and join it with the previous
 * row's runs it touches (8-connected): they are sorted, so the forward
 * pointer *j suffices. */
static inline rl_err add_run(rl_label *lb, int a, int b, int *n, int *j, int prev_end)
{
    int32_t *p = lb->tag, root = *n;
    int jj;
    if (*n == lb->cap_runs)
        return RL_ELIMIT;
    lb->x0[*n] = (uint16_t)a;
    lb->x1[*n] = (uint16_t)b;
    p[*n] = *n;
    while (*j < prev_end && (int)lb->x1[*j] + 1 < a)
        (*j)++;
    for (jj = *j; jj < prev_end && (int)lb->x0[jj] <= b + 1; jj++)
        root = unite(p, root, jj);
    (*n)++;
    return RL_OK;
}

/* The band's width above lo under a threshold, as a byte: 0 for an
 * empty band; 256 (the whole range) does not occur with a map, whose
 * thresholds are bytes, and is taken apart by the caller. */
static uint8_t band_span(int lo, int hi)
{
    return (uint8_t)(hi <= lo ? 0 : hi - lo > 255 ? 255 : hi - lo);
}

/* Each pixel's band width in span[0 .. width - 1] under its tile's
 * threshold (his, tiles of 1 << sh), and the pixels from the first tile
 * with a band to the end of the last in [*xa, *xb) (a second labelling's
 * few marked tiles: the rest of the row holds no run); 0 when every band
 * is empty (the tile row has nothing to label), else 1. */
static int tile_spans(uint8_t *span, int width, int lo, const uint8_t *his, int sh, int *xa, int *xb)
{
    int x, t;
    *xa = width;
    *xb = 0;
    for (t = 0, x = 0; x < width; t++) {
        int end = (t + 1) << sh;
        uint8_t w = band_span(lo, his[t]);
        end = end < width ? end : width;
        memset(span + x, w, (size_t)(end - x));
        if (w != 0) {
            *xa = *xa < x ? *xa : x;
            *xb = end;
        }
        x = end;
    }
    return *xb > *xa;
}

/* Row y's runs in pixels xa .. width - 1 (none before xa) appended from
 * *n on, each joined with the previous row's (prev_start .. prev_end - 1)
 * it touches. RL_ELIMIT past cap_runs. */
static rl_err row_runs(rl_label *lb, const uint8_t *row, int xa, int width, int lo, int all, int *n,
                       int prev_start, int prev_end)
{
    int x, j = prev_start, open = -1;
    rl_err e;
    if (all)
        return add_run(lb, 0, width - 1, n, &j, prev_end);
    for (x = xa; x < width; x += CHUNK) {
        int len = width - x < CHUNK ? width - x : CHUNK;
        uint64_t bits, edges;
        /* outside a run, a chunk with no pixel in the band changes
         * nothing (in a run it ends the run: its tests say where) */
        if (open < 0 && lo > 0 && len == CHUNK && chunk_under(row + x, lo))
            continue;
        bits = chunk_bits(row + x, lb->span + x, lo, len, x);
        /* a bit where a pixel's test differs from the one before it (the
         * chunk's first against the run open or not): the starts and ends
         * in turn, lowest first, one word for the chunk. In a short chunk
         * the bits past the row are clear, so a run that reaches the row's
         * end ends at the first of them, where the row ends it anyway. */
        edges = bits ^ (bits << 1 | (uint64_t)(open >= 0));
        while (edges) {
            int pos = trailing_zeros(edges);
            edges &= edges - 1;
            if (open < 0) {
                open = x + pos;
            } else {
                if ((e = add_run(lb, open, x + pos - 1, n, &j, prev_end)) != RL_OK)
                    return e;
                open = -1;
            }
        }
    }
    return open < 0 ? RL_OK : add_run(lb, open, width - 1, n, &j, prev_end);
}

/* The runs of pixels in [lo, hi) (hi per tile column of the row's tile
 * row when map is given), row by row. Past cap_runs the rows left are
 * counted, not labelled. */
static void collect_runs(rl_label *lb, const rl_image *img, int lo, int hi, const rl_label_map *map)
{
    int y, n = 0, prev_start = 0, prev_end = 0, sh = 0, live = 1, xa = 0, xb = img->width;
    int all = map == NULL && lo == 0 && hi >= 256; /* every pixel in the band */
    while (map && (1 << sh) < map->tile)
        sh++;
    if (map == NULL)
        memset(lb->span, band_span(lo, hi), (size_t)img->width);
    for (y = 0; y < img->height; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        int start = n;
        if (map && (y & ((1 << sh) - 1)) == 0)
            live = tile_spans(lb->span, img->width, lo,
                              map->hi + (size_t)(y >> sh) * (size_t)map->nx, sh, &xa, &xb);
        lb->row[y] = n;
        if (!live) { /* a tile row with every band empty: no runs */
            prev_start = prev_end = n;
            continue;
        }
        if (row_runs(lb, row, xa, xb, lo, all, &n, prev_start, prev_end) != RL_OK) {
            /* out of runs (a frame of noise or a fine pattern): the rows
             * before this one are labelled, this one and the rest are left
             * out and counted */
            int k;
            lb->rows_left = img->height - y;
            n = lb->row[y];
            for (k = y + 1; k <= img->height; k++)
                lb->row[k] = n;
            lb->n_runs = n;
            return;
        }
        prev_start = start;
        prev_end = n;
    }
    lb->row[img->height] = n;
    lb->n_runs = n;
}

/* Runs into regions (specks, and regions past cap_regions, dropped). */
static void resolve_regions(rl_label *lb, int min_area)
{
    int r, n = lb->n_runs;
    int32_t *p = lb->tag;
    /* The tag array goes through three meanings, one linear pass each; the
     * root of a region is its first run in raster order (see unite), and
     * every run's parent is an earlier run (or itself: a root), so a root
     * is always visited before its members:
     * 1. roots hold -area, members their root: a member's parent q was
     *    visited before it, so q's tag is already q's root, or q is a root
     *    and holds its -area so far (one pass, no find);
     * 2. roots hold the encoded region (-2 - index) or -1 if dropped (a
     *    speck, or past cap_regions), members copy their root's;
     * 3. tag = region index or -1 (region_stats, as it reads the runs). */
    for (r = 0; r < n; r++) {
        int32_t len = lb->x1[r] - lb->x0[r] + 1, q = p[r];
        if (q == r) {
            p[r] = -len;
            continue;
        }
        if (p[q] >= 0) { /* q is a member: its tag is the root */
            q = p[q];
            p[r] = q;
        }
        p[q] -= len;
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
}

/* Each run's tag decoded (resolve_regions' third meaning: region index or
 * -1), and area, box and coordinate sums of every region. The x sums are
 * summed doubled, in whole numbers (exact in a double: under 2^49 for any
 * region of a 65535-wide image), and halved at the end: the same value as
 * summing the halves. */
static void region_stats(rl_label *lb)
{
    int32_t *p = lb->tag;
    int y, r;
    for (y = 0; y < lb->height; y++)
        for (r = lb->row[y]; r < lb->row[y + 1]; r++) {
            rl_region *g;
            int len;
            p[r] = p[r] <= -2 ? -2 - p[r] : -1;
            if (p[r] < 0)
                continue;
            g = &lb->reg[p[r]];
            len = lb->x1[r] - lb->x0[r] + 1;
            g->area += len;
            if (lb->x0[r] < g->x0) g->x0 = (int16_t)lb->x0[r];
            if (lb->x1[r] > g->x1) g->x1 = (int16_t)lb->x1[r];
            if (y < g->y0) g->y0 = (int16_t)y;
            if (y > g->y1) g->y1 = (int16_t)y;
            g->sx += (double)((int64_t)(lb->x0[r] + lb->x1[r]) * len);
            g->sy += (double)((int64_t)y * len);
        }
    for (r = 0; r < lb->n_regions; r++)
        lb->reg[r].sx *= 0.5;
}

static rl_err label(rl_label *lb, const rl_image *img, int lo, int hi, const rl_label_map *map,
                    int min_area)
{
    if (!rl_image_valid(img) || img->width > lb->max_width || img->height > lb->max_height)
        return RL_EINVAL;
    lb->width = img->width;
    lb->height = img->height;
    lb->n_runs = lb->n_regions = lb->overflow = lb->rows_left = 0;
    /* a band past 255 is one up to 255 (its width is kept in a byte) */
    collect_runs(lb, img, lo < 0 ? 0 : lo, hi > 256 ? 256 : hi, map);
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
