/* rl_illum: the light falling on the ceiling across the frame (internal).
 *
 * Vignetting, a dark wall at one side, a shadow or a lamp make the
 * ceiling's paper-white level change across a frame, so one threshold for
 * the whole frame loses the landmarks on its darker side (their paper
 * falls below it) or merges them with a bright background. The frame is
 * cut into tiles; each tile's ceiling level is the mean of its brighter
 * half (lamps left out), spread over the neighbouring tiles (a tile can
 * lie wholly inside a landmark's ink), and the dark threshold of the
 * histogram analysis is scaled by that level over the frame's background.
 *
 *   rl_illum il;
 *   if (rl_illum_init(&il, &ws, 640, 480) == RL_OK) {
 *       rl_illum_measure(&il, &img, &res.levels);
 *       use(il.map.hi[0], rl_illum_scale(&il, 320.0, 240.0));
 *   }
 */
#ifndef RL_ILLUM_H
#define RL_ILLUM_H

#include <stdint.h>
#include "rl_label.h"
#include "rl_recog.h"
#include "rl_workspace.h"

typedef struct {
    int tile, nx, ny;
    uint8_t *level;   /* per tile: its ceiling level, 0 when unknown (all lamp) */
    uint8_t *bright;  /* per tile: the level spread over its neighbours */
    uint8_t *hi;      /* per tile: the dark threshold (what map points to) */
    rl_label_map map; /* the thresholds as the labeller takes them */
    double typical;   /* the frame's typical ceiling level (the median tile's) */
} rl_illum;

/* Carve the tile arrays for W x H frames from ws. */
RL_CHECK rl_err rl_illum_init(rl_illum *il, rl_ws *ws, int W, int H);

/* Measure img's tiles and set the thresholds from the frame's levels. */
void rl_illum_measure(rl_illum *il, const rl_image *img, const rl_levels *lv);

/* The ceiling level at (u, v) over the frame's typical one (1 on a frame
 * lit evenly). */
double rl_illum_scale(const rl_illum *il, double u, double v);

#endif
