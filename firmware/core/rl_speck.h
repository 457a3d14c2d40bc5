/* rl_speck: the area under which a dark region is a speck, not part of a
 * landmark (internal). Every labelling of the recognizer (the frame's,
 * the second labellings, the local pass's windows) drops regions smaller
 * than it.
 *
 *   int a = rl_speck_area(&cfg);   // 10% of code zone 1 of the smallest landmark
 */
#ifndef RL_SPECK_H
#define RL_SPECK_H

#include "rl_recog.h"

/* Specks: regions smaller than 10% of the narrowest code ring of the
 * smallest landmark considered (the paper's rule), at least 2 px; cfg's
 * min_radius resolved (> 0). */
int rl_speck_area(const rl_recog_config *cfg);

#endif
