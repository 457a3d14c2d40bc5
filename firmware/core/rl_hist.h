/* rl_hist: histogram analysis and image clustering (the paper's first
 * step of global recognition).
 *
 * The histogram of a frame gives the light-source threshold (pixels at or
 * above it are light sources and their glare), and K-means clustering of
 * the remaining intensities gives the foreground (dark ROI) and background
 * levels and the threshold between them (internal). Intensity is one-
 * dimensional, so K-means runs on the 256 bins instead of the pixels: the
 * exact optimum over groups of 4 grey levels by dynamic programming, then
 * Lloyd's iterations on single levels from there, then each boundary moved
 * within two groups while that lowers the error: a local optimum next to
 * the coarse global one, in microseconds (tests/test_oracles.cpp compares
 * it with OpenCV's K-means on the pixels).
 *
 *   rl_hist h;
 *   rl_levels lv;
 *   rl_hist_compute(&img, &h);
 *   if (rl_hist_levels(&h, &tone, &lv) == RL_OK)
 *       use(lv.threshold);     // dark is < threshold
 */
#ifndef RL_HIST_H
#define RL_HIST_H

#include <stdint.h>
#include "rl_error.h"
#include "rl_image.h"
#include "rl_recog.h" /* rl_levels */
#include "rl_tone.h"

typedef struct {
    uint32_t bin[256];
    uint32_t total;
} rl_hist;

/* Histogram of every pixel of the view (stride honoured). */
void rl_hist_compute(const rl_image *img, rl_hist *h);

/* Histogram of every row_step-th row: the levels of a frame do not need
 * every pixel, and half the rows halve the cost. */
void rl_hist_compute_rows(const rl_image *img, rl_hist *h, int row_step);

/* 1-D K-means on bins [lo, hi) as above: k (1..3) centres, ascending, and
 * the first bin of each cluster in `start` (may be NULL). RL_EINVAL for a
 * bad range or k, RL_ERANGE when the range has fewer than k occupied
 * bins. */
RL_CHECK rl_err rl_hist_kmeans(const rl_hist *h, int lo, int hi, int k, double *centres,
                               int *start);

/* Light threshold, K-means levels and the ROI threshold of a histogram:
 * dark is what lies under halfway, in light (tone), from the ink to the
 * darkest surface, the first cluster above the ink that holds a fair
 * share of the frame (a cluster of a few percent between them is the
 * mixed pixels of blurred edges, which motion makes many). */
RL_CHECK rl_err rl_hist_levels(const rl_hist *h, const rl_tone *tone, rl_levels *lv);

#endif
