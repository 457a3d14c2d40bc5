/* rl_survey_moved: which landmarks moved since an older map.
 *
 * The survey's landmarks are paired with the old map's by id (the nearest
 * of that id where a site repeats ids). The new map is fitted onto the
 * old by a similarity (rotation, shift, scale: two surveys' scales differ
 * a little), robustly: pairs that disagree are left out of the fit and
 * the fit redone. A landmark moved when its distance from its old place
 * after the fit is more than `sigmas` times the standard deviation of
 * that distance: both maps' covariances along it (at least the typical
 * landmark's: the origin and axis have none in their own maps), and the
 * fit's own spread (the landmarks' median distance after the fit, which
 * holds what the covariances do not: systematic differences between two
 * drives).
 *
 *   static rl_survey sv;
 *   rl_survey_move mv[16];
 *   int n = rl_survey_moved(&sv, &map, 3.0, mv, 16);
 *   if (n > 0)
 *       use(mv[0].id, mv[0].distance);
 */
#ifndef RL_SURVEY_MOVED_H
#define RL_SURVEY_MOVED_H

#include "rl_map.h"
#include "rl_survey.h"

typedef struct {
    int id;
    double x, y;         /* where the survey put it */
    double old_x, old_y; /* where the old map had it, in the survey's frame */
    double distance;     /* m */
    double sigmas;       /* distance / its standard deviation */
} rl_survey_move;

/* The moved landmarks, the most sigmas first, up to max into mv; how
 * many it stored (-1 out of memory). Landmarks only one of the maps has
 * are not counted. */
int rl_survey_moved(const rl_survey *sv, const rl_map *old, double sigmas, rl_survey_move *mv, int max);

#endif
