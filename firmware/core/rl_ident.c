#include "rl_ident.h"

#include <math.h>
#include <string.h>

static const double blur_levels[RL_BLUR_LEVELS] = {0.0, 0.03, 0.06, 0.10};

size_t rl_ident_bytes(int n)
{
    return (size_t)n * (sizeof(int) + sizeof(float) * RL_BLUR_LEVELS * RL_PROFILE_BINS) +
           2 * RL_WS_ALIGN;
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
                id->tmpl[((size_t)i * RL_BLUR_LEVELS + b) * RL_PROFILE_BINS + k] = (float)(acc / w);
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
    /* gather a little beyond the profile so that shifted centres still
     * find their outermost pixels */
    double ext = RL_PROFILE_EXTENT * r, bw = ext / RL_PROFILE_BINS, lim = ext + 2.0 * bw;
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
        double dy = y - cy;
        for (x = x0; x <= x1; x++) {
            double dx = x - cx, d = sqrt(dx * dx + dy * dy), v = row[x];
            if (d >= lim || row[x] >= light)
                continue;
            k = (int)(d / bw);
            if (k >= RL_PROFILE_BINS)
                k = RL_PROFILE_BINS - 1; /* the extra ring lands in the last bin */
            sct = sector_of(dx, dy);
            pol->n[sct][k] += 1;
            pol->s[sct][k] += v;
            pol->q[sct][k] += v * v;
        }
    }
    /* sector black and white: extreme means over groups of 4 bins */
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
            for (k = 0; k < RL_PROFILE_BINS; k++) {
                double n = pol->n[sct][k], sv = pol->s[sct][k], qv = pol->q[sct][k];
                pol->s[sct][k] = n * a - b * sv;
                pol->q[sct][k] = n * a * a - 2 * a * b * sv + b * b * qv;
            }
        }
    }
}

void rl_ident_polar_profile(const rl_polar *pol, double dx, double dy, rl_profile *p)
{
    double bw = RL_PROFILE_EXTENT * pol->r / RL_PROFILE_BINS, sxx = 0;
    int sct, k;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->n[k] = p->sx[k] = 0;
    for (sct = 0; sct < RL_SECTORS; sct++) {
        /* the whole sector moves by the same fraction of a bin */
        double shift, w;
        int j0, lo, hi;
        if (!pol->usable[sct])
            continue;
        shift = -(dx * pol->ux[sct] + dy * pol->uy[sct]) / bw;
        j0 = (int)floor(shift);
        w = shift - j0; /* share going one bin further out */
        lo = -j0 > 0 ? -j0 : 0;
        hi = RL_PROFILE_BINS - j0 < RL_PROFILE_BINS ? RL_PROFILE_BINS - j0 : RL_PROFILE_BINS;
        for (k = lo; k < hi; k++) { /* k + j0 in range */
            p->n[k + j0] += (1 - w) * pol->n[sct][k];
            p->sx[k + j0] += (1 - w) * pol->s[sct][k];
            sxx += (1 - w) * pol->q[sct][k];
        }
        lo = -j0 - 1 > 0 ? -j0 - 1 : 0;
        hi = RL_PROFILE_BINS - j0 - 1 < RL_PROFILE_BINS ? RL_PROFILE_BINS - j0 - 1 : RL_PROFILE_BINS;
        for (k = lo; k < hi; k++) { /* k + j0 + 1 in range */
            p->n[k + j0 + 1] += w * pol->n[sct][k];
            p->sx[k + j0 + 1] += w * pol->s[sct][k];
            sxx += w * pol->q[sct][k];
        }
    }
    p->sxx = sxx;
    p->total = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        p->total += p->n[k];
}

static void match_one(const rl_ident *id, const rl_profile *p, int i, double n, double sx,
                      double *best, double *gainv, int *best_b)
{
    int b, k;
    *best = -1.0;
    *gainv = 0.0;
    *best_b = 0;
    for (b = 0; b < RL_BLUR_LEVELS; b++) {
        const float *t = id->tmpl + ((size_t)i * RL_BLUR_LEVELS + b) * RL_PROFILE_BINS;
        double st = 0, stt = 0, sxt = 0, vx, vt, r;
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            st += p->n[k] * t[k];
            stt += p->n[k] * t[k] * t[k];
            sxt += p->sx[k] * t[k];
        }
        vx = n * p->sxx - sx * sx;
        vt = n * stt - st * st;
        if (vx <= 0 || vt <= 0)
            continue;
        r = (n * sxt - sx * st) / sqrt(vx * vt);
        if (r > *best) {
            *best = r;
            *best_b = b;
            *gainv = (n * sxt - sx * st) / vt;
        }
    }
}

/* Keep the best and the runner-up (of any other id). */
static void keep_best(rl_match *m, int id, double r, double gain, int blur)
{
    if (r > m->score) {
        m->second = m->score;
        m->score = r;
        m->id = id;
        m->contrast = gain;
        m->blur = blur;
    } else if (r > m->second) {
        m->second = r;
    }
}

/* Score the templates of `ids` (every template when ids is NULL). */
static void match_some(const rl_ident *id, const rl_profile *p, const int *ids, int n_ids,
                       rl_match *m)
{
    double n = p->total, sx = 0;
    int i, j, k;
    m->id = -1;
    m->score = m->second = -1.0;
    m->contrast = 0.0;
    m->blur = 0;
    if (n < 16)
        return;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        sx += p->sx[k];
    for (i = 0; i < id->n; i++) {
        double best, g;
        int b, wanted = ids == NULL;
        for (j = 0; j < n_ids && !wanted; j++)
            wanted = id->ids[i] == ids[j];
        if (!wanted)
            continue;
        match_one(id, p, i, n, sx, &best, &g, &b);
        keep_best(m, id->ids[i], best, g, b);
    }
}

void rl_ident_match_ids(const rl_ident *id, const rl_profile *p, const int *ids, int n_ids,
                        rl_match *m)
{
    match_some(id, p, ids, n_ids, m);
}

void rl_ident_match(const rl_ident *id, const rl_profile *p, rl_match *m)
{
    match_some(id, p, NULL, 0, m);
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
