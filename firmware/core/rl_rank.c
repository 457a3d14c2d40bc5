#include "rl_rank.h"

void rl_rank_sort(const rl_profile *p, rl_rank_order *ord)
{
    double mean[RL_PROFILE_BINS];
    int k, j;
    ord->n = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        double m;
        if (p->n[k] <= 0)
            continue;
        m = p->sx[k] / p->n[k];
        /* insertion: 64 bins, mostly in order already (a landmark's
         * darkness runs in bands) */
        for (j = ord->n; j > 0 && mean[j - 1] > m; j--) {
            mean[j] = mean[j - 1];
            ord->bin[j] = ord->bin[j - 1];
            ord->w[j] = ord->w[j - 1];
        }
        mean[j] = m;
        ord->bin[j] = k;
        ord->w[j] = p->n[k];
        ord->n++;
    }
}

double rl_rank_score(const rl_templates *tt, const rl_rank_order *ord, int i, int blur)
{
    /* pooled blocks of the regression: weight, weighted sum, and the
     * weighted sum of squares of the template values they hold */
    double bw[RL_PROFILE_BINS], bs[RL_PROFILE_BINS], bq[RL_PROFILE_BINS];
    double sw = 0, s = 0, q = 0, sse = 0, sst;
    int k, nb = 0;
    if (ord->n < 3)
        return 0.0;
    for (k = 0; k < ord->n; k++) {
        double t = rl_templates_bin(tt, i, blur, ord->bin[k]), w = ord->w[k];
        sw += w;
        s += w * t;
        q += w * t * t;
        bw[nb] = w;
        bs[nb] = w * t;
        bq[nb] = w * t * t;
        nb++;
        /* pool while a block's mean is below the one before it */
        while (nb > 1 && bs[nb - 1] * bw[nb - 2] < bs[nb - 2] * bw[nb - 1]) {
            bw[nb - 2] += bw[nb - 1];
            bs[nb - 2] += bs[nb - 1];
            bq[nb - 2] += bq[nb - 1];
            nb--;
        }
    }
    for (k = 0; k < nb; k++)
        sse += bq[k] - bs[k] * bs[k] / bw[k];
    sst = q - s * s / sw;
    return sst > 1e-12 ? 1.0 - sse / sst : 0.0;
}
