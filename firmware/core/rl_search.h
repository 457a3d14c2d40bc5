/* rl_search: the local pass's identification of a DUCLR, searching the
 * centre and radius that fit the likely ids best (internal).
 *
 * Identification runs on sector-normalized grey levels (glare varies by
 * direction), gathered once into polar cells (rl_polar.h) around the edge
 * fit's centre. That centre and radius can be off where glare or the
 * border hides most of the outer edge, and a radius read a few percent
 * short reads the outer ring as a code ring: so the centre and radius that
 * fit the likely ids best are searched, scoring them at the first match's
 * blur: a sweep to a larger radius, then a cross over the centre and one
 * step either way in radius; if the cross's centre stays best, the peak
 * of a parabola through each axis's three scores is tried and the search
 * ends, else a finer cross follows the same way. Every id at every blur
 * is scored at the end, and every id one code zone from the winner (its
 * twins in the two zones next to the outer ring and the ids that differ
 * in an inner zone) at radii around the found one, each at every blur:
 * their best counts as the runner-up.
 *
 *   rl_match m;
 *   rl_match_kept *keep;                              // the caller's memory
 *   if (rl_match_kept_init(&keep, &ws, &tt) == RL_OK) { // once, for tt
 *       rl_search_identify(&tt, pol, keep, &img, &tone, light, 0.75, &cx, &cy, &r, &m);
 *       use(m.id, cx, cy, r);
 *   }
 */
#ifndef RL_SEARCH_H
#define RL_SEARCH_H

#include "rl_match.h"
#include "rl_polar.h"
#include "rl_templates.h"

/* Radius scales (of the found radius) at which the ids one zone from the
 * winner are scored: their best there counts as the runner-up. */
#define RL_SEARCH_TWIN_SCALES 4
extern const double rl_search_twin_scale[RL_SEARCH_TWIN_SCALES];

/* Identify the candidate at (*cx, *cy, *r) with pol and keep as scratch
 * (keep: the first match's column sums, for the ids one zone away; made
 * by rl_match_kept_init for tt); the
 * centre and radius are updated to the best fit, the match of every id
 * there is in *m (m->id < 0: nothing matched). The ids one zone from
 * the winner are scored only when it scores at least min_score (the rule's): under
 * it no rule takes the match whatever its runner-up, and m->second is the
 * runner-up over every id alone (-INFINITY: always scored). */
void rl_search_identify(const rl_templates *tt, rl_polar *pol, rl_match_kept *keep, const rl_image *img,
                        const rl_tone *tone, int light, double min_score, double *cx, double *cy,
                        double *r, rl_match *m);

/* rl_search_identify that reads no further where neither the first match
 * (every id at every blur at (*cx, *cy, *r) as given) nor the search's
 * first step (its likely ids at that blur, the radius 1.06 times
 * larger: the step for edge fits glare makes short) scores min_first: 0
 * then, the first match in *m and the circle unchanged; else 1 and the
 * whole search (also when nothing matched, m->id < 0). */
int rl_search_identify_over(const rl_templates *tt, rl_polar *pol, rl_match_kept *keep, const rl_image *img,
                            const rl_tone *tone, int light, double min_first, double min_score, double *cx,
                            double *cy, double *r, rl_match *m);

/* The match of the candidate pol holds, at (cx, cy, r) after
 * rl_search_identify, read along one axis at a time: across a motion the
 * rings are sharp and the code plain where the full circle averages it
 * with the smeared directions. reads[0 .. n_reads - 1] are octant masks
 * (rl_polar_profile_octants): an axis, or the half of one in the frame.
 * Of the reads whose best id is `id`, the one where it leads its
 * runner-up (every id one zone from it there included) most, into *m;
 * m->id < 0 when none reads `id` at a blur level up to max_blur (a read
 * along the motion matches the softest). keep is scratch, as
 * rl_search_identify's. */
void rl_search_across_motion(const rl_templates *tt, const rl_polar *pol, rl_match_kept *keep, double cx,
                             double cy, double r, int id, int max_blur, const unsigned *reads, int n_reads,
                             rl_match *m);

#endif
