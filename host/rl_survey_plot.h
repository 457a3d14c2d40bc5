/* rl_survey_plot: a picture of a survey (PNG, cairo): the landmarks with
 * their ids and uncertainty ellipses (3 sigma, enlarged by a stated
 * factor so that they show), the drive (the camera's path, frames left
 * out as crosses), the origin and axis, and moved landmarks in red with
 * an arrow from their old place.
 *
 *   static rl_survey sv;
 *   char err[256];
 *   if (rl_survey_plot("survey.png", &sv, NULL, 0, err, sizeof err) != RL_OK)
 *       use(err);
 */
#ifndef RL_SURVEY_PLOT_H
#define RL_SURVEY_PLOT_H

#include <stddef.h>
#include "rl_survey.h"
#include "rl_survey_moved.h"

RL_CHECK rl_err rl_survey_plot(const char *path, const rl_survey *sv, const rl_survey_move *mv, int n_mv,
                               char *err, size_t errlen);

#endif
