/* rl_twins_cut: whether a cut local read's circle lies on its landmark's
 * outer edge (rl_twins_cut.c says why and when it is judged), and how
 * much of its code zone 1 the frame shows; a small cut global read's twins
 * at 9%. Internal: rl_twins_check's.
 *
 *   int on_edge = rl_twins_cut_on_edge(&img, rec->tone, res.levels.light, &res.landmarks[0], 0.0);
 *   double shown = rl_twins_cut_zone1_shown(&img, &rec->templates.fam, &res.landmarks[0]);
 */
#ifndef RL_TWINS_CUT_H
#define RL_TWINS_CUT_H

#include "rl_recog_state.h"

/* Whether the local read d of a landmark the border cuts lies on its
 * outer edge (RL_TWINS_CUT_BULGE), judged only where its radius is
 * RL_TWINS_CUT_SIZE or more over size, the frame's other whole
 * landmarks' median radius (0: none known); tone, light: the frame's curve and light level. */
int rl_twins_cut_on_edge(const rl_image *img, const rl_tone *tone, int light, const rl_detection *d,
                         double size);

/* The share of d's code zone 1 (of family fam; the zone next to the
 * outer ring, whose bit tells the zone twins 16 apart in ring5) inside
 * the frame of img, by its middle circle on d's circle (128 points). */
double rl_twins_cut_zone1_shown(const rl_image *img, const rl_family *fam, const rl_detection *d);

/* 1 where d, a small read, may keep its id as a cut global read in a
 * frame read through a curve (curved): its rivals rv[0 .. n) at 0.91 ..
 * 1.09 of its radius through rec's own curve do not lead it (rl_twins_lead,
 * far); 1 without a look for a whole, local or linear read. */
int rl_twins_cut_global_fits(const rl_recog *rec, const rl_image *img, const rl_detection *d, const int *rv, int n,
                             int curved);

#endif
