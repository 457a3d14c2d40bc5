/* rl_verify: a predicted landmark's id verified where a tracking window
 * puts it (internal).
 *
 * A tracked frame knows each landmark's id, image centre and radius before
 * reading it (rl_track.h). Instead of the recognizer's full read of a
 * candidate (its box's radius searched along rays, or a window labelled
 * and its ring fitted), the landmark is read at the prediction: its
 * centre drawn to its ink (rl_refine_centre over a disk a little larger
 * than the landmark, counting only what is darker than midway to the ink;
 * one step when the prediction is a few pixels off), the profile gathered
 * there once, a little wider than the predicted radius, and read at the
 * predicted radius or the one a few percent either side where the id
 * matches best (rl_profile_rescale). The match is judged by the global
 * pass's rule (rl_accept) against every id at every blur, as the global
 * pass matches, and a code ring of a larger landmark is not taken (as the
 * global pass drops one); the frame's reads then go through the zone
 * twins' check as a full frame's do (rl_track). Only the predicted id can
 * be confirmed, and only where the recognizer's own rule would take it
 * over every id; anything unclear returns 0, and the caller reads the
 * window as before (rl_global_read, rl_local_read).
 *
 *   rl_detection d;
 *   int away;
 *   if (rl_verify_read(rec, &img, &res, 17, 0, 320.5, 240.2, 25.4, &d, &away))
 *       use(d.u, d.v);   // id 17 there
 *   else if (away)
 *       use(0);          // its ink is not near the prediction
 */
#ifndef RL_VERIFY_H
#define RL_VERIFY_H

#include "rl_recog_state.h"

/* The radii a window's profile is read at, worked out once into
 * rec->verify_scales (rl_recog_init calls it). A recognizer without them
 * (zeroed) reads the same, rescaling by division. */
void rl_verify_init(rl_recog *rec);

/* 1 when the landmark of `id` predicted at (u, v) with radius r (px) is
 * read there, into *d (centre refined, the radius within a few percent
 * of r). known 1: the track already knows the landmark there (read in
 * the frame before, by windows or in full, its pose taken): when id's templates score
 * RL_RIVALS_TAKEN or more and the map holds rivals of id, id is judged
 * against its rivals alone (rl_rivals.h: the ids whose landmark can score
 * that high as id; the runner-up reported is theirs) instead of every id.
 * known 0: every id, always. Returns 0 when the read is not clear (cut by the border, not found near the
 * prediction, another id or a runner-up too close, a zone twin that fits
 * as well at its own best radius, a code ring): read the
 * window in full. res: the frame's levels (the last full frame's).
 * *away (when not NULL) is 1 when the read failed because the centre,
 * drawn to the ink, left the prediction by more than 1.5 radii, or there
 * was nothing darker than midway grey within 2.5 radii of it. A hint, not
 * a proof that the landmark is not near: a centre can settle just past
 * 1.5 radii off a landmark that is within them, and a faint landmark can
 * have nothing under midway grey (rl_track reads such a window the costly
 * way); on failure d's id, score and runner-up are unspecified. */
int rl_verify_read(const rl_recog *rec, const rl_image *img, const rl_result *res, int id, int known,
                   double u, double v, double r, rl_detection *d, int *away);

/* The same read of a landmark next to the border (the centre step's disk
 * would leave the frame: rl_verify_read gives no read there), its centre
 * the circle through its outer edge's visible part (rl_edge_fit_rays, from
 * the prediction, fitted twice, its radius within 10% of r, within 1.5
 * radii of the prediction); then gathered, judged and checked as
 * rl_verify_read's (known as there). 0 at once for a prediction clear of the border (1.2
 * radii of room). The caller uses it for a window the costly reads would
 * otherwise take (rl_track). */
int rl_verify_read_border(const rl_recog *rec, const rl_image *img, const rl_result *res, int id, int known,
                          double u, double v, double r, rl_detection *d);

#endif
