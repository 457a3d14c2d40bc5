/* rl_global: the global pass's identification of one CLR, the paper's
 * fourth step (internal).
 *
 *   rl_clr c;
 *   c.box.x0 = 100; c.box.y0 = 80; c.box.x1 = 150; c.box.y1 = 131;   // an outer CLR
 *   c.shape = rl_shape_circle();
 *   rl_global_identify(rec, &img, &c, &res);
 */
#ifndef RL_GLOBAL_H
#define RL_GLOBAL_H

#include "rl_clr.h"
#include "rl_recog_state.h"

/* Place the CLR of box b (centre and radius refined on the grey levels),
 * identify it if it is closed (complete, or with at most a sliver cut by
 * the border) and add it to res as a landmark or as unidentified. Corner
 * cuts are not candidates. */
void rl_global_identify(const rl_recog *rec, const rl_image *img, const rl_clr *c, rl_result *res);

#endif
