#include "rl_templates.h"

#include <math.h>
#include <string.h>

static const double blur_levels[RL_BLUR_LEVELS] = {0.0, 0.03, 0.06, 0.10};

/* Columns per bin, padded to whole blocks. */
static int padded_columns(int n)
{
    return (n * RL_BLUR_LEVELS + RL_MATCH_BLOCK - 1) / RL_MATCH_BLOCK * RL_MATCH_BLOCK;
}

size_t rl_templates_bytes(int n)
{
    return (size_t)n * sizeof(int) + sizeof(float) * RL_PROFILE_BINS * (size_t)padded_columns(n) +
           2 * RL_WS_ALIGN;
}

static size_t table_index(const rl_templates *tt, int i, int blur, int k)
{
    return (size_t)k * (size_t)tt->stride + (size_t)i * RL_BLUR_LEVELS + (size_t)blur;
}

float rl_templates_bin(const rl_templates *tt, int i, int blur, int k)
{
    return tt->table[table_index(tt, i, blur, k)];
}

int rl_templates_find(const rl_templates *tt, int id)
{
    int i;
    for (i = 0; i < tt->n; i++)
        if (tt->ids[i] == id)
            return i;
    return -1;
}

double rl_templates_value_at(const rl_family *fam, int id, double rho, double sigma)
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

/* Mean darkness over bin k's annulus, weighted by radius (area). */
static float bin_mean(const rl_family *fam, int id, double sigma, int k)
{
    double acc = 0, w = 0;
    int s;
    for (s = 0; s < 8; s++) {
        double rho = (k + (s + 0.5) / 8) * RL_PROFILE_EXTENT / RL_PROFILE_BINS;
        acc += rho * rl_templates_value_at(fam, id, rho, sigma);
        w += rho;
    }
    return (float)(acc / w);
}

rl_err rl_templates_init(rl_templates *tt, rl_ws *ws, const rl_family *fam, const int *ids,
                         int n_ids)
{
    int i, b, k, n = ids ? n_ids : rl_family_count(fam);
    rl_err e;
    if (n <= 0)
        return RL_EINVAL;
    tt->fam = *fam;
    tt->n = n;
    if ((e = rl_ws_alloc(ws, (size_t)n * sizeof(int), RL_WS_ALIGN, (void **)&tt->ids)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)padded_columns(n) * RL_PROFILE_BINS * sizeof(float),
                         RL_WS_ALIGN, (void **)&tt->table)) != RL_OK)
        return e;
    tt->stride = padded_columns(n);
    if (rl_ws_is_sizing(ws))
        return RL_OK;
    memset(tt->table, 0, (size_t)tt->stride * RL_PROFILE_BINS * sizeof(float)); /* the pads */
    for (i = 0; i < n; i++) {
        tt->ids[i] = ids ? ids[i] : i + 1;
        if (!rl_family_valid(fam, tt->ids[i]))
            return RL_ERANGE;
        for (b = 0; b < RL_BLUR_LEVELS; b++)
            for (k = 0; k < RL_PROFILE_BINS; k++)
                tt->table[table_index(tt, i, b, k)] = bin_mean(fam, tt->ids[i], blur_levels[b], k);
    }
    return RL_OK;
}
