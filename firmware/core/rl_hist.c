#include "rl_hist.h"

#include <math.h>
#include <string.h>

/* Fewest pixels (fraction of the frame) at the top of the range that make
 * a light source; fewer are specular glints and count as background. */
#define LIGHT_MIN_FRACTION 0.0005
/* Most of the frame (fraction) that can be light: a larger saturated
 * population is an over-exposed background (white paper, bright tiles).
 * Large fixtures with their halo can wash out well over half of a frame
 * and still be lights, with the landmarks between them to be found. */
#define LIGHT_MAX_FRACTION 0.9
/* Lowest intensity a light threshold may take: lights saturate. */
#define LIGHT_MIN_LEVEL 235
/* Least foreground/background separation (grey levels) for a dark class. */
#define MIN_CONTRAST 12.0
/* Least share of the pixels under the light threshold that makes a
 * cluster a surface (ceiling, paper); fewer are the mixed pixels of
 * blurred edges or small things. */
#define SURFACE_MIN_SHARE 0.05


void rl_hist_compute(const rl_image *img, rl_hist *h)
{
    rl_hist_compute_rows(img, h, 1);
}

void rl_hist_compute_rows(const rl_image *img, rl_hist *h, int row_step)
{
    int x, y;
    /* Four partial histograms break the store-to-load dependency when
     * neighbouring pixels share a bin (flat ceilings). */
    uint32_t part[4][256];
    memset(part, 0, sizeof part);
    if (row_step < 1)
        row_step = 1;
    for (y = 0; y < img->height; y += row_step) {
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
    h->total = (uint32_t)img->width * (uint32_t)((img->height + row_step - 1) / row_step);
}

/* Grey levels per coarse bin for the first, exact-on-groups pass, and
 * the most coarse bins a histogram has. */
#define COARSE 4
#define COARSE_BINS ((256 + COARSE - 1) / COARSE)

/* Exact K-means by dynamic programming over `n` (at most COARSE_BINS)
 * groups of grey levels given as prefix sums of (count, sum, sum of
 * squares). b[m] gets the first bin of cluster m, b[k] = n. */
static void kmeans_dp(const double *cnt, const double *sum, const double *sq, int n, int k,
                      int *b)
{
    /* prefix sums make the within-cluster squared error of a bin range
     * O(1); D[m][j] is the least error of m + 1 clusters over bins 0..j */
    double D[3][COARSE_BINS];
    int arg[3][COARSE_BINS], i, j, m;
#define COST(a, z)                                                                           \
    ((cnt[(z) + 1] - cnt[a]) > 0 ? (sq[(z) + 1] - sq[a]) - (sum[(z) + 1] - sum[a]) *      \
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
}

/* 1. The exact optimum over groups of COARSE grey levels (COARSE^2 times
 * less work than over single levels): its boundaries into bound. */
static void coarse_bounds(const rl_hist *h, int lo, int hi, int k, int *bound)
{
    double cnt[COARSE_BINS + 1], sum[COARSE_BINS + 1], sq[COARSE_BINS + 1];
    int i, m, n = hi - lo, nc, b[4];
    nc = (n + COARSE - 1) / COARSE;
    cnt[0] = sum[0] = sq[0] = 0.0;
    for (i = 0; i < nc; i++) {
        double c = 0, s = 0, q = 0;
        int v;
        for (v = lo + i * COARSE; v < lo + (i + 1) * COARSE && v < hi; v++) {
            if (h->bin[v] == 0)
                continue; /* it would add +0.0 to sums that are +0.0 or more: no bit moves */
            c += h->bin[v];
            s += (double)h->bin[v] * v;
            q += (double)h->bin[v] * v * v;
        }
        cnt[i + 1] = cnt[i] + c;
        sum[i + 1] = sum[i] + s;
        sq[i + 1] = sq[i] + q;
    }
    kmeans_dp(cnt, sum, sq, nc, k, b); /* nc <= COARSE_BINS: hi - lo <= 256 */
    for (m = 0; m <= k; m++)
        bound[m] = lo + b[m] * COARSE < hi ? lo + b[m] * COARSE : hi;
}

/* 2. Lloyd's iterations on single levels from there: each boundary moves
 * to the midpoint of its neighbouring centres until nothing changes, a
 * fixed point of K-means next to the optimum. */
static void lloyd(const rl_hist *h, int k, int *bound, double *centres)
{
    int i, m, iter;
    for (iter = 0; iter < 64; iter++) {
        int changed = 0;
        for (m = 0; m < k; m++) {
            double c = 0, s = 0;
            for (i = bound[m]; i < bound[m + 1]; i++) {
                if (h->bin[i] == 0)
                    continue; /* as in coarse_bounds: an empty level adds +0.0 */
                c += h->bin[i];
                s += (double)h->bin[i] * i;
            }
            centres[m] = c > 0 ? s / c : 0.5 * (bound[m] + bound[m + 1] - 1);
        }
        for (m = 1; m < k; m++) {
            /* levels strictly below the midpoint go to the lower cluster */
            int nb = (int)floor(0.5 * (centres[m - 1] + centres[m])) + 1;
            if (nb <= bound[m - 1])
                nb = bound[m - 1] + 1;
            if (nb >= bound[m + 1])
                nb = bound[m + 1] - 1;
            if (nb != bound[m]) {
                bound[m] = nb;
                changed = 1;
            }
        }
        if (!changed)
            break;
    }
}

/* 3. Lloyd can stop next to the optimum: each boundary moves within two
 * coarse bins while the exact squared error falls (prefix sums over
 * single levels make each try O(1)); the optimum over single levels lies
 * within a coarse bin of the optimum over groups. The centres follow. */
static void polish(const rl_hist *h, int lo, int hi, int k, int *bound, double *centres)
{
    int i, m, n = hi - lo;
    {
        double pc[257], ps[257], pq[257];
        int moved = 1, guard = 0;
        pc[0] = ps[0] = pq[0] = 0.0;
        for (i = 0; i < n; i++) {
            double c = h->bin[lo + i], v = lo + i;
            pc[i + 1] = pc[i] + c;
            ps[i + 1] = ps[i] + c * v;
            pq[i + 1] = pq[i] + c * v * v;
        }
#define SSE(a, z) /* levels a..z-1, relative to lo */                                     \
    ((pc[z] - pc[a]) > 0 ? (pq[z] - pq[a]) - (ps[z] - ps[a]) * (ps[z] - ps[a]) / (pc[z] - pc[a]) \
                         : 0.0)
        while (moved && guard++ < 16) {
            moved = 0;
            for (m = 1; m < k; m++) {
                int a = bound[m - 1] - lo, z = bound[m + 1] - lo, best = bound[m] - lo, t;
                double best_e = SSE(a, best) + SSE(best, z);
                for (t = best - 2 * COARSE; t <= best + 2 * COARSE; t++) {
                    double e;
                    if (t <= a || t >= z)
                        continue;
                    e = SSE(a, t) + SSE(t, z);
                    if (e < best_e - 1e-9 * best_e) {
                        best_e = e;
                        best = t;
                    }
                }
                if (best + lo != bound[m]) {
                    bound[m] = best + lo;
                    moved = 1;
                }
            }
        }
#undef SSE
        for (m = 0; m < k; m++) {
            double c = pc[bound[m + 1] - lo] - pc[bound[m] - lo];
            centres[m] = c > 0 ? (ps[bound[m + 1] - lo] - ps[bound[m] - lo]) / c
                               : 0.5 * (bound[m] + bound[m + 1] - 1);
        }
    }
}

rl_err rl_hist_kmeans(const rl_hist *h, int lo, int hi, int k, double *centres, int *start)
{
    int occupied = 0, i, m, n = hi - lo, bound[4];
    if (h == NULL || centres == NULL || k < 1 || k > 3 || lo < 0 || hi > 256 || n < 1)
        return RL_EINVAL;
    for (i = lo; i < hi; i++)
        occupied += h->bin[i] != 0;
    if (occupied < k)
        return RL_ERANGE;
    coarse_bounds(h, lo, hi, k, bound);
    lloyd(h, k, bound, centres);
    polish(h, lo, hi, k, bound, centres);
    for (m = 0; m < k && start; m++)
        start[m] = bound[m];
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

/* Pixels in bins [a, b). */
static double bins_count(const rl_hist *h, int a, int b)
{
    double n = 0;
    int i;
    for (i = a; i < b; i++)
        n += h->bin[i];
    return n;
}

/* The ROI threshold from the k clusters (their first bins in start). */
static void dark_threshold(const rl_hist *h, const rl_tone *t, int k, const int *start,
                           rl_levels *lv)
{
    double below = bins_count(h, 0, lv->light), ink = lv->centre[0], surface;
    int m, s = k - 1;
    if (!(below > 0) || k < 2) {
        lv->threshold = 0; /* no dark class: nothing is foreground */
        return;
    }
    for (m = 1; m < k; m++)
        if (bins_count(h, start[m], m + 1 < k ? start[m + 1] : lv->light) >= SURFACE_MIN_SHARE * below) {
            s = m;
            break;
        }
    surface = lv->centre[s];
    lv->threshold = surface - ink >= MIN_CONTRAST ? rl_tone_midway(t, ink, surface) : 0;
}

rl_err rl_hist_levels(const rl_hist *h, const rl_tone *tone, rl_levels *lv)
{
    rl_err e;
    int k, start[3];
    if (h == NULL || lv == NULL || h->total == 0)
        return RL_EINVAL;
    memset(lv, 0, sizeof *lv);
    lv->light = light_threshold(h);
    for (k = 3; k >= 1; k--) {
        e = rl_hist_kmeans(h, 0, lv->light, k, lv->centre, start);
        if (e == RL_OK)
            break;
    }
    if (k < 1)
        return RL_ERANGE; /* nothing below the light threshold */
    lv->k = k;
    lv->fg = lv->centre[0];
    lv->bg = lv->centre[k - 1];
    dark_threshold(h, tone, k, start, lv);
    return RL_OK;
}
