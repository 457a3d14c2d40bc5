/* rl_twins_cut: whether a cut local read's circle lies on its landmark's
 * outer edge (rl_twins_cut.c says why and when it is judged). Internal:
 * rl_twins_check's.
 *
 *   int on_edge = rl_twins_cut_on_edge(&img, rec->tone, res.levels.light, &res.landmarks[0], 0.0);
 */
#ifndef RL_TWINS_CUT_H
#define RL_TWINS_CUT_H

#include "rl_recog_state.h"

/* Whether the local read d of a landmark the border cuts lies on its
 * outer edge (RL_TWINS_CUT_BULGE), judged only where its radius is
 * RL_TWINS_CUT_SIZE or more over size, the frame's other whole
 * landmarks' median radius (0: none known); tone, light: the frame's curve and light level. */
int rl_twins_cut_on_edge(const rl_image *img, const rl_tone *tone, int light, const rl_detection *d,
                         double size);

#endif
