#include "rl_hist.h"

#include <string.h>

/* Fewest pixels (fraction of the frame) at the top of the range that make
 * a light source; fewer are specular glints and count as background. */
#define LIGHT_MIN_FRACTION 0.0005
/* Most of the frame (fraction) that can be light: a larger saturated
 * population is an over-exposed background (white paper, bright tiles). */
#define LIGHT_MAX_FRACTION 0.6
/* Lowest intensity a light threshold may take: lights saturate. */
#define LIGHT_MIN_LEVEL 235
/* Least foreground/background separation (grey levels) for a dark class. */
#define MIN_CONTRAST 12.0

void rl_hist_compute(const rl_image *img, rl_hist *h)
{
    int x, y;
    /* Four partial histograms break the store-to-load dependency when
     * neighbouring pixels share a bin (flat ceilings). */
    uint32_t part[4][256];
    memset(part, 0, sizeof part);
    for (y = 0; y < img->height; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        for (x = 0; x + 3 < img->width; x += 4) {
            part[0][row[x]]++;
            part[1][row[x + 1]]++;
            part[2][row[x + 2]]++;
            part[3][row[x + 3]]++;
        }
        for (; x < img->width; x++)
            part[0][row[x]]++;
    }
    for (x = 0; x < 256; x++)
        h->bin[x] = part[0][x] + part[1][x] + part[2][x] + part[3][x];
    h->total = (uint32_t)img->width * (uint32_t)img->height;
}

rl_err rl_hist_kmeans(const rl_hist *h, int lo, int hi, int k, double *centres, int *start)
{
    /* Prefix sums of count, sum and sum of squares make the within-cluster
     * squared error of any bin range O(1); D[m][j] is the least error of
     * m + 1 clusters over bins lo..j. */
    double cnt[257], sum[257], sq[257], D[3][256];
    int arg[3][256], occupied = 0, i, j, m, n = hi - lo, b[4];
    if (h == NULL || centres == NULL || k < 1 || k > 3 || lo < 0 || hi > 256 || n < 1)
        return RL_EINVAL;
    cnt[0] = sum[0] = sq[0] = 0.0;
    for (i = 0; i < n; i++) {
        double c = h->bin[lo + i], v = lo + i;
        cnt[i + 1] = cnt[i] + c;
        sum[i + 1] = sum[i] + c * v;
        sq[i + 1] = sq[i] + c * v * v;
        occupied += h->bin[lo + i] != 0;
    }
    if (occupied < k)
        return RL_ERANGE;
#define COST(a, z) /* bins a..z inclusive, relative to lo */                                \
    ((cnt[(z) + 1] - cnt[a]) > 0 ? (sq[(z) + 1] - sq[a]) - (sum[(z) + 1] - sum[a]) *     \
                                                              (sum[(z) + 1] - sum[a]) /  \
                                                              (cnt[(z) + 1] - cnt[a])    \
                                 : 0.0)
    for (j = 0; j < n; j++) {
        D[0][j] = COST(0, j);
        arg[0][j] = 0;
    }
    for (m = 1; m < k; m++)
        /* the last level is only needed at the last bin */
        for (j = m == k - 1 ? n - 1 : m; j < n; j++) {
            double best = -1.0;
            int bi = m;
            for (i = m; i <= j; i++) {
                double c = D[m - 1][i - 1] + COST(i, j);
                if (best < 0.0 || c < best) {
                    best = c;
                    bi = i;
                }
            }
            D[m][j] = best;
            arg[m][j] = bi;
        }
#undef COST
    b[k] = n;
    j = n - 1;
    for (m = k - 1; m >= 0; m--) {
        b[m] = arg[m][j];
        j = b[m] - 1;
    }
    for (m = 0; m < k; m++) {
        double c = cnt[b[m + 1]] - cnt[b[m]];
        centres[m] = c > 0 ? (sum[b[m + 1]] - sum[b[m]]) / c : lo + (b[m] + b[m + 1]) / 2.0;
        if (start)
            start[m] = lo + b[m];
    }
    return RL_OK;
}

/* Light threshold: a saturated population at the top of the histogram,
 * separated from the background by the histogram's valley. Glare makes a
 * smooth ramp instead of a valley; the threshold then stays high so that
 * only the washed-out core is called light. */
static int light_threshold(const rl_hist *h)
{
    uint32_t top = 0, best;
    int i, t;
    for (i = 250; i < 256; i++)
        top += h->bin[i];
    if ((double)top < LIGHT_MIN_FRACTION * h->total ||
        (double)top > LIGHT_MAX_FRACTION * h->total)
        return 256;
    t = 250;
    best = h->bin[250] + h->bin[249] + h->bin[248];
    for (i = 249; i >= LIGHT_MIN_LEVEL; i--) {
        uint32_t s = h->bin[i - 1] + h->bin[i] + h->bin[i + 1];
        if (s <= best) {
            best = s;
            t = i;
        }
    }
    return t;
}

rl_err rl_hist_levels(const rl_hist *h, rl_levels *lv)
{
    rl_err e;
    int k;
    if (h == NULL || lv == NULL || h->total == 0)
        return RL_EINVAL;
    memset(lv, 0, sizeof *lv);
    lv->light = light_threshold(h);
    for (k = 3; k >= 1; k--) {
        e = rl_hist_kmeans(h, 0, lv->light, k, lv->centre, NULL);
        if (e == RL_OK)
            break;
    }
    if (k < 1)
        return RL_ERANGE; /* nothing below the light threshold */
    lv->k = k;
    lv->fg = lv->centre[0];
    lv->bg = lv->centre[k - 1];
    if (k >= 2 && lv->centre[1] - lv->centre[0] >= MIN_CONTRAST)
        lv->threshold = (int)(0.5 * (lv->centre[0] + lv->centre[1]) + 0.5);
    else
        lv->threshold = 0; /* no dark class: nothing is foreground */
    return RL_OK;
}
