/* The labeller reads only the pixels of the image it is given (the
 * speed work reads a row's short last chunk as the whole chunk ending
 * with it): every image lies against a page the process may not touch,
 * its last byte just before one (an over-read faults) or its first byte
 * just after one (an under-read faults), in a buffer of exactly
 * (height - 1) * stride + width bytes, and windows are cut at the
 * buffer's first and last pixel. Widths 1-200 (under one chunk of 64,
 * between one and two, several), strides wider than the width. The
 * regions must be those of an 8-connected flood fill written here; a band
 * that reaches past 255 is the band up to 255. Light bands (lo 235-255,
 * and others over 0) too, where the labeller passes by whole chunks
 * under lo: SSE2's maximum on x86, 64-bit words elsewhere (aarch64 in the
 * cross build, RL_NO_VECTOR_EXT in the sanitizer build). */
#define _DEFAULT_SOURCE
#include "rl_test.h"
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>
#include "rl_label.h"

#define MAXW 200
#define MAXH 6
static uint8_t wsmem[1 << 20];
static rl_label lb;

typedef struct {
    long area;
    int x0, y0, x1, y1;
    double sx, sy;
} region;

static unsigned seed = 12345;
static unsigned rnd(void)
{
    seed = seed * 1103515245u + 12345u;
    return seed >> 8;
}

/* n bytes against a forbidden page: ending just before it (at_end) or
 * starting just after it. *map and *len to unmap. */
static uint8_t *guarded(size_t n, int at_end, void **map, size_t *len)
{
    size_t pg = (size_t)sysconf(_SC_PAGESIZE), body = (n + pg - 1) / pg * pg;
    uint8_t *m;
    *len = body + 2 * pg;
    *map = mmap(NULL, *len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    assert_true(*map != MAP_FAILED);
    m = *map;
    assert_int_equal(mprotect(m, pg, PROT_NONE), 0);
    assert_int_equal(mprotect(m + pg + body, pg, PROT_NONE), 0);
    return at_end ? m + pg + body - n : m + pg;
}

static int in_band(const rl_image *im, int x, int y, int lo, int hi)
{
    int v = im->data[(size_t)y * (size_t)im->stride + (size_t)x];
    return v >= lo && v < hi;
}

/* 8-connected regions of lo <= I < hi, by flood fill (mark: w * h). */
static int flood(const rl_image *im, int lo, int hi, region *out, uint8_t *mark)
{
    static int stack[MAXW * MAXH * 9];
    int n = 0, x, y, w = im->width, h = im->height;
    memset(mark, 0, (size_t)w * (size_t)h);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            int top = 0;
            region g = {0, x, y, x, y, 0, 0};
            if (mark[y * w + x] || !in_band(im, x, y, lo, hi))
                continue;
            mark[y * w + x] = 1;
            stack[top++] = y * w + x;
            while (top > 0) {
                int p = stack[--top], px = p % w, py = p / w, dx, dy;
                g.area++;
                g.x0 = px < g.x0 ? px : g.x0;
                g.x1 = px > g.x1 ? px : g.x1;
                g.y0 = py < g.y0 ? py : g.y0;
                g.y1 = py > g.y1 ? py : g.y1;
                g.sx += px;
                g.sy += py;
                for (dy = -1; dy <= 1; dy++)
                    for (dx = -1; dx <= 1; dx++) {
                        int qx = px + dx, qy = py + dy;
                        if (qx < 0 || qy < 0 || qx >= w || qy >= h || mark[qy * w + qx] ||
                            !in_band(im, qx, qy, lo, hi))
                            continue;
                        mark[qy * w + qx] = 1;
                        stack[top++] = qy * w + qx;
                    }
            }
            out[n++] = g;
        }
    return n;
}

static int by_place(const void *a, const void *b)
{
    const region *p = a, *q = b;
    if (p->y0 != q->y0)
        return p->y0 - q->y0;
    if (p->x0 != q->x0)
        return p->x0 - q->x0;
    return (p->area > q->area) - (p->area < q->area);
}

/* Label im and compare with the flood fill; 0 when they agree. */
static int compare(const rl_image *im, int lo, int hi)
{
    static region want[MAXW * MAXH], got[MAXW * MAXH];
    static uint8_t mark[MAXW * MAXH];
    int n = flood(im, lo, hi, want, mark), i;
    assert_int_equal(rl_label_band(&lb, im, lo, hi, 1), RL_OK);
    if (lb.n_regions != n || lb.overflow || lb.rows_left)
        return 1;
    for (i = 0; i < n; i++) {
        const rl_region *r = &lb.reg[i];
        region g = {r->area, r->x0, r->y0, r->x1, r->y1, r->sx, r->sy};
        got[i] = g;
    }
    qsort(want, (size_t)n, sizeof *want, by_place);
    qsort(got, (size_t)n, sizeof *got, by_place);
    for (i = 0; i < n; i++)
        if (want[i].area != got[i].area || want[i].x0 != got[i].x0 || want[i].y0 != got[i].y0 ||
            want[i].x1 != got[i].x1 || want[i].y1 != got[i].y1 || want[i].sx != got[i].sx || want[i].sy != got[i].sy)
            return 1;
    return 0;
}

/* Bands of random width and level, so that runs start and end anywhere
 * in a chunk, at the first and the last pixel included. */
static void fill(uint8_t *p, size_t n)
{
    size_t i = 0;
    while (i < n) {
        size_t run = 1 + rnd() % 9;
        uint8_t v = (uint8_t)(rnd() % 4 == 0 ? 60 + rnd() % 40 : 150 + rnd() % 100);
        for (; run > 0 && i < n; run--)
            p[i++] = v;
    }
}

static void images_against_forbidden_pages(void **state)
{
    int W, H, at_end, cases = 0, bad = 0;
    rl_ws ws;
    (void)state;
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_label_init(&lb, &ws, MAXW, MAXH, 20000, 4000), RL_OK);
    for (W = 1; W <= MAXW; W += W < 140 ? 1 : 7)
        for (H = 1; H <= MAXH; H += 2)
            for (at_end = 0; at_end < 2; at_end++) {
                int stride = W + (int)(rnd() % 3) * (int)(rnd() % 70);
                size_t n = (size_t)stride * (size_t)(H - 1) + (size_t)W, len;
                void *map;
                uint8_t *buf = guarded(n, at_end, &map, &len);
                rl_image im = rl_image_view(W, H, stride, buf), win;
                fill(buf, n);
                bad += compare(&im, 0, 128);
                cases++;
                /* windows at the buffer's first and its last pixel */
                if (W > 2 && H > 1) {
                    int w = 1 + (int)(rnd() % (unsigned)(W - 1)), h = 1 + (int)(rnd() % (unsigned)(H - 1));
                    assert_int_equal(rl_image_sub(&im, 0, 0, w, h, &win), RL_OK);
                    bad += compare(&win, 0, 128);
                    assert_int_equal(rl_image_sub(&im, W - w, H - h, w, h, &win), RL_OK);
                    bad += compare(&win, 100, 200);
                    cases += 2;
                }
                assert_int_equal(munmap(map, len), 0);
            }
    /* a band reaching past 255 (lo 79, hi 271): no pixel under lo in it */
    {
        void *map;
        size_t len;
        uint8_t *buf = guarded(64, 1, &map, &len);
        rl_image im = rl_image_view(64, 1, 64, buf);
        memset(buf, 0, 64);
        memset(buf + 10, 200, 5);
        bad += compare(&im, 79, 271);
        assert_int_equal(lb.n_regions, 1);
        assert_int_equal(munmap(map, len), 0);
    }
    printf("  %d images and windows against forbidden pages: %d differ from the flood fill\n", cases, bad);
    assert_int_equal(bad, 0);
}

/* A light band (lo 235 or more, as rl_light's; and any other lo over 0,
 * which takes the same path): a ceiling under lo with a few runs over it,
 * so that whole chunks hold no pixel of the band (the labeller passes
 * them by) next to chunks that do; a quarter of the ceiling's pixels at
 * lo - 1, the band's foot missed by one; the runs often end on a chunk's
 * last pixel (63, 127, 191), the next chunk under lo, where the run must
 * end, not be carried on over the chunk passed by. */
static void fill_lights(uint8_t *p, int w, int h, int stride, int lo)
{
    int y, k, base = lo > 100 ? 100 : 0;
    for (y = 0; y < h; y++) {
        uint8_t *row = p + (size_t)y * (size_t)stride;
        int runs = (int)(rnd() % 4);
        for (k = 0; k < w; k++) /* under lo */
            row[k] = (uint8_t)(rnd() % 4 == 0 ? lo - 1 : base + (int)(rnd() % (unsigned)(lo - base)));
        for (k = 0; k < runs; k++) {
            int len = 1 + (int)(rnd() % 20), end, a;
            /* half of them end on a chunk's last pixel */
            end = rnd() % 2 ? 63 + 64 * (int)(rnd() % 4) : (int)(rnd() % (unsigned)w);
            if (end >= w)
                end = w - 1;
            for (a = end - len + 1 < 0 ? 0 : end - len + 1; a <= end; a++)
                row[a] = (uint8_t)(lo + rnd() % (unsigned)(256 - lo));
        }
    }
}

/* The light labelling's feet, and others on either side of 128 (the
 * word-wise test, where there is no SSE2, takes those apart). */
static const int light_feet[] = {235, 240, 245, 250, 255, 1, 2, 64, 127, 128, 129, 200};

static void light_bands(void **state)
{
    int W, H, f, cases = 0, bad = 0;
    rl_ws ws;
    (void)state;
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_label_init(&lb, &ws, MAXW, MAXH, 20000, 4000), RL_OK);
    for (W = 60; W <= MAXW; W += 1 + (int)(rnd() % 5))
        for (H = 1; H <= MAXH; H++)
            for (f = 0; f < (int)(sizeof light_feet / sizeof light_feet[0]); f++) {
                static uint8_t buf[MAXW * MAXH + 64];
                int lo = light_feet[f];
                int stride = W + (int)(rnd() % 9);
                rl_image im = rl_image_view(W, H, stride, buf);
                fill_lights(buf, W, H, stride, lo);
                bad += compare(&im, lo, 256);
                bad += compare(&im, lo, 256 + (int)(rnd() % 40));
                cases += 2;
            }
    printf("  %d light bands: %d differ from the flood fill\n", cases, bad);
    assert_int_equal(bad, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(images_against_forbidden_pages),
        cmocka_unit_test(light_bands),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
