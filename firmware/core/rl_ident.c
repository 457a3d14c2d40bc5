#include "rl_ident.h"

#include <math.h>
#include <string.h>

static const double blur_levels[RL_BLUR_LEVELS] = {0.0, 0.03, 0.06, 0.10};

/* Columns scored together: their sums stay in registers or L1, and a
 * whole block has a fixed length the compiler can vectorize. */
#define MATCH_BLOCK 8

/* GCC and Clang: a block is scored in 4-lane vectors (SSE, NEON) that
 * stay in registers; elsewhere in plain C. */
#if defined(__GNUC__) && MATCH_BLOCK == 8
#define RL_V4
typedef float rl_v4 __attribute__((vector_size(16)));
#endif

/* Columns per bin, padded to whole blocks. */
static int padded_columns(int n)
{
    return (n * RL_BLUR_LEVELS + MATCH_BLOCK - 1) / MATCH_BLOCK * MATCH_BLOCK;
}

size_t rl_ident_bytes(int n)
{
    return (size_t)n * sizeof(int) + sizeof(float) * RL_PROFILE_BINS * (size_t)padded_columns(n) +
           2 * RL_WS_ALIGN;
}

/* Templates are stored bin-major: for each bin, the values of every (id,
 * blur) column side by side, so that scoring walks the profile once and
 * updates every column with its own sums (no long dependency chains, and
 * each sum still adds the bins in order). */
static size_t tmpl_index(const rl_ident *id, int i, int blur, int k)
{
    return (size_t)k * (size_t)id->stride + (size_t)i * RL_BLUR_LEVELS + (size_t)blur;
}

float rl_ident_template_bin(const rl_ident *id, int i, int blur, int k)
{
    return id->tmpl[tmpl_index(id, i, blur, k)];
}

double rl_ident_template_at(const rl_family *fam, int id, double rho, double sigma)
{
    /* Darkness is a sum of steps at the zone edges: going inwards across
     * edge r[i] the darkness changes from the zone outside to the zone
     * inside. Blurring turns each step into a Gaussian CDF. */
    double r[RL_MAX_BITS + 2], d = 0.0;
    int i, n = fam->bits, outside = 0;
    rl_family_radii(fam, r);
    for (i = 0; i <= n; i++) {
        int inside = i == 0 ? 1 : rl_family_bit(fam, id, i);
        if (inside != outside) {
            double step = sigma > 0 ? 0.5 * (1.0 + erf((r[i] - rho) / (sigma * sqrt(2.0))))
                                    : (rho < r[i] ? 1.0 : 0.0);
            d += (inside - outside) * step;
        }
        outside = inside;
    }
    return d;
}

rl_err rl_ident_init(rl_ident *id, rl_ws *ws, const rl_family *fam, const int *ids, int n_ids)
{
    int i, b, k, s, n = ids ? n_ids : rl_family_count(fam);
    rl_err e;
    if (n <= 0)
        return RL_EINVAL;
    id->fam = *fam;
    id->n = n;
    if ((e = rl_ws_alloc(ws, (size_t)n * sizeof(int), RL_WS_ALIGN, (void **)&id->ids)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)padded_columns(n) * RL_PROFILE_BINS * sizeof(float),
                         RL_WS_ALIGN, (void **)&id->tmpl)) != RL_OK)
        return e;
    id->stride = padded_columns(n);
    if (rl_ws_is_sizing(ws))
        return RL_OK;
    memset(id->tmpl, 0, (size_t)id->stride * RL_PROFILE_BINS * sizeof(float)); /* the pads */
    for (i = 0; i < n; i++) {
        id->ids[i] = ids ? ids[i] : i + 1;
        if (!rl_family_valid(fam, id->ids[i]))
            return RL_ERANGE;
        for (b = 0; b < RL_BLUR_LEVELS; b++)
            for (k = 0; k < RL_PROFILE_BINS; k++) {
                /* mean over the bin's annulus, weighted by radius (area) */
                double acc = 0, w = 0;
                for (s = 0; s < 8; s++) {
                    double rho = (k + (s + 0.5) / 8) * RL_PROFILE_EXTENT / RL_PROFILE_BINS;
                    acc += rho * rl_ident_template_at(fam, id->ids[i], rho, blur_levels[b]);
                    w += rho;
                }
                id->tmpl[tmpl_index(id, i, b, k)] = (float)(acc / w);
            }
    }
    return RL_OK;
}

void rl_ident_profile(const rl_image *img, double cx, double cy, double r, rl_profile *p)
{
    double ext = RL_PROFILE_EXTENT * r, scale = RL_PROFILE_BINS / ext, e2 = ext * ext;
    int x, y, k, x0 = (int)ceil(cx - ext), x1 = (int)floor(cx + ext);
    int y0 = (int)ceil(cy - ext), y1 = (int)floor(cy + ext);
    double sxx = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->n[k] = p->sx[k] = 0;
    /* pixels outside the image are not gathered: a cut landmark meets cut
     * templates */
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > img->width - 1) x1 = img->width - 1;
    if (y1 > img->height - 1) y1 = img->height - 1;
    for (y = y0; y <= y1; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - cy, dy2 = dy * dy;
        for (x = x0; x <= x1; x++) {
            double dx = x - cx, d2 = dx * dx + dy2, v;
            if (d2 >= e2)
                continue;
            k = (int)(sqrt(d2) * scale);
            v = 255 - row[x];
            p->n[k] += 1;
            p->sx[k] += v;
            sxx += v * v;
        }
    }
    p->sxx = sxx;
    p->total = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->total += p->n[k];
}


/* Pixels of a row whose cells are found before they are summed. */
#define GATHER_CHUNK 64
#define GATHER_BLOCK 16

/* A cell's packed sums: from the top, the count in 12 bits, the sum of
 * grey levels in 20 and the sum of their squares in the low 32 (used up
 * to 31): room for PACK_MAX pixels of level 255. The two halves are
 * unpacked as 32-bit integers. */
#define PACK_N_SHIFT 52
#define PACK_S_SHIFT 32
#define PACK_MAX 4095 /* 4095 * 255 < 2^20, 4095 * 255^2 < 2^31 */

/* Add the packed sums to the raw float cells and clear them. */
static void unpack_cells(rl_polar *pol)
{
    int sct, k;
    for (sct = 0; sct < RL_SECTORS; sct++) {
        uint64_t *a = pol->acc[sct] + RL_POLAR_PAD;
        float *n = pol->n[sct] + RL_POLAR_PAD, *sm = pol->s[sct] + RL_POLAR_PAD;
        float *q = pol->q[sct] + RL_POLAR_PAD;
        for (k = 0; k < RL_POLAR_BINS; k++) {
            uint32_t hi = (uint32_t)(a[k] >> PACK_S_SHIFT), lo = (uint32_t)a[k];
            n[k] += (float)(int32_t)(hi >> (PACK_N_SHIFT - PACK_S_SHIFT));
            sm[k] += (float)(int32_t)(hi & ((1u << (PACK_N_SHIFT - PACK_S_SHIFT)) - 1));
            q[k] += (float)(int32_t)lo;
            a[k] = 0;
        }
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

void rl_ident_polar(const rl_image *img, double cx, double cy, double r, int light,
                    double min_contrast, rl_polar *pol)
{
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
    int y, k, sct, y0 = iceil(cy - lim), y1 = ifloor(cy + lim), rows = 0;
    uint64_t *acc = &pol->acc[0][0];
    memset(pol->acc, 0, sizeof pol->acc);
    memset(pol->n, 0, sizeof pol->n);
    memset(pol->s, 0, sizeof pol->s);
    memset(pol->q, 0, sizeof pol->q);
    if (flush_rows < 1)
        flush_rows = 1;
    for (k = 0; k < 256; k++)
        pol->lut[k] = k < light ? ((uint64_t)1 << PACK_N_SHIFT) | ((uint64_t)k << PACK_S_SHIFT) |
                                      (uint64_t)(k * k)
                                : 0; /* light is not gathered */
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
            unpack_cells(pol);
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
            for (i = 0; i < nx; i++)
                acc[cell[i]] += pol->lut[row[xs + i]];
        }
    }
    unpack_cells(pol);
    /* sector black and white: extreme means over groups of 4 bins of the
     * profile's extent */
    for (sct = 0; sct < RL_SECTORS; sct++) {
        const float *cn = pol->n[sct] + RL_POLAR_PAD, *cs = pol->s[sct] + RL_POLAR_PAD;
        pol->lo[sct] = 1e9;
        pol->hi[sct] = -1e9;
        for (k = 0; k + 3 < RL_PROFILE_BINS; k += 4) {
            float n = cn[k] + cn[k + 1] + cn[k + 2] + cn[k + 3];
            double m;
            if (n < 2)
                continue;
            m = (double)(cs[k] + cs[k + 1] + cs[k + 2] + cs[k + 3]) / n;
            if (m < pol->lo[sct]) pol->lo[sct] = m;
            if (m > pol->hi[sct]) pol->hi[sct] = m;
        }
        pol->usable[sct] = pol->hi[sct] - pol->lo[sct] >= min_contrast;
    }
    /* Normalized (darkness v = a - b I maps a sector's white to 0 and its
     * black to 255), the two sectors of each octant are summed for the
     * profiles: a shift moves a pixel by d . u for its own direction u,
     * which the octant's middle direction gives within cos(22.5 deg), 8%
     * of a shift of at most 1.5 px. Half the cells, half the work of every
     * profile. A washed-out sector is left out. Octant o is written over
     * sector o, which octant o / 2 has already read. */
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

/* Guard bins either side of the shifted profile: a shift of up to
 * SHIFT_GUARD - 1 bins (1.5 px at the smallest landmarks) stays inside. */
#define SHIFT_GUARD 8
#define SHIFT_SPAN (RL_POLAR_BINS + RL_POLAR_PAD) /* cells written per sector */
#define MID_BINS (SHIFT_SPAN + 2 * SHIFT_GUARD)

void rl_ident_polar_profile(const rl_polar *pol, double dx, double dy, double scale,
                            rl_profile *p)
{
    /* Two steps. First every sector is moved by its own fraction of a bin
     * (the shift, the same for all its cells: a two-tap filter) and the
     * sectors are summed; then the sum is rescaled, each cell shared
     * between the two output bins around where its centre lands. */
    double bw = RL_PROFILE_EXTENT * pol->r / RL_PROFILE_BINS, sxx = 0, a = 1.0 / scale, b;
    float mn[MID_BINS], ms[MID_BINS], mq[MID_BINS];
    int sct, k, m;
    memset(mn, 0, sizeof mn);
    memset(ms, 0, sizeof ms);
    memset(mq, 0, sizeof mq);
    for (sct = 0; sct < RL_SECTORS / 2; sct++) {
        /* c[k] is bin k; c[-1] and c[RL_POLAR_BINS] are pads */
        const float *cn = pol->n[sct] + RL_POLAR_PAD, *cs = pol->s[sct] + RL_POLAR_PAD;
        const float *cq = pol->q[sct] + RL_POLAR_PAD;
        float u, w, *on, *os, *oq;
        double sh;
        int j0;
        if (!pol->merged_usable[sct])
            continue;
        /* cell k moves to k + sh: (1 - w) of it to k + j0, w to k + j0 + 1 */
        sh = -(dx * pol->ux[sct] + dy * pol->uy[sct]) / bw;
        if (sh > SHIFT_GUARD - 1) sh = SHIFT_GUARD - 1;
        if (sh < 1 - SHIFT_GUARD) sh = 1 - SHIFT_GUARD;
        j0 = (int)(sh + SHIFT_GUARD) - SHIFT_GUARD; /* floor: sh + SHIFT_GUARD > 0 */
        w = (float)(sh - j0);
        u = 1.0f - w;
        on = mn + SHIFT_GUARD + j0;
        os = ms + SHIFT_GUARD + j0;
        oq = mq + SHIFT_GUARD + j0;
        /* bin k + j0 from cells k and k - 1, over whole vectors */
        for (k = 0; k < SHIFT_SPAN; k++) {
            on[k] += u * cn[k] + w * cn[k - 1];
            os[k] += u * cs[k] + w * cs[k - 1];
            oq[k] += u * cq[k] + w * cq[k - 1];
        }
    }
    /* mid bin m (centre m - SHIFT_GUARD + 0.5 bins out) lands at output
     * t = a (m - SHIFT_GUARD + 0.5) - 0.5, (1 - w) of it in bin j = floor(t)
     * and w in j + 1. t grows with m, so bins j and j + 1 are summed in
     * registers and bin j is written once t has moved past it. */
    if (scale == 1.0) {
        /* as gathered: mid bin SHIFT_GUARD + j is bin j */
        float tn = 0, tq = 0;
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            p->n[k] = mn[SHIFT_GUARD + k];
            p->sx[k] = ms[SHIFT_GUARD + k];
            tn += mn[SHIFT_GUARD + k];
            tq += mq[SHIFT_GUARD + k];
        }
        p->total = tn;
        p->sxx = tq;
        return;
    }
    b = a * (0.5 - SHIFT_GUARD) - 0.5;
    m = (int)((-1.0 - b) / a); /* the first m with t >= -1, or one before */
    if (m < 0)
        m = 0;
    {
        float n0 = 0, n1 = 0, s0 = 0, s1 = 0, q0 = 0, q1 = 0, tq = 0, tn = 0;
        int cur = -1; /* the bin n0, s0, q0 hold; n1, s1, q1 hold cur + 1 */
        for (;; m++) {
            /* past the last mid bin or the last output bin, every bin
             * still open is written */
            double t = m < MID_BINS ? a * m + b : RL_PROFILE_BINS;
            int last = t >= RL_PROFILE_BINS, j;
            float w, v;
            if (t < -1.0)
                continue;
            j = last ? RL_PROFILE_BINS : (int)(t + 1.0) - 1; /* floor: t >= -1 */
            while (cur < j) {
                /* bin cur is complete */
                if (cur >= 0) {
                    p->n[cur] = n0;
                    p->sx[cur] = s0;
                    tn += n0;
                    tq += q0;
                }
                cur++;
                n0 = n1;
                s0 = s1;
                q0 = q1;
                n1 = s1 = q1 = 0;
            }
            if (last)
                break;
            w = (float)(t - j);
            v = 1.0f - w;
            n0 += v * mn[m];
            s0 += v * ms[m];
            q0 += v * mq[m];
            n1 += w * mn[m];
            s1 += w * ms[m];
            q1 += w * mq[m];
        }
        sxx = tq;
        p->total = tn;
    }
    p->sxx = sxx;
}

/* What every column's correlation shares: the profile's pixels, their
 * sum and 1 / sqrt of their variance term. */
typedef struct {
    double n, sx, ivx;
} profile_terms;

/* Pearson's r of one column from its sums, kept as best or runner-up (of
 * any other id). A column that cannot beat the runner-up is dropped
 * before its square root. */
static void keep_column(rl_match *m, const profile_terms *z, int id, int blur, double st,
                        double stt, double sxt)
{
    double vt = z->n * stt - st * st, num, r;
    if (vt <= 0)
        return;
    num = z->n * sxt - z->sx * st;
    if (m->second >= 0 &&
        (num <= 0 || num * num * z->ivx * z->ivx <= m->second * m->second * vt))
        return;
    r = num * z->ivx / sqrt(vt);
    if (r > m->score) {
        if (id != m->id)
            m->second = m->score;
        m->score = r;
        m->id = id;
        m->contrast = num / vt; /* the fitted gain */
        m->blur = blur;
    } else if (r > m->second && id != m->id) {
        m->second = r;
    }
}

/* Score nc <= MATCH_BLOCK columns, anywhere in the table, together (their
 * sums are independent, so they run side by side). */
static void score_columns(const rl_ident *id, const float *fn, const float *fs, const int *cols,
                          int nc, const profile_terms *z, rl_match *m)
{
    float st[MATCH_BLOCK] = {0}, stt[MATCH_BLOCK] = {0}, sxt[MATCH_BLOCK] = {0};
    int k, c;
    if (nc <= 4) {
        /* the usual short list: four lanes of fixed count, the unused
         * ones repeating the first column */
        int c4[4];
        for (c = 0; c < 4; c++)
            c4[c] = cols[c < nc ? c : 0];
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            const float *t = id->tmpl + (size_t)k * (size_t)id->stride;
            float nk = fn[k], sk = fs[k];
            for (c = 0; c < 4; c++) {
                float tv = t[c4[c]];
                st[c] += nk * tv;
                stt[c] += nk * tv * tv;
                sxt[c] += sk * tv;
            }
        }
    } else {
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            const float *t = id->tmpl + (size_t)k * (size_t)id->stride;
            float nk = fn[k], sk = fs[k];
            if (nk == 0)
                continue;
            for (c = 0; c < nc; c++) {
                float tv = t[cols[c]];
                st[c] += nk * tv;
                stt[c] += nk * tv * tv;
                sxt[c] += sk * tv;
            }
        }
    }
    for (c = 0; c < nc; c++)
        keep_column(m, z, id->ids[cols[c] / RL_BLUR_LEVELS], cols[c] % RL_BLUR_LEVELS, st[c],
                    stt[c], sxt[c]);
}

/* Score the templates of `ids` (every template when ids is NULL) at the
 * blur levels [b0, b1), in single precision: 64 bins of sums lose no more
 * than 1e-5 of the correlation. */
static void match_some(const rl_ident *id, const rl_profile *p, const int *ids, int n_ids,
                       int b0, int b1, rl_match *m)
{
    double n = p->total, sx = 0, vx;
    float fn[RL_PROFILE_BINS], fs[RL_PROFILE_BINS];
    profile_terms z;
    int ncol = id->n * RL_BLUR_LEVELS, c0, c, k, j;
    m->id = -1;
    m->score = m->second = -1.0;
    m->contrast = 0.0;
    m->blur = 0;
    if (n < 16)
        return;
    {
        /* two partial sums: half the chain of dependent adds */
        double s0 = 0, s1 = 0;
        for (k = 0; k < RL_PROFILE_BINS; k += 2) {
            s0 += p->sx[k];
            s1 += p->sx[k + 1];
        }
        sx = s0 + s1;
    }
    vx = n * p->sxx - sx * sx;
    if (!(vx > 0))
        return; /* a flat candidate correlates with nothing */
    z.n = n;
    z.sx = sx;
    z.ivx = 1.0 / sqrt(vx);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        fn[k] = (float)p->n[k];
        fs[k] = (float)p->sx[k];
    }
    if (ids != NULL) {
        /* a short list: its columns gathered, scored together */
        int cols[MATCH_BLOCK], nc = 0;
        for (j = 0; j < n_ids; j++) {
            int i, b;
            for (i = 0; i < id->n && id->ids[i] != ids[j]; i++)
                ;
            for (b = b0; b < b1 && i < id->n; b++) {
                cols[nc++] = i * RL_BLUR_LEVELS + b;
                if (nc == MATCH_BLOCK) {
                    score_columns(id, fn, fs, cols, nc, &z, m);
                    nc = 0;
                }
            }
        }
        if (nc > 0)
            score_columns(id, fn, fs, cols, nc, &z, m);
        return;
    }
    /* every column, a block at a time */
    for (c0 = 0; c0 < ncol; c0 += MATCH_BLOCK) {
        float st[MATCH_BLOCK], stt[MATCH_BLOCK], sxt[MATCH_BLOCK];
        int nc = ncol - c0 < MATCH_BLOCK ? ncol - c0 : MATCH_BLOCK;
        for (c = 0; c < MATCH_BLOCK; c++)
            st[c] = stt[c] = sxt[c] = 0;
#ifdef RL_V4
        {
            /* two 4-lane vectors per sum, kept in registers */
            rl_v4 s0 = {0, 0, 0, 0}, s1 = s0, ss0 = s0, ss1 = s0, sx0 = s0, sx1 = s0;
            for (k = 0; k < RL_PROFILE_BINS; k++) {
                const float *t = id->tmpl + (size_t)k * (size_t)id->stride + c0;
                float nk = fn[k], sk = fs[k];
                rl_v4 t0, t1, nv = {nk, nk, nk, nk}, sv = {sk, sk, sk, sk};
                if (nk == 0)
                    continue; /* bins outside the image or in light */
                memcpy(&t0, t, sizeof t0);
                memcpy(&t1, t + 4, sizeof t1);
                s0 += nv * t0;
                s1 += nv * t1;
                ss0 += nv * t0 * t0;
                ss1 += nv * t1 * t1;
                sx0 += sv * t0;
                sx1 += sv * t1;
            }
            memcpy(st, &s0, sizeof s0);
            memcpy(st + 4, &s1, sizeof s1);
            memcpy(stt, &ss0, sizeof ss0);
            memcpy(stt + 4, &ss1, sizeof ss1);
            memcpy(sxt, &sx0, sizeof sx0);
            memcpy(sxt + 4, &sx1, sizeof sx1);
        }
#else
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            const float *t = id->tmpl + (size_t)k * (size_t)id->stride + c0;
            float nk = fn[k], sk = fs[k];
            if (nk == 0)
                continue; /* bins outside the image or in light */
            for (c = 0; c < MATCH_BLOCK; c++) {
                st[c] += nk * t[c];
                stt[c] += nk * t[c] * t[c];
                sxt[c] += sk * t[c];
            }
        }
#endif
        for (c = 0; c < nc; c++) {
            int b = (c0 + c) % RL_BLUR_LEVELS;
            if (b >= b0 && b < b1)
                keep_column(m, &z, id->ids[(c0 + c) / RL_BLUR_LEVELS], b, st[c], stt[c], sxt[c]);
        }
    }
}

void rl_ident_match_ids(const rl_ident *id, const rl_profile *p, const int *ids, int n_ids,
                        int blur, rl_match *m)
{
    match_some(id, p, ids, n_ids, blur < 0 ? 0 : blur, blur < 0 ? RL_BLUR_LEVELS : blur + 1, m);
}

void rl_ident_match(const rl_ident *id, const rl_profile *p, rl_match *m)
{
    match_some(id, p, NULL, 0, 0, RL_BLUR_LEVELS, m);
}

double rl_pearson(const uint8_t *a, const uint8_t *b, const uint8_t *mask, int n)
{
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, c = 0, va, vb;
    int i;
    for (i = 0; i < n; i++) {
        if (mask && !mask[i])
            continue;
        sa += a[i];
        sb += b[i];
        saa += (double)a[i] * a[i];
        sbb += (double)b[i] * b[i];
        sab += (double)a[i] * b[i];
        c += 1;
    }
    va = c * saa - sa * sa;
    vb = c * sbb - sb * sb;
    if (va <= 0 || vb <= 0)
        return 0.0;
    return (c * sab - sa * sb) / sqrt(va * vb);
}
