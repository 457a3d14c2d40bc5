#include "rl_rank.h"

/* Merge the runs a[lo .. mid) and a[mid .. hi) of bins, each in order of
 * mean, into b (the first run's first on ties: the sort is stable). */
static void merge(const double *mean, const int *a, int lo, int mid, int hi, int *b)
{
    int i = lo, j = mid, k;
    for (k = lo; k < hi; k++)
        b[k] = j >= hi || (i < mid && mean[a[i]] <= mean[a[j]]) ? a[i++] : a[j++];
}

void rl_rank_sort(const rl_profile *p, rl_rank_order *ord)
{
    double mean[RL_PROFILE_BINS];
    int tmp[RL_PROFILE_BINS], *a = ord->bin, *b = tmp, *t, k, run, n = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        if (p->n[k] > 0) {
            mean[k] = p->sx[k] / p->n[k];
            a[n++] = k;
        }
    /* bottom-up merge sort (64 bins, 6 rounds), ties by radius */
    for (run = 1; run < n; run *= 2) {
        for (k = 0; k < n; k += 2 * run)
            merge(mean, a, k, k + run < n ? k + run : n, k + 2 * run < n ? k + 2 * run : n, b);
        t = a, a = b, b = t;
    }
    ord->n = n;
    ord->sw = 0;
    for (k = 0; k < n; k++) {
        ord->bin[k] = a[k];
        ord->w[k] = p->n[a[k]];
        ord->sw += ord->w[k];
    }
}

/* The template's spread about its mean over ord's bins (weighted): SST. */
static double spread(const float *col, int stride, const rl_rank_order *ord)
{
    double s = 0, q = 0;
    int k;
    for (k = 0; k < ord->n; k++) {
        double t = col[(size_t)ord->bin[k] * (size_t)stride], w = ord->w[k];
        s += w * t;
        q += w * t * t;
    }
    return q - s * s / ord->sw;
}

double rl_rank_score_over(const rl_templates *tt, const rl_rank_order *ord, int i, int blur, double bar)
{
    /* pooled blocks of the regression: weight and weighted sum of the
     * template values they hold */
    double bw[RL_PROFILE_BINS], bs[RL_PROFILE_BINS];
    const float *col = tt->table + (size_t)i * RL_BLUR_LEVELS + (size_t)blur;
    double sse = 0, sst, most;
    int k, nb = 0;
    if (ord->n < 3)
        return 0.0;
    /* the fit of a prefix pools no more than the whole one does, so its
     * error only grows; and the spread of values in 0 .. 1 is at most a
     * quarter of the weight: past `most` the score is under bar */
    most = (1.0 - bar) * 0.25 * ord->sw * (1.0 + 1e-9);
    for (k = 0; k < ord->n; k++) {
        double w = ord->w[k];
        bw[nb] = w;
        bs[nb] = w * col[(size_t)ord->bin[k] * (size_t)tt->stride];
        nb++;
        /* pool while a block's mean is below the one before it; the
         * error grows by w1 w2 / (w1 + w2) (m1 - m2)^2 */
        while (nb > 1 && bs[nb - 1] * bw[nb - 2] < bs[nb - 2] * bw[nb - 1]) {
            double w1 = bw[nb - 2], w2 = bw[nb - 1], d = bs[nb - 2] * w2 - bs[nb - 1] * w1;
            sse += d * d / (w1 * w2 * (w1 + w2));
            bw[nb - 2] = w1 + w2;
            bs[nb - 2] += bs[nb - 1];
            nb--;
        }
        if (sse > most)
            return bar - 1.0;
    }
    sst = spread(col, tt->stride, ord);
    return sst > 1e-12 ? 1.0 - sse / sst : 0.0;
}

/* Each blur of the id whose column starts at col pushed bin by bin into
 * one block kept per blur, merged into it while under its mean (a merge
 * of adjacent violators, as the regression makes, so the error so far is
 * never over the regression's), until its error passes most (the blurs
 * still under it kept side by side in on[]): how many are left at the
 * end, their blurs in on[]. */
static int left_in(const float *col, int stride, const rl_rank_order *ord, double most, int *on)
{
    double lw[RL_BLUR_LEVELS], ls[RL_BLUR_LEVELS], sse[RL_BLUR_LEVELS];
    int k, j, n = RL_BLUR_LEVELS;
    for (j = 0; j < n; j++) {
        on[j] = j;
        lw[j] = ord->w[0];
        ls[j] = ord->w[0] * col[(size_t)ord->bin[0] * (size_t)stride + (size_t)j];
        sse[j] = 0;
    }
    for (k = 1; k < ord->n && n > 0; k++) {
        const float *row = col + (size_t)ord->bin[k] * (size_t)stride;
        double w = ord->w[k];
        for (j = 0; j < n; j++) {
            double s = w * row[on[j]], d = ls[j] * w - s * lw[j], v = d > 0 ? 1.0 : 0.0;
            sse[j] += v * d * d / (lw[j] * w * (lw[j] + w));
            lw[j] = v * lw[j] + w;
            ls[j] = v * ls[j] + s;
        }
        /* a blur out: the last one in its place */
        for (j = 0; j < n; j++)
            if (sse[j] > most) {
                n--;
                on[j] = on[n], lw[j] = lw[n], ls[j] = ls[n], sse[j] = sse[n];
                j--;
            }
    }
    return n;
}

int rl_rank_any_over(const rl_templates *tt, const rl_rank_order *ord, int i, double bar)
{
    int on[RL_BLUR_LEVELS], n, j;
    if (ord->n < 3)
        return bar < 0.0;
    n = left_in(tt->table + (size_t)i * RL_BLUR_LEVELS, tt->stride, ord,
                (1.0 - bar) * 0.25 * ord->sw * (1.0 + 1e-9), on);
    for (j = 0; j < n; j++)
        if (rl_rank_score_over(tt, ord, i, on[j], bar) > bar)
            return 1;
    return 0;
}

double rl_rank_score(const rl_templates *tt, const rl_rank_order *ord, int i, int blur)
{
    return rl_rank_score_over(tt, ord, i, blur, -1.0);
}
