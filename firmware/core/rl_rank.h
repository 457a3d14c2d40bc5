/* rl_rank: how well a template explains a profile through any monotone
 * tone curve (internal).
 *
 * Blur mixes light before the camera's curve or grey levels after it; a
 * printed landmark is two levels (ink and paper), so under either the
 * profile is some monotone function of the template blurred the same way,
 * in light or in grey levels. Pearson's r fixes that function to be a
 * line (the formation the frame is read through); here it is any
 * nondecreasing one: the template is regressed on the profile's bin
 * means by isotonic regression (pool adjacent violators), and the score
 * is the share of the template's spread that explains, 1 - SSE / SST. A
 * wrong formation bends every edge the same way, which a monotone curve
 * takes back: so the zone twins a formation makes cannot lead here.
 *
 *   rl_rank_order ord;
 *   rl_rank_sort(&p, &ord);                    // once per profile
 *   use(rl_rank_score(&tt, &ord, i, 0));       // per template: id tt.ids[i], blur 0
 */
#ifndef RL_RANK_H
#define RL_RANK_H

#include "rl_profile.h"
#include "rl_templates.h"

/* A profile's non-empty bins in order of their mean darkness. */
typedef struct {
    int bin[RL_PROFILE_BINS];
    double w[RL_PROFILE_BINS]; /* pixels in that bin */
    int n;
} rl_rank_order;

/* Order p's non-empty bins by mean darkness (ties by radius). */
void rl_rank_sort(const rl_profile *p, rl_rank_order *ord);

/* The score of the i-th id of tt at blur level `blur` (0 .. 1, 1 when a
 * nondecreasing curve maps the profile onto the template exactly; 0 for
 * a flat template or fewer than 3 bins). */
double rl_rank_score(const rl_templates *tt, const rl_rank_order *ord, int i, int blur);

#endif
