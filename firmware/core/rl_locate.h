/* rl_locate: a DUCLR's landmark found again in a window of its own, the
 * local pass's extension, local clustering and re-extraction (internal).
 *
 * A window around the candidate, kept out of the lights; a threshold by
 * K-means on the landmark's own square there (stepping towards the ink
 * where the first joins the outer ring to its surroundings); the region
 * taken for the outer ring, one around the candidate's centre before a
 * larger one; and the circle of its visible outer edge, from the
 * region's outline and then along rays from that centre. The frame's
 * dark labelling is reused for the window.
 *
 *   rl_box box;
 *   double cx, cy, r;
 *   if (rl_locate_outer_ring(rec, &img, &res, &res.unidentified[0], 25.0, &box, &cx, &cy, &r))
 *       use(cx, cy, r);
 */
#ifndef RL_LOCATE_H
#define RL_LOCATE_H

#include "rl_recog_state.h"

/* The outer ring of candidate u, landmarks of the frame R px in radius:
 * its box and its circle (*cx, *cy, *r) in the frame; 0 when the window,
 * the threshold, the ring or its edge is not found, or the circle is not
 * of about the frame's size. The circle is the outer edge found along
 * rays from the centre of the region's outline, or from the candidate's
 * centre where none is found and the outline's circle lies over half a
 * radius from it (the region was an arc of a ring motion broke), then
 * only with at least 9 of the 24 rays' edge points within max(1 px, a
 * 25th of its radius) of its circle. Where a
 * code ring was taken for the centre it surrounds, 0 when neither finds
 * the edge. The box is the circle's within the frame, whatever region
 * was taken (the outer ring, a code ring, an arc or a part of a ring
 * motion broke; a cut landmark's is clipped to the frame). */
int rl_locate_outer_ring(rl_recog *rec, const rl_image *img, const rl_result *res,
                         const rl_detection *u, double R, rl_box *box, double *cx, double *cy,
                         double *r);

#endif
