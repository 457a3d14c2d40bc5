/* rl_result_*: adding to a frame's result within its limits (internal).
 * What does not fit is counted in res->dropped, never cut silently.
 *
 *   rl_result_clear(&res, 640, 480);
 *   if (!rl_result_add_landmark(&res, &d))
 *       use(res.dropped.landmarks);      // it did not fit, and is counted
 */
#ifndef RL_RESULT_H
#define RL_RESULT_H

#include "rl_recog.h"

/* Empty result for a W x H frame (the large arrays are not touched). */
void rl_result_clear(rl_result *res, int W, int H);

/* Append an identified landmark; 0 (and counted) when the list is full. */
int rl_result_add_landmark(rl_result *res, const rl_detection *d);

/* Append an unidentified candidate (its id set to -1); 0 (and counted)
 * when the list is full. */
int rl_result_add_unidentified(rl_result *res, const rl_detection *d);

/* Append a light source's box; 0 (and counted) when the list is full. */
int rl_result_add_light(rl_result *res, const rl_box *b);

/* Median radius of the identified landmarks (ICLRs), or 0. */
double rl_result_median_radius(const rl_result *res);

/* Gap in pixels between a box and the nearest light (1e9 with no light). */
double rl_result_light_gap(const rl_result *res, const rl_box *b);

#endif
