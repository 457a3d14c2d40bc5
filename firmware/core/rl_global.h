/* rl_global: the global pass's identification of one CLR, the paper's
 * fourth step (internal).
 *
 *   rl_clr c;
 *   c.box.x0 = 100; c.box.y0 = 80; c.box.x1 = 150; c.box.y1 = 131;   // an outer CLR
 *   c.shape = rl_shape_circle();
 *   rl_detection d;
 *   rl_global_read(rec, &img, &c, rec->tone, &res, &d);
 *   use(d.id, d.score);   // d.id -1: a candidate, not identified
 */
#ifndef RL_GLOBAL_H
#define RL_GLOBAL_H

#include "rl_clr.h"
#include "rl_recog_state.h"

/* Place the CLR c (centre and radius refined on the grey levels and, for
 * the radius, light through tone), and identify it through tone if it is
 * closed (complete, or with at most a sliver cut by the border): into *d,
 * its id -1 when not identified (a corner cut never: the local pass reads
 * it). res: the frame's levels and lights so far. */
void rl_global_read(const rl_recog *rec, const rl_image *img, const rl_clr *c, const rl_tone *tone,
                   const rl_result *res, rl_detection *d);

/* rl_global_read of c with its centre given: (u, v), where rl_global_read
 * through any curve placed it (its d->u, d->v: the centre is refined on
 * the grey levels alone, the same through every curve); the same read,
 * without refining the centre again; for the tone reads' count (its
 * twins_led not read). */
void rl_global_read_placed(const rl_recog *rec, const rl_image *img, const rl_clr *c, const rl_tone *tone,
                           const rl_result *res, double u, double v, rl_detection *d);

/* 1 when rl_global_read may identify the CLR c in a W x H frame (its box
 * leaves it closed: complete, or with at most a sliver cut by the
 * border); 0 when its read's id is -1 through any curve. */
int rl_global_readable(const rl_clr *c, int W, int H);

#endif
