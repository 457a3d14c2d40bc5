/* rl_filter: what is done with a frame's identified landmarks after both
 * passes (internal).
 *
 *   rl_filter_duplicates(&res);          // after each pass
 *   rl_filter_size(&res, 0.35);          // then once
 *   rl_filter_sort(&res);
 */
#ifndef RL_FILTER_H
#define RL_FILTER_H

#include "rl_recog.h"

/* Detections that overlap (centres closer than a radius) are one
 * landmark: the better match stays, the others become unidentified. Two
 * landmarks of one id at different places both stay: a large site's map
 * repeats ids, and where it does not the pose finds which one fits. */
void rl_filter_duplicates(rl_result *res);

/* Landmarks in one frame have nearly the same size (the camera faces the
 * ceiling): with three or more identified, one whose radius is more than
 * tolerance times the median away from it becomes unidentified. */
void rl_filter_size(rl_result *res, double tolerance);

/* Identified landmarks in order of u, then v. */
void rl_filter_sort(rl_result *res);

#endif
