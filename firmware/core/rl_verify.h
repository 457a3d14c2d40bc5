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
 * pass's rule (rl_accept): first against the id's rivals (the ids whose
 * templates come close to its own, found once per id) with every other
 * id's score bounded by how far its templates lie; when that is not clear,
 * against every id at every blur, as the global pass matches. Only the
 * predicted id can be confirmed, and only where the recognizer's own rule
 * would take it over every id; anything unclear returns 0, and the caller
 * reads the window as before (rl_global_read, rl_local_read).
 *
 *   static uint64_t rivals[RL_VERIFY_MASK_WORDS];
 *   rl_detection d;
 *   if (rl_verify_rivals(&rec->templates, 17, rivals) &&
 *       rl_verify_read(rec, &img, &res, 17, 320.5, 240.2, 25.4, rivals, &d))
 *       use(d.u, d.v);   // id 17 there
 */
#ifndef RL_VERIFY_H
#define RL_VERIFY_H

#include <stdint.h>
#include "rl_recog_state.h"

/* Words of a rival mask: bit i % 64 of word i / 64 stands for the
 * templates' i-th id (rl_templates.ids). */
#define RL_VERIFY_MASK_WORDS ((RL_MAX_IDS + 63) / 64)

/* The ids a read of `id` could be confused with (rl_verify.c: their
 * templates come close to its own), into mask; 0 (mask empty) when tt
 * does not hold id. */
int rl_verify_rivals(const rl_templates *tt, int id, uint64_t *mask);

/* 1 when the landmark of `id` predicted at (u, v) with radius r (px) is
 * read there: into *d (centre refined, the radius within a few percent of
 * r). rivals: id's (rl_verify_rivals), matched first, the rest bounded
 * (rl_verify.c); NULL: every id matched. 0 when the
 * read is not clear (cut by the border, not found near the prediction,
 * another id or a runner-up too close): read the window in full. res: the
 * frame's levels (the last full frame's). */
int rl_verify_read(const rl_recog *rec, const rl_image *img, const rl_result *res, int id, double u,
                   double v, double r, const uint64_t *rivals, rl_detection *d);

#endif
