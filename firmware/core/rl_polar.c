#include "rl_polar.h"

#include <math.h>
#include <string.h>
#include "rl_clones.h"


/* Pixels of a row whose cells are found before they are summed. */
#define GATHER_CHUNK 64
#define GATHER_BLOCK 16

/* On x86 the per-pixel and per-bin loops are also built for AVX2
 * (rl_clones.h): 8-lane vectors, the same float operations element by
 * element, no fused multiply-add and no sum reordered (no fast-math): the
 * same numbers. */
#define POLAR_CLONES RL_CLONES_AVX2

/* A cell's packed sums: from the top, the count in 12 bits, the sum of
 * grey levels in 20 and the sum of their squares in the low 32 (used up
 * to 31): room for PACK_MAX pixels of level 255. The two halves are
 * unpacked as 32-bit integers. */
#define PACK_N_SHIFT 52
#define PACK_S_SHIFT 32
#define PACK_MAX 4095 /* 4095 * 255 < 2^20, 4095 * 255^2 < 2^31 */

/* Add the packed sums to the raw float cells (first: into cells not yet
 * written, set to them: the same floats as 0 plus them) and clear them. */
POLAR_CLONES
static void unpack_cells(rl_polar *pol, int first)
{
    int sct, k;
    for (sct = 0; sct < RL_SECTORS; sct++) {
        uint64_t *a = pol->acc[sct] + RL_POLAR_PAD;
        float *n = pol->n[sct] + RL_POLAR_PAD, *sm = pol->s[sct] + RL_POLAR_PAD;
        float *q = pol->q[sct] + RL_POLAR_PAD;
        if (first)
            for (k = 0; k < RL_POLAR_BINS; k++) {
                uint32_t hi = (uint32_t)(a[k] >> PACK_S_SHIFT), lo = (uint32_t)a[k];
                n[k] = (float)(int32_t)(hi >> (PACK_N_SHIFT - PACK_S_SHIFT));
                sm[k] = (float)(int32_t)(hi & ((1u << (PACK_N_SHIFT - PACK_S_SHIFT)) - 1));
                q[k] = (float)(int32_t)lo;
                a[k] = 0;
            }
        else
            for (k = 0; k < RL_POLAR_BINS; k++) {
                uint32_t hi = (uint32_t)(a[k] >> PACK_S_SHIFT), lo = (uint32_t)a[k];
                n[k] += (float)(int32_t)(hi >> (PACK_N_SHIFT - PACK_S_SHIFT));
                sm[k] += (float)(int32_t)(hi & ((1u << (PACK_N_SHIFT - PACK_S_SHIFT)) - 1));
                q[k] += (float)(int32_t)lo;
                a[k] = 0;
            }
    }
}

/* The float cells' pads (RL_POLAR_PAD either side of a sector's bins, read
 * by a shifted profile's two-tap filter) zeroed; their bins are written
 * by the first unpack_cells. */
static void clear_pads(float (*c)[RL_POLAR_CELLS])
{
    int sct;
    for (sct = 0; sct < RL_SECTORS; sct++) {
        memset(c[sct], 0, RL_POLAR_PAD * sizeof c[sct][0]);
        memset(c[sct] + RL_POLAR_PAD + RL_POLAR_BINS, 0, RL_POLAR_PAD * sizeof c[sct][0]);
    }
}

/* Smallest integer >= v and largest <= v, without libm calls. */
static int iceil(double v)
{
    int t = (int)v;
    return t < v ? t + 1 : t;
}

static int ifloor(double v)
{
    int t = (int)v;
    return t > v ? t - 1 : t;
}

/* The brightest grey level under `light` on a coarse grid over the
 * candidate's disk of reach lim (at least 1). */
#if defined(__GNUC__) && !defined(RL_NO_VECTOR_EXT) && defined(__BYTE_ORDER__) && \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define POLAR_VECTORS 1
typedef uint16_t polar_u16x8 __attribute__((vector_size(16)));
#endif

/* The brightest of row[x0], row[x0 + 2], .. up to x1 under light, or top
 * where none is brighter. In vectors, 16 bytes at a time: their even bytes
 * (the low byte of each 16-bit lane: little-endian), those at light or over
 * zeroed, the lanes' maximum kept; the same maximum as one by one. */
static int brightest_in_row(const uint8_t *row, int x0, int x1, int light, int top)
{
    int x = x0;
#ifdef POLAR_VECTORS
    if (x1 - x0 >= 15) {
        uint16_t l = (uint16_t)(light > 256 ? 256 : light), m[8];
        polar_u16x8 lim = {l, l, l, l, l, l, l, l}, low = {255, 255, 255, 255, 255, 255, 255, 255};
        polar_u16x8 best = {0, 0, 0, 0, 0, 0, 0, 0};
        int k;
        for (; x + 15 <= x1; x += 16) {
            polar_u16x8 v, keep;
            memcpy(&v, row + x, sizeof v);
            v &= low;
            v &= (polar_u16x8)(v < lim);
            keep = (polar_u16x8)(v > best);
            best = (v & keep) | (best & ~keep);
        }
        memcpy(m, &best, sizeof m);
        for (k = 0; k < 8; k++)
            top = m[k] > top ? m[k] : top;
    }
#endif
    for (; x <= x1; x += 2)
        if (row[x] < light && row[x] > top)
            top = row[x];
    return top;
}

static int brightest_below(const rl_image *img, double cx, double cy, double lim, int light)
{
    int y, top = 1;
    int x0 = (int)(cx - lim), x1 = (int)(cx + lim), y0 = (int)(cy - lim), y1 = (int)(cy + lim);
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > img->width - 1) x1 = img->width - 1;
    if (y1 > img->height - 1) y1 = img->height - 1;
    for (y = y0; y <= y1; y += 2)
        top = brightest_in_row(img->data + (size_t)y * (size_t)img->stride, x0, x1, light, top);
    return top;
}

/* Clear the cells, fill the per-level table and the sector directions.
 * The table holds light (tone) in 8 bits, the candidate's brightest level
 * at 255: a landmark in a dark corner keeps its steps. */
static void polar_setup(rl_polar *pol, const rl_tone *tone, int top, double cx, double cy, double r,
                        int light)
{
    int k, sct;
    double scale = 255.0 / (tone->light[top] > 1 ? tone->light[top] : 1);
    memset(pol->acc, 0, sizeof pol->acc);
    clear_pads(pol->n);
    clear_pads(pol->s);
    clear_pads(pol->q);
    for (k = 0; k < 256; k++)
    {
        double l = tone->light[k] * scale;
        uint64_t v = (uint64_t)(l > 255 ? 255 : l + 0.5);
        pol->lut[k] = k < light ? ((uint64_t)1 << PACK_N_SHIFT) | (v << PACK_S_SHIFT) | (v * v)
                                : 0; /* light is not gathered */
    }
    pol->cx = cx;
    pol->cy = cy;
    pol->r = r;
    for (sct = 0; sct < RL_SECTORS; sct++) {
        /* mid-angle of each sector, laid out as in the gather below */
        /* cos and sin of 11.25 and 33.75 degrees */
        static const double cs[2][2] = {{0.98078528040323043, 0.19509032201612825},
                                        {0.83146961230254524, 0.55557023301960218}};
        int oct = sct / 2, sub = sct % 2, major = oct % 2;
        double ax = major ? cs[sub][0] : cs[sub][1], ay = major ? cs[sub][1] : cs[sub][0];
        pol->ux[sct] = (oct / 4 ? -1.0 : 1.0) * ax;
        pol->uy[sct] = ((oct / 2) % 2 ? -1.0 : 1.0) * ay;
    }
}

/* Add every pixel within reach (not light) to its cell's packed sums, and
 * move the sums to the float cells. */
POLAR_CLONES
static void gather_cells(rl_polar *pol, const rl_image *img)
{
    double cx = pol->cx, cy = pol->cy, r = pol->r;
    double bw = RL_PROFILE_EXTENT * r / RL_PROFILE_BINS, lim = RL_POLAR_BINS * bw;
    /* Pixels a cell can hold: it fits a box of bw plus the arc's bulge
     * (0.02 lim) by the sector's chord (0.4 lim), which holds at most
     * (w + 1) (h + 1) pixels, and a row meets at most w + h + 1 of them.
     * Past PACK_MAX (landmarks of some 380 px radius) the sums are moved
     * out every few rows. */
    double bw_box = bw + 0.02 * lim, ch_box = 0.4 * lim;
    int flush_rows = (bw_box + 1.0) * (ch_box + 1.0) <= PACK_MAX
                         ? 1 << 30
                         : (int)(PACK_MAX / (bw_box + ch_box + 1.0));
    float inv = (float)(1.0 / bw), fcx = (float)cx;
    int y, y0 = iceil(cy - lim), y1 = ifloor(cy + lim), rows = 0, first = 1;
    uint64_t *acc = &pol->acc[0][0];
    const uint64_t *lut = pol->lut;
    if (flush_rows < 1)
        flush_rows = 1;
    if (y0 < 0) y0 = 0;
    if (y1 > img->height - 1) y1 = img->height - 1;
    for (y = y0; y <= y1; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - cy, half = lim * lim - dy * dy;
        float fdy = (float)dy, dy2 = fdy * fdy, ady = fabsf(fdy);
        /* sector s's cells start at s * RL_POLAR_CELLS; s = 8 (left) + 4
         * (above) + 2 (|dx| > |dy|) + 1 (the half of the octant away from
         * the axis) */
        int x0, x1, xs, rowbase = (dy < 0 ? 4 * RL_POLAR_CELLS : 0) + RL_POLAR_PAD;
        if (half <= 0)
            continue;
        if (++rows > flush_rows) {
            unpack_cells(pol, first);
            first = 0;
            rows = 1;
        }
        /* the row's span inside the outer circle */
        half = sqrt(half);
        x0 = iceil(cx - half);
        x1 = ifloor(cx + half);
        if (x0 < 0) x0 = 0;
        if (x1 > img->width - 1) x1 = img->width - 1;
        /* a chunk of the row at a time: first every pixel's cell (plain
         * arithmetic), then the sums */
        for (xs = x0; xs <= x1; xs += GATHER_CHUNK) {
            int nx = x1 - xs + 1 < GATHER_CHUNK ? x1 - xs + 1 : GATHER_CHUNK, i;
            int cell[GATHER_CHUNK], b;
            /* blocks of GATHER_BLOCK pixels: a fixed count the compiler
             * vectorizes (the block's tail past the row costs nothing) */
            for (b = 0; b < nx; b += GATHER_BLOCK) {
                float bx = (float)(xs + b) - fcx;
                int *cb = cell + b;
                for (i = 0; i < GATHER_BLOCK; i++) {
                    float dx = bx + (float)i, adx = fabsf(dx);
                    float lo = adx < ady ? adx : ady, hi = adx < ady ? ady : adx;
                    /* the bin, the rim's rounding kept in the last one */
                    float d = sqrtf(dx * dx + dy2) * inv;
                    d = d < RL_POLAR_BINS - 0.5f ? d : RL_POLAR_BINS - 0.5f;
                    /* 16 sectors from the octant and whether the smaller
                     * coordinate is above tan(22.5 deg) of the larger (no atan2) */
                    cb[i] = rowbase + (dx < 0 ? 8 * RL_POLAR_CELLS : 0) +
                            (adx > ady ? 2 * RL_POLAR_CELLS : 0) +
                            (lo > 0.41421356f * hi ? RL_POLAR_CELLS : 0) + (int)d;
                }
            }
            /* four pixels a step (the loop's own count and test were half
             * its instructions); integer sums, in the same order anyway */
            for (i = 0; i + 3 < nx; i += 4) {
                acc[cell[i]] += lut[row[xs + i]];
                acc[cell[i + 1]] += lut[row[xs + i + 1]];
                acc[cell[i + 2]] += lut[row[xs + i + 2]];
                acc[cell[i + 3]] += lut[row[xs + i + 3]];
            }
            for (; i < nx; i++)
                acc[cell[i]] += lut[row[xs + i]];
        }
    }
    unpack_cells(pol, first);
}

/* Each sector's black and white (extreme means over groups of 4 bins of
 * the profile's extent); a sector with less contrast is not usable. The
 * extreme groups are found by comparing their sums crosswise (s1 n2 <
 * s2 n1: floats' products, exact in double), and only their means
 * divided out: the division rounds monotonically, so the extremes are
 * the same doubles as the least and largest of every group's mean. */
static void sector_levels(rl_polar *pol, double min_contrast)
{
    int sct, k;
    for (sct = 0; sct < RL_SECTORS; sct++) {
        const float *cn = pol->n[sct] + RL_POLAR_PAD, *cs = pol->s[sct] + RL_POLAR_PAD;
        double ls = 0, ln = 0, hs = 0, hn = 0; /* the darkest and brightest group's sum and count */
        int any = 0;
        for (k = 0; k + 3 < RL_PROFILE_BINS; k += 4) {
            float n = cn[k] + cn[k + 1] + cn[k + 2] + cn[k + 3];
            double sd, nd;
            if (n < 2)
                continue;
            sd = (double)(cs[k] + cs[k + 1] + cs[k + 2] + cs[k + 3]);
            nd = (double)n;
            if (!any) {
                ls = hs = sd;
                ln = hn = nd;
                any = 1;
                continue;
            }
            if (sd * ln < ls * nd) {
                ls = sd;
                ln = nd;
            }
            if (sd * hn > hs * nd) {
                hs = sd;
                hn = nd;
            }
        }
        pol->lo[sct] = any ? ls / ln : 1e9;
        pol->hi[sct] = any ? hs / hn : -1e9;
        pol->usable[sct] = pol->hi[sct] - pol->lo[sct] >= min_contrast;
    }
}

/* Normalized (darkness v = a - b I maps a sector's white to 0 and its
 * black to 255), the two sectors of each octant are summed for the
 * profiles: a shift moves a pixel by d . u for its own direction u,
 * which the octant's middle direction gives within cos(22.5 deg), 8%
 * of a shift of at most 1.5 px. Half the cells, half the work of every
 * profile. A washed-out sector is left out. Octant o is written over
 * sector o, which octant o / 2 has already read. */
POLAR_CLONES
static void merge_octants(rl_polar *pol)
{
    int sct, k;
    for (sct = 0; sct < RL_SECTORS / 2; sct++) {
        int h, k0 = RL_POLAR_PAD;
        double ux = pol->ux[2 * sct] + pol->ux[2 * sct + 1];
        double uy = pol->uy[2 * sct] + pol->uy[2 * sct + 1], len = sqrt(ux * ux + uy * uy);
        float on[RL_POLAR_BINS], os[RL_POLAR_BINS], oq[RL_POLAR_BINS];
        for (k = 0; k < RL_POLAR_BINS; k++)
            on[k] = os[k] = oq[k] = 0;
        for (h = 0; h < 2; h++) {
            int from = 2 * sct + h;
            const float *cn = pol->n[from] + k0, *cs = pol->s[from] + k0, *cq = pol->q[from] + k0;
            float b, a, a2, ab2, b2;
            if (!pol->usable[from])
                continue;
            b = (float)(255.0 / (pol->hi[from] - pol->lo[from]));
            a = (float)(b * pol->hi[from]);
            a2 = a * a;
            ab2 = 2 * a * b;
            b2 = b * b;
            for (k = 0; k < RL_POLAR_BINS; k++) {
                on[k] += cn[k];
                os[k] += cn[k] * a - b * cs[k];
                oq[k] += cn[k] * a2 - ab2 * cs[k] + b2 * cq[k];
            }
        }
        memcpy(pol->n[sct] + k0, on, sizeof on);
        memcpy(pol->s[sct] + k0, os, sizeof os);
        memcpy(pol->q[sct] + k0, oq, sizeof oq);
        pol->ux[sct] = ux / len;
        pol->uy[sct] = uy / len;
        pol->merged_usable[sct] = pol->usable[2 * sct] || pol->usable[2 * sct + 1];
    }
}

void rl_polar_gather(const rl_image *img, const rl_tone *tone, double cx, double cy, double r,
                     int light, double min_contrast, rl_polar *pol)
{
    polar_setup(pol, tone, brightest_below(img, cx, cy, RL_PROFILE_EXTENT * r, light), cx, cy, r,
                light);
    gather_cells(pol, img);
    sector_levels(pol, min_contrast);
    merge_octants(pol);
}

int rl_polar_opposite(int o)
{
    return o ^ 6;
}

int rl_polar_mirror(int o)
{
    return o ^ 4;
}
