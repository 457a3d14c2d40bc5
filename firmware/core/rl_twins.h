/* rl_twins: while the camera's tone curve is still being learned
 * (rl_tones.h), a landmark of the local pass (cut by the border or next to
 * a light, read from sector-normalized levels, where a wrong curve does
 * most harm) keeps its id only if none of its zone twins
 * (the codes one zone next to the outer ring away, which a wrong curve
 * turns it into) reads better through the other curve (internal).
 *
 *   const rl_tone *other = rl_tones_doubt(&rec->tones, rec->tone);
 *   if (other != NULL)
 *       rl_twins_check(rec, &img, other, &res);   // after both passes
 */
#ifndef RL_TWINS_H
#define RL_TWINS_H

#include "rl_recog_state.h"

/* Each landmark of res the local pass identified scored, with its zone twins, through
 * `other` at its centre and radius (and 3% either side); one a twin beats
 * there becomes unidentified. */
void rl_twins_check(const rl_recog *rec, const rl_image *img, const rl_tone *other, rl_result *res);

#endif
