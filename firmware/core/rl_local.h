/* rl_local: the paper's local recognition pass (internal).
 *
 * Unidentified CLRs next to a light or on the image border (DUCLRs) are
 * retried in their own window of the frame: extension (a window around
 * the candidate, kept out of the lights), local clustering (K-means on
 * the landmark's own square, so the threshold follows the local
 * illumination), re-extraction of the outer ring, its centre and radius
 * from the visible outer edge (rl_locate.h), then identification with a
 * search over centre and radius
 * (rl_search.h), accepted by the local rule (rl_accept.h). The frame's
 * dark labelling is reused for the windows: its regions have been turned
 * into candidates by then.
 *
 *   rl_local_pass(rec, &img, &res);   // after the global pass
 *   use(res.local_tried, res.local_found);
 */
#ifndef RL_LOCAL_H
#define RL_LOCAL_H

#include "rl_recog_state.h"

/* A whole candidate (its box's circle and its fitted circle in the frame)
 * whose first match (every id at every blur at the located circle) and
 * the search's step out (the radius 1.06 times larger, for edge fits
 * glare makes short) both score under this is read no further in the
 * local pass (the default of rl_recog_config.local_min_first; counted in
 * rl_result.local_floored). One whose first match names no id is not
 * stopped (rl_search_identify_over). On the development folders'
 * composites whole candidates under 0.5 at the circle took a fifth of the
 * pass's time; 2 of the 331 there were taken by a later read, neither
 * reaching the output (docs/results.md): lossless as measured, not by
 * construction. The step out is there for a whole 6 next to a light that
 * a floor on the first match alone lost on held-out photos. A circle the
 * arc fallback found (rl_locate's rays from the candidate's centre, a ring
 * the motion broke) is floored as any other: of 8 that reached the floor
 * on the generated sets one was stopped, none lost (measured, not by
 * design). A cut candidate's read at its box, where no other of its reads
 * took it, is floored the same (rl_result.local_box_floored; its first
 * read is not: cut landmarks were taken from first matches under 0.1).
 * Not in rl_local_read. */
#define RL_LOCAL_MIN_FIRST 0.5

/* Retry every DUCLR of res; identified ones move from res->unidentified
 * to res->landmarks. */
void rl_local_pass(rl_recog *rec, const rl_image *img, rl_result *res);

/* 1 when candidate u is whole for the floor in a W x H frame: its box's
 * circle (u->complete) and the circle (cx, cy, r) fitted to its edge both
 * in the frame (the reads the floor skips go by the fitted circle). */
int rl_local_whole(int W, int H, const rl_detection *u, double cx, double cy, double r);

/* Read one window: the candidate u (its centre, radius, box, complete
 * and visible; the landmark R px in radius) found again and identified
 * as a DUCLR is (rl_locate, the search, the local rule); 1 with it in
 * *out. The tracker's reads of predicted landmarks (rl_track.h). */
int rl_local_read(rl_recog *rec, const rl_image *img, const rl_result *res, const rl_detection *u, double R,
                  rl_detection *out);

/* The local pass's reads of candidate u (as rl_local_read) from the
 * circle (cx, cy, r) as if its outer edge had been fitted there
 * (rl_locate skipped; the pass's floor, rl_recog_config.local_min_first,
 * held): for tests that place the circles as an edge fit errs. 1 with
 * the read in *out (its box u's). */
int rl_local_read_circle(rl_recog *rec, const rl_image *img, const rl_result *res, const rl_detection *u,
                         double R, double cx, double cy, double r, rl_detection *out);

#endif
