/* rl_split: second labellings where the frame's thresholds fail a
 * landmark (internal).
 *
 * The frame's dark threshold lies between the ceiling's paper-white and
 * the ink, tile by tile (rl_illum). It fails a landmark two ways:
 * - too high: a ceiling darker than the paper (a grey panel, the strip
 *   between two lamps) comes under it too, and where a sheet's margin is
 *   narrow (3 mm of a letter sheet beside a 210 mm landmark) the outer
 *   ring touches that ceiling: ring and ceiling are one region, too large
 *   and misshapen for a CLR;
 * - too low: motion in dim light smears the thin outer ring lighter than
 *   the threshold, and what is left are pieces of arc too thin to pair.
 * So, from the frame's labelling, the tiles under every region large
 * enough to hold a landmark beside something else (and not a candidate
 * the border leaves whole) get thresholds nearer the ink
 * (RL_SPLIT_LOWER of the frame's), the tiles around thin landmark-sized
 * pieces in no candidate thresholds nearer the paper (RL_SPLIT_HIGHER;
 * a region may be both), and the rest 0;
 * after the identification, each set is labelled (the labeller skips
 * tile rows with nothing in their band) and its CLRs are the new
 * candidates, save those at a landmark already identified, or where a
 * candidate was already read, or at one's code rings.
 *
 *   static rl_clr cand[RL_MAX_CANDIDATES];
 *   static uint8_t thr[20 * 15];            // the frame's thresholds, 32 px tiles
 *   static const rl_label_map frame_thr = {thr, 32, 20, 15};
 *   rl_split sp;
 *   memset(thr, 100, sizeof thr);           // rl_illum_measure sets them tile by tile
 *   if (rl_split_init(&sp, &ws, &frame_thr) == RL_OK &&
 *       rl_label_dark(&lb, &img, &frame_thr, 3) == RL_OK) {
 *       n = rl_clr_find(&lb, &cfg, &res, cand, RL_MAX_CANDIDATES);
 *       rl_split_mark(&sp, &lb, cand, n, &cfg);
 *       use(cand[0].box.x0);                // the candidates read into res here
 *       n = rl_split_find(&sp, &lb, &img, &cfg, 3, &res, cand, RL_MAX_CANDIDATES);
 *   }
 */
#ifndef RL_SPLIT_H
#define RL_SPLIT_H

#include <stdint.h>
#include "rl_clr.h"
#include "rl_label.h"
#include "rl_recog.h"
#include "rl_workspace.h"

/* The second labellings' thresholds, as fractions of the frame's (grey
 * levels, tile by tile). */
#define RL_SPLIT_LOWER 0.8
#define RL_SPLIT_HIGHER 1.15

typedef struct {
    const rl_label_map *frame; /* the frame's thresholds (rl_illum's map) */
    uint8_t *lower, *higher;   /* per tile: the second thresholds, 0 where unmarked */
    int n_lower, n_higher;     /* regions marked for each */
    rl_clr *found;             /* RL_MAX_CANDIDATES: one labelling's CLRs */
} rl_split;

/* Carve the tile arrays and the CLR scratch for the tiles of `frame` (which
 * must outlive sp: its thresholds are read at each rl_split_mark). */
RL_CHECK rl_err rl_split_init(rl_split *sp, rl_ws *ws, const rl_label_map *frame);

/* Mark the tiles under lb's regions (the frame's labelling under sp's
 * frame thresholds; cand[0 .. n) its CLRs; cfg's radii resolved). */
void rl_split_mark(rl_split *sp, const rl_label *lb, const rl_clr *cand, int n,
                   const rl_recog_config *cfg);

/* Label the marked tiles of img under each second threshold (into lb),
 * and their CLRs into out (at most cap, the rest counted in
 * res->dropped.candidates), save those at an identified landmark of res
 * or at one of its unidentified candidates or its code rings; the
 * labellings' limits are counted in res->dropped.regions (and
 * rl_clr_find's own in dropped.candidates: an arc or CLR the first
 * labelling had too may count twice). Returns how many. */
int rl_split_find(rl_split *sp, rl_label *lb, const rl_image *img, const rl_recog_config *cfg,
                  int speck, rl_result *res, rl_clr *out, int cap);

#endif
