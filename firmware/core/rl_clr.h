/* rl_clr: candidate landmark regions (CLRs) from the dark ROIs, the
 * paper's third step of global recognition (internal).
 *
 * A CLR is a dark region shaped like a landmark's outer ring (with
 * whatever code rings merged into it): landmark-sized, round, filling a
 * ring's share of its bounding box, centroid near the box centre. A
 * region cut by the image border keeps its uncut extent as the diameter.
 * A region next to a light that fails the shape test is kept too, for the
 * local pass: glare may have washed part of an outer ring out; and two
 * arcs of a ring a motion broke are paired into one (one of them may run
 * into the border). A CLR whose box lies inside another's is an inner
 * ring, not a landmark.
 *
 *   static rl_clr cand[RL_MAX_CANDIDATES];
 *   n = rl_clr_find(&lb, &cfg, &res, cand, RL_MAX_CANDIDATES);
 *   for (i = 0; i < n; i++)
 *       if (!rl_clr_is_inner(cand, n, i)) {
 *           rl_clr_geometry(&cand[i].box, W, H, &d);
 *           use(d.u, d.v, d.radius);
 *       }
 */
#ifndef RL_CLR_H
#define RL_CLR_H

#include "rl_label.h"
#include "rl_profile.h"
#include "rl_recog.h"

/* A CLR: its box, and its shape (an ellipse from the region's moments
 * when it is whole and ring-shaped, else the circle). */
typedef struct {
    rl_box box;
    rl_shape shape;
} rl_clr;

/* The CLRs among the regions of lb (the frame's dark labelling), with the
 * radius limits and light distance of cfg (resolved: min_radius and
 * max_radius > 0) and the lights of res; at most cap boxes into cand,
 * the rest counted in res->dropped.candidates. */
int rl_clr_find(const rl_label *lb, const rl_recog_config *cfg, rl_result *res, rl_clr *cand,
                int cap);

/* 1 if cand[i] lies inside another of the n boxes no more than 3.2 times
 * its size, as a code ring lies inside its outer ring (of two equal boxes
 * the later one counts as inside). */
int rl_clr_is_inner(const rl_clr *cand, int n, int i);

/* Centre, radius and visible fraction of a CLR from its box into d: an
 * uncut box is the disk's; a box cut by one image side keeps the true
 * diameter across the cut, and the centre lies one radius in from the far
 * side; a corner cut (two sides) takes its longer side for the diameter,
 * the centre one radius in from both far sides (the local pass fits the
 * circle). */
void rl_clr_geometry(const rl_box *b, int W, int H, rl_detection *d);

#endif
