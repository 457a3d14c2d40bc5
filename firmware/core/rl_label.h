/* rl_label: connected regions of an intensity band, by runs (internal).
 *
 * Pixels with lo <= I < hi are collected as horizontal runs row by row and
 * joined 8-connected with union-find over runs, so no binary or label
 * image is ever stored: memory is ~8 bytes per run, and a ceiling frame
 * has far fewer runs than pixels. Regions smaller than min_area (specks)
 * are dropped. Every array lives in the caller's workspace.
 *
 *   rl_label labels;
 *   if (rl_label_init(&labels, &ws, img.width, img.height, 40000, RL_MAX_REGIONS) == RL_OK &&
 *       rl_label_band(&labels, &img, 0, 90, 3) == RL_OK)
 *       for (i = 0; i < labels.n_regions; i++)
 *           use(labels.reg[i].area, labels.overflow);    // overflow: regions dropped
 */
#ifndef RL_LABEL_H
#define RL_LABEL_H

#include <stdint.h>
#include "rl_error.h"
#include "rl_image.h"
#include "rl_workspace.h"

typedef struct {
    int32_t area;             /* pixels */
    int16_t x0, y0, x1, y1;   /* bounding box, inclusive */
    double sx, sy;            /* sums of x and y (centroid = sx / area) */
} rl_region;

typedef struct {
    int width, height;        /* the image last labelled */
    int max_width;            /* the widest image it labels (width at init) */
    int max_height;           /* rows the row index holds (height at init) */
    int cap_runs, cap_regions;
    int n_runs, n_regions;
    int overflow;             /* regions dropped because cap_regions was reached */
    int rows_left;            /* rows not labelled because cap_runs was reached */
    uint16_t *x0, *x1;        /* run extents, inclusive */
    int32_t *tag;             /* per run: union-find parent, then region index or -1 */
    int32_t *row;             /* row y's runs are row[y] .. row[y+1]-1 */
    rl_region *reg;
    uint8_t *span;            /* per pixel of a row: its band's width above lo */
} rl_label;

/* Bytes rl_label_init takes from a workspace for these capacities. */
size_t rl_label_bytes(int width, int height, int cap_runs, int cap_regions);

/* Carve the arrays from ws. RL_ENOMEM if ws is too small, RL_EINVAL for
 * bad sizes. */
RL_CHECK rl_err rl_label_init(rl_label *lb, rl_ws *ws, int width, int height, int cap_runs,
                              int cap_regions);

/* Label pixels with lo <= I < hi in img: any image at most as wide and
 * as high as the size given at init (a frame, or a window of it). Regions of fewer than min_area pixels are dropped. RL_EINVAL for a
 * larger image. Neither limit is an error: past cap_runs (a frame of
 * noise, a fine pattern) the rows left are counted in lb->rows_left and
 * not labelled; regions past cap_regions are counted in lb->overflow. */
RL_CHECK rl_err rl_label_band(rl_label *lb, const rl_image *img, int lo, int hi, int min_area);

/* Thresholds per tile: pixel (x, y) is dark when I < hi[(y / tile) * nx +
 * x / tile] (illumination that changes across the frame). */
typedef struct {
    const uint8_t *hi;
    int tile, nx, ny;   /* tile: a power of two */
} rl_label_map;

/* Label the dark pixels of img under per-tile thresholds (as
 * rl_label_band otherwise; a tile row whose thresholds are all 0 costs
 * next to nothing). RL_EINVAL when the map does not cover img. */
RL_CHECK rl_err rl_label_dark(rl_label *lb, const rl_image *img, const rl_label_map *map,
                              int min_area);

/* Central second moments (covariance) of region reg of the last
 * labelling, from its runs (a shape, when it is needed, costs no memory
 * per region). */
void rl_label_moments(const rl_label *lb, int reg, double *cxx, double *cxy, double *cyy);

/* Region index of run r, or -1 for a dropped speck. */
static inline int rl_label_region_of(const rl_label *lb, int r)
{
    return lb->tag[r];
}

#endif
