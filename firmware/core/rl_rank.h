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
 * A decision needs only whether a score passes a bar: the regression's
 * error over a prefix of the order never exceeds its error over the
 * whole, and a template of values in 0 .. 1 spreads at most a quarter of
 * the weight, so a score under the bar shows as soon as the error passes
 * (1 - bar) / 4 of it (most ids a few bins in); rl_rank_any_over first
 * pools every blur of an id side by side with one block each, merged
 * while the bins come in under its mean (merges the regression makes
 * too, so their error is no more than its), and runs the regression only
 * for the blurs that bound leaves.
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
    double sw; /* pixels in all */
} rl_rank_order;

/* Order p's non-empty bins by mean darkness (ties by radius). */
void rl_rank_sort(const rl_profile *p, rl_rank_order *ord);

/* The score of the i-th id of tt at blur level `blur` (0 .. 1, 1 when a
 * nondecreasing curve maps the profile onto the template exactly; 0 for
 * a flat template or fewer than 3 bins; the table's values in 0 .. 1). */
double rl_rank_score(const rl_templates *tt, const rl_rank_order *ord, int i, int blur);

/* The same score where it is over bar; a value under bar otherwise,
 * returned as soon as the regression's error says so. */
double rl_rank_score_over(const rl_templates *tt, const rl_rank_order *ord, int i, int blur, double bar);

/* 1 when the i-th id of tt scores over bar at some blur level. */
int rl_rank_any_over(const rl_templates *tt, const rl_rank_order *ord, int i, double bar);

#endif
