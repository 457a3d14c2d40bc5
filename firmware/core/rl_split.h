/* rl_split: landmarks joined to the ceiling beside them, taken apart
 * (internal).
 *
 * The frame's dark threshold lies between the ceiling's paper-white and
 * the ink. A ceiling darker than the paper (a grey panel, the strip
 * between two lamps) can come under it too, and where a sheet's margin is
 * narrow (3 mm of a letter sheet beside a 210 mm landmark) the outer ring
 * touches that ceiling: ring and ceiling make one dark region, too large
 * and misshapen for a CLR, and the landmark is never a candidate. Beside
 * a lamp it is worse, as the lamp raises its tiles' thresholds.
 *
 * The tiles under every region large enough to hold a landmark beside
 * something else are labelled again under thresholds nearer the ink
 * (RL_SPLIT_RATIO of the frame's), the rest of the frame not at all (its
 * tiles' thresholds are 0, and the labeller skips what has nothing in its
 * band); the CLRs that come apart there, and that the first labelling did
 * not find already, are added.
 *
 *   static rl_clr cand[RL_MAX_CANDIDATES];
 *   static uint8_t thr[20 * 15];        // the frame's per-tile thresholds
 *   rl_label_map frame_thr = {thr, 32, 20, 15};
 *   rl_split sp;
 *   if (rl_split_init(&sp, &ws, &frame_thr) == RL_OK &&
 *       rl_label_dark(&lb, &img, &frame_thr, 3) == RL_OK) {
 *       n = rl_clr_find(&lb, &cfg, &res, cand, RL_MAX_CANDIDATES);
 *       n = rl_split_find(&sp, &frame_thr, &lb, &img, &cfg, 3, &res, cand, n, RL_MAX_CANDIDATES);
 *   }
 */
#ifndef RL_SPLIT_H
#define RL_SPLIT_H

#include <stdint.h>
#include "rl_clr.h"
#include "rl_label.h"
#include "rl_recog.h"
#include "rl_workspace.h"

/* The thresholds of the second labelling, as a fraction of the frame's:
 * a fifth of the way nearer the ink. */
#define RL_SPLIT_RATIO 0.8

typedef struct {
    uint8_t *hi;      /* per tile: the lowered threshold, 0 where no large region lies */
    rl_label_map map; /* hi as the labeller takes it */
} rl_split;

/* Carve the tile array for the tiles of the frame's map from ws. */
RL_CHECK rl_err rl_split_init(rl_split *sp, rl_ws *ws, const rl_label_map *frame);

/* With lb holding the frame's labelling under the thresholds `frame`, and
 * cand[0 .. n) its CLRs: label the tiles under lb's large regions again
 * under lowered thresholds (into lb: the first labelling is gone after)
 * and add the new CLRs to cand, at most cap in all (the rest counted in
 * res->dropped.candidates). Returns the new count. */
int rl_split_find(rl_split *sp, const rl_label_map *frame, rl_label *lb, const rl_image *img,
                  const rl_recog_config *cfg, int speck, rl_result *res, rl_clr *cand, int n,
                  int cap);

#endif
