#include "rl_ident.h"

#include <math.h>

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

void rl_ident_match(const rl_ident *id, const rl_profile *p, rl_match *m)
{
    double n = p->total, sx = 0;
    int i, b, k;
    m->id = -1;
    m->score = m->second = -1.0;
    m->contrast = 0.0;
    m->blur = 0;
    if (n < 16)
        return;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        sx += p->sx[k];
    for (i = 0; i < id->n; i++) {
        double best = -1.0, best_gain = 0.0;
        int best_b = 0;
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
            if (r > best) {
                best = r;
                best_b = b;
                best_gain = (n * sxt - sx * st) / vt; /* darkness per unit of template */
            }
        }
        if (best > m->score) {
            m->second = m->score;
            m->score = best;
            m->id = id->ids[i];
            m->contrast = best_gain;
            m->blur = best_b;
        } else if (best > m->second) {
            m->second = best;
        }
    }
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
