/* rl_twins_rank: the rank read of rl_twins_check, blind to the tone curve
 * (rl_rank): whether a landmark's id leads the ids a zone or two from it
 * through any monotone curve, about its centre and, for a whole local
 * read, about its outer edge's centre too (rl_twins_rank.c). Internal:
 * rl_twins_check's.
 *
 *   int kept = rl_twins_rank_keeps(rec, &img, rec->tone, res.levels.light, &res.landmarks[0]);
 */
#ifndef RL_TWINS_RANK_H
#define RL_TWINS_RANK_H

#include "rl_recog_state.h"

/* An outer edge's circle is the same landmark's where its radius is
 * within RL_TWINS_EDGE_RADIUS of the read's (the search reads 0.88 .. 1.06
 * of a fitted one) and its centre within RL_TWINS_EDGE_REACH radii of the
 * read's (not a neighbour's ring). */
#define RL_TWINS_EDGE_RADIUS 0.2
#define RL_TWINS_EDGE_REACH 0.25

/* Whether d's id leads every id two zones from it or fewer by
 * RL_TWINS_RANK_LEAD read through any monotone curve, from gathers
 * through tone (light: the frame's light level). */
int rl_twins_rank_keeps(const rl_recog *rec, const rl_image *img, const rl_tone *tone, int light,
                        const rl_detection *d);

#endif
