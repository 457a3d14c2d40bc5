#include "rl_profile.h"

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "rl_clones.h"
#include "rl_geom.h"
#include "rl_motion.h"

/* Pixels of a row handled at a time: their bins first, in blocks of
 * GATHER_BLOCK (a fixed count the compiler vectorizes), then the sums. */
#define GATHER_CHUNK 64
#define GATHER_BLOCK 16
/* A bin's count and sum of darkness packed in one word: one add a pixel.
 * The darkness (0 .. RL_TONE_MAX a pixel) is the low 32 bits, so a word
 * holds PACK_PIXELS pixels before its sum would carry into the count:
 * 4,198,404, more than a 1280x960 frame holds. Larger gathers (a frame
 * over 4.2 megapixels at a radius of thousands of pixels) unpack their
 * words into the profile's doubles every PACK_PIXELS pixels. */
#if RL_TONE_PACK_COUNT != (1ull << 32)
#error "rl_profile unpacks a bin's count from the high 32 bits"
#endif
#define PACK_PIXELS (0xffffffffu / RL_TONE_MAX)

/* The row's span of x where the shape's normalized radius about (cx, cy)
 * is under ext (dy from the centre): [*xa, *xb], empty when *xa > *xb. */
static void row_span(const rl_shape *sh, double cx, double dy, double ext, int *xa, int *xb)
{
    /* a dx^2 + 2 b dy dx + c dy^2 < ext^2 */
    double disc = sh->b * sh->b * dy * dy - sh->a * (sh->c * dy * dy - ext * ext), h, mid;
    if (disc <= 0) {
        *xa = 1;
        *xb = 0;
        return;
    }
    h = sqrt(disc) / sh->a;
    mid = cx - sh->b * dy / sh->a;
    *xa = (int)ceil(mid - h);
    *xb = (int)floor(mid + h);
}

/* Sums over the gathered pixels for the plane that light falling across a
 * candidate adds: coordinates relative to the centre, their squares and
 * products, and their products with the darkness. */
typedef struct {
    double n, v, x, y, xx, yy, xy, xv, yv;
    int clipped; /* the image's border cut the disk */
} plane_sums;

/* Add a row's pixels x0 .. x1 at dy (rv: their darkness summed, rxv: the
 * sum of x v in absolute x) to the plane sums. Inline in gather's AVX2
 * clone (RL_CLONE_INLINE): called from it out of line, the plain build's
 * SSE code after the clone's AVX cost a quarter of a gather's time on the
 * development machine (the same double operations either way). */
RL_CLONE_INLINE
static void plane_row(plane_sums *ps, double cx, double dy, int x0, int x1, double rv, double rxv)
{
    double n = x1 - x0 + 1, a = x0 - cx, b = x1 - cx;
    /* sums of dx and dx^2 for dx = a, a + 1, .., b */
    double sx = 0.5 * n * (a + b), sxx = (b * (b + 1) * (2 * b + 1) - (a - 1) * a * (2 * a - 1)) / 6.0;
    if (n <= 0)
        return;
    ps->n += n;
    ps->v += rv;
    ps->x += sx;
    ps->y += n * dy;
    ps->xx += sxx;
    ps->yy += n * dy * dy;
    ps->xy += sx * dy;
    ps->xv += rxv - cx * rv;
    ps->yv += dy * rv;
}

/* The part of the darkness's sum of squares a plane explains; 0 for a disk
 * the border cut (there a plane is not apart from the rings). Inline in
 * gather's clone too (RL_CLONE_INLINE). */
RL_CLONE_INLINE
static double plane_explained(const plane_sums *ps)
{
    double cxx, cyy, cxy, cxv, cyv, det;
    if (ps->clipped || ps->n < 16)
        return 0;
    cxx = ps->xx - ps->x * ps->x / ps->n;
    cyy = ps->yy - ps->y * ps->y / ps->n;
    cxy = ps->xy - ps->x * ps->y / ps->n;
    cxv = ps->xv - ps->x * ps->v / ps->n;
    cyv = ps->yv - ps->y * ps->v / ps->n;
    det = cxx * cyy - cxy * cxy;
    if (!(det > 0))
        return 0;
    return (cyy * cxv * cxv - 2 * cxy * cxv * cyv + cxx * cyv * cyv) / det;
}

/* Pixels binned by the shape's normalized radius, a circle's included.
 * On x86 also built for AVX2 and chosen at load time: the bins' 16-pixel
 * blocks in 8-lane vectors, the same float operations pixel by pixel (no
 * fused multiply-add: rl_clones.h). */
/* The packed sums of both sets (acc[0], acc[1]) added into p's bins, and
 * emptied. */
static void unpack_bins(uint64_t acc[2][RL_PROFILE_BINS], rl_profile *p)
{
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        uint64_t w = acc[0][k] + acc[1][k];
        p->n[k] += (double)(w >> 32);
        p->sx[k] += (double)(w & 0xffffffffu);
    }
    memset(acc, 0, sizeof(uint64_t) * 2 * RL_PROFILE_BINS);
}

RL_CLONES_AVX2
static void gather(const rl_image *img, const rl_tone *tone, double cx, double cy, double r,
                   const rl_shape *sh, int ystep, rl_profile *p)
{
    double ext = RL_PROFILE_EXTENT * r, scale = RL_PROFILE_BINS / ext;
    /* the ellipse's extent along y */
    double hy = ext * sqrt(sh->a);
    float fa = (float)sh->a, fscale = (float)scale;
    int y, k, y0 = (int)ceil(cy - hy), y1 = (int)floor(cy + hy);
    /* two sets of sums, even and odd pixels: neighbours share a bin, and
     * one set would make every add wait on the one before */
    uint64_t acc[2][RL_PROFILE_BINS], sxx = 0; /* (count, sum) packed: PACK_PIXELS pixels in all */
    uint32_t pending = 0; /* pixels in acc since it was last unpacked */
    /* each grey level's (1, darkness) packed as a bin adds it, made with
     * the curve: one load and one add a pixel, its darkness the low word */
    const uint64_t *packed = tone->packed;
    plane_sums ps;
    memset(acc, 0, sizeof acc);
    memset(&ps, 0, sizeof ps);
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->n[k] = p->sx[k] = 0;
    ps.clipped = y0 < 0 || y1 > img->height - 1;
    /* pixels outside the image are not gathered: a cut landmark meets cut
     * templates */
    if (y0 < 0) y0 = 0;
    if (y1 > img->height - 1) y1 = img->height - 1;
    for (y = y0; y <= y1; y += ystep) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - cy;
        float b2dy = (float)(2 * sh->b * dy), cdy2 = (float)(sh->c * dy * dy);
        int x0, x1, xs;
        uint64_t rs = 0, rv = 0, rxv = 0; /* a row's squares (1023^2 each), sum, x v */
        row_span(sh, cx, dy, ext, &x0, &x1);
        if (x0 <= x1 && (x0 < 0 || x1 > img->width - 1))
            ps.clipped = 1;
        if (x0 < 0) x0 = 0;
        if (x1 > img->width - 1) x1 = img->width - 1;
        if (x0 <= x1) {
            if (pending > PACK_PIXELS - (uint32_t)(x1 - x0 + 1)) {
                unpack_bins(acc, p); /* the next row could carry */
                pending = 0;
            }
            pending += (uint32_t)(x1 - x0 + 1);
        }
        for (xs = x0; xs <= x1; xs += GATHER_CHUNK) {
            int nx = x1 - xs + 1 < GATHER_CHUNK ? x1 - xs + 1 : GATHER_CHUNK, i, b;
            int bin[GATHER_CHUNK];
            uint32_t v[GATHER_CHUNK], s1, s2, s3;
            float dx0 = (float)(xs - cx);
            for (b = 0; b < nx; b += GATHER_BLOCK) {
                int *kb = bin + b;
                float bx = dx0 + (float)b;
                for (i = 0; i < GATHER_BLOCK; i++) {
                    float dx = bx + (float)i, d2 = (fa * dx + b2dy) * dx + cdy2;
                    int kk = (int)(sqrtf(d2) * fscale);
                    /* a pixel on the rim (the span's rounding) in the last bin */
                    kb[i] = kk < RL_PROFILE_BINS - 1 ? kk : RL_PROFILE_BINS - 1;
                }
            }
            /* the bins' sums in pairs, the even pixel's in acc[0], the odd
             * one's in acc[1]; each pixel's darkness kept for the row's sums */
            for (i = 0; i + 1 < nx; i += 2) {
                uint64_t w0 = packed[row[xs + i]], w1 = packed[row[xs + i + 1]];
                v[i] = (uint32_t)w0;
                v[i + 1] = (uint32_t)w1;
                acc[0][bin[i]] += w0;
                acc[1][bin[i + 1]] += w1;
            }
            if (i < nx) {
                uint64_t w = packed[row[xs + i]];
                v[i] = (uint32_t)w;
                acc[0][bin[i]] += w;
            }
            /* the row's sums, vectorized; in 32 bits: a chunk's squares
             * are under 64 * 1023^2, its i v under 2016 * 1023 */
            for (i = 0, s1 = s2 = s3 = 0; i < nx; i++) {
                s1 += v[i];
                s2 += v[i] * v[i];
                s3 += (uint32_t)i * v[i];
            }
            rv += s1;
            rs += s2;
            rxv += (uint64_t)xs * s1 + s3;
        }
        sxx += rs;
        plane_row(&ps, cx, dy, x0, x1, (double)rv, (double)rxv);
    }
    p->sxx = (double)sxx;
    p->plane = plane_explained(&ps);
    unpack_bins(acc, p);
    p->total = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->total += p->n[k];
}

void rl_profile_gather(const rl_image *img, const rl_tone *tone, double cx, double cy, double r,
                       rl_profile *p)
{
    rl_shape circle = rl_shape_circle();
    gather(img, tone, cx, cy, r, &circle, 1, p);
}

void rl_profile_gather_shaped(const rl_image *img, const rl_tone *tone, double cx, double cy,
                              double r, const rl_shape *sh, rl_profile *p)
{
    rl_shape circle = rl_shape_circle();
    gather(img, tone, cx, cy, r, sh ? sh : &circle, 1, p);
}

void rl_profile_gather_rows(const rl_image *img, const rl_tone *tone, double cx, double cy, double r,
                            int step, rl_profile *p)
{
    rl_shape circle = rl_shape_circle();
    gather(img, tone, cx, cy, r, &circle, step < 1 ? 1 : step, p);
}

/* The bin that bin k's middle falls in at scale s, the last for those
 * past it. */
static int rescaled_bin(int k, double s)
{
    /* compared before the cast: at a tiny s the quotient is past int's
     * range, at s <= 0 (no caller's) negative or -inf: the cast would be
     * undefined or the bin out of range; NaN goes to bin 0 */
    double j = (k + 0.5) / s;
    return !(j > 0) ? 0 : j < RL_PROFILE_BINS - 1 ? (int)j : RL_PROFILE_BINS - 1;
}

void rl_profile_rescale(const rl_profile *src, double s, rl_profile *dst)
{
    rl_profile_scale sc;
    rl_profile_scale_make(s, &sc);
    rl_profile_rescale_by(src, &sc, dst);
}

void rl_profile_scale_make(double s, rl_profile_scale *sc)
{
    int k;
    sc->s = s;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        sc->to[k] = (unsigned char)rescaled_bin(k, s);
    sc->made = 1;
}

void rl_profile_rescale_by(const rl_profile *src, const rl_profile_scale *sc, rl_profile *dst)
{
    int k;
    dst->sxx = src->sxx;
    dst->plane = src->plane;
    dst->total = src->total;
    memset(dst->n, 0, sizeof dst->n);
    memset(dst->sx, 0, sizeof dst->sx);
    /* each bin's sums added in k's order into a zeroed bin
     * (rl_profile_rescale is this, by the moves made at its s) */
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        int j = sc->to[k];
        dst->n[j] += src->n[k];
        dst->sx[j] += src->sx[k];
    }
}

void rl_profile_gather_axis(const rl_image *img, const rl_tone *tone, double cx, double cy, double r, int a,
                            rl_profile *p)
{
    double ext = RL_PROFILE_EXTENT * r, scale = RL_PROFILE_BINS / ext;
    rl_box b;
    int x, y, k, x0, x1;
    memset(p, 0, sizeof *p);
    rl_geom_square_in(img->width, img->height, cx, cy, ext, 0, &b);
    x0 = b.x0;
    x1 = b.x1;
    for (y = b.y0; y <= b.y1; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - cy;
        for (x = x0; x <= x1; x++) {
            double dx = x - cx, d = sqrt(dx * dx + dy * dy);
            double v;
            if (d >= ext || !rl_motion_on_axis(dx, dy, a))
                continue;
            k = (int)(d * scale);
            k = k < RL_PROFILE_BINS - 1 ? k : RL_PROFILE_BINS - 1;
            v = (double)(uint32_t)tone->packed[row[x]];
            p->n[k] += 1;
            p->sx[k] += v;
            p->sxx += v * v;
        }
    }
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->total += p->n[k];
}
