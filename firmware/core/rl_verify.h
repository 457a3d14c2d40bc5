/* rl_verify: a predicted landmark's id verified where a tracking window
 * puts it (internal).
 *
 * A tracked frame knows each landmark's id, image centre and radius before
 * reading it (rl_track.h). Instead of the recognizer's full read of a
 * candidate (its box labelled, radius searched along rays), the window is
 * read at the prediction: the centre drawn to the landmark's dark mass
 * (rl_refine_centre, a few steps from the prediction), the profile
 * gathered there at the predicted radius, and the match judged by the
 * global pass's rule (rl_accept) against the ids it could be confused
 * with. Only the predicted id can be confirmed, and only when it leads
 * every id the matcher scores; anything unclear returns 0 and the caller
 * reads the window as today (rl_global_read, rl_local_read).
 *
 *   rl_detection d;
 *   if (rl_verify_read(rec, &img, &res, 17, 320.5, 240.2, 25.4, &d))
 *       use(d.u, d.v);   // id 17 there
 */
#ifndef RL_VERIFY_H
#define RL_VERIFY_H

#include "rl_recog_state.h"

/* 1 when the landmark of `id` predicted at (u, v) with radius r (px) is
 * read there: into *d (centre refined, the predicted radius). 0 when the
 * read is not clear (cut by the border, not found near the prediction,
 * another id or a runner-up too close): read the window in full. res: the
 * frame's levels (the last full frame's). */
int rl_verify_read(const rl_recog *rec, const rl_image *img, const rl_result *res, int id, double u,
                   double v, double r, rl_detection *d);

#endif
