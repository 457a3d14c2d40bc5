/* rl_hist: histogram analysis and image clustering (the paper's first
 * step of global recognition).
 *
 * The histogram of a frame gives the light-source threshold (pixels at or
 * above it are light sources and their glare), and K-means clustering of
 * the remaining intensities gives the foreground (dark ROI) and background
 * levels and the threshold between them. Intensity is one-dimensional, so
 * K-means runs exactly on the 256 bins: the globally optimal partition by
 * dynamic programming, identical to Lloyd's K-means on every pixel at its
 * best optimum, in microseconds.
 *
 *   rl_hist h;
 *   rl_hist_compute(&img, &h);
 *   rl_levels lv;
 *   rl_hist_levels(&h, &lv);   // lv.threshold: dark is < threshold
 */
#ifndef RL_HIST_H
#define RL_HIST_H

#include <stdint.h>
#include "rl_error.h"
#include "rl_image.h"

typedef struct {
    uint32_t bin[256];
    uint32_t total;
} rl_hist;

typedef struct {
    int light;         /* light-source threshold: pixels >= light are light; 256 = none */
    int threshold;     /* ROI threshold: pixels < threshold are dark (foreground) */
    double fg, bg;     /* mean foreground and background levels */
    double centre[3];  /* K-means centres, ascending */
    int k;             /* clusters used */
} rl_levels;

/* Histogram of every pixel of the view (stride honoured). */
void rl_hist_compute(const rl_image *img, rl_hist *h);

/* Histogram of every row_step-th row: the levels of a frame do not need
 * every pixel, and half the rows halve the cost. */
void rl_hist_compute_rows(const rl_image *img, rl_hist *h, int row_step);

/* Exact 1-D K-means on bins [lo, hi): k (1..3) centres, ascending, and
 * the first bin of each cluster in `start` (may be NULL). RL_EINVAL for a
 * bad range or k, RL_ERANGE when the range has fewer than k occupied
 * bins. */
RL_CHECK rl_err rl_hist_kmeans(const rl_hist *h, int lo, int hi, int k, double *centres,
                               int *start);

/* Light threshold, K-means levels and the ROI threshold of a histogram. */
RL_CHECK rl_err rl_hist_levels(const rl_hist *h, rl_levels *lv);

#endif
