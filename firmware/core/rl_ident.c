#include "rl_ident.h"

#include <math.h>
#include <string.h>

static const double blur_levels[RL_BLUR_LEVELS] = {0.0, 0.03, 0.06, 0.10};

size_t rl_ident_bytes(int n)
{
    return (size_t)n * (sizeof(int) + sizeof(float) * RL_BLUR_LEVELS * RL_PROFILE_BINS) +
           2 * RL_WS_ALIGN;
}

/* Templates are stored bin-major: for each bin, the values of every (id,
 * blur) column side by side, so that scoring walks the profile once and
 * updates every column with its own sums (no long dependency chains, and
 * each sum still adds the bins in order). */
static size_t tmpl_index(const rl_ident *id, int i, int blur, int k)
{
    return (size_t)k * (size_t)id->n * RL_BLUR_LEVELS + (size_t)i * RL_BLUR_LEVELS + (size_t)blur;
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
        (e = rl_ws_alloc(ws, (size_t)n * RL_BLUR_LEVELS * RL_PROFILE_BINS * sizeof(float),
                         RL_WS_ALIGN, (void **)&id->tmpl)) != RL_OK)
        return e;
    if (rl_ws_is_sizing(ws))
        return RL_OK;
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


/* Sector of a pixel offset: 16 sectors from the octant and whether the
 * smaller coordinate is above tan(22.5 deg) of the larger (no atan2). */
static int sector_of(double dx, double dy)
{
    double ax = fabs(dx), ay = fabs(dy);
    int major = ax > ay, sub = major ? ay > 0.41421356 * ax : ax > 0.41421356 * ay;
    return ((dx < 0) * 4 + (dy < 0) * 2 + major) * 2 + sub;
}

void rl_ident_polar(const rl_image *img, double cx, double cy, double r, int light,
                    double min_contrast, rl_polar *pol)
{
    double bw = RL_PROFILE_EXTENT * r / RL_PROFILE_BINS, inv = 1.0 / bw, lim = RL_POLAR_BINS * bw;
    double lim2 = lim * lim;
    int x, y, k, sct, x0 = (int)ceil(cx - lim), x1 = (int)floor(cx + lim);
    int y0 = (int)ceil(cy - lim), y1 = (int)floor(cy + lim);
    memset(pol, 0, sizeof *pol);
    pol->cx = cx;
    pol->cy = cy;
    pol->r = r;
    for (sct = 0; sct < RL_SECTORS; sct++) {
        /* mid-angle of each sector, as sector_of lays them out */
        int oct = sct / 2, sub = sct % 2, major = oct % 2;
        double a = (sub ? 33.75 : 11.25) * M_PI / 180.0;
        double ax = major ? cos(a) : sin(a), ay = major ? sin(a) : cos(a);
        pol->ux[sct] = (oct / 4 ? -1.0 : 1.0) * ax;
        pol->uy[sct] = ((oct / 2) % 2 ? -1.0 : 1.0) * ay;
    }
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > img->width - 1) x1 = img->width - 1;
    if (y1 > img->height - 1) y1 = img->height - 1;
    for (y = y0; y <= y1; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - cy, dy2 = dy * dy;
        for (x = x0; x <= x1; x++) {
            double dx = x - cx, d2 = dx * dx + dy2, v = row[x];
            if (d2 >= lim2 || row[x] >= light)
                continue;
            k = (int)(sqrt(d2) * inv);
            if (k >= RL_POLAR_BINS)
                k = RL_POLAR_BINS - 1; /* rounding at the rim */
            sct = sector_of(dx, dy);
            pol->n[sct][k] += 1;
            pol->s[sct][k] += v;
            pol->q[sct][k] += v * v;
        }
    }
    /* sector black and white: extreme means over groups of 4 bins of the
     * profile's extent */
    for (sct = 0; sct < RL_SECTORS; sct++) {
        pol->lo[sct] = 1e9;
        pol->hi[sct] = -1e9;
        for (k = 0; k + 3 < RL_PROFILE_BINS; k += 4) {
            double n = pol->n[sct][k] + pol->n[sct][k + 1] + pol->n[sct][k + 2] + pol->n[sct][k + 3];
            double m;
            if (n < 2)
                continue;
            m = (pol->s[sct][k] + pol->s[sct][k + 1] + pol->s[sct][k + 2] + pol->s[sct][k + 3]) / n;
            if (m < pol->lo[sct]) pol->lo[sct] = m;
            if (m > pol->hi[sct]) pol->hi[sct] = m;
        }
        /* normalize once: darkness v = a - b I maps the sector's white to
         * 0 and its black to 255 */
        pol->usable[sct] = pol->hi[sct] - pol->lo[sct] >= min_contrast;
        if (pol->usable[sct]) {
            double b = 255.0 / (pol->hi[sct] - pol->lo[sct]), a = b * pol->hi[sct];
            for (k = 0; k < RL_POLAR_BINS; k++) {
                double n = pol->n[sct][k], sv = pol->s[sct][k], qv = pol->q[sct][k];
                pol->s[sct][k] = n * a - b * sv;
                pol->q[sct][k] = n * a * a - 2 * a * b * sv + b * b * qv;
            }
        }
    }
}

void rl_ident_polar_profile(const rl_polar *pol, double dx, double dy, double scale,
                            rl_profile *p)
{
    double bw = RL_PROFILE_EXTENT * pol->r / RL_PROFILE_BINS, sxx = 0, inv = 1.0 / scale;
    int sct, k;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->n[k] = p->sx[k] = 0;
    for (sct = 0; sct < RL_SECTORS; sct++) {
        /* cell k's centre, (k + 0.5) bins out, lands at continuous bin
         * t = a k + b of the new profile and is shared between the two
         * bins around t */
        double shift, a = inv, b;
        const double *cn = pol->n[sct], *cs = pol->s[sct], *cq = pol->q[sct];
        if (!pol->usable[sct])
            continue;
        shift = (dx * pol->ux[sct] + dy * pol->uy[sct]) / bw;
        b = (0.5 - shift) * inv - 0.5;
        for (k = 0; k < RL_POLAR_BINS; k++) {
            double t = a * k + b, w;
            int j;
            if (t >= RL_PROFILE_BINS)
                break; /* t grows with k */
            if (t < -1.0 || cn[k] == 0)
                continue;
            j = t < 0 ? -1 : (int)t;
            w = t - j; /* share going to bin j + 1 */
            if (j >= 0) {
                p->n[j] += (1 - w) * cn[k];
                p->sx[j] += (1 - w) * cs[k];
                sxx += (1 - w) * cq[k];
            }
            if (j + 1 < RL_PROFILE_BINS) {
                p->n[j + 1] += w * cn[k];
                p->sx[j + 1] += w * cs[k];
                sxx += w * cq[k];
            }
        }
    }
    p->sxx = sxx;
    p->total = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->total += p->n[k];
}

/* Pearson's r of column c (id index i, blur b) from its sums; -2 when
 * either side is constant. */
static double column_r(double n, double sx, double sxx, double st, double stt, double sxt,
                       double *gain)
{
    double vx = n * sxx - sx * sx, vt = n * stt - st * st;
    if (vx <= 0 || vt <= 0)
        return -2.0;
    *gain = (n * sxt - sx * st) / vt;
    return (n * sxt - sx * st) / sqrt(vx * vt);
}

/* Keep the best and the runner-up (of any other id). */
static void keep_best(rl_match *m, int id, double r, double gain, int blur)
{
    if (r > m->score) {
        if (id != m->id)
            m->second = m->score;
        m->score = r;
        m->id = id;
        m->contrast = gain;
        m->blur = blur;
    } else if (r > m->second && id != m->id) {
        m->second = r;
    }
}

/* Columns scored together: their sums stay in registers or L1. */
#define MATCH_BLOCK 32

/* Score the templates of `ids` (every template when ids is NULL) at the
 * blur levels [b0, b1). */
static void match_some(const rl_ident *id, const rl_profile *p, const int *ids, int n_ids,
                       int b0, int b1, rl_match *m)
{
    double n = p->total, sx = 0, st[MATCH_BLOCK], stt[MATCH_BLOCK], sxt[MATCH_BLOCK], g = 0;
    int ncol = id->n * RL_BLUR_LEVELS, c0, c, k, j;
    m->id = -1;
    m->score = m->second = -1.0;
    m->contrast = 0.0;
    m->blur = 0;
    if (n < 16)
        return;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        sx += p->sx[k];
    if (ids != NULL) {
        /* a short list: each of its columns on its own */
        for (j = 0; j < n_ids; j++) {
            int i, b;
            for (i = 0; i < id->n && id->ids[i] != ids[j]; i++)
                ;
            if (i == id->n)
                continue;
            for (b = b0; b < b1; b++) {
                double a = 0, aa = 0, ax = 0, r;
                for (k = 0; k < RL_PROFILE_BINS; k++) {
                    double t = id->tmpl[tmpl_index(id, i, b, k)];
                    a += p->n[k] * t;
                    aa += p->n[k] * t * t;
                    ax += p->sx[k] * t;
                }
                r = column_r(n, sx, p->sxx, a, aa, ax, &g);
                keep_best(m, ids[j], r, g, b);
            }
        }
        return;
    }
    for (c0 = 0; c0 < ncol; c0 += MATCH_BLOCK) {
        int nc = ncol - c0 < MATCH_BLOCK ? ncol - c0 : MATCH_BLOCK;
        for (c = 0; c < nc; c++)
            st[c] = stt[c] = sxt[c] = 0;
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            const float *t = id->tmpl + (size_t)k * (size_t)ncol + c0;
            double nk = p->n[k], sk = p->sx[k];
            if (nk == 0)
                continue; /* bins outside the image or in light */
            for (c = 0; c < nc; c++) {
                double tv = t[c];
                st[c] += nk * tv;
                stt[c] += nk * tv * tv;
                sxt[c] += sk * tv;
            }
        }
        for (c = 0; c < nc; c++) {
            int b = (c0 + c) % RL_BLUR_LEVELS;
            double r;
            if (b < b0 || b >= b1)
                continue;
            r = column_r(n, sx, p->sxx, st[c], stt[c], sxt[c], &g);
            keep_best(m, id->ids[(c0 + c) / RL_BLUR_LEVELS], r, g, b);
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
